MODULE record_named_like_an_option_type
  ! A task's own RECORD of the name of an option's data type (Production
  ! Manager's partdata, in a task without the option) is the task's: its
  ! aggregates, components, arrays and parameters are those it declares.
  RECORD partdata
    string name;
    num count;
    pos offset;
  ENDRECORD

  CONST partdata first := ["A", 0, [0, 0, 0]];
  VAR partdata parts{2} := [["B", 0, [100, 0, 0]], ["C", 0, [200, 0, 0]]];
  VAR partdata empty;
  VAR num k := 2;

  PROC main()
    TPWrite first.name + " "\Num:=first.offset.x;
    Bump parts{k};
    Bump parts{k};
    TPWrite parts{2}.name + " "\Num:=parts{2}.count;
    TPWrite "empty """ + empty.name + """ "\Num:=empty.count;
    empty := first;
    empty.offset.z := 50;
    TPWrite ValToStr(empty);
  ENDPROC

  PROC Bump(INOUT partdata p)
    p.count := p.count + 1;
  ENDPROC
ENDMODULE
!> A 0
!> C 2
!> empty "" 0
!> ["A",0,[0,0,50]]
