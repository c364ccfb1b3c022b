MODULE pers_interrupts
  ! IPers: a trap routine runs each time the persistent changes value (not
  ! when it is written with the value it holds); \Single only once;
  ! IDelete ends the watch.
  PERS num count := 0;
  PERS string state := "idle";
  VAR intnum on_count;
  VAR intnum on_state;
  VAR num seen := 0;

  PROC main()
    CONNECT on_count WITH count_changed;
    IPers count, on_count;
    CONNECT on_state WITH state_changed;
    IPers \Single, state, on_state;
    count := 1;
    count := 1;
    count := 2;
    state := "run";
    state := "stop";
    WaitTime 0.1;
    TPWrite "seen "\Num:=seen;
    IDelete on_count;
    count := 3;
    WaitTime 0.1;
    TPWrite "seen "\Num:=seen;
  ENDPROC

  TRAP count_changed
    seen := seen + 1;
    TPWrite "count "\Num:=count;
  ENDTRAP

  TRAP state_changed
    TPWrite "state " + state;
  ENDTRAP
ENDMODULE
!> count 1
!> count 2
!> state run
!> seen 2
!> seen 2
