MODULE motion_trigg_errors
  ! Error paths of the trigger definitions, each handled by name and skipped (TRYNEXT):
  ! an interrupt that is not connected (ERR_UNKINO, as for ISignalDI), a negative
  ! Distance (ERR_ARGVALERR), a signal variable that is not connected to a signal
  ! (ERR_NO_ALIASIO_DEF, as any signal access, manual 1.9), and a TriggLIOs array
  ! naming a signal the I/O configuration does not have (ERR_SIG_NAME; this program
  ! runs with no I/O configuration, so no name is known).
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR triggdata t;
  VAR intnum never;
  VAR intnum mark;
  VAR signaldi diNone;
  VAR triggios bad{1} := [[TRUE, 0, TRUE, 0, "doNone", 1, 0]];
  VAR num stage := 0;

  PROC main()
    stage := 1;
    TriggInt t, 10, never;
    stage := 2;
    CONNECT mark WITH on_mark;
    TriggCheckIO t, -5 \Start, diNone, EQ, 1, mark;
    stage := 3;
    TriggCheckIO t, 10 \Start, diNone, EQ, 1, mark;
    stage := 4;
    MoveJ p0, v1000, fine, tool0;
    TriggLIOs Offs(p0, 10, 0, 0), v100 \TriggData1:=bad, fine, tool0;
    TPWrite "done";
    IDelete mark;
  ERROR
    IF ERRNO = ERR_UNKINO TPWrite "stage " + NumToStr(stage, 0) + ": ERR_UNKINO";
    IF ERRNO = ERR_ARGVALERR TPWrite "stage " + NumToStr(stage, 0) + ": ERR_ARGVALERR";
    IF ERRNO = ERR_NO_ALIASIO_DEF TPWrite "stage " + NumToStr(stage, 0) + ": ERR_NO_ALIASIO_DEF";
    IF ERRNO = ERR_SIG_NAME TPWrite "stage " + NumToStr(stage, 0) + ": ERR_SIG_NAME";
    TRYNEXT;
  ENDPROC

  TRAP on_mark
    TPWrite "mark";
  ENDTRAP
ENDMODULE
