MODULE param_named_args
    ! Required arguments may be written with the parameter name
    ! (manual 1.3.4: Polar(Dist:=3.937, Angle:=0.785398)).
    PROC polar(num Dist, num Angle)
        TPWrite "dist=" \Num:=Dist;
        TPWrite "angle=" \Num:=Angle;
    ENDPROC

    FUNC num area(num w, num h)
        RETURN w * h;
    ENDFUNC

    PROC main()
        polar 3, 45;
        polar Dist:=5, Angle:=90;
        TPWrite "area=" \Num:=area(w:=3, h:=4);
        TPWrite "area=" \Num:=area(2, h:=8);
    ENDPROC
ENDMODULE
