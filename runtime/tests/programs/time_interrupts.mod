MODULE time_interrupts
  ! A simulated clock: WaitTime, clocks, CTime; ITimer and ISignalDI
  ! interrupts run their traps while the program waits.
  VAR intnum tick;
  VAR intnum part;
  VAR num ticks := 0;
  VAR clock watch;
  !set di_part=1@2.5

  PROC main()
    ClkStart watch;
    CONNECT tick WITH OnTick;
    ITimer 1, tick;
    CONNECT part WITH OnPart;
    ISignalDI di_part, 1, part;
    WaitTime 3.5;
    ClkStop watch;
    TPWrite "ticks "\Num:=ticks;
    TPWrite "clock "\Num:=ClkRead(watch);
    IDelete tick;
    WaitTime 2;
    TPWrite "ticks after delete "\Num:=ticks;
    TPWrite "time " + CTime();
    TPWrite "date " + CDate();
  ENDPROC

  TRAP OnTick
    Incr ticks;
    TPWrite "tick "\Num:=ticks;
  ENDTRAP

  TRAP OnPart
    TPWrite "part arrived, ticks so far "\Num:=ticks;
  ENDTRAP
ENDMODULE
!> tick 1
!> tick 2
!> part arrived, ticks so far 2
!> tick 3
!> ticks 3
!> clock 3.5
!> ticks after delete 3
!> time 00:00:05
!> date 2024-01-01
