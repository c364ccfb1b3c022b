MODULE late_binding
  ! Late binding (%name%, %"module:name"%) and CallByVar, with unknown
  ! procedures handled.
  PROC main()
    VAR string name;
    FOR i FROM 1 TO 2 DO
      %"station_" + NumToStr(i, 0)% i * 10;
    ENDFOR
    CallByVar "step", 2;
    %"late_binding:hidden"%;
    name := "missing";
    %name% 1;
    TPWrite "after missing";
  ERROR
    IF ERRNO = ERR_REFUNKPRC THEN
      TPWrite "no such procedure";
      TRYNEXT;
    ENDIF
  ENDPROC

  PROC station_1(num v)
    TPWrite "station one "\Num:=v;
  ENDPROC

  PROC station_2(num v)
    TPWrite "station two "\Num:=v;
  ENDPROC

  LOCAL PROC hidden()
    TPWrite "a local procedure named with its module";
  ENDPROC

  PROC step2()
    TPWrite "step two";
  ENDPROC
ENDMODULE
!> station one 10
!> station two 20
!> step two
!> a local procedure named with its module
!> no such procedure
!> after missing
