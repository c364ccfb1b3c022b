MODULE raw_bytes_files
  ! WriteRawBytes writes a rawbytes' valid bytes (or \NoOfBytes of them) to
  ! a binary file; ReadRawBytes reads them back (up to 1024 at a time),
  ! then ERR_RANYBIN_EOF at the end of the file.
  VAR iodev f;
  VAR rawbytes out;
  VAR rawbytes back;
  VAR num x;
  VAR string s;
  PROC main()
    PackRawBytes 2.5, out, 1 \Float4;
    PackRawBytes "abc", out, 5 \ASCII;
    Open "HOME:/data.bin", f \Write \Bin;
    WriteRawBytes f, out;
    WriteRawBytes f, out \NoOfBytes:=4;
    Close f;
    Open "HOME:/data.bin", f \Read \Bin;
    ReadRawBytes f, back;
    TPWrite "read "\Num:=RawBytesLen(back);
    UnpackRawBytes back, 1, x \Float4;
    UnpackRawBytes back, 5, s \ASCII:=3;
    TPWrite "first " + ValToStr(x) + " " + s;
    UnpackRawBytes back, 8, x \Float4;
    TPWrite "second "\Num:=x;
    ReadRawBytes f, back;
    TPWrite "never";
  ERROR
    TPWrite "end "\Bool:=ERRNO = ERR_RANYBIN_EOF;
    Close f;
  ENDPROC
ENDMODULE
!> read 11
!> first 2.5 abc
!> second 2.5
!> end TRUE
