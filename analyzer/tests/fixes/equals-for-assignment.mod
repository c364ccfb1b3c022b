! fix: safe, preferred: Replace `=` with `:=`
MODULE m
  VAR num count = 0;
  PROC main()
    count = count + 1;
  ENDPROC
ENDMODULE
