MODULE Cell
  ! An IRB 120 (580 mm reach) with a short gripper over a small table.
  PERS tooldata tGrip := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[300,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS robtarget pPick := [[50,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPlace := [[0,100,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pSpare := [[0,-100,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    MoveJ pPick, v200, z10, tGrip\WObj:=wTable;
    MoveL pPlace, v200, fine, tGrip\WObj:=wTable;
  ENDPROC
ENDMODULE
