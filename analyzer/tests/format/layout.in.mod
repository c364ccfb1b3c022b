! fmt: style=spaced indent-width=4
%%%
VERSION:1
      LANGUAGE:ENGLISH
%%%
module Layout(sysmodule,noview)
! a module comment
var num counter:=0;
  PERS tooldata tGripper:=[TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
local const num limits{3}:=[1,-2,3*4];
proc main()
var num i;
  counter:=counter+1;if counter>10 then counter:=0;endif
for i from 1 to 10 step 2 do
   TPWrite "i = "\Num:=i;
endfor
while counter<5 and not stopped do counter:=counter+1; endwhile
IF counter=1 counter:=2;
  test counter
  case 1,2:
  MoveL p10,v100,fine,tool0\WObj:=wobj0;
  case 3:
  StopMove\Quick;
  default:
  Stop;
  endtest
error
  if errno=ERR_DIVZERO then
  retry;
  elseif errno=ERR_NOTPRES then
  trynext;
  else
  raise;
  endif
endproc
func num Double(num x,\switch Half|switch Quarter,inout num y{*})
  return x*2;
endfunc
trap OnStop
  reset doGripper;
endtrap
record point2
num x;
  num y;
endrecord
endmodule
