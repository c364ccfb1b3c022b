MODULE robot_limit
  ! A modelled IRB 120 (axis 5 from -120 to 120 degrees): a MoveAbsJ beyond
  ! a working range stops the program with event 50050, which the ERROR
  ! handler does not take.
  !robot IRB 120-3/0.58
  !entry limit
  CONST jointtarget bent := [[0,0,0,0,130,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC limit()
    MoveAbsJ bent, v1000, fine, tool0;
  ERROR
    TPWrite "never here";
  ENDPROC
ENDMODULE
!! 50050 Position outside reach at 10
