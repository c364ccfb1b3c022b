MODULE Clock
  VAR clock clock1;

  FUNC num secondsToMinutes(num seconds)
    RETURN seconds / 60;
  ENDFUNC
ENDMODULE
