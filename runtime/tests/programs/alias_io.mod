MODULE alias_io
  ! Signal variables connected to configured signals with AliasIO, and
  ! disconnected again; controller queries.
  !set do_gripper=0
  VAR signaldo grip;

  PROC main()
    AliasIO "do_gripper", grip;
    SetDO grip, 1;
    TPWrite "gripper "\Num:=DOutput(do_gripper);
    TPWrite "real controller "\Bool:=RobOS();
    TPWrite "auto "\Bool:=OpMode() = OP_AUTO;
    AliasIOReset grip;
    SetDO grip, 0;
  ERROR
    TPWrite "not connected "\Bool:=ERRNO = ERR_NO_ALIASIO_DEF;
  ENDPROC
ENDMODULE
!> gripper 1
!> real controller FALSE
!> auto TRUE
!> not connected TRUE
