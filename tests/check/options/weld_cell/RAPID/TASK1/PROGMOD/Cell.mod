MODULE Cell
  ! Arc, SmarTac, Force Control, EGM and Production Manager calls written the way
  ! public RobotWare programs write them (argument counts, switches and order).
  TASK PERS menudata mdCleanTorch:=["Clean the torch","","CleanTorch",1,"",255,TRUE,2,0,FALSE,12];
  TASK PERS partdata pdBracket:=["WeldBracket","Bracket, station 1","",1,0,"","pavBracket"];
  TASK PERS seamdata seamA:=[0,0.4,[0,0,0,0,0,0,0,0,0],0,0,0,0,0,[0,0,0,0,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0.4];
  TASK PERS welddata weldA:=[8,0,[20,0,0,0,0,220,0,0,0],[0,0,0,0,0,0,0,0,0]];
  TASK PERS weavedata weaveA:=[1,0,3,5,0,0,0,0,0,0,0,0,0,0,0];
  TASK PERS trackdata trackA:=[0,TRUE,40,[0,20,20,0,0,0,0,0,0],[0,0,0,0,0,0,0]];
  TASK PERS pose peFound:=[[0,0,0],[1,0,0,0]];
  TASK PERS pose peGroove:=[[0,0,0],[1,0,0,0]];
  TASK PERS num nGrooveWidth:=0;
  TASK PERS robtarget pStop:=[[600,0,300],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  TASK PERS tooldata tGun:=[TRUE,[[0,0,380],[1,0,0,0]],[3,[0,0,100],[1,0,0,0],0,0,0]];
  TASK PERS wobjdata woTable:=[FALSE,TRUE,"",[[800,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  TASK PERS loaddata ldSpindle:=[2,[0,0,60],[1,0,0,0],0,0,0];
  CONST robtarget pA:=[[600,0,300],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pB:=[[650,0,300],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pC:=[[650,50,300],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST jointtarget jPark:=[[0,0,0,0,30,0],[0,9E+09,9E+09,9E+09,9E+09,9E+09]];
  VAR egmident egmId;
  CONST egm_minmax egmConv:=[-0.5,0.5];
  VAR fcforcevector fv;

  PROC main()
    ExecEngine;
  ENDPROC

  PROC WeldBracket()
    Search_1D peFound,pA,pB,v200,tGun;
    Search_1D \Wire,peFound\SearchStop:=pStop,pA,pB,v200,tGun\WObj:=woTable;
    PDispAdd peFound;
    Search_Groove peGroove,nGrooveWidth,pA,pB,25,v200,tGun;
    ArcLStart pA,v100,seamA,weldA\Weave:=weaveA,fine,tGun\WObj:=woTable\Track:=trackA\SeamName:="Bracket";
    ArcL pB,v100,seamA,weldA,z1,tGun\WObj:=woTable\Track:=trackA\PreProcessTracking;
    ArcCEnd pB,pC,v100,seamA,weldA,fine,tGun\WObj:=woTable;
    ArcRefresh \WeldSpeed:=9\WeaveWidth:=4;
    ArcMoveExtJ jPark\ID:=1,v1000,z10\Start;
  ENDPROC

  PROC Press()
    ldSpindle:=FCLoadId(\MaxMoveAx5:=30\MaxMoveAx6:=60);
    FCCalib ldSpindle;
    FCAct tGun\Load:=ldSpindle;
    FCPress1LStart pA,v50\Fz:=40,20\ForceChange:=80\PosSupvDist:=100,z5,tGun\WObj:=woTable;
    FCPressL pB,v20,40,fine,tGun\WObj:=woTable;
    fv:=FCGetForce(\ContactForce);
  ENDPROC

  PROC Guide()
    EGMGetId egmId;
    EGMSetupUC ROB_1,egmId,"default","UCdevice"\Joint\CommTimeout:=5;
    EGMActJoint egmId\Tool:=tGun\WObj:=woTable\TLoad:=ldSpindle\J1:=egmConv\J2:=egmConv\MaxSpeedDeviation:=20;
    EGMRunJoint egmId,EGM_STOP_HOLD\J1\J2\CondTime:=10\RampInTime:=0.1\PosCorrGain:=1;
    EGMReset egmId;
  ENDPROC
ENDMODULE
