MODULE Main
  PERS num nParts := 0;
  PROC main()
    VAR num i;
    VAR bool bOk := TRUE;
    ! pick every part of the tray
    FOR i FROM 1 TO 10 DO
      IF bOk THEN
        pickPart;
        Incr nParts;
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
  PROC oldHelper()
    Stop;
  ENDPROC
ENDMODULE
