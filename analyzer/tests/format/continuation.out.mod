! fmt: style=spaced
MODULE Continuation
    CONST robtarget pts{2} := [
        [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]],
        [[4, 5, 6], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]
    ];
    PROC main()
        MoveL p10,
            v100,
            fine,
            tool0;
        IF a AND
            b THEN
            x := Sum(1,
                2);
        ENDIF
    ENDPROC
ENDMODULE
