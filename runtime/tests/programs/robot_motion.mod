MODULE robot_motion
  ! A modelled IRB 120 (axes 250, 250, 250, 320, 320, 420 deg/s, each at
  ! its speed in 0.2 s; the TCP at 10 m/s2, reorientation at 2000 deg/s2).
  ! Times by hand:
  ! - MoveAbsJ of axis 6 by 180 deg, v1000 (v_ori 500), fine: axis 6 is
  !   slowest: its ramps take 2 * 420 * 0.2 / 2 = 84 deg, so
  !   (180 - 84) / 420 + 2 * 0.2 = 0.628571 s (reorientation alone:
  !   (180 - 125) / 500 + 2 * 0.25 = 0.61 s).
  ! - MoveL of 100 mm, v100, fine to fine: ramps of 0.5 mm each,
  !   (100 - 1) / 100 + 2 * 0.01 = 1.01 s.
  ! - Two MoveL of 100 mm, z10 then fine: the zone hands on its speed,
  !   (100 - 0.5) / 100 + 0.01 = 1.005 s each, 2.01 s together.
  ! - MoveL \T:=2: 2 s. WaitTime 0.25: 0.25 s.
  !robot IRB 120-3/0.58
  CONST jointtarget zero := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[0,0,0,0,0,180],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget bent := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p10 := [[374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[374,100,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p30 := [[374,200,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock c;

  PROC main()
    VAR robtarget here;
    VAR jointtarget j;
    MoveAbsJ zero, v1000, fine, tool0;
    ! tool0 at the calibration position: 374 mm ahead, 630 mm up.
    here := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "home x " \Num:=here.trans.x;
    TPWrite "home z " \Num:=here.trans.z;
    ClkStart c;
    MoveAbsJ turned, v1000, fine, tool0;
    TPWrite "axis 6 move " \Num:=ClkRead(c \HighRes);
    j := CJointT();
    TPWrite "axis 6 " \Num:=j.robax.rax_6;
    MoveAbsJ zero, v1000, fine, tool0;
    MoveJ p10, v1000, fine, tool0;
    ClkReset c;
    ClkStart c;
    MoveL p20, v100, fine, tool0;
    TPWrite "100 mm fine " \Num:=ClkRead(c \HighRes);
    ClkReset c;
    MoveL p30, v100, z10, tool0;
    MoveL p20, v100, fine, tool0;
    TPWrite "two with a zone " \Num:=ClkRead(c \HighRes);
    ClkReset c;
    MoveL p10, v100 \T:=2, fine, tool0;
    WaitTime 0.25;
    TPWrite "T and wait " \Num:=ClkRead(c \HighRes);
    ! Where tool0 is with axis 5 at 90: the flange 72 mm below the wrist.
    here := CalcRobT(bent, tool0);
    TPWrite "bent x " \Num:=here.trans.x;
    TPWrite "bent z " \Num:=here.trans.z;
    j := CalcJointT(p20, tool0);
    here := CalcRobT(j, tool0);
    TPWrite "round trip y " \Num:=here.trans.y;
    here := CRobT(\Tool:=tool0);
    TPWrite "at p10 y " \Num:=here.trans.y;
  ENDPROC
ENDMODULE
!> home x 374
!> home z 630
!> axis 6 move 0.628
!> axis 6 180
!> 100 mm fine 1.01
!> two with a zone 2.01
!> T and wait 2.25
!> bent x 302
!> bent z 558
!> round trip y 100
!> at p10 y 0
