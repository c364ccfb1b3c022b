MODULE dnum_functions
  ! The dnum forms of the arithmetic and bit functions, on values a num
  ! cannot hold exactly (above 2 to the power 24); Max and Min.
  VAR dnum word;

  PROC main()
    word := PowDnum(2, 31) + 5;
    TPWrite "2^31 + 5 = "\Dnum:=word;
    TPWrite "bit 32 "\Bool:=BitCheckDnum(word, 32);
    TPWrite "bit 2 "\Bool:=BitCheckDnum(word, 2);
    TPWrite "and "\Dnum:=BitAndDnum(word, 4294967295 - 1);
    TPWrite "or "\Dnum:=BitOrDnum(word, 2);
    TPWrite "xor "\Dnum:=BitXOrDnum(word, word);
    TPWrite "not "\Dnum:=BitNegDnum(word);
    TPWrite "left "\Dnum:=BitLShDnum(word, 1);
    TPWrite "right "\Dnum:=BitRShDnum(word, 1);
    TPWrite "sin 30 "\Dnum:=SinDnum(30);
    TPWrite "acos 0.5 "\Dnum:=ACosDnum(0.5);
    TPWrite "atan2 "\Dnum:=ATan2Dnum(1, -1);
    TPWrite "max "\Num:=Max(3, -4.5);
    TPWrite "min of a num and a dnum "\Dnum:=Min(3, word);
    TPWrite "bit 33 "\Bool:=BitCheckDnum(word, 33);
  ERROR
    TPWrite "argument error "\Bool:=ERRNO = ERR_ARGVALERR;
  ENDPROC
ENDMODULE
!> 2^31 + 5 = 2147483653
!> bit 32 TRUE
!> bit 2 FALSE
!> and 2147483652
!> or 2147483655
!> xor 0
!> not 2147483642
!> left 10
!> right 1073741826
!> sin 30 0.5
!> acos 0.5 60
!> atan2 135
!> max 3
!> min of a num and a dnum 3
!> argument error TRUE
