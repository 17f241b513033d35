MODULE orient_mult
    ! orient * orient is the rotation link (manual 1.3.1): the quaternion
    ! product with q1 as the scalar part. i*j = k, j*i = -k.
    PROC main()
        VAR orient id := [1, 0, 0, 0];
        VAR orient qi := [0, 1, 0, 0];
        VAR orient qj := [0, 0, 1, 0];
        VAR orient qk := [0, 0, 0, 1];
        VAR orient q := [0.5, 0.5, 0.5, 0.5];
        VAR orient r;
        TPWrite "i*j=k " \Bool:=qi * qj = qk;
        TPWrite "j*i=-k " \Bool:=qj * qi = [0, 0, 0, -1];
        TPWrite "id*q=q " \Bool:=id * q = q;
        TPWrite "q*id=q " \Bool:=q * id = q;
        ! q is a 120 degree turn: q*q = [-0.5,0.5,0.5,0.5], q*q*q = [-1,0,0,0]
        r := q * q;
        TPWrite "q1=" \Num:=r.q1;
        TPWrite "q2=" \Num:=r.q2;
        TPWrite "q3=" \Num:=r.q3;
        TPWrite "q4=" \Num:=r.q4;
        TPWrite "q^3=-1 " \Bool:=r * q = [-1, 0, 0, 0];
    ENDPROC
ENDMODULE
