! fmt: style=spaced
MODULE KeywordCase(SYSMODULE, NOSTEPIN)
    LOCAL VAR Num MyCounter := 0;
    PERS Bool bFlag := TRUE;
    LOCAL FUNC Bool IsReady(VAR Num x)
        RETURN x > 0 AND NOT bFlag OR x MOD 2 = 1 XOR x DIV 3 > 0;
    ENDFUNC

    TRAP tOnStop
        CONNECT intNo WITH tOnStop;
        GOTO lblEnd;
        lblEnd:
        EXIT;
    ENDTRAP
ENDMODULE
