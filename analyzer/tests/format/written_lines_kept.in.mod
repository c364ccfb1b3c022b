! as written: what is on a line stays as it is (blanks, keyword case,
! blanks at line ends, blank lines, several statements on a line)
MODULE LinesKept
    var num  a := 1;   
      PERS tooldata tGripper :=[TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];


    PROC main()
    a:=a+1;  b := b - 1;
        IF a > 1 THEN a := 0; ENDIF
            MoveL p10,v1000,z50,tool0\WObj:=wobj0;!tight comment
        MoveL p20, v1000, z50, tool0 \WObj := wobj0;
   Endproc
ENDMODULE