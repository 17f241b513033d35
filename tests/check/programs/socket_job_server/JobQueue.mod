MODULE JobQueue
    ! Ring buffer of jobs received from the cell PC.

    RECORD job_entry
        num id;
        num station;
    ENDRECORD

    CONST num QUEUE_SIZE:=16;
    VAR job_entry jqJobs{16};
    VAR num nJobHead:=1;
    VAR num nJobTail:=1;
    VAR num nJobCount:=0;

    FUNC bool queue_push(num id,num station)
        IF nJobCount>=QUEUE_SIZE RETURN FALSE;
        jqJobs{nJobTail}.id:=id;
        jqJobs{nJobTail}.station:=station;
        nJobTail:=nJobTail MOD QUEUE_SIZE+1;
        nJobCount:=nJobCount+1;
        RETURN TRUE;
    ENDFUNC

    FUNC bool queue_pop(VAR job_entry job)
        IF nJobCount=0 RETURN FALSE;
        job:=jqJobs{nJobHead};
        nJobHead:=nJobHead MOD QUEUE_SIZE+1;
        nJobCount:=nJobCount-1;
        RETURN TRUE;
    ENDFUNC

    ! Parses "JOB;<id>;<station>" and queues it
    FUNC bool queue_parse_and_push(string line)
        VAR num p1;
        VAR num p2;
        VAR num nId;
        VAR num nStation;
        IF StrPart(line,1,4)<>"JOB;" RETURN FALSE;
        p1:=4;
        p2:=StrFind(line,p1+1,";");
        IF p2>StrLen(line) RETURN FALSE;
        IF NOT StrToVal(StrPart(line,p1+1,p2-p1-1),nId) RETURN FALSE;
        IF NOT StrToVal(StrPart(line,p2+1,StrLen(line)-p2),nStation) RETURN FALSE;
        RETURN queue_push(nId,nStation);
    ERROR
        RETURN FALSE;
    ENDFUNC

ENDMODULE
