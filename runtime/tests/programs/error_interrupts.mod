MODULE error_interrupts
  ! IError: a trap routine runs for each event log entry of the domain and
  ! type ordered (COMMON_ERR: any domain; TYPE_ALL: any type); GetTrapData
  ! and ReadErrData read the entry ErrWrite logged (USER_DEF_ERR, number 1
  ! for an error, 2 for a warning).
  VAR intnum on_error;
  VAR intnum on_warning;

  PROC main()
    CONNECT on_error WITH error_logged;
    IError COMMON_ERR, TYPE_ERR, on_error;
    CONNECT on_warning WITH warning_logged;
    IError USER_DEF_ERR \ErrorId:=2, TYPE_ALL, on_warning;
    ErrWrite "Gripper", "No part" \RL2:="check the sensor";
    ErrWrite \W, "Gripper", "Slow";
    ErrWrite \I, "Cell", "Started";
    WaitTime 0.1;
    IDelete on_error;
    ErrWrite "Gripper", "Again";
    WaitTime 0.1;
    TPWrite "done";
  ENDPROC

  TRAP error_logged
    VAR trapdata t;
    VAR errdomain domain;
    VAR num number;
    VAR errtype kind;
    VAR string title;
    VAR string s1;
    VAR string s2;
    GetTrapData t;
    ReadErrData t, domain, number, kind \Title:=title \Str1:=s1 \Str2:=s2;
    TPWrite "error " + title + ": " + s1 + ", " + s2;
    TPWrite "user "\Bool:=domain = USER_DEF_ERR;
    TPWrite "number "\Num:=number;
    TPWrite "type error "\Bool:=kind = TYPE_ERR;
  ENDTRAP

  TRAP warning_logged
    VAR trapdata t;
    VAR errdomain domain;
    VAR num number;
    VAR errtype kind;
    GetTrapData t;
    ReadErrData t, domain, number, kind;
    TPWrite "warning "\Num:=number;
    TPWrite "type warning "\Bool:=kind = TYPE_WARN;
  ENDTRAP
ENDMODULE
!> 80001 Gripper: No part check the sensor
!> error Gripper: No part, check the sensor
!> user TRUE
!> number 1
!> type error TRUE
!> 80002 Gripper: Slow
!> warning 2
!> type warning TRUE
!> 80003 Cell: Started
!> 80001 Gripper: Again
!> done
