MODULE params
  ! IN, VAR, INOUT and PERS parameters, optional parameters, switches,
  ! Present, conditional arguments, named arguments, recursion.
  PERS num total := 100;

  PROC main()
    VAR num a := 1;
    VAR num arr{3} := [1, 2, 3];
    ByValue a;
    TPWrite "after ByValue "\Num:=a;
    ByRef a;
    TPWrite "after ByRef "\Num:=a;
    ByInout arr{2};
    TPWrite "element "\Num:=arr{2};
    AddTo total;
    TPWrite "total "\Num:=total;
    Options 1;
    Options 2\Scale:=10;
    Options 3\Fast;
    Options 4\Scale:=2\Fast;
    Outer 5;
    Outer 6\Extra:=7;
    Named Second:=2, First:=1;
    TPWrite "sum "\Num:=Sum(arr);
    TPWrite "fact "\Num:=Fact(10);
    TPWrite "fib "\Num:=Fib(15);
    TPWrite "round "\Num:=Rounded(2.3456\Dec:=2);
    TPWrite "round "\Num:=Rounded(2.3456);
  ENDPROC

  PROC ByValue(num x)
    x := x + 10;
  ENDPROC

  PROC ByRef(VAR num x)
    x := x + 10;
  ENDPROC

  PROC ByInout(INOUT num x)
    x := x * 100;
  ENDPROC

  PROC AddTo(PERS num t)
    t := t + 1;
  ENDPROC

  PROC Options(num n, \num Scale, \switch Fast)
    VAR string s;
    s := "n=" + NumToStr(n, 0);
    IF Present(Scale) s := s + " scale=" + NumToStr(Scale, 0);
    IF Present(Fast) s := s + " fast";
    TPWrite s;
  ENDPROC

  PROC Outer(num n, \num Extra)
    Inner n\Extra?Extra;
  ENDPROC

  PROC Inner(num n, \num Extra)
    IF Present(Extra) THEN
      TPWrite "inner with "\Num:=Extra;
    ELSE
      TPWrite "inner without "\Num:=n;
    ENDIF
  ENDPROC

  PROC Named(num First, num Second)
    TPWrite "first "\Num:=First;
    TPWrite "second "\Num:=Second;
  ENDPROC

  FUNC num Sum(num values{*})
    VAR num s := 0;
    FOR i FROM 1 TO Dim(values, 1) DO
      s := s + values{i};
    ENDFOR
    RETURN s;
  ENDFUNC

  FUNC num Fact(num n)
    IF n <= 1 RETURN 1;
    RETURN n * Fact(n - 1);
  ENDFUNC

  FUNC num Fib(num n)
    IF n < 2 RETURN n;
    RETURN Fib(n - 1) + Fib(n - 2);
  ENDFUNC

  FUNC num Rounded(num v, \num Dec)
    RETURN Round(v\Dec?Dec);
  ENDFUNC
ENDMODULE
!> after ByValue 1
!> after ByRef 11
!> element 200
!> total 101
!> n=1
!> n=2 scale=10
!> n=3 fast
!> n=4 scale=2 fast
!> inner without 5
!> inner with 7
!> first 1
!> second 2
!> sum 204
!> fact 3.6288E+06
!> fib 610
!> round 2.35
!> round 2
