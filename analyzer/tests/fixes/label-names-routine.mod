! fix: unsafe, preferred: Call `R_YogaPose` (`R_YogaPose;`)
MODULE m
  PROC main()
    R_YogaPose:
    TPWrite "at home";
  ENDPROC
  PROC R_YogaPose()
    Stop;
  ENDPROC
ENDMODULE
