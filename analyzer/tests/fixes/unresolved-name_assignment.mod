! fix: unsafe, preferred: Declare `VAR robtarget target;` in this routine
MODULE m
  PROC main()
    VAR num n;
    n := 1;
    target := CRobT();
  ENDPROC
ENDMODULE
