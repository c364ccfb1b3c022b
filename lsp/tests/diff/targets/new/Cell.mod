MODULE Cell
  CONST robtarget pHome := [[600,0,820],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPick := [[415.5,-116,310],[0.0087,0.7071,0.7071,0.0087],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pAbove := [[412.5,-120,410],[0,0.7071068,0.7071068,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := Offs(pHome, 0, 250, -300);
  PERS robtarget pTrack := [[100,0,500],[0,0,1,0],[0,0,0,0],[1450,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPath{3} := [[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[50,2,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[100,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
  CONST jointtarget jPark := [[0,-25,30,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tGripper := [TRUE,[[0,0,192],[1,0,0,0]],[3,[0,0,90],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[800,-400,0],[0.9998477,0,0,0.0174524]],[[0,0,0],[1,0,0,0]]];
  PERS loaddata lBox := [4.5,[0,0,75],[1,0,0,0],0,0,0];
  CONST speeddata vApproach := [600,100,5000,1000];
  CONST zonedata zCorner := [FALSE,10,15,15,1.5,15,1.5];
ENDMODULE
