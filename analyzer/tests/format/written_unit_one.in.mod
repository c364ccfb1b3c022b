! as written: one space, as in ABB's user.sys
MODULE user (SYSMODULE)

 ! Predefined user data
 VAR num reg1 := 0;
 VAR num reg2 := 0;
    VAR num reg3 := 0;
 VAR clock clock1;

ENDMODULE
