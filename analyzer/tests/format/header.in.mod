! fmt: style=spaced
%%%
VERSION:1
LANGUAGE:ENGLISH
%%%
MODULE First (SYSMODULE)
ENDMODULE
%%%   VERSION:1   LANGUAGE:ENGLISH   %%%

module Second
endmodule
