! fix: unsafe, preferred: Declare `VAR robtarget p;` in this routine
MODULE m
  PROC main()
	MoveL p, v100, fine, tool0;
	MoveL p, v100, fine, tool0;
  ENDPROC
ENDMODULE
