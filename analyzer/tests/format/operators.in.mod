! fmt: style=spaced
MODULE Operators
    PROC main()
        x:=-1;
        y:=a- -b*(c+d)/e;
        z:=[-1,+2,-a];
        ok:=a<>b AND c<=d AND e>=f AND g<h;
        s:="text with ""quotes"" and \\ backslash"+str;
        r:=Round(v\Dec:=2);
        t:=CRobT(\Tool:=tool0\WObj:=wobj0);
        pos.x:=p{i,j}.trans.x;
        %"proc"+name% a,b;
        StartMove\AllMotionTasks;
        MoveL \Conc,p10,v100,fine,tool0;
        WaitUntil di1=1\MaxTime:=5\TimeFlag:=timeout;
        Foo Bar:=1,\Opt?opt;
        MoveL *,v100,fine,tool0;
    ENDPROC
ENDMODULE
