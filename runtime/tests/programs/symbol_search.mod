MODULE symbol_search
  ! SetDataSearch and GetNextSym go through the module data of a type
  ! whose names match a regular expression (ignoring case): at the task
  ! level the global data, with \Recursive the LOCAL data too; \InMod one
  ! module's; \VarSym and friends one kind. SetDataVal and GetDataVal
  ! \Block reach a match; SetAllDataVal writes every variable and
  ! persistent that matches (not constants, not arrays).
  VAR bool myA := FALSE;
  LOCAL VAR bool myB := FALSE;
  PERS bool myP := FALSE;
  CONST bool myC := TRUE;
  VAR bool other := FALSE;
  VAR num regA := 1;
  VAR num regB := 2;
  CONST num regC := 3;
  VAR num regs{2} := [4, 5];
  VAR datapos block;
  VAR string name;
  VAR bool b;

  PROC main()
    SetDataSearch "bool" \Object:="^my";
    WHILE GetNextSym(name, block) DO
      TPWrite "task: " + name;
    ENDWHILE
    SetDataSearch "BOOL" \Object:="^MY";
    WHILE GetNextSym(name, block \Recursive) DO
      TPWrite "recursive: " + name;
    ENDWHILE
    SetDataSearch "bool" \Object:="^my" \InMod:="symbol_search" \LocalSym;
    WHILE GetNextSym(name, block) DO
      SetDataVal name \Block:=block, TRUE;
      GetDataVal name \Block:=block, b;
      TPWrite "local: " + name + " " \Bool:=b;
    ENDWHILE
    SetDataSearch "bool" \VarSym;
    WHILE GetNextSym(name, block) DO
      TPWrite "var: " + name;
    ENDWHILE
    SetDataSearch "bool" \InMod:="no_such_module";
    TPWrite "none "\Bool:=NOT GetNextSym(name, block);
    SetAllDataVal "num" \Object:="^reg", 9;
    TPWrite "all " + ValToStr(regA) + " " + ValToStr(regB) + " " + ValToStr(regC) + " " + ValToStr(regs);
    SetDataSearch "num" \Object:="(";
  ERROR
    TPWrite "bad pattern "\Bool:=ERRNO = ERR_ARGVALERR;
    SetDataSearch "num" \InRout:="main";
  ENDPROC
ENDMODULE
!> task: myA
!> task: myP
!> task: myC
!> recursive: myA
!> recursive: myB
!> recursive: myP
!> recursive: myC
!> local: myB TRUE
!> var: myA
!> var: other
!> var: b
!> none TRUE
!> all 9 9 3 [4,5]
!> bad pattern TRUE
!! unsupported: SetDataSearch \InRout (a routine's data) at 47
