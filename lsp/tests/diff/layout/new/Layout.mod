module Layout
var speeddata vSlow:=[100,50,5000.0,1000];
pers num nCount:=3;
const robtarget p10:=[[100,0,50],[1,0,0,0],
    [0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
proc main()
var num k:=2;
var num i;
if nCount>2 then
MoveL p10,vSlow,fine,tool0;
else
nCount:=nCount+1;
endif
endproc
endmodule
