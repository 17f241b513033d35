MODULE rec_func_return
    ! A FUNC may return a record value (manual 1.1.5: any type but arrays).
    RECORD part
        string name;
        num weight;
    ENDRECORD

    FUNC part makePart(string n, num w)
        VAR part p;
        p.name := n;
        p.weight := w;
        RETURN p;
    ENDFUNC

    FUNC part heavier(part a, part b)
        IF a.weight >= b.weight RETURN a;
        RETURN b;
    ENDFUNC

    PROC main()
        VAR part x;
        x := makePart("bolt", 3);
        TPWrite x.name + " " + ValToStr(x.weight);
        x := heavier(x, makePart("nut", 7));
        TPWrite x.name + " " + ValToStr(x.weight);
        TPWrite "eq=" \Bool:=makePart("a", 1) = makePart("a", 1);
    ENDPROC
ENDMODULE
