MODULE MainModule
    ! Job server: receives jobs over TCP, executes them in order and
    ! reports the result back to the cell PC.

    PERS tooldata tJob:=[TRUE,[[0,0,120],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
    CONST robtarget pStations{3}:=[[[600,-300,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[600,0,300],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[600,300,300],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
    VAR string sMsg:="";
    VAR job_entry jeCurrent;

    PROC main()
        comm_open;
        WHILE bPcConnected DO
            IF comm_receive(sMsg) THEN
                IF NOT queue_parse_and_push(sMsg) comm_send "FAIL;parse";
            ENDIF
            WHILE queue_pop(jeCurrent) DO
                run_job jeCurrent;
            ENDWHILE
        ENDWHILE
        comm_close;
    ENDPROC

    PROC run_job(job_entry job)
        IF job.station<1 OR job.station>Dim(pStations,1) THEN
            comm_send "FAIL;"+NumToStr(job.id,0);
            RETURN;
        ENDIF
        MoveJ Offs(pStations{job.station},0,0,100),v1000,z20,tJob;
        MoveL pStations{job.station},v200,fine,tJob;
        WaitTime 0.5;
        MoveL Offs(pStations{job.station},0,0,100),v1000,z20,tJob;
        comm_send "DONE;"+NumToStr(job.id,0);
    ENDPROC

ENDMODULE
