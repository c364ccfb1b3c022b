MODULE arc_welding
  ! Arc welding as moves: ArcLStart moves at its speeddata, ArcL and
  ! ArcLEnd at the weld speed, the first component of the welddata
  ! (10 mm/s here), whatever speeddata they name. A 100 mm seam at
  ! 10 mm/s takes 10 s plus the ramps at its ends.
  PERS seamdata seam1 := [1, 1, [1, 0, 14, 127, 0, 0, 0, 0, 0], 0, 0, 0, 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0];
  PERS welddata weld1 := [10, 0, [1, 0, 25, 275, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0]];
  PERS tooldata torch := [TRUE, [[0, 0, 300], [1, 0, 0, 0]], [2, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
  VAR clock seam_clock;

  PROC main()
    VAR robtarget start;
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, torch;
    ConfL \Off;
    start := Offs(CRobT(\Tool:=torch), 0, 0, -200);
    ArcLStart start, v1000, seam1, weld1, fine, torch;
    ClkStart seam_clock;
    ArcL Offs(start, 0, 50, 0), v1000, seam1, weld1, z1, torch;
    ArcLEnd Offs(start, 0, 100, 0), v1000, seam1, weld1, fine, torch;
    ClkStop seam_clock;
    TPWrite "seam of 100 mm, s "\Num:=Round(ClkRead(seam_clock) \Dec:=1);
    TPWrite "at y "\Num:=Round(CRobT(\Tool:=torch).trans.y);
  ENDPROC
ENDMODULE
!robot IRB 1600-6/1.2
!> seam of 100 mm, s 10
!> at y 100
