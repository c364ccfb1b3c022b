! as written: routines at column 0, bodies indented by 2 or 4 at random,
! and a routine's first line typed one space in: no unit fits half of the
! lines, the module body stays at column 0 (as most of its own lines are),
! the stray line moves there and the bodies go to the width that most of
! their lines have (a routine of one width keeps it)
MODULE Flat
VAR num count:=0;
PROC a()
    count:=1;
    count:=2;
    IF count>1 THEN
        count:=3;
    ENDIF
ENDPROC
PROC b()
  count:=1;
  count:=2;
  count:=3;
ENDPROC
PROC c()
    count:=1;
    count:=2;
ENDPROC
PROC d()
    count:=1;
    count:=2;
ENDPROC
ENDMODULE
