MODULE world_zones_timed
  ! With a modelled arm, an output zone's signal changes when the move
  ! ends: a \Conc move's output is still the old one while it moves.
  VAR shapedata box;
  VAR wztemporary over_table;
  PROC main()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    WZBoxDef \Inside, box, [400, -300, 700], [1200, 300, 1400];
    WZDOSet \Temp, over_table \Inside, box, do_over, 1;
    TPWrite "tcp "\Pos:=CPos();
    TPWrite "at the start "\Num:=DOutput(do_over);
    ConfL \Off;
    MoveL Offs(CRobT(), 0, 0, -600), v100, fine, tool0;
    TPWrite "down "\Num:=DOutput(do_over);
    MoveL Offs(CRobT(), 0, 0, 600), v100, z10, tool0 \Conc;
    TPWrite "going up, not there yet "\Num:=DOutput(do_over);
    WaitRob \InPos;
    TPWrite "up "\Num:=DOutput(do_over);
  ENDPROC
ENDMODULE
!robot IRB 1600-6/1.2
!> tcp [806.292,0,929]
!> at the start 1
!> down 0
!> going up, not there yet 0
!> up 1
