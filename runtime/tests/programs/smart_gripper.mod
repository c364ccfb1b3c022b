MODULE smart_gripper
  ! YuMi SmartGripper: the fingers' position from 0 (closed) to 25 mm
  ! (open) after each instruction; calibration; the suction cups are
  ! accepted.
  PROC main()
    TPWrite "calibrated "\Bool:=g_IsCalibrated();
    g_Init \maxSpd:=20 \holdForce:=10 \Calibrate;
    TPWrite "calibrated "\Bool:=g_IsCalibrated();
    TPWrite "at "\Num:=g_GetPos();
    g_GripOut;
    TPWrite "open "\Num:=g_GetPos();
    g_MoveTo 12.5 \NoWait;
    TPWrite "moved "\Num:=g_GetPos();
    g_GripIn \holdForce:=15;
    TPWrite "closed "\Num:=g_GetPos();
    g_GripOut \targetPos:=8;
    TPWrite "opened to "\Num:=g_GetPos();
    g_MoveTo 40;
    TPWrite "at most "\Num:=g_GetPos();
    g_JogIn;
    g_Stop;
    g_BlowOn1;
    g_BlowOff1;
    TPWrite "jogged "\Num:=g_GetPos();
  ENDPROC
ENDMODULE
!> calibrated FALSE
!> calibrated TRUE
!> at 0
!> open 25
!> moved 12.5
!> closed 0
!> opened to 8
!> at most 25
!> jogged 0
