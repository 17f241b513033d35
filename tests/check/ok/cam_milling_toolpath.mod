MODULE cam_milling_toolpath
!*** Post: RobotMill 2.7 (ABB IRC5) ***
!*** Program: POCKET_A  Tool: D6 ball nose ***
!*** Stock allowance -.002 mm, tolerance 0.5E-3 mm ***
PERS tooldata tSpindleD6:=[TRUE,[[-0.125,0.043,236.871],[1,0,0,0]],[11.4,[0,0,102.5],[1,0,0,0],0.16,0.16,0.09]];
PERS wobjdata wobjStock:=[FALSE,TRUE,"",[[1210.55,-95.2,618.003],[0.999999,0,0,-0.00131]],[[0,0,0],[1,0,0,0]]];
CONST num STOCK_ALLOW:=-.002;
CONST num CAM_TOL:=0.5E-3;
CONST num SAFE_Z:=25.;
CONST speeddata vFeed1:=[8.333,50,5000,1000];
CONST speeddata vFeed2:=[16.667,50,5000,1000];
CONST zonedata zMill:=[FALSE,.3,.5,.5,.05,.5,.05];
VAR signaldo do_spindle_run;
VAR signalao ao_spindle_rpm;

PROC main()
    AliasIO "DO_SpindleRun",do_spindle_run;
    AliasIO "AO_SpindleRpm",ao_spindle_rpm;
    ConfL\Off;
    SetAO ao_spindle_rpm,12000;
    Set do_spindle_run;
    WaitTime 3;
    pocket_a;
    Reset do_spindle_run;
    ConfL\On;
ENDPROC

PROC pocket_a()
    ! Approach
    MoveJ[[20,20,SAFE_Z],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v500,z10,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,20,2],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z1,tSpindleD6\WObj:=wobjStock;
    ! Pass 1 Z-1.0
    MoveL[[20,20,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,20,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,23.5,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6,\WObj:=wobjStock;
    MoveL[[20,23.5,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6,\WObj:=wobjStock;
    MoveL[[20,27,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6 \WObj:=wobjStock;
    MoveL[[80,27,-1],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6 \WObj:=wobjStock;
    MoveL[[80,30.5,-1.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,30.5,-1.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    ! Pass 2 Z-2.0
    MoveL[[20,30.5,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,30.5,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,27,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,27,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,23.5,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,23.5,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,20,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,20,-2.0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed2,zMill,tSpindleD6\WObj:=wobjStock;
    ! Finishing pass with stock allowance
    MoveL[[20,20,-2.0+STOCK_ALLOW],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,fine,tSpindleD6\WObj:=wobjStock;
    MoveL[[80,20,-2.0+STOCK_ALLOW],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,z0,tSpindleD6\WObj:=wobjStock;
    MoveC[[82.5,25.25,-2.002],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[80,30.5,-2.002],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,z0,tSpindleD6\WObj:=wobjStock;
    MoveL[[20,30.5,-2.002],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,z0,tSpindleD6\WObj:=wobjStock;
    MoveC[[17.5,25.25,-2.002],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[20,20,-2.002],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],vFeed1,fine,tSpindleD6\WObj:=wobjStock;
    ! Retract
    MoveL[[20,20,SAFE_Z],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v200,z10,tSpindleD6\WObj:=wobjStock;
    MoveL [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z10,tool0\WObj:=wobj0;
    MoveL [[500,0,450],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z10,tool0,\WObj:=wobj0;
    IF Abs(STOCK_ALLOW)>CAM_TOL TPWrite "Stock allowance larger than CAM tolerance";
ENDPROC
ENDMODULE
