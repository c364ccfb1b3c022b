MODULE list_view_result
  ! UIListView: the operator chooses an item and presses the button
  ! \Result asks for, in one answer: an item alone is confirmed with the
  ! first button (OK), a button alone is pressed with the default item,
  ! `ITEM, BUTTON` does both (a btnres button of \Buttons, or a \BtnArray
  ! button by number or label, after a delay); the buttons are numbered
  ! after the items; without buttons the choice ends the dialog; \MaxTime
  ! runs out while nobody answers.
  !answer 2, Cancel
  !answer @2 Green, Later
  !answer 1
  !answer Blue
  !answer Cancel
  !answer 5
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
    n := UIListView(\Result:=res, list \Buttons:=btnOKCancel);
    TPWrite "item "\Num:=n;
    TPWrite "ok "\Bool:=res = resOK;
    n := UIListView(\Result:=res, list \Buttons:=btnOKCancel \DefaultIndex:=2);
    TPWrite "default item "\Num:=n;
    TPWrite "cancel "\Bool:=res = resCancel;
    n := UIListView(\Result:=res, list \Buttons:=btnOKCancel);
    TPWrite "fifth choice, cancel "\Bool:=res = resCancel;
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
!> item 3
!> ok TRUE
!> default item 2
!> cancel TRUE
!> fifth choice, cancel TRUE
!> max time TRUE
