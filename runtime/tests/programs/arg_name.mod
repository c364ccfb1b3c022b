MODULE arg_name
  ! ArgName gives the name of the data object an argument is, through the
  ! parameters it was passed by (value parameters too), the whole object's
  ! name for a component or an element, and ERR_ARGNAME for a value (or,
  ! with \ErrorNumber, that error in the variable and an empty name).
  RECORD part
    num id;
    string label;
  ENDRECORD
  VAR part pBox := [7, "box"];
  PERS num nCount := 3;
  CONST num LIMITS{2} := [10, 20];
  VAR errnum err;

  PROC main()
    VAR num nLocal := 1;
    show pBox;
    byValue pBox.id;
    byValue LIMITS{2};
    byValue nLocal;
    byRef nCount;
    TPWrite "direct " + ArgName(pBox);
    TPWrite "value [" + ArgName(nLocal + 1 \ErrorNumber:=err) + "] "\Bool:=err = ERR_ARGNAME;
    byValue 42;
  ERROR
    TPWrite "error "\Bool:=ERRNO = ERR_ARGNAME;
  ENDPROC

  PROC show(part p)
    TPWrite "show " + ArgName(p);
  ENDPROC

  PROC byValue(num n)
    inner n;
  ENDPROC

  PROC inner(num m)
    TPWrite "inner " + ArgName(m);
  ENDPROC

  PROC byRef(INOUT num n)
    TPWrite "ref " + ArgName(n);
  ENDPROC
ENDMODULE
!> show pBox
!> inner pBox
!> inner LIMITS
!> inner nLocal
!> ref nCount
!> direct pBox
!> value [] TRUE
!> error TRUE
