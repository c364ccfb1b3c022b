MODULE mech_unit_list
  ! GetNextMechUnit goes through MOC.cfg's mechanical units in order: a
  ! robot (its joints counted), a track of one single; \TCPRob, \NoOfAxes,
  ! \Active and \MecRef answer for each; past the last it is FALSE with
  ! an empty name. \MecTaskNo is not simulated.
  !cfg MOC:CFG_1.0:6:0::
  !cfg MECHANICAL_UNIT:
  !cfg       -name "ROB_1" -use_robot "ROB_1" -activate_at_start_up
  !cfg       -name "TRACK" -use_single_0 "TRACK" -activate_at_start_up
  !cfg ROBOT:
  !cfg       -name "ROB_1" -use_robot_type "ROB1_1600_1.45_10" -use_joint_0 "rob1_1" -use_joint_1 "rob1_2" -use_joint_2 "rob1_3" -use_joint_3 "rob1_4" -use_joint_4 "rob1_5" -use_joint_5 "rob1_6"
  VAR num n := 0;
  VAR string name;
  VAR bool robot;
  VAR num axes;
  VAR bool active;
  VAR mecunit unit;
  VAR num taskNo;

  PROC main()
    DeactUnit TRACK;
    WHILE GetNextMechUnit(n, name \MecRef:=unit \TCPRob:=robot \NoOfAxes:=axes \Active:=active) DO
      TPWrite name + " robot " + ValToStr(robot) + " axes " + ValToStr(axes) + " active " + ValToStr(active) + " ref " + GetMecUnitName(unit);
    ENDWHILE
    TPWrite "next " + ValToStr(n) + " [" + name + "]";
    n := 0;
    IF GetNextMechUnit(n, name \MecTaskNo:=taskNo) TPWrite "never";
  ENDPROC
ENDMODULE
!> ROB_1 robot TRUE axes 6 active TRUE ref ROB_1
!> TRACK robot FALSE axes 1 active FALSE ref TRACK
!> next 3 []
!! unsupported: GetNextMechUnit \MecTaskNo at 27
