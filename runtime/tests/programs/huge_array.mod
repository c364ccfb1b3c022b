MODULE huge_array
  ! An array larger than the simulation holds stops the run at its
  ! declaration instead of exhausting memory.
  PROC main()
    VAR num big{100000, 100000};
    TPWrite "not reached";
  ENDPROC
ENDMODULE
!! invalid at 5
