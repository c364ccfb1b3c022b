MODULE no_return
  ! A function that ends without RETURN.
  PROC main()
    TPWrite "value "\Num:=Broken(1);
  ENDPROC

  FUNC num Broken(num x)
    IF x > 5 RETURN x;
  ENDFUNC
ENDMODULE
!! ERR_FNCNORET at 9
