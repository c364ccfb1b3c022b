MODULE speed_settings
  ! VelSet scales every programmed speed and caps the TCP's; SpeedRefresh
  ! scales again from the next move; AccSet scales the accelerations (20 %
  ! at least). 300 mm at 100 mm/s from rest to rest take 3 s and v/a more
  ! (the model's TCP acceleration a is 10 m/s²: 0.01 s).
  !robot IRB1600-6/1.2
  CONST robtarget p1 := [[600,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[600,300,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock c;

  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart c;
    MoveL p2, v100, fine, tool0;
    TPWrite "programmed " \Num:=ClkRead(c);
    VelSet 50, 5000;
    timed p1;
    TPWrite "half " \Num:=ClkRead(c);
    VelSet 100, 30;
    timed p2;
    TPWrite "capped at 30 mm/s " \Num:=ClkRead(c);
    TPWrite "C_MOTSET.vel " + ValToStr(C_MOTSET.vel);
    VelSet 100, 5000;
    SpeedRefresh 50;
    timed p1;
    TPWrite "refreshed to half " \Num:=ClkRead(c);
    ClkReset c;
    ClkStart c;
    MoveL p2, v100 \T:=2, fine, tool0;
    TPWrite "\\T:=2 at half " \Num:=ClkRead(c);
    SpeedRefresh 100;
    AccSet 50, 100;
    timed p1;
    TPWrite "half the acceleration " \Num:=ClkRead(c);
    TPWrite "C_MOTSET.acc " + ValToStr(C_MOTSET.acc);
    AccSet 5, 100;
    timed p2;
    TPWrite "a fifth of it " \Num:=ClkRead(c);
    AccSet 100, 100;
    SpeedRefresh 120;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SPEED_REFRESH_LIM THEN
      TPWrite "120 percent is refused";
      SpeedRefresh 0;
      MoveL p1, v100, fine, tool0;
    ENDIF
  ENDPROC

  PROC timed(robtarget target)
    ClkReset c;
    ClkStart c;
    MoveL target, v100, fine, tool0;
  ENDPROC
ENDMODULE
!> programmed 3.01
!> half 6
!> capped at 30 mm/s 10
!> C_MOTSET.vel [100,30]
!> refreshed to half 6
!> \T:=2 at half 4
!> half the acceleration 3.02
!> C_MOTSET.acc [50,100,100]
!> a fifth of it 3.05
!> 120 percent is refused
!! unsupported: MoveL while the speed override (VelSet, SpeedRefresh) holds the robot at 0 at 46
