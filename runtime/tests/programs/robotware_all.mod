MODULE robotware_all
  ! Without a RobotWare version the catalogue has every version's
  ! components: accdata's finepramp (RobotWare 5) too.
  PROC main()
    VAR accdata a;
    TPWrite ValToStr(a);
    !> [0,0,0]
  ENDPROC
ENDMODULE
