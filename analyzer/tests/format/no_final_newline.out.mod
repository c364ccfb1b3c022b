! fmt: style=spaced
MODULE NoFinalNewline
VAR num a := 1;
ENDMODULE