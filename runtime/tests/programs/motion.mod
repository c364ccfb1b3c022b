MODULE motion
  ! Moves complete at once; CRobT, CPos and CJointT read where the robot
  ! is, through tools and work objects.
  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  TASK PERS wobjdata wTable := [FALSE, TRUE, "", [[1000, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST robtarget p10 := [[100, 200, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR robtarget here;
    MoveAbsJ jHome, v1000, fine, tool0;
    TPWrite "joint 5 "\Num:=CJointT().robax.rax_5;
    MoveJ p10, v1000, z50, tool0;
    TPWrite "at "\Pos:=CPos();
    MoveL Offs(p10, 0, 0, 50), v500, fine, tGripper\WObj:=wTable;
    here := CRobT(\Tool:=tGripper\WObj:=wTable);
    TPWrite "in table "\Pos:=here.trans;
    TPWrite "in world "\Pos:=CPos(\Tool:=tGripper);
    TPWrite "flange "\Pos:=CPos();
    MoveC Offs(p10, 50, 50, 0), p10, v100, z10, tool0;
    TPWrite "back "\Pos:=CPos();
    here := RelTool(CRobT(), 0, 0, 10\Rz:=90);
    MoveL here, v100, fine, tool0;
    TPWrite "turned "\Orient:=CRobT().rot;
  ENDPROC
ENDMODULE
!> joint 5 90
!> at [100,200,300]
!> in table [100,200,350]
!> in world [1100,200,350]
!> flange [1100,200,250]
!> back [100,200,300]
!> turned [0.707107,0,0,0.707107]
