! fix: unsafe, preferred: Replace `=` with `:=`
MODULE m
  VAR num a;
  VAR num b;
  PROC main()
    a := 1; b = 2;
    TPWrite "" \Num:=a + b;
  ENDPROC
ENDMODULE
