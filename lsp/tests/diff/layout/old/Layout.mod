MODULE Layout
  CONST robtarget p10 := [[100,0,50],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num nCount := 3;
  VAR speeddata vSlow := [100,50,5000,1000];
  PROC main()
    VAR num i;
    VAR num k := 2;
    IF nCount > 2 THEN
      MoveL p10, vSlow, fine, tool0;
    ELSE
      nCount := nCount + 1;
    ENDIF
  ENDPROC
ENDMODULE
