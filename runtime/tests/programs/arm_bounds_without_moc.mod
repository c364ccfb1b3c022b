MODULE arm_bounds_without_moc
  ! A program kept without its MOC.cfg reads its arm's working range from
  ! the ARM instances as a controller has them (radians): the modelled
  ! robot's (IRB 1600-10/1.45: axis 1 -180 to 180, axis 3 -245 to 65
  ! degrees). Another attribute, or a robot the controller does not have,
  ! is still not in the configuration.
  !robot IRB 1600-10/1.45
  VAR num upper;
  VAR num lower;

  PROC main()
    ReadCfgData "/MOC/ARM/rob1_1", "upper_joint_bound", upper;
    TPWrite "axis 1 up to "\Num:=upper;
    ReadCfgData "/MOC/ARM/rob1_3", "lower_joint_bound", lower;
    TPWrite "axis 3 down to "\Num:=lower;
    TPWrite "in degrees "\Num:=Round(lower * 180 / pi);
    ReadCfgData "/MOC/ARM/rob2_1", "upper_joint_bound", upper;
  ERROR
    TPWrite "rob2 "\Bool:=ERRNO = ERR_CFG_NOTFND;
  ENDPROC
ENDMODULE
!> axis 1 up to 3.14159
!> axis 3 down to -4.27606
!> in degrees -245
!> rob2 TRUE
