MODULE unload_out_of_order
  ! Modules unloaded in another order than they were loaded: unloading the
  ! first of two loaded modules leaves the second loaded, its routines
  ! callable and its data (a variable, a persistent) at the values they
  ! had; the first's routine is gone.
  VAR iodev f;

  PROC main()
    write_part "liba.mod", "LibA", "a";
    write_part "libb.mod", "LibB", "b";
    Load \Dynamic, "HOME:/liba.mod";
    Load \Dynamic, "HOME:/libb.mod";
    %"bump_a"%;
    %"bump_b"%;
    %"bump_b"%;
    UnLoad "HOME:/liba.mod";
    TPWrite "LibA "\Bool:=ModExist("LibA");
    TPWrite "LibB "\Bool:=ModExist("LibB");
    %"bump_b"%;
    %"bump_a"%;
  ERROR
    TPWrite "gone "\Bool:=ERRNO = ERR_REFUNKPRC;
    UnLoad "HOME:/libb.mod";
    TPWrite "LibB "\Bool:=ModExist("LibB");
  ENDPROC

  PROC write_part(string file, string modname, string tag)
    Open "HOME:/" + file, f \Write;
    Write f, "MODULE " + modname;
    Write f, "  VAR num calls := 0;";
    Write f, "  PERS num total_" + tag + " := 0;";
    Write f, "  PROC bump_" + tag + "()";
    Write f, "    Incr calls;";
    Write f, "    total_" + tag + " := total_" + tag + " + 10;";
    Write f, "    TPWrite """ + tag + " ""\\Num:=calls * 100 + total_" + tag + ";";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
  ENDPROC
ENDMODULE
!> [Load at unload_out_of_order.mod:11] LibA from HOME:/liba.mod
!> [Load at unload_out_of_order.mod:12] LibB from HOME:/libb.mod
!> a 110
!> b 110
!> b 220
!> [UnLoad at unload_out_of_order.mod:16] LibA
!> LibA FALSE
!> LibB TRUE
!> b 330
!> gone TRUE
!> [UnLoad at unload_out_of_order.mod:23] LibB
!> LibB FALSE
