! expect: E0410 line 11
! a late-bound call through a num variable
MODULE E0410_2
  VAR num n := 1;
  VAR string procname := "helper";
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC main()
    % procname %;
    % n %;
  ENDPROC
ENDMODULE
