MODULE manual_examples
  ! The examples of the RAPID reference manual (part 2) that state their
  ! result, run as a program (on variables, not folded as constants).
  VAR num reg1;
  VAR num reg2 := 6;
  VAR num reg3 := 0;

  PROC main()
    VAR string str;
    VAR num val;
    VAR num found;
    VAR bool memb;
    VAR bool ok;
    VAR num nval;
    VAR string str15 := "[600, 500, 225.3]";
    VAR pos pos15;
    VAR pos p := [100, 200, 300];
    str := NumToStr(0.38521, 3);
    TPWrite str;
    reg1 := 0.38521;
    str := NumToStr(reg1, 2\Exp);
    TPWrite str;
    val := Round(0.38521\Dec:=3);
    TPWrite ""\Num:=val;
    val := Round(0.38521\Dec:=1);
    TPWrite ""\Num:=val;
    val := Round(0.38521);
    TPWrite ""\Num:=val;
    found := StrFind("Robotics", 1, "aeiou");
    TPWrite ""\Num:=found;
    found := StrFind("Robotics", 1, "aeiou"\NotInSet);
    TPWrite ""\Num:=found;
    found := StrFind("IRB 6400", 1, STR_DIGIT);
    TPWrite ""\Num:=found;
    found := StrFind("IRB 6400", 1, STR_WHITE);
    TPWrite ""\Num:=found;
    TPWrite ""\Num:=StrLen("Robotics");
    TPWrite StrMap("Robotics", "aeiou", "AEIOU");
    TPWrite StrMap("Robotics", STR_LOWER, STR_UPPER);
    TPWrite ""\Num:=StrMatch("Robotics", 1, "bo");
    memb := StrMemb("Robotics", 2, "aeiou");
    TPWrite ""\Bool:=memb;
    memb := StrMemb("Robotics", 3, "aeiou");
    TPWrite ""\Bool:=memb;
    TPWrite ""\Bool:=StrOrder("FIRST", "SECOND", STR_UPPER);
    TPWrite StrPart("Robotics", 1, 5);
    ok := StrToVal("3.85", nval);
    TPWrite ""\Bool:=ok;
    TPWrite ""\Num:=nval;
    ok := StrToVal(str15, pos15);
    TPWrite ""\Bool:=ok;
    TPWrite ""\Pos:=pos15;
    val := Trunc(0.38521\Dec:=3);
    TPWrite ""\Num:=val;
    val := Trunc(reg1\Dec:=1);
    TPWrite ""\Num:=val;
    val := Trunc(0.38521);
    TPWrite ""\Num:=val;
    TPWrite ValToStr(1.234567);
    TPWrite ValToStr(TRUE);
    TPWrite ValToStr(p);
    ! errnum: a division by zero corrected in the error handler.
    reg1 := reg2 / reg3;
    TPWrite ""\Num:=reg1;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      reg3 := 1;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
!> 0.385
!> 3.85E-01
!> 0.385
!> 0.4
!> 0
!> 2
!> 1
!> 5
!> 4
!> 8
!> RObOtIcs
!> ROBOTICS
!> 3
!> TRUE
!> FALSE
!> TRUE
!> Robot
!> TRUE
!> 3.85
!> TRUE
!> [600,500,225.3]
!> 0.385
!> 0.3
!> 0
!> 1.23457
!> TRUE
!> [100,200,300]
!> 6
