MODULE Pattern_test
    ! Tests of Pattern: `rapid test examples/testing`.

    VAR num row;
    VAR num col;

    PROC setup()
        row := 0;
        col := 0;
    ENDPROC

    PROC first_slot_is_the_origin()
        AssertNearPos SlotPos(1, 1, 1, 120), [0, 0, 0], 0.001;
    ENDPROC

    PROC odd_layers_are_turned()
        AssertNearPos SlotPos(1, 2, 3, 120), [160, 420, 0], 0.001;
        AssertNearPos SlotPos(2, 2, 3, 120), [420, 160, 120], 0.001;
    ENDPROC

    PROC parses_row_and_column()
        ParseSlot "3,12", row, col;
        AssertEqual row, 3;
        AssertEqual col, 12\Message:="column";
    ENDPROC

    PROC rejects_text_without_comma()
        ParseSlot "312", row, col;
        Fail "ParseSlot accepted 312";
    ERROR
        AssertEqual ERRNO, ERR_ARGVALERR;
    ENDPROC
ENDMODULE
