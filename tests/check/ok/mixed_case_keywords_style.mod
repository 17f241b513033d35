module mixed_case_keywords_style
    ! Program typed by hand on an offline editor by several people.
    ! RAPID ignores letter case in keywords, names and argument names,
    ! so all of this loads exactly like the upper case form.

    Pers tooldata tHandling:=[true,[[0,0,155],[1,0,0,0]],[2,[0,0,60],[1,0,0,0],0,0,0]];
    Pers wobjdata wobjTray:=[False,True,"",[[700,300,400],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    Const jointtarget jHomePos:=[[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    Const robtarget pTray:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    var num Counter:=0;
    VAR Num MaxParts:=12;
    var signaldi diTrayPresent;
    var bool bTimedOut:=FALSE;

    proc Main()
        aliasio "DI_TrayPresent",diTrayPresent;
        MoveAbsj jHomePos\NoEoffs,V1000,Z50,tHandling;
        counter:=0;
        While COUNTER<maxparts Do
            If diTrayPresent=1 Then
                place_in_tray counter;
                Counter:=Counter+1;
            ElseIf diTrayPresent=0 THEN
                waitdi diTrayPresent,1\maxtime:=30\timeflag:=bTimedOut;
                if bTimedOut then
                    tpwrite "No tray";
                    Exit;
                endif
            Else
                TPWRITE "unreachable";
            EndIf
        EndWhile
        for k from 1 to 3 step 1 do
            TpWrite "Parts left: "\num:=parts_left();
        endFor
        MOVEABSJ JHOMEPOS,v1000,fine,THANDLING;
    endproc

    Proc place_in_tray(num Slot)
        Var num row;
        Var num col;
        row:=slot Div 4;
        col:=slot Mod 4;
        movej offs(pTray,col*50,row*60,80),v1000,z20,tHandling\Wobj:=wobjTray;
        MoveL Offs(pTray,col*50,row*60,0),v200,FINE,tHandling\wobj:=wobjTray;
        WaitTime\inpos,0.2;
        moveL OFFS(ptray,col*50,row*60,80),V1000,z20,thandling\WOBJ:=WOBJTRAY;
    Error
        If errno=ERR_WAIT_MAXTIME Then
            Retry;
        EndIf
        Raise;
    EndProc

    Func Bool tray_full()
        Return counter>=MaxParts;
    EndFunc

    func num parts_left()
        if not tray_full() then
            return MaxParts-Counter;
        endif
        return 0;
    endfunc

endmodule
