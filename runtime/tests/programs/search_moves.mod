MODULE search_moves
  ! A search watches its signal while the robot moves (a modelled IRB
  ! 1600): a positive flank during the move is the hit, SearchPoint the
  ! TCP then (on the straight path, at 50 mm/s); \Stop ends the move
  ! there (the next search starts from the hit), a flying search goes on
  ! to ToPoint. A signal already 1 at the start is ERR_SIGSUPSEARCH (and
  ! the robot does not move), no flank by the end ERR_WHLSEARCH;
  ! \HighLevel hits at once, where the robot stands.
  !robot IRB 1600-10/1.45
  !set diHit=1@2
  !set diHit=0@4
  !set diHit=1@6
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget found;
  VAR clock c;

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    MoveJ p0, v1000, fine, tool0;
    WaitTime 0.5;
    ClkStart c;
    SearchL \Stop, diHit, found, Offs(p0, 0, 200, 0), v50, tool0;
    ClkStop c;
    TPWrite "stop: y "\Num:=Round(found.trans.y);
    TPWrite "stop: after "\Num:=Round(ClkRead(c) \Dec:=1);
    WaitTime 1;
    Search;
    WaitUntil diHit = 0;
    ClkReset c;
    ClkStart c;
    SearchL diHit, found, Offs(p0, 0, -200, 0), v50, tool0;
    ClkStop c;
    TPWrite "flying: y "\Num:=Round(found.trans.y);
    TPWrite "flying: after "\Num:=Round(ClkRead(c) \Dec:=1);
    SearchL \HighLevel, diHit, found, Offs(p0, 0, 50, 0), v50, tool0;
    TPWrite "level: y "\Num:=Round(found.trans.y);
    SearchL \NegFlank, diHit, found, Offs(p0, 0, 0, 0), v50, tool0;
  ERROR
    TPWrite "no flank "\Bool:=ERRNO = ERR_WHLSEARCH;
  ENDPROC

  PROC Search()
    SearchL \Stop, diHit, found, Offs(p0, 0, 0, 0), v50, tool0;
  ERROR
    TPWrite "already set "\Bool:=ERRNO = ERR_SIGSUPSEARCH;
  ENDPROC
ENDMODULE
!> stop: y 29
!> stop: after 0.6
!> already set TRUE
!> flying: y -71
!> flying: after 4.6
!> level: y -200
!> no flank TRUE
