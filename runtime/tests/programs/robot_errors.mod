MODULE robot_errors
  ! A modelled IRB 120: CalcJointT's errors are RAPID errors a handler
  ! takes; a move the arm cannot make stops the program with the
  ! controller's event (50050 Position outside reach, 50080 Position not
  ! compatible), which no handler takes.
  !robot IRB 120-3/0.58
  CONST robtarget p10 := [[374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  ! Reachable, but with cf1 = 0, not 1.
  CONST robtarget wrongconf := [[374,0,500],[0,0,1,0],[1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[1374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget bent := [[0,0,0,0,130,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    VAR jointtarget j;
    MoveJ p10, v1000, fine, tool0;
    j := CalcJointT(far, tool0);
    TPWrite "after CalcJointT";
    ConfL \Off;
    MoveL wrongconf, v100, fine, tool0;
    TPWrite "ConfL Off: moved";
    ConfL \On;
    MoveL wrongconf, v100, fine, tool0;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_OUTSIDE_REACH THEN
      TPWrite "CalcJointT: outside reach";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
!> CalcJointT: outside reach
!> after CalcJointT
!> ConfL Off: moved
!! 50080 Position not compatible at 22
