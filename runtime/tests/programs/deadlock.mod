MODULE deadlock
  ! Waiting for an input nothing will ever set.
  !set di_never=0
  PROC main()
    TPWrite "waiting";
    WaitDI di_never, 1;
  ENDPROC
ENDMODULE
!> waiting
!! deadlock at 6
