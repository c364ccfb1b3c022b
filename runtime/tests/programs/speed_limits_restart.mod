MODULE speed_limits_restart
  ! SpeedLimAxis and SpeedLimCheckPoint set the speeds the controller keeps
  ! to while it limits speed, which the simulation never does: traced, the
  ! robot is not slowed; a negative limit is an argument error. WarmStart
  ! restarts the controller: the program stops there.
  PROC main()
    SpeedLimAxis ROB_1, 1, 10;
    SpeedLimCheckPoint 250;
    TPWrite "set";
    SpeedLimCheckPoint -1;
  ERROR
    TPWrite "negative "\Bool:=ERRNO = ERR_ARGVALERR;
    WarmStart;
    TPWrite "never";
  ENDPROC
ENDMODULE
!> [SpeedLimAxis at speed_limits_restart.mod:7] axis 1 at most 10 while the controller limits speed, which the simulation never does
!> [SpeedLimCheckPoint at speed_limits_restart.mod:8] the check points at most 250 while the controller limits speed, which the simulation never does
!> set
!> negative TRUE
!> [WarmStart at speed_limits_restart.mod:13] the controller restarts; the program stops
!! stopped at 13
