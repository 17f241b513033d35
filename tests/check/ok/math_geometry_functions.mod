MODULE math_geometry_functions
    ! Math helpers for the bending cell: sheet geometry, bend
    ! allowance and rounding for the PLC interface.
    ! Uses Sqrt, Pow, ATan2, Sin/Cos/Tan, ASin/ACos, Abs, Exp,
    ! Round/Trunc with \Dec, DIV and MOD.

    CONST num DEG_PER_RAD:=57.29578;
    CONST num K_FACTOR:=0.44;
    CONST num SMALL:=0.5E-3;
    CONST num TOLERANCE:=-.002;

    VAR num nResult:=0;

    PROC main()
        TPWrite "Hypotenuse 3/4: "\Num:=hypot(3,4);
        TPWrite "Angle of (1,1): "\Num:=ATan2(1,1);
        TPWrite "Bend allowance: "\Num:=bend_allowance(90,2,1.5);
        TPWrite "Sheet flat length: "\Num:=flat_length(120,80,90,2,1.5);
        TPWrite "Round 2 dec: "\Num:=Round(12.34567\Dec:=2);
        TPWrite "Trunc 1 dec: "\Num:=Trunc(12.34567\Dec:=1);
        TPWrite "Round int: "\Num:=Round(12.5);
        split_time 3725;
        TPWrite "Decay: "\Num:=decay(100,0.25,4);
        TPWrite "Triangle angle C: "\Num:=triangle_angle(7,8,9);
        check_equal 0.1+0.2,0.3;
    ENDPROC

    FUNC num hypot(num a,num b)
        RETURN Sqrt(Pow(a,2)+Pow(b,2));
    ENDFUNC

    ! Bend allowance in mm for angle (deg), inner radius and thickness
    FUNC num bend_allowance(num angle,num radius,num thickness)
        RETURN angle/DEG_PER_RAD*(radius+K_FACTOR*thickness);
    ENDFUNC

    FUNC num flat_length(num leg1,num leg2,num angle,num radius,num thickness)
        VAR num nSetback;
        nSetback:=Tan(angle/2)*(radius+thickness);
        RETURN leg1+leg2-2*nSetback+bend_allowance(angle,radius,thickness);
    ENDFUNC

    ! Law of cosines, result in degrees
    FUNC num triangle_angle(num a,num b,num c)
        VAR num nCos;
        nCos:=(Pow(a,2)+Pow(b,2)-Pow(c,2))/(2*a*b);
        IF nCos>1 nCos:=1;
        IF nCos<-1 nCos:=-1;
        RETURN ACos(nCos);
    ENDFUNC

    ! Exponential decay value*e^(-rate*t)
    FUNC num decay(num value,num rate,num t)
        RETURN value*Exp(-rate*t);
    ENDFUNC

    ! Integer arithmetic with DIV and MOD
    PROC split_time(num seconds)
        VAR num h;
        VAR num m;
        VAR num s;
        h:=seconds DIV 3600;
        m:=(seconds MOD 3600) DIV 60;
        s:=seconds MOD 60;
        TPWrite NumToStr(h,0)+"h "+NumToStr(m,0)+"m "+NumToStr(s,0)+"s";
    ENDPROC

    ! Floating point compare with a tolerance
    PROC check_equal(num a,num b)
        IF Abs(a-b)<SMALL THEN
            TPWrite "equal within tolerance";
        ELSEIF a-b<TOLERANCE THEN
            TPWrite "a is smaller";
        ELSE
            TPWrite "a is larger";
        ENDIF
        ! Sine/cosine identity check, should be 1
        nResult:=Pow(Sin(30),2)+Pow(Cos(30),2);
        nResult:=nResult+ASin(0.5)-30;
    ENDPROC

ENDMODULE
