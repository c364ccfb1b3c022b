MODULE external_axes
  ! MoveExtJ moves the external axes only: the arm stays where the last
  ! move left it (its joints and its TCP), the active tool stays, and
  ! CJointT and CRobT give the new external axes. External axes are not
  ! modelled: they arrive at once.
  PERS tooldata torch := [TRUE, [[0, 0, 300], [1, 0, 0, 0]], [2, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
  CONST jointtarget turned := [[9E9, 9E9, 9E9, 9E9, 9E9, 9E9], [90, 250, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR robtarget before;
    VAR robtarget after;
    VAR jointtarget j;
    MoveAbsJ [[10, 0, 0, 0, 30, 0], [0, 0, 9E9, 9E9, 9E9, 9E9]], v1000, fine, torch;
    before := CRobT(\Tool:=torch);
    MoveExtJ turned, vrot50, fine;
    j := CJointT();
    TPWrite "axis 1 "\Num:=j.robax.rax_1;
    TPWrite "axis 5 "\Num:=j.robax.rax_5;
    TPWrite "eax a "\Num:=j.extax.eax_a;
    TPWrite "eax b "\Num:=j.extax.eax_b;
    after := CRobT(\Tool:=torch);
    TPWrite "TCP moved mm "\Num:=Round(Distance(before.trans, after.trans) \Dec:=3);
    TPWrite "robtarget eax a "\Num:=after.extax.eax_a;
    TPWrite "active tool is torch "\Bool:=CTool() = torch;
  ENDPROC
ENDMODULE
!robot IRB 1600-6/1.2
!> axis 1 10
!> axis 5 30
!> eax a 90
!> eax b 250
!> TCP moved mm 0
!> robtarget eax a 90
!> active tool is torch TRUE
