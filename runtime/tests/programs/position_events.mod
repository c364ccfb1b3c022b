MODULE position_events
  ! TriggIO, TriggEquip and TriggInt: outputs set and traps run where a TriggL passes a point. A
  ! modelled IRB 1600 moves 200 mm down at v100 (2 s at 100 mm/s, plus
  ! the ramps): the glue goes on 150 mm before the end (3/4 of the time
  ! before it: 0.5 s after the start), the valve 50 mm before the end less
  ! its 0.1 s equipment lag (1.4 s); on the way back up the lamp goes on
  ! 0.3 s before the end (\Time); going down again, TriggInt runs its trap
  ! 100 mm before the end, halfway.
  VAR triggdata glue_on;
  VAR triggdata lamp;
  VAR triggdata valve;
  VAR triggdata halfway;
  VAR intnum passed;
  VAR clock c;

  PROC main()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    ConfL \Off;
    TriggIO glue_on, 150 \DOp:=do_glue, 1;
    TriggIO lamp, 0.3 \Time \DOp:=do_lamp, 1;
    TriggEquip valve, 50, 0.1 \DOp:=do_valve, 1;
    ClkStart c;
    TriggL Offs(CRobT(), 0, 0, -200), v100, glue_on \T2:=valve, fine, tool0 \Conc;
    WaitDO do_glue, 1;
    TPWrite "glue on after s "\Num:=Round(ClkRead(c) \Dec:=1);
    WaitDO do_valve, 1;
    TPWrite "valve after s "\Num:=Round(ClkRead(c) \Dec:=1);
    WaitRob \InPos;
    TPWrite "arrived after s "\Num:=Round(ClkRead(c) \Dec:=1);
    TriggL Offs(CRobT(), 0, 0, 200), v100, lamp, fine, tool0;
    TPWrite "lamp "\Num:=DOutput(do_lamp);
    CONNECT passed WITH at_point;
    TriggInt halfway, 100, passed;
    ClkReset c;
    ClkStart c;
    TriggL Offs(CRobT(), 0, 0, -200), v100, halfway, fine, tool0;
    TPWrite "arrived after s "\Num:=Round(ClkRead(c) \Dec:=1);
  ENDPROC

  TRAP at_point
    TPWrite "the trap runs after s "\Num:=Round(ClkRead(c) \Dec:=1);
  ENDTRAP
ENDMODULE
!robot IRB 1600-6/1.2
!> glue on after s 0.5
!> valve after s 1.4
!> arrived after s 2
!> lamp 1
!> the trap runs after s 1
!> arrived after s 2
