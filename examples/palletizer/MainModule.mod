MODULE MainModule
    ! Picks boxes from an infeed conveyor and stacks them on a pallet,
    ! layer by layer, in a grid of nRows x nCols.

    CONST num nRows := 3;
    CONST num nCols := 4;
    CONST num nLayers := 2;
    CONST num boxHeight := 120;
    CONST num pitchX := 210;
    CONST num pitchY := 160;

    VAR num nPlaced := 0;
    VAR intnum irStop;
    PERS bool bStopRequested := FALSE;

    CONST robtarget pPickAbove := [[812.5,-402.1,455],[0.00469,0.70712,-0.70706,0.00421],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPalletOrigin := [[150,900,180],[0.0046,0.0001,-0.99998,0.00421],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jHome := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        Initialise;
        FOR layer FROM 1 TO nLayers DO
            FOR row FROM 1 TO nRows DO
                FOR col FROM 1 TO nCols DO
                    IF bStopRequested THEN
                        GoHome;
                        RETURN;
                    ENDIF
                    PickBox;
                    PlaceBox layer, row, col;
                ENDFOR
            ENDFOR
        ENDFOR
        TPWrite "Pallet complete: " \Num:=nPlaced;
        GoHome;
    ENDPROC

    PROC Initialise()
        nPlaced := 0;
        bStopRequested := FALSE;
        AccSet 70, 70;
        VelSet 100, 2000;
        IDelete irStop;
        CONNECT irStop WITH StopTrap;
        ISignalDI diStopCycle, 1, irStop;
        GoHome;
    ENDPROC

    PROC GoHome()
        MoveAbsJ jHome\NoEOffs, v1000, fine, tGripper;
    ENDPROC

    PROC PickBox()
        WaitDI diBoxPresent, 1 \MaxTime:=30;
        MoveJ Offs(pPickAbove, 0, 0, 100), v1500, z50, tGripper\WObj:=wobjConveyor;
        MoveL pPickAbove, v300, fine, tGripper\WObj:=wobjConveyor;
        SetDO doVacuum, 1;
        WaitTime 0.2;
        MoveL Offs(pPickAbove, 0, 0, 100), v500, z20, tGripper\WObj:=wobjConveyor;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            TPWrite "No box arrived within 30 s";
            RETRY;
        ENDIF
    ENDPROC

    PROC PlaceBox(num layer, num row, num col)
        VAR robtarget pTarget;

        pTarget := SlotTarget(layer, row, col);
        MoveJ Offs(pTarget, 0, 0, 150), v1500, z50, tGripper\WObj:=wobjPallet;
        MoveL pTarget, v200, fine, tGripper\WObj:=wobjPallet;
        SetDO doVacuum, 0;
        WaitTime 0.1;
        MoveL Offs(pTarget, 0, 0, 150), v500, z20, tGripper\WObj:=wobjPallet;
        Incr nPlaced;
    ENDPROC

    FUNC robtarget SlotTarget(num layer, num row, num col)
        ! Position of one slot of the grid, relative to the pallet origin.
        RETURN Offs(pPalletOrigin, (col - 1) * pitchX, (row - 1) * pitchY, (layer - 1) * boxHeight);
    ENDFUNC

    TRAP StopTrap
        bStopRequested := TRUE;
    ENDTRAP
ENDMODULE
