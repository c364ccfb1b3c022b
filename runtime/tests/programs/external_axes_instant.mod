MODULE external_axes_instant
  ! Without a kinematic model too, MoveExtJ leaves what the last move made
  ! known: after a MoveL the TCP is still known (and the joints are not).
  CONST robtarget p1 := [[500, 100, 400], [0, 0, 1, 0], [0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget track := [[9E9, 9E9, 9E9, 9E9, 9E9, 9E9], [1200, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR robtarget now;
    MoveL p1, v500, fine, tool0;
    MoveExtJ track, v500, fine;
    now := CRobT();
    TPWrite "y "\Num:=now.trans.y;
    TPWrite "track "\Num:=now.extax.eax_a;
  ENDPROC
ENDMODULE
!> y 100
!> track 1200
