MODULE mech_units
  ! Mechanical units activated and deactivated (every unit is active at
  ! the start); MotionSup is accepted.
  PROC main()
    TPWrite "at start "\Bool:=IsMechUnitActive(ROB_1);
    DeactUnit ROB_1;
    TPWrite "deactivated "\Bool:=IsMechUnitActive(ROB_1);
    ActUnit ROB_1;
    TPWrite "activated "\Bool:=IsMechUnitActive(ROB_1);
    MotionSup \On \TuneValue:=150;
  ENDPROC
ENDMODULE
!> at start TRUE
!> deactivated FALSE
!> activated TRUE
