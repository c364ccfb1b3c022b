MODULE mixed
  ! Predefined data (v100, tool0), string TEST, arrays by reference, nested records,
  ! operators on negative numbers, boolean operators.
  RECORD frame
    string name;
    pose at;
  ENDRECORD

  VAR frame frames{2};
  VAR num reg1;

  PROC main()
    VAR num values{4} := [4, -7, 10, 3];
    VAR string mode := "fast";
    reg1 := 5;
    Incr reg1;
    TPWrite "reg1 "\Num:=reg1;
    TEST mode
    CASE "slow":
      TPWrite "slow";
    CASE "fast", "rapid":
      TPWrite "fast mode";
    ENDTEST
    Double values;
    TPWrite ValToStr(values);
    TPWrite "max "\Num:=Biggest(values);
    Rename frames{2}, "table";
    frames{2}.at.trans.z := 120;
    TPWrite frames{2}.name + " "\Pos:=frames{2}.at.trans;
    TPWrite "mod "\Num:=-7 MOD 3;
    TPWrite "div "\Num:=-7 DIV 2;
    TPWrite "xor "\Bool:=TRUE XOR FALSE;
    TPWrite "not "\Bool:=NOT (1 > 2 AND TRUE);
    TPWrite "";
    TPWrite "speed "\Num:=v100.v_tcp;
    TPWrite "tool z "\Num:=tool0.tframe.trans.z;
    TPWrite "scaled "\Num:=Scaled(2) + Scaled(2\Factor:=10);
  ENDPROC

  PROC Double(VAR num arr{*})
    FOR i FROM 1 TO Dim(arr, 1) DO
      arr{i} := arr{i} * 2;
    ENDFOR
  ENDPROC

  FUNC num Biggest(num arr{*})
    VAR num best;
    best := arr{1};
    FOR i FROM 2 TO Dim(arr, 1) DO
      IF arr{i} > best best := arr{i};
    ENDFOR
    RETURN best;
  ENDFUNC

  PROC Rename(INOUT frame f, string name)
    f.name := name;
  ENDPROC

  FUNC num Scaled(num x, \num Factor)
    IF Present(Factor) RETURN x * Factor;
    RETURN x;
  ENDFUNC
ENDMODULE
!> reg1 6
!> fast mode
!> [8,-14,20,6]
!> max 20
!> table [0,0,120]
!> mod -1
!> div -3
!> xor TRUE
!> not TRUE
!>
!> speed 100
!> tool z 0
!> scaled 22
