MODULE Settings

! the cell's addresses
  VAR string host:="10.0.0.5";  ! the PC
  VAR num port:=3000;

CONST speeddata vSlow:=[50,10,20,5];
VAR zonedata zPath:=[FALSE,25,40,40,10,35,5];
VAR robtarget pPick;
VAR num count:=0;
PERS string lastRun:="";
ENDMODULE
