MODULE files
  ! Files in the sandbox folder: write, read back, end of file, copy,
  ! rename, errors, bytes read as text (ReadStrBin).
  PROC main()
    VAR iodev f;
    VAR string line;
    VAR num n;
    Open "HOME:" \File:="log.txt", f\Write;
    Write f, "first line";
    Write f, "count "\Num:=3;
    Write f, "42";
    Close f;
    Open "HOME:/log.txt", f\Append;
    Write f, "appended";
    Close f;
    Open "HOME:/log.txt", f\Read;
    line := ReadStr(f);
    TPWrite "read: " + line;
    line := ReadStr(f);
    TPWrite "read: " + line;
    n := ReadNum(f);
    TPWrite "number "\Num:=n + 1;
    TPWrite "read: " + ReadStr(f);
    TPWrite "end: " + ReadStr(f);
    Close f;
    TPWrite "exists "\Bool:=IsFile("HOME:/log.txt");
    CopyFile "HOME:/log.txt", "HOME:/copy.txt";
    RenameFile "HOME:/log.txt", "HOME:/old.txt";
    TPWrite "renamed: log "\Bool:=IsFile("HOME:/log.txt");
    TPWrite "renamed: old "\Bool:=IsFile("HOME:/old.txt");
    Open "HOME:/copy.txt", f\Read;
    TPWrite "copy: " + ReadStr(f);
    Close f;
    Open "HOME:/copy.txt", f\Read \Bin;
    TPWrite "bytes: " + ReadStrBin(f, 5) + "|" + ReadStrBin(f, 5);
    Close f;
    copy_onto_existing;
    Open "HOME:/missing.txt", f\Read;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_FILEOPEN THEN
      TPWrite "cannot open the missing file";
      RETURN;
    ENDIF
  ENDPROC

  PROC copy_onto_existing()
    CopyFile "HOME:/copy.txt", "HOME:/old.txt";
  ERROR
    TPWrite "the new path exists "\Bool:=ERRNO = ERR_FILEEXIST;
    RETURN;
  ENDPROC
ENDMODULE
!> read: first line
!> read: count 3
!> number 43
!> read: appended
!> end: EOF
!> exists TRUE
!> renamed: log FALSE
!> renamed: old TRUE
!> copy: first line
!> bytes: first| line
!> the new path exists TRUE
!> cannot open the missing file
