MODULE divmod_time_split
    ! 3725 s = 1 h 2 min 5 s.
    PROC main()
        VAR num secs := 3725;
        VAR num h;
        VAR num m;
        VAR num s;
        h := secs DIV 3600;
        m := (secs MOD 3600) DIV 60;
        s := secs MOD 60;
        TPWrite "h=" \Num:=h;
        TPWrite "m=" \Num:=m;
        TPWrite "s=" \Num:=s;
        TPWrite "back=" \Num:=h * 3600 + m * 60 + s;
    ENDPROC
ENDMODULE
