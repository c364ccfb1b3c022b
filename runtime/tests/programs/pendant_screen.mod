MODULE pendant_screen
  ! What the pendant shows without asking: TPErase, TPShow and UIShow are
  ! traced with where the program asked; UIMsgWrite writes its message
  ! without waiting; a window that is no tpnum stops the run.
  VAR uishownum instance;
  VAR num status := -1;

  PROC main()
    TPWrite "before";
    TPErase;
    TPShow TP_LATEST;
    TPShow TP_PROGRAM;
    UIShow "TpsViewCell.dll", "ABB.Cell.View" \InitCmd:="start" \InstanceID:=instance \Status:=status;
    TPWrite "instance "\Num:=instance;
    TPWrite "status "\Num:=status;
    UIMsgWrite "Cell", "Loading parts";
    UIMsgWriteAbort;
    TPShow 7;
  ENDPROC
ENDMODULE
!> before
!> [TPErase at pendant_screen.mod:10] the operator window is cleared
!> [TPShow at pendant_screen.mod:11] the pendant shows the window shown before
!> [TPShow at pendant_screen.mod:12] the pendant shows the Production window
!> [UIShow at pendant_screen.mod:13] the pendant opens ABB.Cell.View of TpsViewCell.dll (start)
!> instance 1
!> status 0
!> Cell: Loading parts
!> [UIMsgWriteAbort at pendant_screen.mod:17] the message of UIMsgWrite is removed
!! invalid at 18
