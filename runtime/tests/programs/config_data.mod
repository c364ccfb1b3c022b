MODULE config_data
  ! ReadCfgData and WriteCfgData on the backup's configuration (in memory):
  ! an instance by name, a search with \ListNo to END_OF_LIST, flags as
  ! bools, a written value read back, and the errors the controller
  ! raises: no such instance, a value of the wrong type, a \ListNo beyond
  ! the matches; GetSysInfo answers from MOC.cfg and the virtual
  ! controller's documented answers.
  !cfg MOC:CFG_1.0:6:0::
  !cfg SINGLE:
  !cfg       -name "TRACK" -use_single_type "TRACK_T" -base_frame_pos_x 1.25
  !cfg ROBOT_SERIAL_NUMBER:
  !cfg       -name "rob1" -robot_serial_number_high_part "120" -robot_serial_number_low_part 501234
  !cfg EIO:CFG_1.0:6:1::
  !cfg EIO_SIGNAL:
  !cfg       -Name "doGrip" -SignalType "DO" -Device "d652"
  !cfg       -Name "diPart" -SignalType "DI" -Device "d652"
  !cfg       -Name "doLamp" -SignalType "DO" -Device "d652" -Invert
  VAR num x;
  VAR string s;
  VAR bool b;
  VAR num list := 0;

  PROC main()
    ReadCfgData "/MOC/SINGLE/TRACK", "base_frame_pos_x", x;
    TPWrite "x "\Num:=x;
    ReadCfgData "MOC/SINGLE/track", "use_single_type", s;
    TPWrite "type " + s;
    WHILE list <> END_OF_LIST DO
      ReadCfgData "/EIO/EIO_SIGNAL/SignalType/DO", "Name", s \ListNo:=list;
      TPWrite "DO " + s;
    ENDWHILE
    ReadCfgData "/EIO/EIO_SIGNAL/doLamp", "Invert", b;
    TPWrite "lamp inverted "\Bool:=b;
    ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Invert", b;
    TPWrite "grip inverted "\Bool:=b;
    WriteCfgData "/MOC/SINGLE/TRACK", "base_frame_pos_x", x + 0.5;
    ReadCfgData "/MOC/SINGLE/TRACK", "base_frame_pos_x", x;
    TPWrite "written "\Num:=x;
    TPWrite "serial " + GetSysInfo(\SerialNo);
    TPWrite "lan " + GetSysInfo(\LanIp);
    TPWrite "language " + GetSysInfo(\CtrlLang);
    TPWrite "system <" + GetSysInfo(\SystemName) + ">";
    ReadCfgData "/MOC/SINGLE/CONVEYOR", "base_frame_pos_x", x;
    ReadCfgData "/MOC/SINGLE/TRACK", "use_single_type", x;
    list := 5;
    ReadCfgData "/EIO/EIO_SIGNAL/SignalType/DO", "Name", s \ListNo:=list;
    ReadCfgData "/PROC/ARC_EQUIP/stdIO", "SchedulePort", s;
  ERROR
    IF ERRNO = ERR_CFG_NOTFND TPWrite "not found";
    IF ERRNO = ERR_CFG_ILLTYPE TPWrite "wrong type";
    IF ERRNO = ERR_CFG_OUTOFBOUNDS TPWrite "out of bounds";
    TRYNEXT;
  ENDPROC
ENDMODULE
!> x 1.25
!> type TRACK_T
!> DO doGrip
!> DO doLamp
!> lamp inverted TRUE
!> grip inverted FALSE
!> written 1.75
!> serial 120-501234
!> lan VC
!> language en
!> system <>
!> not found
!> wrong type
!> out of bounds
!> not found
