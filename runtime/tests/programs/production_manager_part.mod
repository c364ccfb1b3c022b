MODULE production_manager_part
  ! ExecEngine: an answer that names no procedure without parameters
  ! stops the run at the engine, naming what was expected.
  !answer Weld
  PROC main()
    ExecEngine;
  ENDPROC

  PROC Weld(num seam)
    TPWrite "seam "\Num:=seam;
  ENDPROC
ENDMODULE
!! operator at 6
