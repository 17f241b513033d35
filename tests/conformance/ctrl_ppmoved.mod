MODULE ctrl_ppmoved
  ! `rapid run` starts as the operator's PP to Main followed by Start: the PP was
  ! moved, to Main, in the stop state before the start (IsStopStateEvent), and the
  ! run never stops and restarts, so both answers stay TRUE. In automatic mode that
  ! move was not made in manual mode (PPMovedInManMode FALSE). ResetPPMoved clears
  ! only the manual-mode flag. Without a switch IsStopStateEvent has nothing to
  ! answer: ERR_ARGVALERR (docs/semantics.md, uncertain).
  VAR bool answer;

  PROC main()
    TPWrite "moved in manual mode " \Bool:=PPMovedInManMode();
    TPWrite "moved " \Bool:=IsStopStateEvent(\PPMoved);
    TPWrite "to main " \Bool:=IsStopStateEvent(\PPToMain);
    ResetPPMoved;
    TPWrite "moved in manual mode " \Bool:=PPMovedInManMode();
    TPWrite "moved " \Bool:=IsStopStateEvent(\PPMoved);
    answer := IsStopStateEvent();
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_ARGVALERR THEN
      TPWrite "no switch: ERR_ARGVALERR";
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
