MODULE production_manager
  ! ExecEngine (Production Manager): the operator chooses each part by its
  ! procedure's name; the engine runs it and asks again. A part chosen
  ! after a delay runs then; when nobody answers, the task waits for the
  ! operator at the engine.
  !answer PartA
  !answer @3 PartB
  !answer "parta"
  !answer -
  VAR clock clk;
  VAR num runs;

  PROC main()
    ClkStart clk;
    ExecEngine;
    TPWrite "never";
  ENDPROC

  PROC PartA()
    Incr runs;
    TPWrite "A "\Num:=runs;
  ENDPROC

  PROC PartB()
    Incr runs;
    TPWrite "B after "\Num:=ClkRead(clk);
  ENDPROC
ENDMODULE
!> A 1
!> B after 3
!> A 3
!! operator at 15
