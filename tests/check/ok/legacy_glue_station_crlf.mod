%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE GLUE_ST2
  ! Glue station 2 - old program saved from an S4C+ controller
  ! on a Windows PC (CRLF line ends).
  PERS tooldata tglue:=[TRUE,[[0,0,187.5],[1,0,0,0]],[1.8,[0,0,70],[1,0,0,0],0,0,0]];
  PERS wobjdata wpanel:=[FALSE,TRUE,"",[[1100,-250,700],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  CONST robtarget pg10:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pg20:=[[400,0,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pg30:=[[450,50,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pg40:=[[400,100,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pg50:=[[0,100,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST speeddata vglue:=[120,300,5000,1000];
  VAR signaldo doglue;
  VAR signalao aoflow;
  VAR num beadcount:=0;

  PROC main()
    AliasIO "do21_GlueGun",doglue;
    AliasIO "ao21_GlueFlow",aoflow;
    SetAO aoflow,6.5;
    glue_panel;
    beadcount:=beadcount+1;
    TPWrite "Beads: "\Num:=beadcount;
  ENDPROC

  PROC glue_panel()
    MoveJ Offs(pg10,0,0,50),v1000,z20,tglue\WObj:=wpanel;
    MoveL pg10,v200,fine,tglue\WObj:=wpanel;
    SetDO\SDelay:=0.05,doglue,1;
    MoveL pg20,vglue,z5,tglue\WObj:=wpanel;
    MoveC pg30,pg40,vglue,z5,tglue\WObj:=wpanel;
    MoveL pg50,vglue,z5,tglue\WObj:=wpanel;
    MoveL pg10,vglue,fine,tglue\WObj:=wpanel;
    SetDO doglue,0;
    MoveL Offs(pg10,0,0,50),v500,z20,tglue\WObj:=wpanel;
  ERROR
    SetDO doglue,0;
    RAISE;
  ENDPROC
ENDMODULE
