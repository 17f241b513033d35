MODULE motion_stationary_tool
    ! A stationary tool (robhold FALSE): the robot carries the work object (robhold
    ! TRUE, its frame 100 mm along the flange's z) past a TCP fixed at [400,0,250],
    ! pointing down. MoveL moves the object in a straight line under the TCP: the
    ! TCP's position in the object frame goes from [0,-50,0] to [0,50,0].
    ! Worked by hand: 100 mm at v100 with the IRB 120's 10 m/s² path acceleration
    ! takes 100/100 + 100/10000 = 1.01 s, plus 0.05 s settle at the fine point
    ! (ClkRead: 1.06). The trapezoid is symmetric, so at 0.505 s the TCP is half way:
    ! [0,0,0] in the object frame.
    PERS tooldata tStat := [FALSE,[[400,0,250],[0,0,1,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
    PERS wobjdata wHeld := [TRUE,TRUE,"",[[0,0,100],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pA := [[0,-50,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pB := [[0,50,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR intnum tick;
    VAR robtarget seen;
    VAR clock clk;

    PROC main()
        ConfJ \Off;
        ConfL \Off;
        MoveJ pA, v500, fine, tStat \WObj:=wHeld;
        seen := CRobT(\Tool:=tStat \WObj:=wHeld);
        TPWrite "start " \Pos:=seen.trans;
        CONNECT tick WITH look;
        ClkStart clk;
        ITimer \Single, 0.505, tick;
        MoveL pB, v100, fine, tStat \WObj:=wHeld;
        ClkStop clk;
        TPWrite "moved in " \Num:=ClkRead(clk);
        seen := CRobT(\Tool:=tStat \WObj:=wHeld);
        TPWrite "end " \Pos:=seen.trans;
    ENDPROC

    TRAP look
        seen := CRobT(\Tool:=tStat \WObj:=wHeld);
        TPWrite "half way " \Pos:=seen.trans;
    ENDTRAP
ENDMODULE
