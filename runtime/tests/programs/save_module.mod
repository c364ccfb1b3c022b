MODULE save_module
  ! Save writes the module as the controller does: persistents at their
  ! current values, everything else as written.
  PERS num count := 0;
  PERS string label;
  VAR num unsaved := 7;
  PERS pos place{2} := [[0, 0, 0], [1, 2, 3]];

  PROC main()
    VAR iodev f;
    VAR string line;
    count := count + 1.5;
    label := "ready";
    unsaved := 8;
    place{2}.z := 30;
    Save "save_module" \FilePath:="HOME:/" \File:="saved.mod";
    Open "HOME:/saved.mod", f \Read;
    line := ReadStr(f);
    WHILE line <> EOF DO
      IF StrLen(line) > 8 THEN
        IF StrPart(line, 1, 6) = "  PERS" OR StrPart(line, 1, 9) = "  VAR num" TPWrite line;
      ENDIF
      line := ReadStr(f);
    ENDWHILE
    Close f;
    save_as "no_such_module", "HOME:/x.mod";
    save_as "save_module", "HOME:/missing/folder/saved.mod";
    Save \TaskName:="T_NONE", "save_module" \FilePath:="HOME:/y.mod";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "no task T_NONE";
    RETURN;
  ENDPROC

  PROC save_as(string name, string path)
    Save name \FilePath:=path;
  ERROR
    IF ERRNO = ERR_MODULE TPWrite "no module " + name;
    IF ERRNO = ERR_FILEOPEN TPWrite "cannot write " + path;
    TRYNEXT;
  ENDPROC
ENDMODULE
!>   PERS num count := 1.5;
!>   PERS string label:="ready";
!>   VAR num unsaved := 7;
!>   PERS pos place{2} := [[0,0,0],[1,2,30]];
!> no module no_such_module
!> cannot write HOME:/missing/folder/saved.mod
!> no task T_NONE
