MODULE arr_record_array_copy
    ! Assigning a record into an array element copies it.
    RECORD item
        string name;
        num qty;
    ENDRECORD

    PROC main()
        VAR item bin{3};
        VAR item it := ["screw", 10];
        bin{1} := it;
        it.qty := 0;
        it.name := "nail";
        bin{2} := it;
        TPWrite bin{1}.name + " " + ValToStr(bin{1}.qty);
        TPWrite bin{2}.name + " " + ValToStr(bin{2}.qty);
        TPWrite "[" + bin{3}.name + "] " + ValToStr(bin{3}.qty);
    ENDPROC
ENDMODULE
