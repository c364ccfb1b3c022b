MODULE text_tables
  ! A cell's texts in a user text table: the program writes the table's
  ! file (as a backup holds it in HOME), installs it once (TextTabFreeToUse
  ! says whether its name is taken), and reads texts by the table's
  ! number and each text's index; "" is an empty text. A file that is not
  ! there is ERR_FILEOPEN.
  VAR iodev f;
  VAR num cell;

  PROC main()
    Open "HOME:/cell_text.eng", f \Write;
    Write f, "# texts of the cell";
    Write f, "cell_text::";
    Write f, "0: #tStart";
    Write f, "Press start to run";
    Write f, "#";
    Write f, "1: #tEmpty";
    Write f, """""";
    Write f, "2:";
    Write f, "Parts done: ";
    Close f;
    TPWrite "free "\Bool:=TextTabFreeToUse("cell_text");
    IF TextTabFreeToUse("cell_text") TextTabInstall "HOME:/cell_text.eng";
    TPWrite "free after "\Bool:=TextTabFreeToUse("CELL_TEXT");
    TextTabInstall "HOME:/cell_text.eng";
    cell := TextTabGet("cell_text");
    TPWrite TextGet(cell, 0);
    TPWrite "[" + TextGet(cell, 1) + "]";
    TPWrite TextGet(cell, 2)\Num:=12;
    TextTabInstall "HOME:/missing.eng";
  ERROR
    TPWrite "no file "\Bool:=(ERRNO = ERR_FILEOPEN);
    TRYNEXT;
  ENDPROC
ENDMODULE
!> free TRUE
!> free after FALSE
!> Press start to run
!> []
!> Parts done: 12
!> no file TRUE
