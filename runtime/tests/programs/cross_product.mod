MODULE cross_product
  ! CrossProd: the pos perpendicular to two pos vectors, right-handed;
  ! with DotProd and VectMagn, the normal of a plane from three points.
  CONST pos origin := [100, 0, 0];
  CONST pos alongX := [200, 0, 0];
  CONST pos alongY := [100, 50, 0];
  VAR pos normal;

  PROC main()
    TPWrite "x by y "\Pos:=CrossProd([1, 0, 0], [0, 1, 0]);
    TPWrite "y by x "\Pos:=CrossProd([0, 1, 0], [1, 0, 0]);
    TPWrite "parallel "\Pos:=CrossProd([2, 4, 6], [1, 2, 3]);
    normal := CrossProd(alongX - origin, alongY - origin);
    TPWrite "normal "\Pos:=normal;
    TPWrite "unit "\Pos:=normal * (1 / VectMagn(normal));
    TPWrite "perpendicular "\Bool:=DotProd(normal, alongX - origin) = 0;
    TPWrite "general "\Pos:=CrossProd([1, 2, 3], [4, 5, 6]);
  ENDPROC
ENDMODULE
!> x by y [0,0,1]
!> y by x [0,0,-1]
!> parallel [0,0,0]
!> normal [0,0,5000]
!> unit [0,0,1]
!> perpendicular TRUE
!> general [-3,6,-3]
