MODULE press_fit_soft_servo
    ! Press fitting of a bushing: the last millimetres are done with
    ! soft servo on axes 5 and 6 so the part can align itself.
    ! Contact force is watched on an analog input.

    PERS tooldata tPressFinger:=[TRUE,[[0,0,205],[1,0,0,0]],[4.5,[0,0,90],[1,0,0,0],0.02,0.02,0.01]];
    PERS wobjdata wobjHousing:=[FALSE,TRUE,"",[[1010,120,560],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadBushing:=[0.35,[0,0,15],[1,0,0,0],0,0,0];
    CONST robtarget pBore:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR signalai ai_force;
    VAR num nPeakForce:=0;
    VAR intnum irForce;
    VAR bool bOverForce:=FALSE;
    CONST num FORCE_LIMIT:=850;

    PROC main()
        AliasIO "AI_PressForce",ai_force;
        GripLoad loadBushing;
        press_fit;
        GripLoad load0;
    ENDPROC

    PROC press_fit()
        bOverForce:=FALSE;
        nPeakForce:=0;
        CONNECT irForce WITH trap_force;
        ISignalAI ai_force,AIO_ABOVE_HIGH,FORCE_LIMIT,0,0,irForce;
        MoveJ Offs(pBore,0,0,60),v800,z10,tPressFinger\WObj:=wobjHousing;
        MoveL Offs(pBore,0,0,5),v100,fine,tPressFinger\WObj:=wobjHousing;
        SoftAct 5,60\Ramp:=150;
        SoftAct 6,60;
        MoveL Offs(pBore,0,0,-22),v5,fine,tPressFinger\WObj:=wobjHousing;
        SoftDeact\Ramp:=150;
        MoveL Offs(pBore,0,0,60),v300,z10,tPressFinger\WObj:=wobjHousing;
        IDelete irForce;
        IF bOverForce TPWrite "Force limit reached, peak [N]: "\Num:=nPeakForce;
    ENDPROC

    TRAP trap_force
        bOverForce:=TRUE;
        nPeakForce:=AInput(ai_force);
        StopMove;
        SoftDeact;
        StartMove;
    ENDTRAP

ENDMODULE
