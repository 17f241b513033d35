MODULE ctrl_ppmoved_manual
  ! Run with --mode manual-reduced (ctrl_ppmoved_manual.args): the PP to Main before
  ! the start was made in manual mode, so PPMovedInManMode is TRUE until
  ! ResetPPMoved clears it (manual 1.17).
  PROC main()
    IF PPMovedInManMode() THEN
      TPWrite "the PP was moved in manual mode: confirm the start point";
      ResetPPMoved;
    ENDIF
    TPWrite "moved in manual mode " \Bool:=PPMovedInManMode();
    ResetPPMoved;
    TPWrite "moved in manual mode " \Bool:=PPMovedInManMode();
  ENDPROC
ENDMODULE
