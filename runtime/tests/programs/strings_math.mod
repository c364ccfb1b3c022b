MODULE strings_math
  ! The evaluator's functions at run time, on variables.
  PROC main()
    VAR string s := "Robot Studio";
    VAR num n;
    VAR bool ok;
    VAR pos p;
    TPWrite StrPart(s, 7, 6);
    TPWrite "find "\Num:=StrFind(s, 1, " ");
    TPWrite StrMap(s, "abcdefghijklmnopqrstuvwxyz", "ABCDEFGHIJKLMNOPQRSTUVWXYZ");
    TPWrite NumToStr(2 / 3, 3);
    TPWrite "round "\Num:=Round(2.567\Dec:=1);
    TPWrite "trunc "\Num:=Trunc(-2.567);
    TPWrite "sqrt "\Num:=Sqrt(2);
    TPWrite "sin "\Num:=Sin(30);
    TPWrite "atan2 "\Num:=ATan2(1, 1);
    TPWrite "pow "\Num:=Pow(2, 10);
    TPWrite "abs "\Num:=Abs(-7);
    ok := StrToVal("42.5", n);
    TPWrite "parsed "\Num:=n;
    ok := StrToVal("[1,2,3]", p);
    TPWrite "parsed "\Pos:=p;
    ok := StrToVal("abc", n);
    TPWrite "not a number "\Bool:=ok;
    TPWrite "hex " + DecToHex("255");
    TPWrite "bits "\Num:=BitAnd(12, 10);
    TPWrite ValToStr(0.1 + 0.2);
    TPWrite "dnum "\Dnum:=NumToDnum(0.1) + 0.2;
    TPWrite "memb "\Bool:=StrMemb(s, 1, STR_UPPER);
    TPWrite "order "\Bool:=StrOrder("abc", "abd", STR_LOWER);
    TPWrite "distance "\Num:=Distance([0, 0, 0], [3, 4, 0]);
    TPWrite "string " + ByteToStr(65\Char);
  ENDPROC
ENDMODULE
!> Studio
!> find 6
!> ROBOT STUDIO
!> 0.667
!> round 2.6
!> trunc -2
!> sqrt 1.41421
!> sin 0.5
!> atan2 45
!> pow 1024
!> abs 7
!> parsed 42.5
!> parsed [1,2,3]
!> not a number FALSE
!> hex FF
!> bits 8
!> 0.3
!> dnum 0.300000001490116
!> memb TRUE
!> order TRUE
!> distance 5
!> string A
