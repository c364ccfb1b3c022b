MODULE motor_torque
  ! GetMotorTorque: the simulation has no dynamics model, every motor
  ! reads 0 Nm; an axis that does not exist raises ERR_AXIS_PAR.
  VAR num total;

  PROC main()
    FOR i FROM 1 TO 6 DO
      total := total + Abs(GetMotorTorque(i));
    ENDFOR
    TPWrite "torque "\Num:=total;
    TPWrite "rob1 axis 4 "\Num:=GetMotorTorque(\MecUnit:=ROB_1, 4);
    total := GetMotorTorque(7);
  ERROR
    TPWrite "no axis 7 "\Bool:=ERRNO = ERR_AXIS_PAR;
  ENDPROC
ENDMODULE
!> torque 0
!> rob1 axis 4 0
!> no axis 7 TRUE
