MODULE signal_origin
  ! GetSignalOrigin: a configured signal, a signal variable connected with
  ! AliasIO, and one connected to nothing; SignalName gets the configured
  ! name.
  !set do_lamp=0
  VAR signaldo lamp;
  VAR string name := "x";
  VAR signalorigin origin;

  PROC main()
    origin := GetSignalOrigin(do_lamp, name);
    TPWrite "configured "\Bool:=origin = SIGORIG_CFG;
    TPWrite "name " + name;
    origin := GetSignalOrigin(lamp, name);
    TPWrite "none "\Bool:=origin = SIGORIG_NONE;
    TPWrite "name <" + name + ">";
    AliasIO do_lamp, lamp;
    origin := GetSignalOrigin(lamp, name);
    TPWrite "alias "\Bool:=origin = SIGORIG_ALIAS;
    TPWrite "name " + name;
  ENDPROC
ENDMODULE
!> configured TRUE
!> name do_lamp
!> none TRUE
!> name <>
!> alias TRUE
!> name do_lamp
