MODULE records_arrays
  ! Records, aggregates, components, arrays of one and two dimensions.
  RECORD part
    string name;
    num weight;
    pos place;
  ENDRECORD

  VAR part parts{2} := [["bolt", 0.5, [1, 2, 3]], ["nut", 0.25, [0, 0, 0]]];
  VAR num grid{2, 3} := [[1, 2, 3], [4, 5, 6]];
  CONST robtarget pHome := [[500, 0, 600], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR part p;
    VAR pos shift;
    VAR robtarget t;
    p := parts{1};
    p.weight := p.weight * 4;
    p.place.z := 30;
    TPWrite p.name + " "\Num:=p.weight;
    TPWrite "place "\Pos:=p.place;
    TPWrite "original "\Pos:=parts{1}.place;
    parts{2}.name := "washer";
    TPWrite parts{2}.name;
    TPWrite "grid "\Num:=grid{2, 3};
    grid{1, 2} := grid{1, 2} + grid{2, 1};
    TPWrite "grid row "\Num:=grid{1, 2};
    TPWrite "dims "\Num:=Dim(grid, 1) * 10 + Dim(grid, 2);
    shift := [10, 20, 30] + p.place;
    TPWrite "shift "\Pos:=shift;
    TPWrite "scaled "\Pos:=2 * shift;
    t := Offs(pHome, 0, 0, 100);
    TPWrite "offs "\Pos:=t.trans;
    TPWrite ValToStr(parts{2});
    TPWrite "equal "\Bool:=parts{1}.place = [1, 2, 3];
    TPWrite "bad " \Num:=grid{3, 1};
  ENDPROC
ENDMODULE
!> bolt 2
!> place [1,2,30]
!> original [1,2,3]
!> washer
!> grid 6
!> grid row 6
!> dims 23
!> shift [11,22,60]
!> scaled [22,44,120]
!> offs [500,0,700]
!> ["washer",0.25,[0,0,0]]
!> equal TRUE
!! ERR_OUTOFBND at 36
