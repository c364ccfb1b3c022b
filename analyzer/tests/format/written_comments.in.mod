! as written: comments on their own lines follow the code around them
MODULE Comments
    ! before a declaration, like it
    VAR num a:=1;   ! trailing comments stay where they are
! at column 0: stays
    PROC main()
    !* a routine's header comment at the routine's column stays
      ! like the next line, which moves
      a:=1;
        IF a THEN
            b:=1;
            ! after the last statement of a body
        ELSE
        ! alone in an else body
        ENDIF
            ! deeper than ENDPROC that follows: in the body
    ENDPROC
ENDMODULE
