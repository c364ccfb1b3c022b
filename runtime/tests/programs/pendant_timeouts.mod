MODULE pendant_timeouts
  ! The dialogs' ways out: \MaxTime with and without \BreakFlag, a
  ! \DIBreak signal set while the question waits, an answer that comes
  ! too late, and an error handler that takes ERR_TP_MAXTIME.
  !set di_stop=1@12
  !answer -
  !answer @5 1
  !answer -
  !answer @20 Yes
  !answer -
  !answer -
  VAR num key;
  VAR errnum flag;
  VAR btnres res;
  VAR clock clk;

  PROC main()
    ClkStart clk;
    TPReadFK key, "No answer", "A", "B", stEmpty, stEmpty, stEmpty \MaxTime:=2 \BreakFlag:=flag;
    TPWrite "timed out "\Bool:=flag = ERR_TP_MAXTIME;
    TPWrite "at "\Num:=ClkRead(clk);
    TPReadFK key, "Late", "A", "B", stEmpty, stEmpty, stEmpty \MaxTime:=3 \BreakFlag:=flag;
    TPWrite "late "\Bool:=flag = ERR_TP_MAXTIME;
    TPWrite "at "\Num:=ClkRead(clk);
    TPReadNum key, "Until the stop button" \DIBreak:=di_stop \BreakFlag:=flag;
    TPWrite "broken "\Bool:=flag = ERR_TP_DIBREAK;
    TPWrite "at "\Num:=ClkRead(clk);
    res := UIMessageBox(\Message:="Late answer" \Buttons:=btnYesNo \MaxTime:=10 \BreakFlag:=flag);
    TPWrite "unknown "\Bool:=res = resUnkwn;
    TPWrite "flag "\Bool:=flag = ERR_TP_MAXTIME;
    TPWrite "at "\Num:=ClkRead(clk);
    ask;
    TPReadNum key, "Nobody answers";
  ENDPROC

  PROC ask()
    TPReadNum key, "Raises" \MaxTime:=1;
  ERROR
    TPWrite "handled "\Bool:=ERRNO = ERR_TP_MAXTIME;
    TRYNEXT;
  ENDPROC
ENDMODULE
!> timed out TRUE
!> at 2
!> late TRUE
!> at 5
!> broken TRUE
!> at 12
!> unknown TRUE
!> flag TRUE
!> at 22
!> handled TRUE
!! operator at 33
