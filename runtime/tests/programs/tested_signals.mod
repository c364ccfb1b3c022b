MODULE tested_signals
  ! Without an EIO.cfg, a TEST of a name declared nowhere whose CASE
  ! values are numbers reads a signal: a group input when a value is past
  ! 0 and 1, else a digital input (0 until the script sets it).
  !set partSensor=1@2
  PROC main()
    TEST recipe
    CASE 0:
      TPWrite "no recipe";
    CASE 2, 3:
      TPWrite "recipe "\Num:=recipe;
    ENDTEST
    TEST partSensor
    CASE 1:
      TPWrite "part";
    DEFAULT:
      TPWrite "no part yet";
    ENDTEST
    WaitTime 2;
    TEST partSensor
    CASE 1:
      TPWrite "part";
    ENDTEST
  ENDPROC
ENDMODULE
!> no recipe
!> no part yet
!> part
