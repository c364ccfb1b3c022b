MODULE load_modules
  ! Modules loaded while the program runs: a part program is written to a
  ! file, loaded, run by late binding, unloaded; the next part program
  ! declares the same routine. ModExist, ERR_FILNOTFND, ERR_LOADED,
  ! ERR_SYNTAX, ERR_UNLOAD; StartLoad and WaitLoad; Save to the file a
  ! module was loaded from (persistents at their values); a persistent of
  ! an unloaded module starts again at its declared value when loaded
  ! again.
  VAR iodev f;
  VAR loadsession session;
  VAR num stage;

  PROC main()
    write_part "part1.mod", "Part1", "first";
    write_part "part2.mod", "Part2", "second";
    TPWrite "before "\Bool:=ModExist("Part1");
    Load \Dynamic, "HOME:" \File:="part1.mod";
    TPWrite "loaded "\Bool:=ModExist("Part1");
    %"part_main"%;
    UnLoad "HOME:" \File:="part1.mod";
    TPWrite "unloaded "\Bool:=ModExist("Part1");
    StartLoad \Dynamic, "HOME:/part2.mod", session;
    WaitLoad session;
    %"part_main"%;
    Save "Part2";
    UnLoad "HOME:/part2.mod";
    Open "HOME:/part2.mod", f \Read;
    TPWrite "saved: " + ReadStr(f);
    TPWrite "saved: " + ReadStr(f);
    Close f;
    stage := 1;
    Load "HOME:/missing.mod";
    stage := 2;
    Load "HOME:/part1.mod";
    %"part_main"%;
    Load "HOME:/part1.mod";
    stage := 3;
    UnLoad "HOME:/part1.mod";
    Open "HOME:/bad.mod", f \Write;
    Write f, "MODULE Bad";
    Write f, "  PROC x() TPWrite ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/bad.mod";
    stage := 4;
    UnLoad "HOME:/never.mod";
  ERROR
    TEST ERRNO
    CASE ERR_FILNOTFND:
      TPWrite "not found "\Num:=stage;
    CASE ERR_LOADED:
      TPWrite "already loaded "\Num:=stage;
    CASE ERR_SYNTAX:
      TPWrite "syntax "\Num:=stage;
    CASE ERR_UNLOAD:
      TPWrite "not loaded "\Num:=stage;
      RETURN;
    ENDTEST
    TRYNEXT;
  ENDPROC

  PROC write_part(string file, string name, string word)
    Open "HOME:" \File:=file, f \Write;
    Write f, "MODULE " + name;
    Write f, "  PERS num runs" + name + " := 10;";
    Write f, "  PROC part_main()";
    Write f, "    Incr runs" + name + ";";
    Write f, "    TPWrite \22" + name + " " + word + " \22\\Num:=runs" + name + ";";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
  ENDPROC
ENDMODULE";
    Close f;
  ENDPROC
ENDMODULE
!> before FALSE
!> [Load at load_modules.mod:17] Part1 from HOME:part1.mod
!> loaded TRUE
!> Part1 first 11
!> [UnLoad at load_modules.mod:20] Part1
!> unloaded FALSE
!> [WaitLoad at load_modules.mod:23] Part2 from HOME:/part2.mod
!> Part2 second 11
!> [UnLoad at load_modules.mod:26] Part2
!> saved: MODULE Part2
!> saved:   PERS num runsPart2 := 11;
!> not found 1
!> [Load at load_modules.mod:34] Part1 from HOME:/part1.mod
!> Part1 first 11
!> already loaded 2
!> [UnLoad at load_modules.mod:38] Part1
!> syntax 3
!> not loaded 4
