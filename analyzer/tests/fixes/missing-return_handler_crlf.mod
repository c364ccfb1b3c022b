! fix: unsafe, preferred: Add `RETURN 0;` at the end of `ratio`
MODULE m
  FUNC num ratio(num a, num b)
    IF b <> 0 THEN
      RETURN a / b;
    ENDIF
  ERROR
    TRYNEXT;
  ENDFUNC
  PROC main()
    TPWrite "" \Num:=ratio(1, 2);
  ENDPROC
ENDMODULE
