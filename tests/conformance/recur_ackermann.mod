MODULE recur_ackermann
    ! Ackermann's function: deep, nested recursion.
    FUNC num ack(num m, num n)
        IF m = 0 RETURN n + 1;
        IF n = 0 RETURN ack(m - 1, 1);
        RETURN ack(m - 1, ack(m, n - 1));
    ENDFUNC

    PROC main()
        TPWrite "ack(0,0)=" \Num:=ack(0, 0);
        TPWrite "ack(1,2)=" \Num:=ack(1, 2);
        TPWrite "ack(2,3)=" \Num:=ack(2, 3);
    ENDPROC
ENDMODULE
