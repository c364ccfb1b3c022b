MODULE MainModule
  VAR egmident egmId;
  PROC main()
    EGMGetId egmId;
    EGMSetupUC ROB_1, egmId, "default", "UCdevice" \Pose;
    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
  ENDPROC
ENDMODULE
