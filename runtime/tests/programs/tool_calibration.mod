MODULE tool_calibration
  ! MToolTCPCalib: four joint positions put a tool's tip (200 mm out on
  ! the flange's z axis, 20 mm on its x) at one point, each with another
  ! orientation; the calibration finds that TCP again from the joints
  ! alone, with errors of (nearly) zero.
  PERS tooldata true_tool := [TRUE, [[20, 0, 200], [1, 0, 0, 0]], [1, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
  PERS tooldata measured := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
  CONST robtarget tip := [[900, 200, 500], [0, 0, 1, 0], [0, -1, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR jointtarget j1;
    VAR jointtarget j2;
    VAR jointtarget j3;
    VAR jointtarget j4;
    VAR robtarget t;
    VAR num max_err;
    VAR num mean_err;
    ConfJ \Off;
    t := RelTool(tip, 0, 0, 0 \Rx:=20);
    t.robconf := [0, -1, 0, 0];
    j2 := CalcJointT(t, true_tool);
    t := RelTool(tip, 0, 0, 0 \Ry:=20);
    t.robconf := [0, 0, 0, 0];
    j3 := CalcJointT(t, true_tool);
    t := RelTool(tip, 0, 0, 0 \Rx:=-15 \Rz:=60);
    t.robconf := [0, 0, 0, 0];
    j4 := CalcJointT(t, true_tool);
    j1 := CalcJointT(tip, true_tool);
    MToolTCPCalib j1, j2, j3, j4, measured, max_err, mean_err;
    TPWrite "tcp "\Pos:=[Round(measured.tframe.trans.x \Dec:=1), Round(measured.tframe.trans.y \Dec:=1), Round(measured.tframe.trans.z \Dec:=1)];
    TPWrite "max error below 0.01 mm "\Bool:=max_err < 0.01;
    TPWrite "mean error below 0.01 mm "\Bool:=mean_err < 0.01;
  ENDPROC
ENDMODULE
!robot IRB 1600-6/1.2
!> tcp [20,0,200]
!> max error below 0.01 mm TRUE
!> mean error below 0.01 mm TRUE
