MODULE Cell
  CONST robtarget pHome := [[600,0,800],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPick := [[412.5,-120,310],[0.0087,0.7071,0.7071,0.0087],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pAbove := [[412.5,-120,410],[0.0087,0.7071,0.7071,0.0087],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := Offs(pHome, 0, 250, -300);
  PERS robtarget pTrack := [[100,0,500],[0,0,1,0],[0,0,0,0],[1200,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pPath{3} := [[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[50,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[100,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
  CONST jointtarget jPark := [[0,-30,30,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tGripper := [TRUE,[[0,0,185],[1,0,0,0]],[2.5,[0,0,90],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[800,-400,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS loaddata lBox := [4,[0,0,60],[1,0,0,0],0,0,0];
  CONST speeddata vApproach := [400,100,5000,1000];
  CONST zonedata zCorner := [FALSE,20,30,30,3,30,3];
ENDMODULE
