! fix: unsafe, -: Remove the declaration of `spare`
MODULE m
  LOCAL VAR num used := 1; LOCAL VAR num spare;
  PROC main()
    TPWrite "" \Num:=used;
  ENDPROC
ENDMODULE
