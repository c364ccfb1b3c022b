MODULE unsupported
  ! What the simulation does not do stops the run with its name.
  VAR socketdev sock;
  PROC main()
    TPWrite "before";
    SocketCreate sock;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
!> before
!! unsupported: SocketCreate at 6
