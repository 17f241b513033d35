MODULE MainModule
  ! The right arm: where it stands when the system starts.
  PROC main()
    VAR jointtarget j;
    WaitTime 0.05;
    j := CJointT();
    TPWrite "R start " + ValToStr(j.robax) + " " + ValToStr(j.extax.eax_a);
  ENDPROC
ENDMODULE
