MODULE ctrl_sysdata
  ! The active tool, work object and payload (manual 1.17): tool0, wobj0 and load0
  ! after PP to Main; SetSysData activates another object without changing any value,
  ! GripLoad activates a payload, GetSysData copies the active object and gives its
  ! name. The controller refers to the active object, so GetSysData sees a change
  ! made to it after SetSysData.
  PERS tooldata tGrip := [TRUE, [[10, 20, 30], [1, 0, 0, 0]], [2, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  PERS tooldata tRead := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wTable := [FALSE, TRUE, "", [[100, 200, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS wobjdata wRead := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS loaddata lBox := [5, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0];
  PERS loaddata lRead := [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0];
  VAR string name;

  PROC main()
    GetSysData tRead \ObjectName:=name;
    TPWrite name + " x " \Num:=tRead.tframe.trans.x;
    GetSysData wRead \ObjectName:=name;
    TPWrite name;
    GetSysData lRead \ObjectName:=name;
    TPWrite name + " mass " \Num:=lRead.mass;
    ! tool0's mass is 0.001 kg (catalogue): the copy is the whole object.
    GetSysData tRead;
    TPWrite "tool0 mass " \Num:=tRead.tload.mass;

    SetSysData tGrip;
    GetSysData tRead \ObjectName:=name;
    TPWrite name + " z " \Num:=tRead.tframe.trans.z;
    tGrip.tframe.trans.z := 35;
    GetSysData tRead;
    TPWrite "after the change z " \Num:=tRead.tframe.trans.z;

    ! \ObjectName names the object to activate; SourceObject only gives the type.
    SetSysData wRead \ObjectName:="wTable";
    GetSysData wRead \ObjectName:=name;
    TPWrite name + " y " \Num:=wRead.uframe.trans.y;

    GripLoad lBox;
    GetSysData lRead \ObjectName:=name;
    TPWrite name + " mass " \Num:=lRead.mass;
    SetSysData lRead \ObjectName:="load0";
    GetSysData lRead \ObjectName:=name;
    TPWrite name + " mass " \Num:=lRead.mass;

    ! The own task, named by its taskid or its name.
    GetSysData \TaskRef:=T_ROB1Id, tRead \ObjectName:=name;
    TPWrite "T_ROB1Id: " + name;
    GetSysData \TaskName:="T_ROB1", wRead \ObjectName:=name;
    TPWrite "T_ROB1: " + name;
  ENDPROC
ENDMODULE
