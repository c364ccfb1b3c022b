MODULE trap_moves_keep_their_events
  ! An error handler stops the robot and moves it on a path level of its
  ! own (StorePath): the TriggIO and TriggInt events of that move fire as
  ! the arm passes them, while the stopped move's event waits for
  ! StartMove. The main move (\Conc): 200 mm at 100 mm/s on a modelled
  ! IRB 1600, 2.01 s, its TriggInt 50 mm before the point (1.5075 s in);
  ! stopped at 0.5 s (a WaitDI's \MaxTime), the handler's moves take
  ! 0.26 s each (as in stop_move_in_a_trap.mod), its own events 5 mm
  ! before its point, at 0.5 + 0.26 - 5 / 25 x 0.26 = 0.708 s (held with
  ! the stopped move, they would come after StartMove); StartMove at
  ! 1.02 s: the main event comes 1.0075 s
  ! later, at 2.0275 s (ClkRead \HighRes: 2.027), and the move ends at
  ! 2.53 s.
  !robot IRB 1600-10/1.45
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum passing;
  VAR intnum aside;
  VAR triggdata mainint;
  VAR triggdata asideint;
  VAR triggdata asideio;
  VAR clock c;

  PROC main()
    VAR robtarget here;
    ConfL \Off;
    MoveJ p0, v1000, fine, tool0;
    CONNECT passing WITH tPassing;
    CONNECT aside WITH tAside;
    TriggInt mainint, 50, passing;
    ClkStart c;
    TriggL \Conc, Offs(p0, 0, 200, 0), v100, mainint, fine, tool0;
    WaitDI diNever, 1 \MaxTime:=0.5;
    WaitRob \InPos;
    TPWrite "main move ends after "\Num:=ClkRead(c \HighRes);
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      StopMove;
      here := CRobT();
      StorePath;
      TriggInt asideint, 5, aside;
      TriggIO asideio, 5 \DOp:=doAside, 1;
      TriggL Offs(here, 0, 0, 25), v100, asideint \T2:=asideio, fine, tool0;
      TPWrite "aside set "\Num:=DOutput(doAside);
      MoveL here, v100, fine, tool0;
      RestoPath;
      TPWrite "start again after "\Num:=ClkRead(c \HighRes);
      StartMove;
      TRYNEXT;
    ENDIF
  ENDPROC

  TRAP tAside
    TPWrite "aside passing after "\Num:=ClkRead(c \HighRes);
  ENDTRAP

  TRAP tPassing
    TPWrite "main move passing after "\Num:=ClkRead(c \HighRes);
  ENDTRAP
ENDMODULE
!> aside passing after 0.708
!> aside set 1
!> start again after 1.02
!> main move passing after 2.027
!> main move ends after 2.53
