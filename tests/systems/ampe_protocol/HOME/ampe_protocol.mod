MODULE ampe_protocol
    ! Our own interpreter of abb-motion-program-exec's binary motion program (file
    ! version 10011), written from the Python client's encoder (util.py, commands.py):
    ! every field is a little-endian float32 ("num"), strings a num length then 32
    ! ASCII bytes padded with spaces. It runs MoveAbsJ (1), MoveJ (2), MoveL (3),
    ! MoveC (4) and WaitTime (5) and writes the joint log the client parses: the
    ! version, a string timestamp and a string header (a num length then exactly that
    ! many bytes), then rows of float32 "timestamp,cmdnum,J1..J6". Its name goes to
    ! the event log (ErrWrite \I, code 80003) where the client looks for it.

    CONST num file_version := 10011;
    CONST string log_header := "timestamp,cmdnum,J1,J2,J3,J4,J5,J6";

    ! The program's tool and work object: moves need persistents.
    TASK PERS tooldata ap_tool := [TRUE,[[0,0,0],[1,0,0,0]],[0.001,[0,0,0.001],[1,0,0,0],0,0,0]];
    TASK PERS wobjdata ap_wobj := [FALSE,TRUE,"",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    TASK PERS loaddata ap_load := [0.001,[0,0,0.001],[1,0,0,0],0,0,0];

    ! The program file, read 4 bytes at a time from chunks of at most 1024 bytes: every
    ! field is a multiple of 4 bytes and whole chunks are 1024, so no num straddles two.
    VAR iodev program_file;
    VAR rawbytes chunk;
    VAR num chunk_pos := 1;
    VAR num chunk_len := 0;

    ! The joint log: its file, clock, the command under way and the timer.
    VAR iodev log_file;
    VAR clock log_clock;
    VAR num cmd_num := -1;
    VAR intnum log_timer;

    PROC main()
        VAR num version;
        VAR string timestamp;
        VAR string log_name;
        VAR num opcode;

        chunk_pos := 1;
        chunk_len := 0;
        cmd_num := -1;
        Open "RAMDISK:" \File:="motion_program.bin", program_file \Read \Bin;
        version := next_num();
        IF version <> file_version THEN
            ErrWrite "Motion Program Failed", "Invalid file version " + NumToStr(version, 0);
            Stop;
        ENDIF
        read_tool;
        read_wobj;
        ap_load := next_load();
        timestamp := next_str();
        ! seqno: a driver's sequence number, not used here.
        version := next_num();
        IF next_num() <> 0 THEN
            ErrWrite "Motion Program Failed", "EGM is not supported by this system";
            Stop;
        ENDIF
        GripLoad ap_load;

        log_name := "log-" + timestamp + ".bin";
        open_log timestamp, log_name;
        WHILE has_more() DO
            cmd_num := next_num();
            opcode := next_num();
            log_row;
            run_command opcode;
        ENDWHILE
        ! The last row: where the robot stands once its last move is done.
        WaitRob \InPos;
        log_row;
        close_log log_name;
        Close program_file;
    ENDPROC

    PROC run_command(num opcode)
        VAR jointtarget joints;
        VAR robtarget via;
        VAR robtarget target;
        VAR speeddata speed;
        VAR zonedata zone;
        VAR num seconds;

        TEST opcode
        CASE 1:
            joints := next_joints();
            speed := next_speed();
            zone := next_zone();
            MoveAbsJ joints, speed, zone, ap_tool \WObj:=ap_wobj;
        CASE 2:
            target := next_robtarget();
            speed := next_speed();
            zone := next_zone();
            MoveJ target, speed, zone, ap_tool \WObj:=ap_wobj;
        CASE 3:
            target := next_robtarget();
            speed := next_speed();
            zone := next_zone();
            MoveL target, speed, zone, ap_tool \WObj:=ap_wobj;
        CASE 4:
            via := next_robtarget();
            target := next_robtarget();
            speed := next_speed();
            zone := next_zone();
            MoveC via, target, speed, zone, ap_tool \WObj:=ap_wobj;
        CASE 5:
            ! Read first: a wait our VM resumes after a trap evaluates its
            ! arguments again, and next_num moves through the file.
            seconds := next_num();
            WaitTime seconds;
        DEFAULT:
            ErrWrite "Motion Program Failed", "Unsupported command " + NumToStr(opcode, 0);
            Stop;
        ENDTEST
    ENDPROC

    ! The log: opened and named in the event log, a row now and every 0.1 s (the
    ! timer's floor) until it is closed.
    PROC open_log(string timestamp, string log_name)
        VAR rawbytes head;

        Open "RAMDISK:" \File:=log_name, log_file \Write \Bin;
        ClearRawBytes head;
        PackRawBytes file_version, head, 1 \Float4;
        pack_str timestamp, head;
        pack_str log_header, head;
        WriteRawBytes log_file, head;
        ClkReset log_clock;
        ClkStart log_clock;
        ErrWrite \I, "Motion program log file opened", log_name;
        CONNECT log_timer WITH log_trap;
        ITimer 0.1, log_timer;
    ENDPROC

    PROC close_log(string log_name)
        IDelete log_timer;
        ClkStop log_clock;
        Close log_file;
        ErrWrite \I, "Motion program log file closed", log_name;
    ENDPROC

    PROC pack_str(string text, INOUT rawbytes raw)
        PackRawBytes StrLen(text), raw, RawBytesLen(raw) + 1 \Float4;
        PackRawBytes text, raw, RawBytesLen(raw) + 1 \ASCII;
    ENDPROC

    PROC log_row()
        VAR rawbytes row;
        VAR jointtarget now;

        now := CJointT();
        ClearRawBytes row;
        PackRawBytes ClkRead(log_clock), row, 1 \Float4;
        PackRawBytes cmd_num, row, 5 \Float4;
        PackRawBytes now.robax.rax_1, row, 9 \Float4;
        PackRawBytes now.robax.rax_2, row, 13 \Float4;
        PackRawBytes now.robax.rax_3, row, 17 \Float4;
        PackRawBytes now.robax.rax_4, row, 21 \Float4;
        PackRawBytes now.robax.rax_5, row, 25 \Float4;
        PackRawBytes now.robax.rax_6, row, 29 \Float4;
        WriteRawBytes log_file, row;
    ENDPROC

    TRAP log_trap
        log_row;
    ENDTRAP

    ! Reading the program file.
    FUNC bool has_more()
        IF chunk_pos <= chunk_len RETURN TRUE;
        ReadRawBytes program_file, chunk;
        chunk_pos := 1;
        chunk_len := RawBytesLen(chunk);
        RETURN chunk_len > 0;
    ERROR
        IF ERRNO = ERR_RANYBIN_EOF RETURN FALSE;
        RAISE;
    ENDFUNC

    FUNC num next_num()
        VAR num value;

        IF NOT has_more() THEN
            ErrWrite "Motion Program Failed", "The program file ends inside a command";
            Stop;
        ENDIF
        UnpackRawBytes chunk, chunk_pos, value \Float4;
        chunk_pos := chunk_pos + 4;
        RETURN value;
    ENDFUNC

    FUNC bool next_bool()
        RETURN next_num() <> 0;
    ENDFUNC

    ! A num length, then 32 bytes padded with spaces, read 4 at a time.
    FUNC string next_str()
        VAR num len;
        VAR string text := "";
        VAR string part;

        len := next_num();
        FOR i FROM 1 TO 8 DO
            IF NOT has_more() THEN
                ErrWrite "Motion Program Failed", "The program file ends inside a string";
                Stop;
            ENDIF
            UnpackRawBytes chunk, chunk_pos, part \ASCII:=4;
            chunk_pos := chunk_pos + 4;
            text := text + part;
        ENDFOR
        IF len <= 0 RETURN "";
        RETURN StrPart(text, 1, len);
    ENDFUNC

    FUNC pos next_pos()
        VAR pos p;

        p.x := next_num();
        p.y := next_num();
        p.z := next_num();
        RETURN p;
    ENDFUNC

    FUNC orient next_orient()
        VAR orient q;

        q.q1 := next_num();
        q.q2 := next_num();
        q.q3 := next_num();
        q.q4 := next_num();
        RETURN q;
    ENDFUNC

    FUNC pose next_pose()
        VAR pose p;

        p.trans := next_pos();
        p.rot := next_orient();
        RETURN p;
    ENDFUNC

    FUNC loaddata next_load()
        VAR loaddata l;

        l.mass := next_num();
        l.cog := next_pos();
        l.aom := next_orient();
        l.ix := next_num();
        l.iy := next_num();
        l.iz := next_num();
        RETURN l;
    ENDFUNC

    PROC read_tool()
        ap_tool.robhold := next_bool();
        ap_tool.tframe := next_pose();
        ap_tool.tload := next_load();
    ENDPROC

    PROC read_wobj()
        ap_wobj.robhold := next_bool();
        ap_wobj.ufprog := next_bool();
        ap_wobj.ufmec := next_str();
        ap_wobj.uframe := next_pose();
        ap_wobj.oframe := next_pose();
    ENDPROC

    FUNC extjoint next_extax()
        VAR extjoint e;

        e.eax_a := next_num();
        e.eax_b := next_num();
        e.eax_c := next_num();
        e.eax_d := next_num();
        e.eax_e := next_num();
        e.eax_f := next_num();
        RETURN e;
    ENDFUNC

    FUNC jointtarget next_joints()
        VAR jointtarget j;

        j.robax.rax_1 := next_num();
        j.robax.rax_2 := next_num();
        j.robax.rax_3 := next_num();
        j.robax.rax_4 := next_num();
        j.robax.rax_5 := next_num();
        j.robax.rax_6 := next_num();
        j.extax := next_extax();
        RETURN j;
    ENDFUNC

    FUNC robtarget next_robtarget()
        VAR robtarget r;

        r.trans := next_pos();
        r.rot := next_orient();
        r.robconf.cf1 := next_num();
        r.robconf.cf4 := next_num();
        r.robconf.cf6 := next_num();
        r.robconf.cfx := next_num();
        r.extax := next_extax();
        RETURN r;
    ENDFUNC

    FUNC speeddata next_speed()
        VAR speeddata s;

        s.v_tcp := next_num();
        s.v_ori := next_num();
        s.v_leax := next_num();
        s.v_reax := next_num();
        RETURN s;
    ENDFUNC

    FUNC zonedata next_zone()
        VAR zonedata z;

        z.finep := next_bool();
        z.pzone_tcp := next_num();
        z.pzone_ori := next_num();
        z.pzone_eax := next_num();
        z.zone_ori := next_num();
        z.zone_leax := next_num();
        z.zone_reax := next_num();
        RETURN z;
    ENDFUNC
ENDMODULE
