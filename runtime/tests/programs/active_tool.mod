MODULE active_tool
  ! CTool and CWObj: the tool and work object of the last move, tool0 and
  ! wobj0 before any move, or the ones SetSysData made active.
  PERS tooldata gripper := [TRUE, [[0, 0, 120], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata table := [FALSE, TRUE, "", [[400, 0, 200], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];

  PROC main()
    VAR tooldata t;
    VAR wobjdata w;
    t := CTool();
    w := CWObj();
    TPWrite "before any move: tool mass "\Num:=t.tload.mass;
    TPWrite "before any move: user frame x "\Num:=w.uframe.trans.x;
    MoveL [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, gripper \WObj:=table;
    t := CTool();
    w := CWObj();
    TPWrite "tool mass "\Num:=t.tload.mass;
    TPWrite "tool z "\Num:=t.tframe.trans.z;
    TPWrite "user frame x "\Num:=w.uframe.trans.x;
    MoveL [[0, 0, 50], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;
    w := CWObj();
    TPWrite "no work object named: user frame x "\Num:=w.uframe.trans.x;
    SetSysData gripper;
    SetSysData wobj0 \ObjectName:="table";
    t := CTool();
    w := CWObj();
    TPWrite "SetSysData: tool mass "\Num:=t.tload.mass;
    TPWrite "SetSysData by name: user frame x "\Num:=w.uframe.trans.x;
  ENDPROC
ENDMODULE
!> before any move: tool mass 0.001
!> before any move: user frame x 0
!> tool mass 1.5
!> tool z 120
!> user frame x 400
!> no work object named: user frame x 0
!> SetSysData: tool mass 1.5
!> SetSysData by name: user frame x 400
