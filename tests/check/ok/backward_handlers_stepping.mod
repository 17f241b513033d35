MODULE backward_handlers_stepping
    ! Teach-friendly motion routines for a gluing robot.
    ! The BACKWARD handlers mirror the forward motion so the operator
    ! can step backwards through a whole routine call with the
    ! FlexPendant BACKWARD button. MoveC keeps its CirPoint/ToPoint order.

    PERS tooldata tGlue:=[TRUE,[[0,48,201],[0.965926,0,-0.258819,0]],[1.6,[0,10,90],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjWindow:=[FALSE,TRUE,"",[[980,-300,720],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    CONST robtarget pApproach:=[[0,0,120],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pCorner1:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pEdge1:=[[480,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pRadiusMid:=[[515.1,14.6,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pRadiusEnd:=[[530,50,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pEdge2:=[[530,620,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pDepart:=[[530,620,120],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR signaldo do_glue_gun;

    PROC main()
        AliasIO "doGlueGun",do_glue_gun;
        approach_window;
        glue_first_edge;
        glue_radius;
        depart_window;
    ENDPROC

    PROC approach_window()
        MoveJ pApproach,v800,z20,tGlue\WObj:=wobjWindow;
        MoveL pCorner1,v200,fine,tGlue\WObj:=wobjWindow;
    BACKWARD
        MoveL pCorner1,v200,fine,tGlue\WObj:=wobjWindow;
        MoveJ pApproach,v800,z20,tGlue\WObj:=wobjWindow;
    ENDPROC

    PROC glue_first_edge()
        SetDO do_glue_gun,1;
        MoveL pEdge1,v150,z5,tGlue\WObj:=wobjWindow;
    BACKWARD
        ! Going backwards the gun must stay closed
        MoveL pEdge1,v150,z5,tGlue\WObj:=wobjWindow;
    ENDPROC

    PROC glue_radius()
        MoveC pRadiusMid,pRadiusEnd,v100,z1,tGlue\WObj:=wobjWindow;
        MoveL pEdge2,v150,fine,tGlue\WObj:=wobjWindow;
        SetDO do_glue_gun,0;
    BACKWARD
        MoveL pEdge2,v150,fine,tGlue\WObj:=wobjWindow;
        MoveC pRadiusMid,pRadiusEnd,v100,z1,tGlue\WObj:=wobjWindow;
    ERROR
        SetDO do_glue_gun,0;
        RAISE;
    ENDPROC

    PROC depart_window()
        MoveL pDepart,v300,z20,tGlue\WObj:=wobjWindow;
    BACKWARD
        MoveL pDepart,v300,z20,tGlue\WObj:=wobjWindow;
    ENDPROC

    ! An empty backward handler: the call is a no-op when stepping back
    PROC count_window()
        Incr reg1;
    BACKWARD
    ENDPROC

ENDMODULE
