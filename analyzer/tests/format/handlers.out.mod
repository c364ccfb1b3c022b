! fmt: style=spaced
MODULE Handlers
    PROC main()
        x := 1;
    ERROR (ERR_ONE, ERR_TWO)
        IF ERRNO = ERR_ONE RETRY;
        TRYNEXT;
    UNDO
        x := 0;
    ENDPROC

    PROC moveIt()
        MoveL p10, v100, fine, tool0;
    BACKWARD
        MoveL p20, v100, fine, tool0;
    ERROR
        RAISE;
    ENDPROC
ENDMODULE
