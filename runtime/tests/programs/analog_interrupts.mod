MODULE analog_interrupts
  ! ISignalAO/ISignalAI: the reference is the value when the interrupt is
  ! ordered; a value that meets the condition and moves more than
  ! DeltaValue from the reference becomes the reference, and raises the
  ! interrupt when it moves the way \DPos or \DNeg asks.
  !set ai_temp=3@1
  !set ai_temp=2.5@2
  !set ai_temp=7@3
  !set ai_temp=12@4
  VAR intnum out_int;
  VAR intnum up_int;
  VAR intnum once_int;
  VAR num seen := 0;

  PROC main()
    SetAO ao_current, 5;
    CONNECT out_int WITH on_current;
    ISignalAO ao_current, AIO_BETWEEN, 10, 2, 1, out_int;
    ! 5.5: within 1 of the reference 5, no interrupt
    SetAO ao_current, 5.5;
    ! 8: more than 1 away, between 2 and 10: an interrupt
    SetAO ao_current, 8;
    ! 3: down by 5, an interrupt (either way)
    SetAO ao_current, 3;
    ! 11: outside the band: nothing
    SetAO ao_current, 11;
    ! 1: outside the band: nothing
    SetAO ao_current, 1;
    WaitTime 0.1;
    IDelete out_int;
    SetAO ao_current, 6;
    CONNECT up_int WITH on_temp;
    ISignalAI ai_temp, AIO_ALWAYS, 0, 0, 1 \DPos, up_int;
    CONNECT once_int WITH on_once;
    ISignalAI \Single, ai_temp, AIO_ABOVE_HIGH, 5, 0, 0, once_int;
    WaitTime 5;
    TPWrite "interrupts " \Num:=seen;
  ENDPROC

  TRAP on_current
    seen := seen + 1;
    TPWrite "current " \Num:=AOutput(ao_current);
  ENDTRAP

  TRAP on_temp
    seen := seen + 1;
    TPWrite "temperature up " \Num:=AInput(ai_temp);
  ENDTRAP

  TRAP on_once
    seen := seen + 1;
    TPWrite "temperature above 5 " \Num:=AInput(ai_temp);
  ENDTRAP
ENDMODULE
!> current 8
!> current 3
!> temperature up 3
!> temperature up 7
!> temperature above 5 7
!> temperature up 12
!> interrupts 6
