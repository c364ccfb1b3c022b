MODULE Main
  PERS num nParts := 0;
  PROC main()
    VAR bool bOk := TRUE;
    VAR num i;
    ! pick every part of the tray, twice
    FOR i FROM 1 TO 12 DO
      IF bOk THEN
        pickPart;
        Incr nParts;
        checkPart;
      ELSE
        TPWrite "skipped";
      ENDIF
    ENDFOR
    TEST nParts
    CASE 10:
      TPWrite "tray done";
    DEFAULT:
      Stop;
    ENDTEST
  ENDPROC
  PROC pickPart()
    WaitTime 0.5;
  ENDPROC
  PROC checkPart()
    WaitTime 0.2;
  ENDPROC
ENDMODULE
