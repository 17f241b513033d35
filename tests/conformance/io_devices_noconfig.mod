MODULE io_devices_noconfig
  ! Without an I/O configuration (a single module) there are no devices and no
  ! configured signals, only the controller's own network Local (manual 1.9). Unknown
  ! device and network names raise ERR_NAME_INVALID; signal data that is not connected
  ! has the origin SIGORIG_NONE with an empty name, is not valid, and GetGroupSignalInfo
  ! and ISignalAI on it raise ERR_NO_ALIASIO_DEF.
  VAR signaldo lamp;
  VAR signalgo code;
  VAR signalai level;
  VAR intnum irq;
  VAR string name := "x";
  VAR busstate bs;
  VAR dnum maxv;

  PROC main()
    IF GetSignalOrigin(lamp, name) = SIGORIG_NONE TPWrite "origin none '" + name + "'";
    TPWrite "valid " \Bool:=ValidIO(lamp);
    IOBusState "Local", bs;
    IF bs = BUSSTATE_RUN TPWrite "Local runs";
    IOBusStart "Local";
    TPWrite "state " \Num:=IOUnitState("d652");
    IODisable "d652", 5;
    IOEnable "d652", 5;
    IOBusState "DeviceNet", bs;
    GetGroupSignalInfo code \MaxDvalue:=maxv;
    CONNECT irq WITH tLevel;
    ISignalAI level, AIO_ALWAYS, 0, 0, 0, irq;
    TPWrite "done";
  ERROR
    IF ERRNO = ERR_NAME_INVALID THEN
      TPWrite "ERR_NAME_INVALID";
      TRYNEXT;
    ENDIF
    IF ERRNO = ERR_NO_ALIASIO_DEF THEN
      TPWrite "ERR_NO_ALIASIO_DEF";
      TRYNEXT;
    ENDIF
  ENDPROC

  TRAP tLevel
    TPWrite "never";
  ENDTRAP
ENDMODULE
