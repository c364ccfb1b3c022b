! as written: two spaces per level, as the file has them
MODULE Two
  PROC main()
    IF a THEN
      b:=1;
        c:=2;
    ENDIF
  ENDPROC
ENDMODULE
