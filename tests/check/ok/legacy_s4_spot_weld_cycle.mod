%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE SPOTCYC
  !*******************************************
  !* Spot weld cycle, converted from S4C    *
  !* Pneumatic gun, 2 pressure stages       *
  !*******************************************
  PERS tooldata tgun1:=[TRUE,[[146.5,0,410.2],[0.707107,0,0.707107,0]],[48,[25,0,180],[1,0,0,0],0.8,1.2,0.9]];
  PERS wobjdata wframe1:=[FALSE,TRUE,"",[[1402.5,-611,912],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  CONST robtarget p10:=[[1035.12,-215.67,1108.43],[0.00421,0.70711,0.70709,-0.00418],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget p20:=[[0,0,0],[0.00421,0.70711,0.70709,-0.00418],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget p30:=[[45,0,0],[0.00421,0.70711,0.70709,-0.00418],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget p40:=[[90,0,0],[0.00421,0.70711,0.70709,-0.00418],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget p50:=[[135,0,2.5],[0.00421,0.70711,0.70709,-0.00418],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  VAR signaldo dogunclose;
  VAR signaldo dohighpress;
  VAR signaldo doweldstart;
  VAR signaldi digunclosed;
  VAR signaldi diweldready;
  VAR num weldno:=0;

  PROC main()
    AliasIO "do12_GunClose",dogunclose;
    AliasIO "do13_HighPress",dohighpress;
    AliasIO "do14_WeldStart",doweldstart;
    AliasIO "di12_GunClosed",digunclosed;
    AliasIO "di14_WeldReady",diweldready;
    reg1:=0;
    MoveJ p10,v1500,z100,tgun1;
    spot p20,1;
    spot p30,1;
    spot p40,2;
    spot p50,2;
    MoveJ p10,v1500,z100,tgun1;
    TPWrite "SPOTS WELDED:"\Num:=reg1;
  ENDPROC

  PROC spot(robtarget spotpos,num schedule)
    MoveJ RelTool(spotpos,0,0,-60),v1000,z10,tgun1\WObj:=wframe1;
    MoveL spotpos,v500,fine,tgun1\WObj:=wframe1;
    Set dogunclose;
    IF schedule=2 Set dohighpress;
    WaitDI digunclosed,1;
    WaitDI diweldready,1;
    PulseDO\PLength:=0.1,doweldstart;
    WaitTime 0.35;
    Reset dohighpress;
    Reset dogunclose;
    WaitDI digunclosed,0;
    reg1:=reg1+1;
    weldno:=weldno+1;
    MoveL RelTool(spotpos,0,0,-60),v1000,z10,tgun1\WObj:=wframe1;
  ENDPROC
ENDMODULE
