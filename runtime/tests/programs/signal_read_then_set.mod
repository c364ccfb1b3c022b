MODULE signal_read_then_set
  ! Without an EIO.cfg, a name compared first and set later is the output
  ! the setting use says it is (a digital output, which reads back what
  ! was set), not the input the comparison alone would take it for.
  PROC main()
    IF doLamp = 0 SetDO doLamp, 1;
    TPWrite "lamp "\Num:=DOutput(doLamp);
    WaitUntil doLamp = 1;
    TPWrite "lit";
  ENDPROC
ENDMODULE
!> lamp 1
!> lit
