MODULE stop_move_holds_path_events
  ! The signals a path still has to set wait while StopMove holds the
  ! move: MoveLDO's output (due at the point, 2.01 s into a 200 mm MoveL
  ! at 100 mm/s on a modelled IRB 1600) comes 1.01 s after StartMove when
  ! the move is held from 1 s to 3 s: at 4.01 s, by hand. A TriggIO event
  ! 50 mm before the point is held the same way, and a TriggInt
  ! interrupt there (due 2.01 - 0.25 x 2.01 = 1.5075 s into the move)
  ! runs its trap 2 s later, at 3.5075 s (ClkRead \HighRes: 3.507);
  ! ClearPath drops the events of the move it clears.
  !robot IRB 1600-10/1.45
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum pause;
  VAR intnum glue;
  VAR clock c;
  VAR bool drop := FALSE;
  VAR triggdata near;
  VAR triggdata nearint;
  VAR intnum passing;

  PROC main()
    ConfL \Off;
    MoveJ p0, v1000, fine, tool0;
    CONNECT glue WITH tGlue;
    ISignalDO doGlue, 1, glue;
    CONNECT pause WITH tPause;
    ITimer \Single, 1, pause;
    ClkStart c;
    MoveLDO Offs(p0, 0, 200, 0), v100, fine, tool0, doGlue, 1;
    TPWrite "move ends after "\Num:=Round(ClkRead(c) \Dec:=2);
    TriggIO near, 50 \DOp:=doFlow, 1;
    CONNECT passing WITH tPassing;
    TriggInt nearint, 50, passing;
    ITimer \Single, 1, pause;
    ClkReset c;
    TriggL p0, v100, near \T2:=nearint, fine, tool0;
    TPWrite "flow after the move "\Num:=DOutput(doFlow);
    drop := TRUE;
    SetDO doGlue, 0;
    ITimer \Single, 1, pause;
    ClkReset c;
    MoveLDO Offs(p0, 0, 200, 0), v100, fine, tool0, doGlue, 1;
    WaitTime 3;
    TPWrite "glue after a cleared move "\Num:=DOutput(doGlue);
    SetDO doFlow, 0;
    ITimer \Single, 0.3, pause;
    TriggL Offs(p0, 0, 200, 0), v100, near \T2:=nearint, fine, tool0;
    WaitTime 3;
    TPWrite "flow after a cleared move "\Num:=DOutput(doFlow);
  ENDPROC

  TRAP tPause
    StopMove;
    IF drop THEN
      ClearPath;
      StartMove;
      RETURN;
    ENDIF
    WaitTime 2;
    TPWrite "flow while held "\Num:=DOutput(doFlow);
    StartMove;
  ENDTRAP

  TRAP tPassing
    TPWrite "passing 50 mm before the point after "\Num:=ClkRead(c \HighRes);
  ENDTRAP

  TRAP tGlue
    TPWrite "glue set after "\Num:=Round(ClkRead(c) \Dec:=2);
  ENDTRAP
ENDMODULE
!> flow while held 0
!> glue set after 4.01
!> move ends after 4.01
!> flow while held 0
!> passing 50 mm before the point after 3.507
!> flow after the move 1
!> glue after a cleared move 0
!> flow after a cleared move 0
