MODULE io_wait_visualize
    ! \Visualize (RAPID instructions manual, RW 6) shows a message box on the
    ! pendant while the instruction waits; the wait itself runs unchanged: it ends
    ! when its condition holds, and \MaxTime with \TimeFlag ends it as without a box.
    VAR clock clk;
    VAR bool late;
    VAR string lines{2} := ["Load the part", "then press start"];

    PROC main()
        ClkStart clk;
        WaitUntil ClkRead(clk) >= 1 \Visualize \Header:="Waiting" \Message:="one second";
        TPWrite "after " \Num:=Round(ClkRead(clk));
        WaitUntil ClkRead(clk) >= 2 \Visualize \MsgArray:=lines \Icon:=iconInfo \VisualizeTime:=0.5;
        TPWrite "after " \Num:=Round(ClkRead(clk));
        WaitUntil FALSE \MaxTime:=1 \TimeFlag:=late \Visualize \Header:="never";
        TPWrite "late " \Bool:=late;
        TPWrite "after " \Num:=Round(ClkRead(clk));
    ENDPROC
ENDMODULE
