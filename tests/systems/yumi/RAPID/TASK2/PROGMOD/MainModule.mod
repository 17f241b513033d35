MODULE MainModule
  ! The left arm: axis 7 in a jointtarget's eax_a, the arm angle in a robtarget's.
  PROC main()
    VAR jointtarget j;
    VAR robtarget p;
    VAR robtarget q;
    VAR robtarget r;
    VAR robtarget goal;
    j := CJointT();
    TPWrite "L start " + ValToStr(j.robax) + " " + ValToStr(j.extax.eax_a);
    MoveAbsJ [[10,-120,20,15,35,-10],[100,9E9,9E9,9E9,9E9,9E9]], v200, fine, tool0;
    j := CJointT();
    TPWrite "L axes " + ValToStr(j.robax) + " " + ValToStr(j.extax.eax_a);
    p := CRobT(\Tool:=tool0 \WObj:=wobj0);
    goal := Offs(p, 20, 10, -15);
    MoveL goal, v100, fine, tool0;
    q := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "moved " \Bool:=Distance(q.trans, goal.trans) < 0.01 AND Distance(goal.trans, p.trans) > 26.9;
    TPWrite "angle kept " \Bool:=Abs(q.extax.eax_a - p.extax.eax_a) < 0.01;
    r := q;
    r.extax.eax_a := q.extax.eax_a + 10;
    MoveL r, v100, fine, tool0;
    q := CRobT(\Tool:=tool0 \WObj:=wobj0);
    j := CJointT();
    TPWrite "elbow turned " \Bool:=Distance(q.trans, r.trans) < 0.01 AND Abs(q.extax.eax_a - r.extax.eax_a) < 0.01;
    TPWrite "axis 7 moved " \Bool:=Abs(j.extax.eax_a - 100) > 1;
    MoveAbsJ [[0,-130,30,0,40,0],[170,9E9,9E9,9E9,9E9,9E9]], v200, fine, tool0;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
