! fmt: style=tight
MODULE TightLines
VAR num a:=1;   ! trailing comment keeps its blanks
PERS tooldata tGripper:=[TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];

PROC main()
        a:=1;
        IF a>1 THEN
                a:=0;
        ENDIF
        MoveL Offs(pHome,100,200,300),
              v1000,
              z50,tGripper\WObj:=wobjTable;
        x:=Sum(1,
                2);
ENDPROC

PROC other()
ENDPROC
ENDMODULE
