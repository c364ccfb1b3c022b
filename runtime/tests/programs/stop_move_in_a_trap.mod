MODULE stop_move_in_a_trap
  ! A timer's trap stops the robot in the middle of a MoveL (200 mm at
  ! 100 mm/s, a modelled IRB 1600: 2.01 s with its acceleration): CRobT
  ! reads where the TCP is then, on the line (1.25 s into the move: y
  ! 1.25 / 2.01 x 200 = 124 mm, by hand); the arm goes 25 mm aside and
  ! back on a path level of its own (StorePath, RestoPath: 0.26 s each),
  ! and StartMove lets the stopped move go on for the 0.76 s it had left:
  ! the move ends after 1.25 + 0.52 + 0.76 = 2.53 s. A second stop is
  ! dropped with ClearPath: the arm stays where it stopped (0.5 s into
  ! the move back, y 150) and the move ends there. An error handler's
  ! StartMoveRetry retries the statement that raised the error.
  !robot IRB 1600-10/1.45
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum pause;
  VAR clock c;
  VAR bool drop := FALSE;
  VAR num tries := 0;

  PROC main()
    ConfL \Off;
    MoveJ p0, v1000, fine, tool0;
    CONNECT pause WITH tPause;
    ITimer \Single, 1.25, pause;
    ClkStart c;
    MoveL Offs(p0, 0, 200, 0), v100, fine, tool0;
    TPWrite "first move ends after "\Num:=Round(ClkRead(c) \Dec:=2);
    TPWrite "stop held "\Bool:=IsStopMoveAct(\FromMoveTask);
    drop := TRUE;
    ITimer \Single, 0.5, pause;
    ClkReset c;
    MoveL p0, v100, fine, tool0;
    TPWrite "second move ends after "\Num:=Round(ClkRead(c) \Dec:=2);
    TPWrite "at y "\Num:=Round(CPos().y);
    WaitDI diGo, 1 \MaxTime:=0.2;
    TPWrite "retried "\Num:=tries;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME AND tries < 2 THEN
      Incr tries;
      StartMoveRetry;
    ENDIF
    TRYNEXT;
  ENDPROC

  TRAP tPause
    VAR robtarget here;
    StopMove;
    TPWrite "held "\Bool:=IsStopMoveAct(\FromMoveTask);
    here := CRobT();
    TPWrite "stopped at y "\Num:=Round(here.trans.y);
    IF drop THEN
      ClearPath;
      StartMove;
      RETURN;
    ENDIF
    StorePath;
    MoveL Offs(here, 0, 0, 25), v100, fine, tool0;
    MoveL here, v100, fine, tool0;
    RestoPath;
    StartMove;
  ENDTRAP
ENDMODULE
!> held TRUE
!> stopped at y 124
!> first move ends after 2.53
!> stop held FALSE
!> held TRUE
!> stopped at y 150
!> second move ends after 0.5
!> at y 150
!> retried 2
