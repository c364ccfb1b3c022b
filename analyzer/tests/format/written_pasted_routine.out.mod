! as written: a routine pasted in from a file written another way (two
! spaces, the module body at column 0) keeps its own indentation, as long
! as it follows it; one that follows no unit gets the file's
MODULE Pasted
    PROC main()
        a:=1;
        IF a THEN
            b:=1;
        ENDIF
    ENDPROC
PROC pasted()
  a:=1;
  IF a THEN
    b:=1;
    c:=2;
  ENDIF
ENDPROC
    PROC last()
        a:=1;
        b:=2;
    ENDPROC
    PROC random()
        a:=1;
        b:=2;
    ENDPROC
ENDMODULE
