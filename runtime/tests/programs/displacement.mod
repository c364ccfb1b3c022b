MODULE displacement
  ! Program displacement: PDispSet, PDispOn (translation, \Rot, \ExeP),
  ! PDispOff and ORobT. Positions the task programs and reads are in the
  ! displaced frame while a displacement is active.
  CONST robtarget p0 := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR robtarget here;

  PROC main()
    TPWrite "no displacement: pdisp x "\Num:=C_PROGDISP.pdisp.trans.x;
    PDispSet [[100, 20, 0], [1, 0, 0, 0]];
    MoveL p0, v100, fine, tool0;
    here := CRobT();
    TPWrite "in the displaced frame "\Pos:=here.trans;
    here := ORobT(CRobT());
    TPWrite "ORobT: in the object frame "\Pos:=here.trans;
    here := ORobT(CRobT() \InPDisp);
    TPWrite "ORobT with InPDisp "\Pos:=here.trans;
    TPWrite "C_PROGDISP x "\Num:=C_PROGDISP.pdisp.trans.x;
    PDispOff;
    here := CRobT();
    TPWrite "after PDispOff "\Pos:=here.trans;
    PDispOn \ExeP:=Offs(p0, 0, 0, 50), p0, tool0;
    here := CRobT();
    TPWrite "PDispOn with ExeP: the robot, in the new frame "\Pos:=here.trans;
    PDispOn p0, tool0;
    here := CRobT();
    TPWrite "PDispOn at the robot "\Pos:=here.trans;
    PDispOff;
    PDispOn \Rot \ExeP:=RelTool(p0, 0, 0, 0 \Rz:=90), p0, tool0;
    here := CRobT();
    TPWrite "PDispOn with Rot: the orientation in the turned frame "\Orient:=here.rot;
    PDispOff;
  ENDPROC
ENDMODULE
!> no displacement: pdisp x 0
!> in the displaced frame [500,0,400]
!> ORobT: in the object frame [600,20,400]
!> ORobT with InPDisp [500,0,400]
!> C_PROGDISP x 100
!> after PDispOff [600,20,400]
!> PDispOn with ExeP: the robot, in the new frame [600,20,350]
!> PDispOn at the robot [500,0,400]
!> PDispOn with Rot: the orientation in the turned frame [0,-0.707107,0.707107,0]
