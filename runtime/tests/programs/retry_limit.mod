MODULE retry_limit
  ! RETRY of the same statement more than four times in a row.
  VAR num tries := 0;
  PROC main()
    VAR num x;
    x := 1 / 0;
  ERROR
    Incr tries;
    TPWrite "retry "\Num:=tries;
    RETRY;
  ENDPROC
ENDMODULE
!> retry 1
!> retry 2
!> retry 3
!> retry 4
!> retry 5
!! ERR_EXCRTYMAX at 6
