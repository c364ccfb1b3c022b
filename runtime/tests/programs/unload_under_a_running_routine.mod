MODULE unload_under_a_running_routine
  ! A routine of a module loaded later unloads one loaded before it: the
  ! later module would be laid out again under its own running routine,
  ! which the simulation does not do; the run stops there.
  VAR iodev f;

  PROC main()
    Open "HOME:/first.mod", f \Write;
    Write f, "MODULE First";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/second.mod", f \Write;
    Write f, "MODULE Second";
    Write f, "  PROC drop_first()";
    Write f, "    UnLoad ""HOME:/first.mod"";";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load \Dynamic, "HOME:/first.mod";
    Load \Dynamic, "HOME:/second.mod";
    %"drop_first"%;
  ENDPROC
ENDMODULE
!> [Load at unload_under_a_running_routine.mod:19] First from HOME:/first.mod
!> [Load at unload_under_a_running_routine.mod:20] Second from HOME:/second.mod
!! unsupported: UnLoad of a module loaded before one whose routine is running at 3
