! as written: a continuation line keeps its distance from its statement,
! or its place under the token it was aligned under
MODULE Continuation
  CONST num speed_ratio{8}:=[0.01, 0.01, 0.01, 0.01,
                             0.05, 0.05, 0.05, 0.05];
    PERS jointtarget jp{3}:=[
    [[0,0,0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],
    [[1,0,0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],
    [[2,0,0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]];
    PROC main()
      MoveL Offs(pHome,100,200,300),
            v1000,
            z50, tGripper\WObj:=wobjTable;
        x:=Sum(1,
            2);
        IF a AND
              b THEN
            c:=1;
        ENDIF
    ENDPROC
ENDMODULE
