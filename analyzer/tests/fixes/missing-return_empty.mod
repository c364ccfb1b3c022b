! fix: unsafe, preferred: Add `RETURN FALSE;` at the end of `ready`
MODULE m
  FUNC bool ready()
  ENDFUNC
  PROC main()
    TPWrite "" \Bool:=ready();
  ENDPROC
ENDMODULE
