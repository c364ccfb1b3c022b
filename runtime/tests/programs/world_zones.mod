MODULE world_zones
  ! World zones: a home-position output from a joint zone, a box and a
  ! sphere that set outputs where moves end, WZDisable/WZEnable/WZFree,
  ! and a limit zone that stops the robot.
  CONST jointtarget home := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget delta := [[2, 2, 2, 2, 2, 2], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget in_box := [[500, 0, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget out_box := [[500, 400, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR shapedata home_shape;
  VAR shapedata box;
  VAR shapedata ball;
  VAR wzstationary at_home;
  VAR wztemporary over_table;
  VAR wztemporary not_near;
  VAR wztemporary forbidden;

  PROC main()
    WZHomeJointDef \Inside, home_shape, home, delta;
    WZDOSet \Stat, at_home \Inside, home_shape, do_home, 1;
    TPWrite "before any move, at home "\Num:=DOutput(do_home);
    MoveAbsJ home, v1000, fine, tool0;
    TPWrite "after MoveAbsJ home "\Num:=DOutput(do_home);
    WZBoxDef \Inside, box, [400, -100, 200], [600, 100, 400];
    WZDOSet \Temp, over_table \Inside, box, do_over_table, 1;
    WZSphDef \Outside, ball, [500, 0, 300], 100;
    WZDOSet \Temp, not_near \Inside, ball, do_far, 1;
    MoveL in_box, v1000, fine, tool0;
    TPWrite "in the box: home "\Num:=DOutput(do_home);
    TPWrite "in the box: over table "\Num:=DOutput(do_over_table);
    TPWrite "in the box: far "\Num:=DOutput(do_far);
    MoveL out_box, v1000, fine, tool0;
    TPWrite "out of the box: over table "\Num:=DOutput(do_over_table);
    TPWrite "out of the box: far "\Num:=DOutput(do_far);
    WZDisable over_table;
    MoveL in_box, v1000, fine, tool0;
    TPWrite "disabled, in the box: over table "\Num:=DOutput(do_over_table);
    WZEnable over_table;
    MoveL in_box, v1000, fine, tool0;
    TPWrite "enabled again: over table "\Num:=DOutput(do_over_table);
    WZFree over_table;
    WZLimSup \Temp, forbidden, box;
    MoveL out_box, v1000, fine, tool0;
    TPWrite "outside the forbidden box";
    MoveL in_box, v1000, fine, tool0;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
!> before any move, at home 0
!> after MoveAbsJ home 1
!> in the box: home 0
!> in the box: over table 1
!> in the box: far 0
!> out of the box: over table 0
!> out of the box: far 1
!> disabled, in the box: over table 0
!> enabled again: over table 1
!> outside the forbidden box
!! world zone violated at 44
