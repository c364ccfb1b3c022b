MODULE basics
  ! Assignment, arithmetic in single precision, strings, booleans.
  VAR num count := 3;
  VAR string greeting := "Hello";
  CONST num limit := 2 * 5;
  PERS bool flag := TRUE;

  PROC main()
    VAR num x;
    VAR dnum d;
    TPWrite greeting + ", world";
    x := count * limit + 0.5;
    TPWrite "x = "\Num:=x;
    TPWrite "third: "\Num:=1 / 3;
    d := 1 / 3;
    TPWrite "dnum third: "\Dnum:=d;
    TPWrite "flag: "\Bool:=flag;
    TPWrite "div "\Num:=17 DIV 5;
    TPWrite "mod "\Num:=17 MOD 5;
    TPWrite "big "\Num:=123456789;
    TPWrite ValToStr([1, 2, 3]);
    TPWrite "pos: "\Pos:=[1, 2.5, -3];
    TPWrite "orient: "\Orient:=OrientZYX(90, 0, 0);
    TPWrite "len " + NumToStr(StrLen(greeting), 0);
  ENDPROC
ENDMODULE
!> Hello, world
!> x = 30.5
!> third: 0.333333
!> dnum third: 0.333333333333333
!> flag: TRUE
!> div 3
!> mod 2
!> big 1.23457E+08
!> [1,2,3]
!> pos: [1,2.5,-3]
!> orient: [0.707107,0,0,0.707107]
!> len 5
