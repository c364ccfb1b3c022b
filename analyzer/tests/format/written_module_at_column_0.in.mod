! as written: the module body at the module's column stays there
MODULE Flat
VAR bool loaded:=FALSE;
PERS num counter:=0;

PROC main()
VAR num i;
    WHILE TRUE DO
        Incr counter;
      IF counter>10 THEN
            counter:=0;
        ENDIF
    ENDWHILE
ERROR
    TRYNEXT;
ENDPROC
ENDMODULE
