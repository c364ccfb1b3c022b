MODULE Broken
    PROC main()
        x := ;
    ENDPROC
ENDMODULE
