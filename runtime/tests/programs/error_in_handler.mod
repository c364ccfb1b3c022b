MODULE error_in_handler
  ! An error inside an error handler is not recovered: the run stops there
  ! even though the caller has a handler.
  VAR num zero := 0;

  PROC main()
    Inner;
    TPWrite "not reached";
  ERROR
    TPWrite "main took it";
    TRYNEXT;
  ENDPROC

  PROC Inner()
    VAR num x;
    x := 1 / zero;
  ERROR
    TPWrite "inner handler";
    x := 2 / zero;
  ENDPROC
ENDMODULE
!> inner handler
!! ERR_DIVZERO at 19
