MODULE search_without_a_robot
  ! Without a modelled robot a move takes no time: a search hits when its
  ! signal has the searched value as the robot arrives, and SearchPoint is
  ! ToPoint; otherwise ERR_WHLSEARCH.
  !set diPart=1
  CONST robtarget p0 := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget found;

  PROC main()
    SearchL \Stop, diPart, found, Offs(p0, 0, 80, 0), v50, tool0;
    TPWrite "hit y "\Num:=found.trans.y;
    SearchL \NegFlank, diPart, found, p0, v50, tool0;
  ERROR
    TPWrite "none "\Bool:=ERRNO = ERR_WHLSEARCH;
  ENDPROC
ENDMODULE
!> hit y 80
!> none TRUE
