MODULE directories
  ! Folders: OpenDir lists "." and ".." first, then the entries by name;
  ! ReadDir is FALSE after the last; a folder that is missing or closed
  ! raises ERR_FILEACC.
  PROC main()
    VAR iodev f;
    VAR dir d;
    VAR string name;
    MakeDir "HOME:/parts";
    MakeDir "HOME:/parts/old";
    Open "HOME:/parts/b.txt", f\Write;
    Close f;
    Open "HOME:/parts/a.txt", f\Write;
    Close f;
    OpenDir d, "HOME:/parts";
    WHILE ReadDir(d, name) DO
      IF name <> "." AND name <> ".." THEN
        IF IsFile("HOME:/parts/" + name \Directory) THEN
          TPWrite "folder " + name;
        ELSE
          TPWrite "file " + name;
        ENDIF
      ELSE
        TPWrite "entry " + name;
      ENDIF
    ENDWHILE
    TPWrite "after the end "\Bool:=ReadDir(d, name);
    CloseDir d;
    read_closed d;
    OpenDir d, "HOME:/nowhere";
    TPWrite "not reached";
  ERROR
    TPWrite "no such folder "\Bool:=ERRNO = ERR_FILEACC;
  ENDPROC

  PROC read_closed(VAR dir d)
    VAR string name;
    IF ReadDir(d, name) TPWrite "not reached";
  ERROR
    TPWrite "closed "\Bool:=ERRNO = ERR_FILEACC;
    RETURN;
  ENDPROC
ENDMODULE
!> entry .
!> entry ..
!> file a.txt
!> file b.txt
!> folder old
!> after the end FALSE
!> closed TRUE
!> no such folder TRUE
