MODULE bits
  ! BitSet and BitClear change one bit of a byte (bit 1 is the lowest);
  ! BitCheck reads it; a position outside 1 to 8 is ERR_ARGVALERR.
  VAR byte flags := 0;

  PROC main()
    BitSet flags, 1;
    BitSet flags, 8;
    TPWrite "set 1 and 8: " \Num:=flags;
    BitSet flags, 8;
    TPWrite "again: " \Num:=flags;
    BitClear flags, 1;
    TPWrite "cleared 1: " \Num:=flags;
    TPWrite "bit 8 " \Bool:=BitCheck(flags, 8);
    BitSet flags, 9;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_ARGVALERR THEN
      TPWrite "bit 9 is refused";
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
!> set 1 and 8: 129
!> again: 129
!> cleared 1: 128
!> bit 8 TRUE
!> bit 9 is refused
