! fmt: style=tight line-width=60
MODULE TightWrapping
    PROC main()
        MoveL Offs(pHome, 100, 200, 300), v1000, z50, tGripper \WObj := wobjTable;
        MoveL p10, v100, fine, tool0;
        TPWrite "A message that is far too long to fit on one line by itself"\Num:=12;
    ENDPROC
ENDMODULE
