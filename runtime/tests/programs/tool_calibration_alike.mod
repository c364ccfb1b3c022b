MODULE tool_calibration_alike
  ! MToolTCPCalib from four positions with one tool orientation: any TCP
  ! fits them, so the run stops rather than invent one.
  PERS tooldata measured := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
  CONST jointtarget j := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR num max_err;
    VAR num mean_err;
    MToolTCPCalib j, j, j, j, measured, max_err, mean_err;
  ENDPROC
ENDMODULE
!robot IRB 120-3/0.58
!! invalid at 9
