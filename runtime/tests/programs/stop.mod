MODULE stop
  ! Stop ends the run where it stands.
  PROC main()
    TPWrite "one";
    ErrWrite "Check", "the gripper is open"\RL2:="second line";
    ErrWrite \W, "Warning", "low air";
    Stop;
    TPWrite "two";
  ENDPROC
ENDMODULE
!> one
!> 80001 Check: the gripper is open second line
!> 80002 Warning: low air
!! stopped at 7
