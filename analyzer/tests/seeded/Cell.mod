MODULE Cell
  ! A small palletising cell: picks parts from a conveyor and stacks them.
  RECORD layer
    num rows;
    num cols;
    num height;
  ENDRECORD

  ALIAS num count_t;

  CONST num MAX_LAYERS := 4;
  CONST robtarget pPick := [[600,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tGripper := [TRUE,[[0,0,150],[1,0,0,0]],[2,[0,0,50],[1,0,0,0],0,0,0]];
  PERS wobjdata wPallet := [FALSE,TRUE,"",[[800,-300,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  TASK PERS count_t placed := 0;
  VAR layer layers{MAX_LAYERS} := [[3,4,100],[3,4,100],[2,3,100],[1,1,100]];
  VAR intnum irStop;
  VAR bool stopRequested := FALSE;
  LOCAL VAR num cycleTime;

  PROC main()
    VAR num level;
    IDelete irStop;
    CONNECT irStop WITH onStop;
    ISignalDI diStop, 1, irStop;
    ClkReset clock1;
    ClkStart clock1;
    FOR l FROM 1 TO MAX_LAYERS DO
      level := l;
      stackLayer layers{level}, level \Slow;
      IF stopRequested THEN
        TPWrite "Stopped after layer " \Num:=level;
        RETURN;
      ENDIF
    ENDFOR
    cycleTime := ClkRead(clock1);
    TPWrite "Cycle: " + NumToStr(cycleTime, 1) + " s";
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      RETRY;
    ENDIF
    RAISE;
  ENDPROC

  PROC stackLayer(layer lay, num level \switch Slow)
    VAR robtarget pPlace;
    VAR speeddata vMove := v1000;
    IF Present(Slow) vMove := v200;
    FOR r FROM 1 TO lay.rows DO
      FOR c FROM 1 TO lay.cols DO
        pPlace := placeTarget(r, c, level * lay.height);
        pickPart;
        MoveJ Offs(pPlace, 0, 0, 100), vMove, z50, tGripper \WObj:=wPallet;
        MoveL pPlace, v100, fine, tGripper \WObj:=wPallet;
        SetDO doGrip, 0;
        WaitTime \InPos, 0.2;
        Incr placed;
        MoveL Offs(pPlace, 0, 0, 100), v500, z10, tGripper \WObj:=wPallet;
      ENDFOR
    ENDFOR
  ENDPROC

  PROC pickPart()
    MoveJ Offs(pPick, 0, 0, 100), v1000, z50, tGripper;
    WaitDI diPartReady, 1 \MaxTime:=30;
    MoveL pPick, v200, fine, tGripper;
    SetDO doGrip, 1;
    WaitTime 0.3;
    MoveL Offs(pPick, 0, 0, 100), v500, z10, tGripper;
  ENDPROC

  FUNC robtarget placeTarget(num row, num col, num z)
    VAR robtarget p;
    p := pPick;
    p.trans := [row * 120, col * 80, z];
    p.rot := OrientZYX(90, 0, 180);
    RETURN p;
  ENDFUNC

  TRAP onStop
    stopRequested := TRUE;
  ENDTRAP
ENDMODULE
