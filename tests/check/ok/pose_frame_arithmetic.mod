MODULE pose_frame_arithmetic
    ! Frame calculations for a camera guided pick:
    ! camera frame -> robot base, part pose from the vision result,
    ! and tool orientation from Euler angles.
    ! Uses pos+pos, pos-pos, num*pos, pos*pos (cross product),
    ! orient*orient, PoseMult, PoseInv, PoseVect, OrientZYX,
    ! EulerZYX, NOrient, DotProd, VectMagn, Distance.

    ! Camera mounted above the conveyor, expressed in the robot base frame
    PERS pose peCamInBase:=[[1250.4,-310.2,1495.7],[0,0.707107,0.707107,0]];
    PERS tooldata tSuction:=[TRUE,[[0,0,168],[1,0,0,0]],[1.1,[0,0,50],[1,0,0,0],0,0,0]];

    VAR pose pePartInCam;
    VAR pose pePartInBase;
    VAR pose peBaseInCam;
    VAR robtarget pPick;
    VAR orient orTool;
    VAR pos psOffset;

    PROC main()
        VAR num nRz;
        ! Vision result: x, y in mm, rotation about Z in degrees
        pePartInCam:=vision_pose(35.2,-12.8,742,27.5);
        ! Chain the frames: base <- camera <- part
        pePartInBase:=PoseMult(peCamInBase,pePartInCam);
        peBaseInCam:=PoseInv(peCamInBase);
        ! Tool points down and follows the part rotation
        orTool:=OrientZYX(0,180,0)*OrientZYX(EulerZYX(\Z,pePartInBase.rot),0,0);
        orTool:=NOrient(orTool);
        nRz:=EulerZYX(\Z,orTool);
        psOffset:=[0,0,25];
        pPick:=[pePartInBase.trans+psOffset,orTool,[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
        MoveJ Offs(pPick,0,0,150),v1000,z20,tSuction;
        MoveL pPick,v200,fine,tSuction;
        TPWrite "Part rotation: "\Num:=nRz;
        TPWrite "Part in camera again: "\Pos:=PoseVect(peBaseInCam,pePartInBase.trans);
        vector_checks;
    ENDPROC

    FUNC pose vision_pose(num x,num y,num z,num rz)
        VAR pose p;
        p.trans:=[x,y,z];
        p.rot:=OrientZYX(rz,0,0);
        RETURN p;
    ENDFUNC

    PROC vector_checks()
        VAR pos a:=[100,0,0];
        VAR pos b:=[0,50,0];
        VAR pos n;
        VAR pos mid;
        VAR num nAngle;
        ! Cross product with the * operator between two pos values
        n:=a*b;
        mid:=0.5*(a+b);
        TPWrite "normal: "\Pos:=n;
        TPWrite "middle: "\Pos:=mid;
        TPWrite "dot: "\Num:=DotProd(a,b);
        TPWrite "len a: "\Num:=VectMagn(a);
        TPWrite "distance a-b: "\Num:=Distance(a,b);
        nAngle:=ACos(DotProd(a,b)/(VectMagn(a)*VectMagn(b)));
        TPWrite "angle between: "\Num:=nAngle;
        ! Quaternion composition and the X/Y Euler angles
        orTool:=OrientZYX(90,0,0)*OrientZYX(0,0,45);
        TPWrite "X angle: "\Num:=EulerZYX(\X,orTool);
        TPWrite "Y angle: "\Num:=EulerZYX(\Y,orTool);
        TPWrite "Z angle: "\Num:=EulerZYX(\Z,orTool);
        TPWrite "orient: "\Orient:=orTool;
        ! Vector division by a scalar
        mid:=(a-b)/2;
        TPWrite "half difference: "\Pos:=mid;
    ENDPROC

ENDMODULE
