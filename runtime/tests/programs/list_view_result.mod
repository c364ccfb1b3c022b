MODULE list_view_result
  ! UIListView: the operator chooses an item, then presses the button
  ! \Result asks for (a btnres button of \Buttons, or a \BtnArray button by
  ! number or label, after a delay); without buttons the choice ends the
  ! dialog; \MaxTime runs out while the button is not pressed.
  !answer 2
  !answer Cancel
  !answer Green
  !answer @2 Later
  !answer 1
  !answer 3
  !answer -
  VAR clock clk;
  VAR btnres res := -7;
  VAR num n;
  VAR listitem list{3} := [["", "Red"], ["", "Green"], ["", "Blue"]];
  VAR string actions{2} := ["Now", "Later"];

  PROC main()
    n := UIListView(\Result:=res \Header:="Colour", list \Buttons:=btnOKCancel);
    TPWrite "item "\Num:=n;
    TPWrite "cancel "\Bool:=res = resCancel;
    ClkStart clk;
    n := UIListView(\Result:=res, list \BtnArray:=actions);
    TPWrite "item "\Num:=n;
    TPWrite "button "\Num:=res;
    TPWrite "after "\Num:=ClkRead(clk);
    res := -7;
    n := UIListView(\Result:=res, list);
    TPWrite "item "\Num:=n;
    TPWrite "unchanged "\Bool:=res = -7;
    n := UIListView(\Result:=res, list \Buttons:=btnOKCancel \MaxTime:=5);
  ERROR
    TPWrite "max time "\Bool:=ERRNO = ERR_TP_MAXTIME;
  ENDPROC
ENDMODULE
!> item 2
!> cancel TRUE
!> item 2
!> button 2
!> after 2
!> item 1
!> unchanged TRUE
!> max time TRUE
