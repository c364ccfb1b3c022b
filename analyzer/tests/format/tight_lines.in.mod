! fmt: style=tight
module TightLines
var num a := 1;   ! trailing comment keeps its blanks   
  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];



proc main() a := 1; if a > 1 then a := 0; endif
MoveL Offs(pHome, 100, 200, 300),
      v1000,
      z50, tGripper \WObj := wobjTable;
        x := Sum(1,
  2);
endproc
proc other()
endproc
endmodule
