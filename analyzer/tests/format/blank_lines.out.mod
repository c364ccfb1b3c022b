! fmt: style=spaced
MODULE BlankLines

    VAR num a;

    VAR num b;
    PROC first()
        a := 1;

        b := 2;
    ENDPROC

    PROC second()
    ENDPROC

    PROC third()
    ENDPROC

    ! a comment that belongs to fourth
    PROC fourth()
    ENDPROC ! trailing after the end keyword

    PROC fifth()
    ENDPROC

    ! separated by a blank line already
    PROC sixth()
    ENDPROC
ENDMODULE
