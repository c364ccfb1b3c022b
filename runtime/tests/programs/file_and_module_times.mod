MODULE file_and_module_times
  ! FileTime and ModTime on the simulated clock (runs start on 2024-01-01,
  ! 1704067200 s after 1970; a num holds such a time to 128 s, so 300 s
  ! later reads 256 s later, as on the controller): a file
  ! the run has not written dates from the start, as do the program's own
  ! modules; a module loaded later has its load time, and a file written
  ! after it is newer, so the manual's "reload if newer" loop reloads it
  ! once. A file that does not exist is ERR_FILEACC, a module that is not
  ! loaded ERR_MODULE.
  VAR iodev f;
  VAR num reloads := 0;

  PROC main()
    TPWrite "start "\Bool:=ModTime("file_and_module_times") = 1704067200;
    write_part "before";
    TPWrite "written at the start "\Bool:=FileTime("HOME:/part.mod" \ModifyTime) = ModTime("file_and_module_times");
    WaitTime 300;
    Load "HOME:/part.mod";
    TPWrite "loaded after 5 minutes "\Num:=ModTime("Part") - ModTime("file_and_module_times");
    TPWrite "not newer "\Bool:=FileTime("HOME:/part.mod" \ModifyTime) > ModTime("Part");
    WaitTime 600;
    write_part "after";
    TPWrite "written later, newer "\Bool:=FileTime("HOME:part.mod") > ModTime("Part");
    TPWrite "read then "\Num:=FileTime("HOME:/part.mod" \AccessTime) - ModTime("Part");
    IF FileTime("HOME:/part.mod" \ModifyTime) > ModTime("Part") THEN
      UnLoad "HOME:/part.mod";
      Load "HOME:/part.mod";
      Incr reloads;
    ENDIF
    TPWrite "reloads "\Num:=reloads;
    TPWrite "missing "\Num:=FileTime("HOME:/none.txt");
    TPWrite "no module "\Num:=ModTime("Nowhere");
  ERROR
    IF ERRNO = ERR_FILEACC THEN
      TPWrite "no such file";
    ELSEIF ERRNO = ERR_MODULE THEN
      TPWrite "no such module";
    ENDIF
    TRYNEXT;
  ENDPROC

  PROC write_part(string word)
    Open "HOME:/part.mod", f \Write;
    Write f, "MODULE Part";
    Write f, "  CONST string word := """ + word + """;";
    Write f, "ENDMODULE";
    Close f;
  ENDPROC
ENDMODULE
!> start TRUE
!> written at the start TRUE
!> [Load at file_and_module_times.mod:18] Part from HOME:/part.mod
!> loaded after 5 minutes 256
!> not newer FALSE
!> written later, newer TRUE
!> read then 640
!> [UnLoad at file_and_module_times.mod:26] Part
!> [Load at file_and_module_times.mod:27] Part from HOME:/part.mod
!> reloads 1
!> no such file
!> no such module
