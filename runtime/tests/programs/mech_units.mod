MODULE mech_units
  ! Mechanical units activated and deactivated (every unit is active at
  ! the start); MotionSup is accepted; GetMecUnitName names a unit.
  PROC main()
    TPWrite "at start "\Bool:=IsMechUnitActive(ROB_1);
    DeactUnit ROB_1;
    TPWrite "deactivated "\Bool:=IsMechUnitActive(ROB_1);
    ActUnit ROB_1;
    TPWrite "activated "\Bool:=IsMechUnitActive(ROB_1);
    MotionSup \On \TuneValue:=150;
    TPWrite "name " + GetMecUnitName(ROB_1);
    show_name ROB_1;
  ENDPROC

  PROC show_name(VAR mecunit unit)
    TPWrite "through a parameter " + GetMecUnitName(unit);
  ENDPROC
ENDMODULE
!> at start TRUE
!> deactivated FALSE
!> activated TRUE
!> name ROB_1
!> through a parameter ROB_1
