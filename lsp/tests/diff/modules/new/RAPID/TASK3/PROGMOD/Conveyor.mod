MODULE Conveyor
  PROC conveyor()
  ENDPROC
ENDMODULE
