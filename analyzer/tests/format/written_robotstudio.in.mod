! as written: RobotStudio writes data after a tab and statements after a
! tab and four spaces: both are at their columns and stay
MODULE Module1
	CONST robtarget Target_10:=[[500,0,400],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
	PROC Path_10()
	    MoveJ Target_10,v1000,z100,tool0\WObj:=wobj0;
	    MoveL Target_10,v1000,z100,tool0\WObj:=wobj0;
	  MoveL Target_10,v1000,fine,tool0\WObj:=wobj0;
	ENDPROC
ENDMODULE
