MODULE named_arguments
  ! Arguments named as their parameters, in any order: bound by the one
  ! binder, as the checker binds them (a named argument moves the position
  ! past its parameter).
  !set do1=0
  PROC main()
    SetDO Signal:=do1, 1;
    TPWrite "do1 "\Num:=DOutput(do1);
    SetDO Value:=0, Signal:=do1;
    TPWrite "do1 "\Num:=DOutput(do1);
    Show B:=2, A:=1;
    Show 3, B:=4;
    Show A:=5, 6;
    TPWrite "round "\Num:=Round(Val:=2.567\Dec:=1);
    TPWrite "sum "\Num:=Sum(Y:=10, X:=1);
  ENDPROC
  PROC Show(num A, num B)
    TPWrite "A "\Num:=A;
    TPWrite "B "\Num:=B;
  ENDPROC
  FUNC num Sum(num X, num Y)
    RETURN X + 2 * Y;
  ENDFUNC
ENDMODULE
!> do1 1
!> do1 0
!> A 1
!> B 2
!> A 3
!> B 4
!> A 5
!> B 6
!> round 2.6
!> sum 21
