! as written: CASE at the column of TEST, as the manual writes it
MODULE Cases
    PROC main()
        TEST reg1
        CASE 1,2,3:
            routine1;
        CASE 4:
            routine2;
            routine3;
        DEFAULT:
            Stop;
        ENDTEST
    ENDPROC
ENDMODULE
