%%%
! <- punctuation.special
  VERSION:1
! ^ attribute
!         ^ constant
  LANGUAGE:ENGLISH
%%%
module Lower
! <- keyword
  PERS wobjdata frame := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
! ^ keyword.modifier
!      ^ type.builtin
!               ^ variable
!                         ^ constant.builtin
!                                      ^ string
  ALIAS num level;
! ^ keyword
!           ^ type.definition
  TRAP OnStop
! ^ keyword.function
!      ^ function
    MoveL *, v100, z10, tool0;
!         ^ variable.builtin
    %"run_" + name% 1;
!   ^ operator
!    ^ string
    CONNECT irq WITH OnStop;
!   ^ keyword
!           ^ variable
!                    ^ function
    WHILE TRUE DO
!   ^ keyword.repeat
!              ^ keyword.repeat
      IF x GOTO next;
!     ^ keyword.conditional
!          ^ keyword.repeat
!               ^ label
    ENDWHILE
    next:
    TEST n
!   ^ keyword.conditional
    CASE 1:
!   ^ keyword.conditional
      <SMT>
!     ^ string.special
    DEFAULT:
      Stop;
!     ^ function.call
    ENDTEST
  UNDO
! ^ keyword.exception
    TRYNEXT;
!   ^ keyword.exception
  endtrap
! ^ keyword.function
ENDMODULE
left-over text after the module
