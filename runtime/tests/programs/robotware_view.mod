MODULE robotware_view
  ! The task's catalogue is the view of its RobotWare version: accdata has
  ! no finepramp component before RobotWare 5, so its value has two.
  !robotware 4.0
  PROC main()
    VAR accdata a;
    TPWrite ValToStr(a);
    !> [0,0]
  ENDPROC
ENDMODULE
