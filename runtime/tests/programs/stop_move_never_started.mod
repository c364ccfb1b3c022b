MODULE stop_move_never_started
  ! A robot held by StopMove with no StartMove to come: the move waits
  ! for ever, a deadlock at its line (the report says StopMove holds it).
  !robot IRB 120-3/0.58
  CONST robtarget p0 := [[400,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum halt;

  PROC main()
    CONNECT halt WITH tHalt;
    ITimer \Single, 0.1, halt;
    MoveJ p0, v100, fine, tool0;
    TPWrite "not reached";
  ENDPROC

  TRAP tHalt
    StopMove;
    TPWrite "held";
  ENDTRAP
ENDMODULE
!> held
!! deadlock at 11
