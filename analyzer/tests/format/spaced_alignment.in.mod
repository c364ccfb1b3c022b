! fmt: style=spaced
MODULE SpacedAlignment
    PROC main()
        MoveL Offs(pHome,100,200,300),v1000,
              z50,tGripper\WObj:=wobjTable;
        value:=Function(argumentOne,
                        argumentTwo,
                           argumentThree);
        CONST num speeds{8}:=[0.01,0.01,0.01,0.01,
                              0.05,0.05,0.05,0.05];
    ENDPROC
ENDMODULE
