MODULE MainModule
  PROC main()
    TPWrite "hello";
  ENDPROC
ENDMODULE
