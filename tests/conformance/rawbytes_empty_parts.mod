MODULE rawbytes_empty_parts
    ! Empty parts of messages, as real drivers send and read them.
    ! CopyRawBytes without \NoOfBytes copies the bytes from FromIndex to the end of
    ! the valid data: at RawBytesLen + 1 that is none, and nothing changes (the
    ! ROS-Industrial driver copies a header-only reply's empty data part so; uncertain,
    ! behavioural evidence, docs/semantics.md). Further out, or with \NoOfBytes, the
    ! index is out of bounds.
    ! UnpackRawBytes \ASCII:=0 reads the empty string (abb_motion_program_exec reads
    ! zero-length strings so; uncertain, the manual gives 1..80). PackRawBytes of an
    ! empty string with \ASCII stays refused (ERR_ARGVALERR, the manual's 1..80).
    PROC main()
        VAR rawbytes payload;
        VAR rawbytes buffer;
        VAR num len;
        VAR string name := "unchanged";
        VAR num outofbnd := 0;
        VAR num argval := 0;
        PackRawBytes 12, buffer, 1 \IntX:=UDINT;
        CopyRawBytes payload, 1, buffer, 5;
        TPWrite "len=" \Num:=RawBytesLen(buffer);
        CopyRawBytes buffer, 5, payload, 1;
        TPWrite "payload=" \Num:=RawBytesLen(payload);
        CopyRawBytes buffer, 6, payload, 1;
        CopyRawBytes buffer, 5, payload, 1 \NoOfBytes:=1;
        TPWrite "outofbnd=" \Num:=outofbnd;

        PackRawBytes 0, buffer, 5 \Float4;
        PackRawBytes "    ", buffer, 9 \ASCII;
        UnpackRawBytes buffer, 5, len \Float4;
        UnpackRawBytes buffer, 9, name \ASCII:=len;
        TPWrite "name=<" + name + ">";
        name := "unchanged";
        UnpackRawBytes buffer, 13, name \ASCII:=0;
        TPWrite "end=<" + name + ">";
        PackRawBytes "", buffer, 13 \ASCII;
        TPWrite "argval=" \Num:=argval;
        TPWrite "len=" \Num:=RawBytesLen(buffer);
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            outofbnd := outofbnd + 1;
            TRYNEXT;
        ELSEIF ERRNO = ERR_ARGVALERR THEN
            argval := argval + 1;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
