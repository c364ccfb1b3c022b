! fix: unsafe, -: Remove the declaration of `spare`
MODULE m
  PROC main()
    VAR num spare; ! left over
    VAR num used;
    used := 1;
    TPWrite "" \Num:=used;
  ENDPROC
ENDMODULE
