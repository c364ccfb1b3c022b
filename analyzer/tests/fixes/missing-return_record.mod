! fix: unsafe, preferred: Add `RETURN [0, FALSE, ""];` at the end of `make`
MODULE m
  RECORD entry
    num id;
    bool done;
    string label;
  ENDRECORD
  FUNC entry make(num id)
      TPWrite "making";
  ENDFUNC
  PROC main()
    TPWrite make(1).label;
  ENDPROC
ENDMODULE
