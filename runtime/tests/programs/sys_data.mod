MODULE sys_data
  ! GetSysData reads the active tool, work object or payload (the last
  ! move's, or what SetSysData set; tool0, wobj0, load0 before any) and,
  ! with \ObjectName, its name.
  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wTable := [FALSE, TRUE, "", [[500, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS loaddata lBox := [2, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0];
  PERS tooldata tSeen := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wSeen := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS loaddata lSeen := [0.001, [0, 0, 0.001], [1, 0, 0, 0], 0, 0, 0];
  CONST robtarget p := [[100, 0, 200], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR string name;
    GetSysData tSeen \ObjectName:=name;
    TPWrite "before any move: " + name;
    MoveL p, v100, fine, tGripper \WObj:=wTable;
    GetSysData tSeen \ObjectName:=name;
    TPWrite name + " " + ValToStr(tSeen.tframe.trans);
    GetSysData wSeen \ObjectName:=name;
    TPWrite name + " " + ValToStr(wSeen.uframe.trans);
    GetSysData lSeen \ObjectName:=name;
    TPWrite name + " " \Num:=lSeen.mass;
    SetSysData lBox;
    SetSysData tool0;
    GetSysData lSeen \ObjectName:=name;
    TPWrite name + " " \Num:=lSeen.mass;
    GetSysData tSeen \ObjectName:=name;
    TPWrite name + " " + ValToStr(tSeen.tframe.trans);
  ENDPROC
ENDMODULE
!> before any move: tool0
!> tGripper [0,0,100]
!> wTable [500,0,0]
!> load0 0.001
!> lBox 2
!> tool0 [0,0,0]
