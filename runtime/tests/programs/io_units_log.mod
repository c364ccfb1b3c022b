MODULE io_units_log
  ! I/O devices (IOUnitState, IODisable, IOEnable, IODeactivate,
  ! IOActivate, ValidIO), a group
  ! output read as a dnum (GOutputDnum), the event
  ! log's text-table messages (ErrLog, ErrRaise, SkipWarn, the SmartGripper
  ! driver's EventLog), StrFormat and
  ! RemainingRetries.
  VAR errnum ERR_GRIPPER := -1;
  VAR num tries := 0;
  VAR num zero := 0;
  VAR signaldo do_alias;

  PROC main()
    TPWrite "running "\Bool:=IOUnitState("d651") = IOUNIT_RUNNING;
    TPWrite "state "\Num:=IOUnitState("d651");
    TPWrite "physical "\Num:=IOUnitState("d651" \Phys);
    IODisable "d651", 1;
    TPWrite "disabled "\Bool:=IOUnitState("D651") = IOUNIT_DISABLE;
    TPWrite "logic "\Num:=IOUnitState("d651" \Logic);
    TPWrite "physical "\Num:=IOUnitState("d651" \Phys);
    IOEnable "d651", 5;
    TPWrite "enabled again "\Bool:=IOUnitState("d651") = IOUNIT_RUNNING;
    IODeactivate "d651", 1;
    TPWrite "deactivated "\Bool:=IOUnitState("d651") = IOUNIT_DISABLE;
    IOActivate "d651", 5;
    TPWrite "activated "\Bool:=IOUnitState("d651") = IOUNIT_RUNNING;
    SetDO do1, 1;
    TPWrite "valid do1 "\Bool:=ValidIO(do1);
    TPWrite "valid alias "\Bool:=ValidIO(do_alias);
    SetGO go_word, 40000;
    TPWrite "group as dnum "\Dnum:=GOutputDnum(go_word) * 100000;
    ErrLog 4800, "Gripper", "no part", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
    ErrLog 4801 \W, "Cell", "slow", "", "", "";
    EventLog 90, 7, TYPE_WARN, "Hand", "stalled", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
    TPWrite StrFormat("part {1} of {2}, {x}{3}" \Arg1:="3" \Arg2:="10");
    retrying;
    BookErrNo ERR_GRIPPER;
    raising;
  ERROR
    TPWrite "raised "\Bool:=ERRNO = ERR_GRIPPER;
    SkipWarn;
    TRYNEXT;
  ENDPROC

  PROC retrying()
    VAR num x;
    x := 1 / zero;
  ERROR
    Incr tries;
    TPWrite "retries left "\Num:=RemainingRetries();
    IF tries < 3 RETRY;
    TRYNEXT;
  ENDPROC

  PROC raising()
    ErrRaise "ERR_GRIPPER", 4802, "Gripper", "lost", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
!> running TRUE
!> state 1
!> physical 21
!> disabled TRUE
!> logic 10
!> physical 20
!> enabled again TRUE
!> deactivated TRUE
!> activated TRUE
!> valid do1 TRUE
!> valid alias FALSE
!> group as dnum 4000000000
!> ErrLog 4800: Gripper no part
!> ErrLog 4801 (warning): Cell slow
!> EventLog 90 7 (warning): Hand stalled
!> part 3 of 10, {x}
!> retries left 4
!> retries left 3
!> retries left 2
!> ErrRaise ERR_GRIPPER 4802: Gripper lost
!> raised TRUE
!> [SkipWarn at io_units_log.mod:41] the handled error's warning is not logged
