MODULE unhandled
  ! An error no handler takes ends the run at its line.
  PROC main()
    TPWrite "start";
    Middle;
    TPWrite "not reached";
  ENDPROC

  PROC Middle()
    VAR string s;
    s := StrPart("abc", 2, 5);
  ENDPROC
ENDMODULE
!> start
!! ERR_OUTOFBND at 11
