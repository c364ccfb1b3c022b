MODULE Vision
  VAR num nCam := 1;
  PROC snap()
  ENDPROC
ENDMODULE
