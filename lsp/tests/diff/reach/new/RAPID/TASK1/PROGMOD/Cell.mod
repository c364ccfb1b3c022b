MODULE Cell
  ! An IRB 120 (580 mm reach) with a short gripper over a small table.
  PERS tooldata tGrip := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[300,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  ! Re-taught 20 mm further out: still reachable.
  PERS robtarget pPick := [[70,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  ! Typed 600 mm too far: out of the arm's reach.
  PERS robtarget pPlace := [[600,100,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  ! No move uses it: its reach is not judged.
  PERS robtarget pSpare := [[0,-120,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    MoveJ pPick, v200, z10, tGrip\WObj:=wTable;
    MoveL pPlace, v200, fine, tGrip\WObj:=wTable;
  ENDPROC
ENDMODULE
