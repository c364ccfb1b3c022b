MODULE Pattern
    ! Where the boxes of a pallet layer go: a grid of rows and columns,
    ! every other layer turned by 90 degrees.

    CONST num pitchX := 210;
    CONST num pitchY := 160;

    ! The position of slot (row, col) of a layer, relative to the pallet
    ! origin, in mm.
    FUNC pos SlotPos(num layer, num row, num col, num boxHeight)
        VAR pos p;
        IF row < 1 OR col < 1 RAISE ERR_OUTOFBND;
        IF layer MOD 2 = 0 THEN
            p := [(col - 1) * pitchX, (row - 1) * pitchY, 0];
        ELSE
            p := [(row - 1) * pitchY, (col - 1) * pitchX, 0];
        ENDIF
        p.z := (layer - 1) * boxHeight;
        RETURN p;
    ENDFUNC

    ! Parses "row,col" as sent by a cell controller.
    PROC ParseSlot(string text, INOUT num row, INOUT num col)
        VAR num comma;
        VAR bool ok;
        comma := StrFind(text, 1, ",");
        IF comma > StrLen(text) RAISE ERR_ARGVALERR;
        ok := StrToVal(StrPart(text, 1, comma - 1), row);
        ok := ok AND StrToVal(StrPart(text, comma + 1, StrLen(text) - comma), col);
        IF NOT ok RAISE ERR_ARGVALERR;
    ENDPROC
ENDMODULE
