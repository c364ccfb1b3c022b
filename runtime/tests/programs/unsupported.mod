MODULE unsupported
  ! What the simulation does not do stops the run with its name.
  VAR egmident egm;
  PROC main()
    TPWrite "before";
    EGMGetId egm;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
!> before
!! unsupported: EGMGetId at 6
