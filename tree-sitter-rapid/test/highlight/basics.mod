MODULE Demo(SYSMODULE)
! <- keyword
!      ^ module
!           ^ keyword.modifier
  LOCAL CONST num limit := 10;
! ^ keyword.modifier
!       ^ keyword.modifier
!             ^ type.builtin
!                 ^ constant
!                          ^ number
  VAR part item;
!     ^ type
!          ^ variable
  RECORD part
! ^ keyword
!        ^ type.definition
    string name;
!          ^ property
  ENDRECORD

  PROC Main(VAR num count, \switch Fast)
! ^ keyword.function
!      ^ function
!           ^ keyword.modifier
!                   ^ variable.parameter
!                          ^ operator
    IF count > limit THEN
!   ^ keyword.conditional
!      ^ variable
!            ^ operator
!                    ^ keyword.conditional
      MoveL p10, v100, fine, tool0\WObj:=wobj1;
!     ^ function.call
!                                   ^ variable.parameter
!                                       ^ operator
    ELSE
!   ^ keyword.conditional
      item.name := "a ""b"" \41";
!          ^ property
!                  ^ string
!                     ^ string.escape
    ENDIF
    FOR i FROM 1 TO 3 DO
!   ^ keyword.repeat
    ENDFOR
    done := NOT TRUE AND x DIV 2 = 1;
!           ^ keyword.operator
!               ^ constant.builtin
!                          ^ keyword.operator
    again:
!   ^ label
    RETURN;
!   ^ keyword.return
  ERROR
! ^ keyword.exception
    RETRY;
!   ^ keyword.exception
  ENDPROC
! ^ keyword.function

  FUNC num Twice(num x)
!      ^ type.builtin
    RETURN Abs(x) * 2;
!          ^ function.call
!                 ^ operator
  ENDFUNC
ENDMODULE
