! as written: a file that follows no unit gets 4 spaces
MODULE Random
      VAR num a;
 PROC main()
   a:=1;
         IF a THEN
  b:=1;
     ENDIF
         ENDPROC
ENDMODULE
