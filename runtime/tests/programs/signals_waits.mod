MODULE signals_waits
  ! Signals start at zero; outputs set by the program; inputs scripted;
  ! WaitDI, WaitUntil with \MaxTime and \TimeFlag.
  !set di_ready=1@4
  !set do_lamp=0
  !set gi_code=5
  VAR bool late;

  PROC main()
    TPWrite "ready at start "\Num:=di_ready;
    SetDO do_lamp, 1;
    TPWrite "lamp "\Num:=DOutput(do_lamp);
    IF do_lamp = 1 TPWrite "lamp is on";
    Reset do_lamp;
    TPWrite "group "\Num:=GInput(gi_code);
    WaitUntil di_ready = 1\MaxTime:=1\TimeFlag:=late;
    TPWrite "timed out "\Bool:=late;
    WaitDI di_ready, 1;
    TPWrite "ready"\Num:=di_ready;
    WaitDI di_ready, 0\MaxTime:=0.5;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      TPWrite "gave up waiting";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
!> ready at start 0
!> lamp 1
!> lamp is on
!> group 5
!> timed out TRUE
!> ready1
!> gave up waiting
!> not reached
