! as written: only where lines start; a text written flat gets 4 spaces
MODULE Structure
    VAR num count:=0;
    RECORD point
        num x;
        num y;
    ENDRECORD
    PROC main()
        VAR num i;
        IF count>10 THEN
            count:=0;
        ELSEIF count<0 THEN
            count:=1;
        ELSE
            Incr count;
        ENDIF
        FOR i FROM 1 TO 3 DO
            WHILE count<5 DO
                Incr count;
            ENDWHILE
        ENDFOR
        TEST count
            CASE 1,2:
                Stop;
            DEFAULT:
                Stop;
        ENDTEST
    ERROR
        RETRY;
    ENDPROC
    TRAP tOnStop
        Stop;
    ENDTRAP
ENDMODULE
