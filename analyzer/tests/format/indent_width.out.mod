! fmt: style=spaced indent-width=2
MODULE IndentWidth
  PROC main()
    WHILE TRUE DO
      FOR i FROM 1 TO 3 DO
        IF i = 2 THEN
          Stop;
        ENDIF
      ENDFOR
    ENDWHILE
  ENDPROC
ENDMODULE
