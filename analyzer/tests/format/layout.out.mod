! fmt: style=spaced indent-width=4
%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
MODULE Layout(SYSMODULE, NOVIEW)
    ! a module comment
    VAR num counter := 0;
    PERS tooldata tGripper:=[TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
    LOCAL CONST num limits{3} := [1, -2, 3 * 4];
    PROC main()
        VAR num i;
        counter := counter + 1;
        IF counter > 10 THEN
            counter := 0;
        ENDIF
        FOR i FROM 1 TO 10 STEP 2 DO
            TPWrite "i = "\Num:=i;
        ENDFOR
        WHILE counter < 5 AND NOT stopped DO
            counter := counter + 1;
        ENDWHILE
        IF counter = 1 counter := 2;
        TEST counter
            CASE 1, 2:
                MoveL p10, v100, fine, tool0\WObj:=wobj0;
            CASE 3:
                StopMove \Quick;
            DEFAULT:
                Stop;
        ENDTEST
    ERROR
        IF errno = ERR_DIVZERO THEN
            RETRY;
        ELSEIF errno = ERR_NOTPRES THEN
            TRYNEXT;
        ELSE
            RAISE;
        ENDIF
    ENDPROC

    FUNC num Double(num x, \switch Half | switch Quarter, INOUT num y{*})
        RETURN x * 2;
    ENDFUNC

    TRAP OnStop
        reset doGripper;
    ENDTRAP
    RECORD point2
        num x;
        num y;
    ENDRECORD
ENDMODULE
