MODULE control_flow
  ! IF, compact IF, FOR with STEP, WHILE, TEST, GOTO, EXIT.
  PROC main()
    VAR num n := 0;
    VAR string s := "";
    FOR i FROM 1 TO 3 DO
      IF i = 1 THEN
        TPWrite "one";
      ELSEIF i = 2 THEN
        TPWrite "two";
      ELSE
        TPWrite "other "\Num:=i;
      ENDIF
    ENDFOR
    FOR i FROM 10 TO 1 STEP -4 DO
      s := s + NumToStr(i, 0) + " ";
    ENDFOR
    TPWrite s;
    s := "";
    FOR i FROM 3 TO 1 DO
      s := s + NumToStr(i, 0);
    ENDFOR
    TPWrite "down: " + s;
    FOR i FROM 0 TO 1 STEP 0.25 DO
      n := n + i;
    ENDFOR
    TPWrite "quarters "\Num:=n;
    FOR i FROM 5 TO 1 STEP 1 DO
      TPWrite "never";
    ENDFOR
    n := 0;
    WHILE n < 5 DO
      Incr n;
      IF n = 2 TPWrite "compact two";
    ENDWHILE
    TPWrite "while done "\Num:=n;
    FOR k FROM 1 TO 6 DO
      TEST k
      CASE 1, 3, 5:
        TPWrite "odd "\Num:=k;
      CASE 2:
        TPWrite "two";
      DEFAULT:
        TPWrite "even "\Num:=k;
      ENDTEST
    ENDFOR
    n := 0;
    again:
    Incr n;
    IF n < 3 GOTO again;
    TPWrite "looped "\Num:=n;
    GOTO skip;
    TPWrite "skipped";
    skip:
    FOR i FROM 1 TO 3 DO
      IF i = 2 GOTO out;
      TPWrite "before out "\Num:=i;
    ENDFOR
    out:
    TPWrite "end of main";
    EXIT;
    TPWrite "after exit";
  ENDPROC
ENDMODULE
!> one
!> two
!> other 3
!> 10 6 2 
!> down: 321
!> quarters 2.5
!> compact two
!> while done 5
!> odd 1
!> two
!> odd 3
!> even 4
!> odd 5
!> even 6
!> looped 3
!> before out 1
!> end of main
!! exited
