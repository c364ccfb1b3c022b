MODULE moves_that_call_procedures
  ! MoveLSync calls its procedure when the robot reaches the point: the
  ! clock reads the move's whole time there (200 mm at 100 mm/s on a
  ! modelled IRB 1600: 2.01 s, as in stop_move_in_a_trap), and the
  ! instruction after it runs after the procedure. MoveLDO sets its
  ! signal at the same moment, not when the move starts. A name that
  ! names no procedure is ERR_REFUNKPRC, a function ERR_CALLPROC.
  !robot IRB 1600-10/1.45
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock c;
  VAR num calls := 0;
  VAR intnum glue;
  VAR intnum peek;

  PROC main()
    ConfL \Off;
    MoveJ p0, v1000, fine, tool0;
    ClkStart c;
    MoveLSync Offs(p0, 0, 200, 0), v100, fine, tool0, "Arrived";
    TPWrite "after the move, calls "\Num:=calls;
    CONNECT glue WITH tGlue;
    ISignalDO doGlue, 1, glue;
    CONNECT peek WITH tPeek;
    ITimer \Single, 1, peek;
    ClkReset c;
    MoveLDO p0, v100, fine, tool0, doGlue, 1;
    MoveJSync p0, v100, fine, tool0, "Nowhere";
  ERROR
    TPWrite "no such procedure "\Bool:=(ERRNO = ERR_REFUNKPRC);
    TRYNEXT;
  ENDPROC

  TRAP tGlue
    TPWrite "glue set after "\Num:=Round(ClkRead(c) \Dec:=2);
  ENDTRAP

  TRAP tPeek
    TPWrite "glue during the move "\Num:=DOutput(doGlue);
  ENDTRAP

  PROC Arrived()
    Incr calls;
    TPWrite "arrived after "\Num:=Round(ClkRead(c) \Dec:=2);
  ENDPROC
ENDMODULE
!> arrived after 2.01
!> after the move, calls 1
!> glue during the move 0
!> glue set after 2.01
!> no such procedure TRUE
