MODULE literal_forms_name_limits
    ! Numeric literal forms, name length limits and maximum string
    ! lengths, as they occur in generated and hand-written programs.
    !   integers        3   -100   3E2   3e-2   9E+09
    !   decimals        3.5   -0.345   -245E-2   .5   7.   1.E3
    !   hex/octal/bin   0xFF  0X1f  0o17  0O7  0b1011  0B1
    ! Identifiers may be 32 characters long; strings 80 characters.

    CONST num N_INT:=3;
    CONST num N_NEG:=-100;
    CONST num N_EXP:=3E2;
    CONST num N_EXP_NEG:=3e-2;
    CONST num N_EXP_PLUS:=9E+09;
    CONST num N_DEC:=3.5;
    CONST num N_DEC_NEG:=-0.345;
    CONST num N_DEC_EXP:=-245E-2;
    CONST num N_LEAD_DOT:=.5;
    CONST num N_TRAIL_DOT:=7.;
    CONST num N_DOT_EXP:=1.E3;
    CONST num N_SMALL:=0.5E-3;
    CONST num N_TINY_NEG:=-.002;
    CONST num N_HEX:=0xFF;
    CONST num N_HEX_UPPER:=0X1f;
    CONST num N_OCT:=0o17;
    CONST num N_OCT_UPPER:=0O7;
    CONST num N_BIN:=0b1011;
    CONST num N_BIN_UPPER:=0B1;
    CONST num N_ARRAY{6}:=[0x10,0o10,0b10,10,1E1,.1E2];

    ! 32 character names: data, routine, parameter, trap
    VAR num station_conveyor_speed_override2:=100;
    PERS num max_allowed_gripper_retry_count1:=3;
    VAR intnum irLightBarrier;
    VAR signaldi di_light_barrier;

    ! 80 character strings
    CONST string S80_A:="Check gripper fingers for wear every 5000 cycles and replace both pads together!";
    CONST string S80_B:="12345678901234567890123456789012345678901234567890123456789012345678901234567890";

    PROC main()
        VAR num nSum;
        AliasIO "DI_LightBarrier",di_light_barrier;
        CONNECT irLightBarrier WITH TRAP_light_barrier_interrupted_x;
        ISignalDI di_light_barrier,0,irLightBarrier;
        nSum:=N_INT+N_NEG+N_EXP+N_EXP_NEG+N_DEC+N_DEC_NEG+N_DEC_EXP;
        nSum:=nSum+N_LEAD_DOT+N_TRAIL_DOT+N_DOT_EXP+N_SMALL+N_TINY_NEG;
        nSum:=nSum+N_HEX+N_HEX_UPPER+N_OCT+N_OCT_UPPER+N_BIN+N_BIN_UPPER;
        TPWrite "Sum of literals: "\Num:=nSum;
        TPWrite "Large literal: "\Num:=N_EXP_PLUS;
        TPWrite "Layer height: "\Num:=calculate_layer_height_with_gap1(4,N_ARRAY{2});
        LongestAllowedRoutineNameIs32Chr station_conveyor_speed_override2;
        TPWrite S80_A;
        TPWrite S80_B;
        IDelete irLightBarrier;
    ENDPROC

    FUNC num calculate_layer_height_with_gap1(num layers,num gap_between_layers_in_millimetre)
        RETURN layers*(120+gap_between_layers_in_millimetre);
    ENDFUNC

    PROC LongestAllowedRoutineNameIs32Chr(num percent)
        VelSet percent,5000;
        IF percent<50 max_allowed_gripper_retry_count1:=5;
    ENDPROC

    TRAP TRAP_light_barrier_interrupted_x
        station_conveyor_speed_override2:=25;
        VelSet station_conveyor_speed_override2,500;
    ENDTRAP

ENDMODULE
