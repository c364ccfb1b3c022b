MODULE controller_state
  ! The controller's state a program reads: CSpeedOverride (the operator's
  ! override is 100 in the simulation; \CTask the task's, as SpeedRefresh
  ! sets it), IsSysId (the serial number MOC.cfg gives), and
  ! GetModalPayloadMode (SYS.cfg's ModalPayLoadMode). TuneServo and
  ! TuneReset are accepted: the simulation has no servo model to tune.
  !cfg MOC:CFG_1.0:6:0::
  !cfg ROBOT_SERIAL_NUMBER:
  !cfg       -name "rob1" -robot_serial_number_high_part "120" -robot_serial_number_low_part 501234
  !cfg SYS:CFG_1.0:6:0::
  !cfg SYS_MISC:
  !cfg       -name "ModalPayLoadMode" -value 0
  PROC main()
    TPWrite "operator "\Num:=CSpeedOverride();
    SpeedRefresh 40;
    TPWrite "task "\Num:=CSpeedOverride(\CTask);
    TPWrite "operator "\Num:=CSpeedOverride();
    TPWrite "this system "\Bool:=IsSysId("120-501234");
    TPWrite "another "\Bool:=IsSysId("120-501235");
    TPWrite "modal payload "\Num:=GetModalPayloadMode();
    TuneServo ROB_1, 1, 110 \Type:=TUNE_KP;
    TuneReset;
  ENDPROC
ENDMODULE
!> operator 100
!> task 40
!> operator 100
!> this system TRUE
!> another FALSE
!> modal payload 0
