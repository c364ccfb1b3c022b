! fmt: style=spaced line-width=60
MODULE Wrapping
    CONST robtarget pLong:=[[100.5,200.25,300.125],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        MoveL Offs(pHome,100,200,300),v1000,z50,tGripper\WObj:=wobjTable;
        MoveL p10,v100,fine,tool0;
        TPWrite "A message that is far too long to fit on one line by itself"\Num:=12;
        MoveJ p20,v500,z10,tGripper\WObj:=wobjTable; ! the trailing comment does not count
        IF bReady MoveL Offs(pHome,100,200,300),v1000,z50,tGripper\WObj:=wobjTable;
        MoveJ [[100.5,200.25,300.125],[1,0,0,0],[0,0,0,0]],v1000,z50,tool0;
        value:=Function(argumentNumberOne,argumentNumberTwo,argumentNumberThree);
    ENDPROC
ENDMODULE
