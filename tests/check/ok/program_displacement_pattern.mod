MODULE program_displacement_pattern
    ! The same engraving pattern is repeated on four positions of a
    ! nameplate holder. The pattern is taught once around pRef, and
    ! each copy is shifted and turned with program displacement.

    PERS tooldata tEngraver:=[TRUE,[[0,0,190.2],[1,0,0,0]],[2.2,[0,0,75],[1,0,0,0],0.01,0.01,0.005]];
    PERS wobjdata wobjHolder:=[FALSE,TRUE,"",[[950,-200,410],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pRef:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pLetter{5}:=[[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[0,20,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[10,10,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[20,20,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[20,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
    CONST pos PLATE_POS{4}:=[[0,0,0],[150,0,0],[0,120,0],[150,120,0]];
    CONST num PLATE_ROT{4}:=[0,90,180,270];
    VAR pose peDisp;
    VAR robtarget pActual;

    PROC main()
        FOR plate FROM 1 TO 4 DO
            peDisp.trans:=PLATE_POS{plate};
            peDisp.rot:=OrientZYX(PLATE_ROT{plate},0,0);
            PDispSet peDisp;
            engrave_pattern;
            PDispOff;
        ENDFOR
        ! Alternative: displacement defined by a moved reference point
        MoveJ Offs(pRef,300,0,30),v500,fine,tEngraver\WObj:=wobjHolder;
        PDispOn\ExeP:=Offs(pRef,300,0,0),pRef,tEngraver\WObj:=wobjHolder;
        engrave_pattern;
        pActual:=CRobT(\Tool:=tEngraver\WObj:=wobjHolder);
        ! Same point without the displacement, in the object frame
        pActual:=ORobT(pActual);
        TPWrite "Last point without displacement: "\Pos:=pActual.trans;
        PDispOff;
    ENDPROC

    PROC engrave_pattern()
        MoveJ Offs(pLetter{1},0,0,10),v500,z5,tEngraver\WObj:=wobjHolder;
        MoveL pLetter{1},v50,fine,tEngraver\WObj:=wobjHolder;
        FOR i FROM 2 TO Dim(pLetter,1) DO
            MoveL pLetter{i},v20,z0,tEngraver\WObj:=wobjHolder;
        ENDFOR
        MoveL Offs(pLetter{Dim(pLetter,1)},0,0,10),v200,z5,tEngraver\WObj:=wobjHolder;
    ENDPROC

ENDMODULE
