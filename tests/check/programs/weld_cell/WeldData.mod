MODULE WeldData
    ! Weld seam definitions shared by the weld cell program.

    RECORD seam_def
        string name;
        num length;
        num speed;
        num voltage;
    ENDRECORD

    PERS tooldata tTorch:=[TRUE,[[125.3,0,398.6],[0.92388,0,0.382683,0]],[3.4,[-35,0,185],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjFixture:=[FALSE,TRUE,"",[[1250,-150,720],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pSeamStart{3}:=[[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[0,100,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[0,200,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
    CONST seam_def SEAMS{3}:=[["S1_bottom",220,9,21.5],["S2_middle",180,10,22],["S3_top",220,9,21.5]];
    CONST jointtarget jWeldHome:=[[0,-25,35,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PERS num nSeamsWelded:=0;

ENDMODULE
