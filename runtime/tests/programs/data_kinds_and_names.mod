MODULE data_kinds_and_names
  ! IsPers and IsVar follow an INOUT parameter back to the caller's data
  ! object; RobName names the task's robot (ROB_1 without MOC.cfg);
  ! FileSize counts a file's bytes; ResetRetryCount lets a handler retry
  ! the full number of times again; PPMovedInManMode is FALSE in a run.
  PERS num nCount := 0;
  VAR num nLocal := 0;
  VAR iodev f;
  VAR num tries := 0;

  PROC main()
    VAR num inRoutine := 0;
    Which nCount;
    Which nLocal;
    Which inRoutine;
    TPWrite "robot " + RobName();
    Open "HOME:/size.txt", f \Write;
    Write f, "12345" \NoNewLine;
    Close f;
    TPWrite "size "\Num:=FileSize("HOME:/size.txt");
    TPWrite "moved "\Bool:=PPMovedInManMode();
    Retrying;
    TPWrite "tries "\Num:=tries;
  ENDPROC

  PROC Which(INOUT num x)
    TPWrite "pers "\Bool:=IsPers(x);
    TPWrite "var "\Bool:=IsVar(x);
  ENDPROC

  PROC Retrying()
    VAR num z;
    z := Fails();
  ERROR
    IF RemainingRetries() = 1 ResetRetryCount;
    RETRY;
  ENDPROC

  FUNC num Fails()
    Incr tries;
    IF tries < 7 RETURN 1 / 0;
    RETURN 1;
  ENDFUNC
ENDMODULE
!> pers TRUE
!> var FALSE
!> pers FALSE
!> var TRUE
!> pers FALSE
!> var TRUE
!> robot ROB_1
!> size 5
!> moved FALSE
!> tries 7
