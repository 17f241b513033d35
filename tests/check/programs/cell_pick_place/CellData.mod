MODULE CellData
    ! Tools, work objects and taught positions of the pick and place
    ! cell. Used by MainModule and GripperModule.

    PERS tooldata tGripper:=[TRUE,[[0,0,172.5],[1,0,0,0]],[1.9,[0,0,70],[1,0,0,0],0.008,0.008,0.005]];
    PERS wobjdata wobjTrayIn:=[FALSE,TRUE,"",[[650,-480,250],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS wobjdata wobjTrayOut:=[FALSE,TRUE,"",[[650,480,250],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadPart:=[0.45,[0,0,22],[1,0,0,0],0,0,0];

    CONST jointtarget jHome:=[[0,-10,20,0,80,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pTrayFirst:=[[30,30,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! Tray layout
    CONST num TRAY_ROWS:=4;
    CONST num TRAY_COLS:=5;
    CONST num TRAY_PITCH_X:=55;
    CONST num TRAY_PITCH_Y:=48;
    CONST num APPROACH_Z:=80;

    ! Production data
    PERS num nPartsTotal:=0;
    PERS num nGripFaults:=0;

    ! Position of slot (row, col) in a tray
    FUNC robtarget tray_slot(num row,num col)
        RETURN Offs(pTrayFirst,(col-1)*TRAY_PITCH_X,(row-1)*TRAY_PITCH_Y,0);
    ENDFUNC

ENDMODULE
