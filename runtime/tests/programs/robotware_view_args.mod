MODULE robotware_view_args
  ! With RobotWare 4.0's catalogue (no \TaskRef or \TaskName yet), the
  ! arguments of CRobT are read by the parameters they were bound to in
  ! that view.
  !robotware 4.0
  PERS tooldata tGrip := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wTable := [FALSE, TRUE, "", [[1000, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST robtarget p1 := [[100, 200, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR robtarget here;
    MoveL p1, v100, fine, tGrip\WObj:=wTable;
    here := CRobT(\Tool:=tGrip\WObj:=wTable);
    TPWrite "in the table "\Pos:=here.trans;
    here := CRobT(\Tool:=tool0\WObj:=wTable);
    TPWrite "flange "\Pos:=here.trans;
  ENDPROC
ENDMODULE
!> in the table [100,200,300]
!> flange [100,200,200]
