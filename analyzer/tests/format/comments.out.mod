! fmt: style=spaced
MODULE Comments
! own-line comment at module level
    VAR num a := 1;   ! trailing comment keeps its blanks
    PROC main()
        ! before a statement
        a := a + 1; !tight trailing comment
        IF a > 1 THEN
            b := 2;
            ! commented-out code at the end of a body
        ELSE
            ! first in the else body
        ENDIF
        TEST a
            ! before the first case
            CASE 1:
                stop;
                ! between cases
            DEFAULT:
                stop;
        ENDTEST
        ! before ENDPROC
    ENDPROC
    ! before ENDMODULE
ENDMODULE
! after ENDMODULE
