! fmt: style=spaced
Module KeywordCase (SysModule, NoStepIn)
    Local Var Num MyCounter := 0;
    Pers Bool bFlag := True;
    Local Func Bool IsReady(Var Num x)
        Return x > 0 AnD Not bFlag Or x Mod 2 = 1 XoR x Div 3 > 0;
    EndFunc
    Trap tOnStop
        Connect intNo With tOnStop;
        GoTo lblEnd;
        lblEnd:
        Exit;
    EndTrap
EndModule
