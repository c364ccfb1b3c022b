! as written: a file indented with tabs stays so; lines typed with
! spaces at another column get tabs
MODULE Tabs
	VAR num a:=1;
	PROC main()
		a:=2;
		a:=3;
		IF a>1 THEN
			a:=0;
		ENDIF
	ENDPROC
ENDMODULE
