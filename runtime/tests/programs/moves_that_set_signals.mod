MODULE moves_that_set_signals
  ! MoveLDO, MoveJAO and MoveLGO set their signal with the move; the
  ! settings a simulation has nothing to change with (PathResol,
  ! ActEventBuffer, SpyStart, StopMoveReset) are accepted.
  CONST robtarget p1 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    PathResol 150;
    ActEventBuffer;
    SpyStart "HOME:/spy.log";
    MoveLDO p1, v500, fine, tool0, doGlue, 1;
    MoveJAO Offs(p1, 0, 50, 0), v500, z10, tool0, aoFlow, 3.5;
    MoveLGO Offs(p1, 0, 100, 0), v500, fine, tool0, goStation, 6;
    SpyStop;
    StopMoveReset;
    DeactEventBuffer;
    TPWrite "glue "\Num:=DOutput(doGlue);
    TPWrite "flow "\Num:=AOutput(aoFlow);
    TPWrite "station "\Num:=GOutput(goStation);
  ENDPROC
ENDMODULE
!> glue 1
!> flow 3.5
!> station 6
