MODULE any_bin_files
  ! A taught path saved with WriteAnyBin and loaded again with ReadAnyBin,
  ! as lead-through teaching programs keep their paths: an array of
  ! records holding jointtargets, read back exactly (not to six digits,
  ! as text would); a second value after it; the end of the file is
  ! ERR_RANYBIN_EOF, data of another type ERR_RANYBIN_CHK.
  RECORD taughtstep
    num tool;
    string name;
    jointtarget joint;
  ENDRECORD
  VAR taughtstep saved{3};
  VAR taughtstep loaded{3};
  VAR iodev f;
  VAR num extra;
  VAR bool wrong;

  PROC main()
    saved{1}.name := "approach";
    saved{1}.joint.robax := [0.1234567, 10, 20, 0, 45, 0];
    saved{2}.tool := 1;
    saved{2}.joint.robax := [30, 15.5, 5, 0, 60, 90];
    saved{3}.name := "leave";
    saved{3}.joint.robax := [-30, 20, 10, 1, 30, -90];
    Open "HOME:/path_a.bin", f \Write \Bin;
    WriteAnyBin f, saved;
    WriteAnyBin f, 42;
    Close f;
    Open "HOME:/path_a.bin", f \Read \Bin;
    ReadAnyBin f, loaded;
    ReadAnyBin f, extra;
    TPWrite loaded{3}.name + ", tool " \Num:=loaded{2}.tool;
    TPWrite "the same "\Bool:=(loaded{1}.joint.robax.rax_1 = saved{1}.joint.robax.rax_1);
    TPWrite "last "\Num:=loaded{3}.joint.robax.rax_6;
    TPWrite "extra "\Num:=extra;
    ReadAnyBin f, extra;
    Rewind f;
    ReadAnyBin f, wrong;
    Close f;
  ERROR
    IF ERRNO = ERR_RANYBIN_EOF THEN
      TPWrite "end of the file";
      TRYNEXT;
    ELSEIF ERRNO = ERR_RANYBIN_CHK THEN
      TPWrite "not a bool";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
!> leave, tool 1
!> the same TRUE
!> last -90
!> extra 42
!> end of the file
!> not a bool
