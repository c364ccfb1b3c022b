MODULE errors
  ! Error recovery: RETRY, TRYNEXT, RETURN from a handler, RAISE to the
  ! caller, user errors, BookErrNo, ERROR lists, propagation, UNDO.
  VAR errnum ERR_MACHINE := -1;
  VAR num divisor := 0;
  VAR num attempts := 0;

  PROC main()
    BookErrNo ERR_MACHINE;
    TPWrite "booked "\Bool:=ERR_MACHINE > 90;
    TPWrite "retry: "\Num:=SafeDivide(10);
    TryNextDemo;
    TPWrite "fallback: "\Num:=Fallback(4);
    Propagate;
    UserErrors;
    OnlyListed;
    UndoDemo;
    TPWrite "end";
  ERROR
    TPWrite "main handler";
  ENDPROC

  FUNC num SafeDivide(num x)
    RETURN x / divisor;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      TPWrite "divide by zero, fixing";
      divisor := 2;
      RETRY;
    ENDIF
  ENDFUNC

  PROC TryNextDemo()
    VAR num a{2} := [1, 2];
    FOR i FROM 1 TO 3 DO
      TPWrite "item "\Num:=a{i};
      TPWrite "after item "\Num:=i;
    ENDFOR
    TPWrite "loop done";
  ERROR
    TPWrite "skipping "\Bool:=ERRNO = ERR_OUTOFBND;
    TRYNEXT;
  ENDPROC

  FUNC num Fallback(num x)
    RETURN Sqrt(-x);
  ERROR
    RETURN -1;
  ENDFUNC

  PROC Propagate()
    attempts := 0;
    Level1;
    TPWrite "propagate done after "\Num:=attempts;
  ERROR
    TPWrite "caught in Propagate "\Num:=attempts;
    RETRY;
  ENDPROC

  PROC Level1()
    Level2;
  ENDPROC

  PROC Level2()
    Incr attempts;
    IF attempts < 3 RAISE ERR_MACHINE;
    TPWrite "level2 ok";
  ENDPROC

  PROC UserErrors()
    Thrower 5;
    TPWrite "after thrower";
  ERROR
    TPWrite "user error "\Num:=ERRNO;
    TRYNEXT;
  ENDPROC

  PROC Thrower(num n)
    RAISE n;
  ERROR
    TPWrite "thrower passes on "\Num:=ERRNO;
    RAISE;
  ENDPROC

  PROC OnlyListed()
    Listed;
  ERROR
    TPWrite "outer took it";
    TRYNEXT;
  ENDPROC

  PROC Listed()
    VAR num a{1};
    a{2} := 1;
  ERROR (ERR_DIVZERO)
    TPWrite "listed took it";
    TRYNEXT;
  ENDPROC

  PROC UndoDemo()
    WithUndo;
  ERROR
    TPWrite "undo demo caught";
    TRYNEXT;
  ENDPROC

  PROC WithUndo()
    TPWrite "working";
    RAISE ERR_MACHINE;
  UNDO
    TPWrite "undo runs";
  ENDPROC
ENDMODULE
!> booked TRUE
!> divide by zero, fixing
!> retry: 5
!> item 1
!> after item 1
!> item 2
!> after item 2
!> skipping TRUE
!> after item 3
!> loop done
!> fallback: -1
!> caught in Propagate 1
!> caught in Propagate 2
!> level2 ok
!> propagate done after 3
!> thrower passes on 5
!> user error 5
!> after thrower
!> outer took it
!> working
!> undo runs
!> undo demo caught
!> end
