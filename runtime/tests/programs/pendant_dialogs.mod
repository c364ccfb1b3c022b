MODULE pendant_dialogs
  ! The operator answers the pendant's questions from a script: function
  ! keys by number or label, numbers, message-box buttons, list items,
  ! text, and an answer that comes after a delay.
  !answer 2
  !answer yes
  !answer 42.5
  !answer @3 7
  !answer Cancel
  !answer 2
  !answer Abort
  !answer 12
  !answer robot one
  !answer Blue
  !answer 0.75
  !answer 9000000001
  VAR clock clk;
  VAR num key;
  VAR num n;
  VAR dnum d;
  VAR btnres res;
  VAR string items{3} := ["red", "green", "blue"];
  VAR listitem list{3} := [["", "Red"], ["", "Green"], ["", "Blue"]];

  PROC main()
    TPErase;
    ClkStart clk;
    TPReadFK key, "Continue?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "key "\Num:=key;
    TPReadFK key, "Again?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "key "\Num:=key;
    TPReadNum n, "How many?";
    TPWrite "n "\Num:=n;
    TPReadDnum d, "Later:";
    TPWrite "d "\Dnum:=d;
    TPWrite "after "\Num:=ClkRead(clk);
    res := UIMessageBox(\Header:="Door" \Message:="Close it?" \Buttons:=btnOKCancel);
    TPWrite "cancel "\Bool:=res = resCancel;
    res := UIMessageBox(\Message:="Pick" \BtnArray:=items);
    TPWrite "button "\Num:=res;
    UIMsgBox "Fault" \Buttons:=btnAbrtRtryIgn \Result:=res;
    TPWrite "abort "\Bool:=res = resAbort;
    n := UINumEntry(\Message:="Parts" \InitValue:=5 \MinValue:=1 \MaxValue:=20 \AsInteger);
    TPWrite "parts "\Num:=n;
    TPWrite "name " + UIAlphaEntry(\Message:="Name" \InitString:="r1");
    n := UIListView(\Result:=res \Header:="Colour", list \Buttons:=btnOKCancel);
    TPWrite "item "\Num:=n;
    TPWrite "ok "\Bool:=res = resOK;
    TPWrite "tuned "\Num:=UINumTune(\Message:="Speed", 0.5, 0.25);
    TPWrite "dtuned "\Dnum:=UIDnumTune(\Message:="Count", 10, 1);
    TPWrite "client "\Bool:=UIClientExist();
  ENDPROC
ENDMODULE
!> [TPErase at pendant_dialogs.mod:26] the operator window is cleared
!> key 2
!> key 1
!> n 42.5
!> d 7
!> after 3
!> cancel TRUE
!> button 2
!> abort TRUE
!> parts 12
!> name robot one
!> item 3
!> ok TRUE
!> tuned 0.75
!> dtuned 9000000001
!> client TRUE
