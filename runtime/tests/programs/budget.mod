MODULE budget
  ! A loop that never ends stops when the step budget runs out.
  !steps 1000
  PROC main()
    VAR num n := 0;
    WHILE TRUE DO
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
!! budget at 7
