! SYNTAX TEST "source.rapid" "statements, calls and expressions"
MODULE Cells(SYSMODULE, NOSTEPIN)
! <------ keyword.other.rapid
!      ^^^^^ entity.name.namespace.rapid
!            ^^^^^^^^^ storage.modifier.rapid
!                       ^^^^^^^^ storage.modifier.rapid
    TASK PERS tooldata tGrip := [TRUE, [[0, 0, 1.5E2], [1, 0, 0, 0]], load0];
!   ^^^^ storage.modifier.rapid
!        ^^^^ storage.modifier.rapid
!             ^^^^^^^^ support.type.rapid
!                      ^^^^^ variable.other.rapid
!                                ^^^^ constant.language.boolean.rapid
!                                              ^^^^^ constant.numeric.rapid
    LOCAL CONST part pDefault := ["box", 0x1F];
!   ^^^^^ storage.modifier.rapid
!               ^^^^ entity.name.type.rapid
!                    ^^^^^^^^ variable.other.constant.rapid
!                                 ^^^^^ string.quoted.double.rapid
!                                        ^^^^ constant.numeric.rapid
    var num counter{2, 3};
!   ^^^ storage.modifier.rapid
!       ^^^ support.type.rapid
!           ^^^^^^^ variable.other.rapid

    LOCAL PROC Pick(PERS wobjdata wobj, \num Speed | switch Slow, num list{*})
!   ^^^^^ storage.modifier.rapid
!         ^^^^ storage.type.function.rapid
!              ^^^^ entity.name.function.rapid
!                   ^^^^ storage.modifier.rapid
!                        ^^^^^^^^ support.type.rapid
!                                 ^^^^ variable.parameter.rapid
!                                       ^ keyword.operator.rapid
!                                        ^^^ support.type.rapid
!                                            ^^^^^ variable.parameter.rapid
!                                                  ^ keyword.operator.rapid
!                                                           ^^^^ variable.parameter.rapid
!                                                                          ^ keyword.operator.rapid
        counter{1, 2} := counter{1, 2} + 1;
!       ^^^^^^^ variable.other.rapid
!                     ^^ keyword.operator.rapid
        MoveL RelTool(p10, 0, 0, -50), v100, z10, tool0 \WObj:=wobj;
!       ^^^^^ entity.name.function.call.rapid
!             ^^^^^^^ entity.name.function.call.rapid
!                                                        ^^^^ variable.parameter.rapid
!                                                            ^^ keyword.operator.rapid
        TPWrite "Count: ""a"" \41" \Num:=Round(x\Dec:=2);
!       ^^^^^^^ entity.name.function.call.rapid
!                       ^^ constant.character.escape.rapid
!                             ^^^ constant.character.escape.rapid
!                                   ^^^ variable.parameter.rapid
!                                        ^^^^^ entity.name.function.call.rapid
!                                                ^^^ variable.parameter.rapid
        Stop;
!       ^^^^ entity.name.function.call.rapid
        pDefault.name := "x";
!       ^^^^^^^^ variable.other.rapid
!                ^^^^ variable.other.property.rapid
        IF NOT bDone AND n MOD 2 = 0 THEN
!       ^^ keyword.control.conditional.rapid
!          ^^^ keyword.operator.word.rapid
!                    ^^^ keyword.operator.word.rapid
!                          ^^^ keyword.operator.word.rapid
!                                    ^^^^ keyword.control.conditional.rapid
            WaitTime 0.5;
!           ^^^^^^^^ entity.name.function.call.rapid
        elseif n > 3 then
!       ^^^^^^ keyword.control.conditional.rapid
            Raise ERR_MY;
!           ^^^^^ keyword.control.exception.rapid
        ENDIF
!       ^^^^^ keyword.control.conditional.rapid
        FOR i FROM 1 TO 10 STEP 2 DO
!       ^^^ keyword.control.loop.rapid
!             ^^^^ keyword.control.loop.rapid
!                          ^^^^ keyword.control.loop.rapid
        ENDFOR
!       ^^^^^^ keyword.control.loop.rapid
        retry_here:
!       ^^^^^^^^^^ entity.name.label.rapid
        ! a comment with "quotes" and IF
!       ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.exclamation.rapid
    ERROR
!   ^^^^^ keyword.control.exception.rapid
        IF ERRNO = ERR_WAIT_MAXTIME RETRY;
!          ^^^^^ variable.other.rapid
!                                   ^^^^^ keyword.control.exception.rapid
    ENDPROC
!   ^^^^^^^ storage.type.function.rapid

    FUNC pose Shift{*}(num dx)
!   ^^^^ storage.type.function.rapid
    ENDFUNC
    FUNC dnum Half(num x)
!        ^^^^ support.type.rapid
!             ^^^^ entity.name.function.rapid
!                      ^ variable.parameter.rapid
        RETURN x / 2;
!       ^^^^^^ keyword.control.return.rapid
    ENDFUNC
ENDMODULE
! <--------- keyword.other.rapid
