MODULE load_slots
  ! Modules loaded and unloaded in any order keep each other's data and routines:
  ! B still works after A (loaded before it) is unloaded, a module loaded later (C)
  ! gets data of its own, and A loaded again starts from its initial values
  ! (manual 1.2.2: data gets its initial value when its module is loaded).
  VAR iodev f;
  VAR num shared := 100;

  PROC main()
    Open "HOME:/A.mod", f \Write;
    Write f, "MODULE A";
    Write f, "VAR num a := 1;";
    Write f, "RECORD apair num x; num y; ENDRECORD";
    Write f, "VAR apair ap := [3, 4];";
    Write f, "PROC a_show() a := a + 1; TPWrite ""a="" \\Num:=a + ap.x + ap.y; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/B.mod", f \Write;
    Write f, "MODULE B";
    Write f, "VAR num b := 20; CONST num bstep := 2;";
    Write f, "PROC b_show() b := b + bstep; shared := shared + 1;";
    Write f, "TPWrite ""b="" \\Num:=b; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/C.mod", f \Write;
    Write f, "MODULE C";
    Write f, "VAR string c := ""c0""; PERS num cp := 7;";
    Write f, "PROC c_show() c := c + ""!""; TPWrite c \\Num:=cp; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/A.mod";
    Load "HOME:/B.mod";
    %"a_show"%;
    %"b_show"%;
    UnLoad "HOME:/A.mod";
    %"b_show"%;
    Load "HOME:/C.mod";
    %"c_show"%;
    %"b_show"%;
    %"c_show"%;
    Load "HOME:/A.mod";
    %"a_show"%;
    %"a_show"%;
    UnLoad "HOME:/B.mod";
    UnLoad "HOME:/C.mod";
    %"a_show"%;
    TPWrite "shared=" \Num:=shared;
  ENDPROC
ENDMODULE
