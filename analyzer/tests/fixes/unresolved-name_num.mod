! fix: unsafe, preferred: Declare `VAR num k;` in this routine
MODULE m
  TRAP t
  ENDTRAP
  PROC main()
    FOR i FROM 1 TO 3 DO
      TPWrite "" \Num:=k;
    ENDFOR
  ENDPROC
ENDMODULE
