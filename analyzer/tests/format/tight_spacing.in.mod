! fmt: style=tight
MODULE TightSpacing
    PROC main()
        reg1 := reg1 + 1;
        x := - 1;
        y := a - -b * ( c + d ) / e;
        ok := a <> b AND c <= d OR NOT ready;
        flag := TRUE ;
        z := [ -1, +2, -a ];
        MoveL p10, v1000, z50, tool0 \WObj := wobj0;
        MoveL \Conc, p10, v100, fine, tool0;
        StopMove \Quick;
        r := Round( v \Dec := 2 );
        t := CRobT( \Tool := tool0 \WObj := wobj0 );
        pos.x := wobjP01 .uframe.trans.x + p{ i, j }.trans.x;
        % "proc" + name % a, b;
        WaitUntil di1 = 1 \MaxTime := 5 \TimeFlag := timeout;
        Foo Bar := 1, \Opt ? opt;
        IF ( a > 1 ) AND b THEN
            n := n DIV 2 + n MOD 2;
        ENDIF
    ENDPROC
    FUNC num Double(num x, \switch Half | switch Quarter, INOUT num y{*})
        RETURN x * 2;
    ENDFUNC
ENDMODULE
