! fmt: style=spaced
MODULE Trailing
VAR num a := 1;
ENDMODULE
  0.  this is not RAPID   {0;0}
  and neither is this:=  ;
