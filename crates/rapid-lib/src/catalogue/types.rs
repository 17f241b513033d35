//! Catalogue chapter: predefined data types (manual ch. 1 type tables, §1.2 and every "数据类型" row).
//!
//! Kinds follow the real controller: atomic value types, ALIAS value types, RECORD value
//! types, non-value (opaque) types and the semi-value signal types. `switch` and `anytype`
//! are not declared here (the checker handles them). Record components are in ABB's order.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // ---- Atomic value types -------------------------------------------------------------
    atomic("num", "Numeric value held as a single-precision float; integers are exact up to 2^23."),
    atomic("dnum", "Numeric value held as a double-precision float; integers are exact up to 2^52."),
    atomic("bool", "Logical value, TRUE or FALSE."),
    atomic("string", "Character string of at most 80 Latin-1 characters."),

    // ---- Alias value types (base num) ---------------------------------------------------
    type_decl("ALIAS num byte;", "Integer 0..255, used by the bit functions and byte arrays."),
    type_decl("ALIAS num dionum;", "Digital signal value: 0 or 1 (constants low, high; edge for triggers)."),
    type_decl("ALIAS num errnum;", "Number of a recoverable error, as found in ERRNO."),
    type_decl("ALIAS num intnum;", "Identity of an interrupt, tied to a trap routine by CONNECT."),
    type_decl("ALIAS num errdomain;", "Event-log domain of an error (COMMON_ERR, MOTION_ERR, ...)."),
    type_decl("ALIAS num errtype;", "Severity of an event-log entry (TYPE_ALL, TYPE_STATE, TYPE_WARN, TYPE_ERR)."),
    type_decl("ALIAS num tpnum;", "Symbolic number of a FlexPendant window, used by TPShow."),
    type_decl("ALIAS num opnum;", "Comparison operator passed as an argument (LT, LTEQ, EQ, NOTEQ, GTEQ, GT)."),
    type_decl("ALIAS num opcalc;", "Arithmetic operator passed to StrDigCalc (OpAdd, OpSub, OpMult, OpDiv, OpMod)."),
    type_decl("ALIAS num symnum;", "Integer with a symbolic name, e.g. the results of OpMode and RunMode."),
    type_decl("ALIAS num socketstatus;", "State of a socket as returned by SocketGetStatus."),
    type_decl("ALIAS num iounit_state;", "State of an I/O device as returned by IOUnitState."),
    type_decl("ALIAS num busstate;", "State of an I/O network as returned by IOBusState."),
    type_decl("ALIAS num aiotrigg;", "Condition for an analog signal interrupt (AIO_ABOVE_HIGH, AIO_BETWEEN, ...)."),
    type_decl("ALIAS num btnres;", "Which push button the operator chose in a UI dialog (resOK, resYes, ...)."),
    type_decl("ALIAS num buttondata;", "Standard set of push buttons for a UI dialog (btnOK, btnYesNo, ...)."),
    type_decl("ALIAS num icondata;", "Standard icon shown in a UI dialog (iconInfo, iconWarning, ...)."),
    type_decl("ALIAS num triggmode;", "Action mode for a trigger definition (TRIGG_MODE1..TRIGG_MODE3)."),
    type_decl("ALIAS num tunetype;", "Kind of servo tuning for TuneServo (TUNE_DF, TUNE_KP, ...)."),
    type_decl("ALIAS num stoppoint;", "Kind of stop point in stoppointdata (inpos, stoptime, fllwtime)."),
    type_decl("ALIAS num event_type;", "Kind of event routine now running, as returned by EventType."),
    type_decl("ALIAS num exec_level;", "Execution level of the running code, as returned by ExecLevel."),
    type_decl("ALIAS num handler_type;", "Kind of handler the code runs in, as returned by ExecHandler."),
    type_decl("ALIAS num paridnum;", "Kind of parameter identification for LoadId and related routines."),
    type_decl("ALIAS num paridvalidnum;", "Result of ParIdRobValid: whether the robot type supports identification."),
    type_decl("ALIAS num loadidnum;", "Load identification variant (MASS_KNOWN, MASS_WITH_AX3)."),
    // uncertain: ABB documents identno as an integer-valued type; we treat it as an alias of num.
    type_decl("ALIAS num identno;", "Identity number that pairs synchronized move instructions in MultiMove."),
    type_decl("ALIAS num inttypes;", "Integer layout for (Un)PackRawBytes \\IntX (USINT, UINT, ..., LINT)."),
    type_decl("ALIAS num signalorigin;", "Where a signal comes from, as returned by GetSignalOrigin."),
    type_decl("ALIAS num tsp_status;", "Task Selection Panel state of a task, as returned by GetTSPStatus."),
    // uncertain: testsignal is documented as a symbolic integer; alias of num assumed.
    type_decl("ALIAS num testsignal;", "Number or name of a motion-system test signal for TestSignDefine."),
    type_decl("ALIAS num uishownum;", "Instance token of a view started with UIShow."),
    type_decl("ALIAS num motionprocessmode;", "Motion process mode for MotionProcessModeSet."),

    // ---- Alias value types (base string) ------------------------------------------------
    type_decl("ALIAS string errstr;", "Text argument of an error or event-log message."),
    type_decl("ALIAS string stringdig;", "String holding only digits: a big non-negative integer."),
    // uncertain: cfgdomain is documented as a symbolic domain name; alias of string assumed.
    type_decl("ALIAS string cfgdomain;", "System-parameter domain for SaveCfgData (EIO_DOMAIN, MOC_DOMAIN, ...)."),

    // ---- Basic geometry records ---------------------------------------------------------
    type_decl("RECORD pos num x; num y; num z; ENDRECORD", "Position or vector in mm: x, y, z."),
    type_decl("RECORD orient num q1; num q2; num q3; num q4; ENDRECORD", "Orientation as a unit quaternion; q1 is the scalar part."),
    type_decl("RECORD pose pos trans; orient rot; ENDRECORD", "Coordinate frame: a translation plus a rotation."),
    type_decl("RECORD confdata num cf1; num cf4; num cf6; num cfx; ENDRECORD", "Robot axis configuration: quadrants of axes 1, 4, 6 and the arm case cfx."),
    type_decl("RECORD extjoint num eax_a; num eax_b; num eax_c; num eax_d; num eax_e; num eax_f; ENDRECORD", "Positions of six external axes in mm or degrees; 9E9 marks an unused axis."),
    type_decl("RECORD robjoint num rax_1; num rax_2; num rax_3; num rax_4; num rax_5; num rax_6; ENDRECORD", "Robot axis angles in degrees from the calibration position."),
    type_decl("RECORD robtarget pos trans; orient rot; confdata robconf; extjoint extax; ENDRECORD", "Cartesian target: TCP position, tool orientation, configuration, external axes."),
    type_decl("RECORD jointtarget robjoint robax; extjoint extax; ENDRECORD", "Target given as robot and external axis positions."),

    // ---- Motion data records ------------------------------------------------------------
    type_decl("RECORD speeddata num v_tcp; num v_ori; num v_leax; num v_reax; ENDRECORD", "Speeds: TCP mm/s, reorientation deg/s, linear and rotating external axes."),
    type_decl("RECORD zonedata bool finep; num pzone_tcp; num pzone_ori; num pzone_eax; num zone_ori; num zone_leax; num zone_reax; ENDRECORD", "Corner zone sizes for fly-by points; finep TRUE makes a stop point."),
    type_decl("RECORD loaddata num mass; pos cog; orient aom; num ix; num iy; num iz; ENDRECORD", "Payload: mass kg, centre of gravity, inertia axes and moments of inertia."),
    type_decl("RECORD tooldata bool robhold; pose tframe; loaddata tload; ENDRECORD", "Tool: whether the robot holds it, its TCP frame and its load."),
    type_decl("RECORD wobjdata bool robhold; bool ufprog; string ufmec; pose uframe; pose oframe; ENDRECORD", "Work object: holder, fixed or moving user frame, coordinating unit, user and object frames."),
    type_decl("RECORD inposdata num position; num speed; num mintime; num maxtime; ENDRECORD", "Convergence criteria of an in-position stop point."),
    // uncertain: the first component is written `type` in ABB's manual; a clone names it `stype`.
    type_decl("RECORD stoppointdata stoppoint type; bool progsynch; inposdata inpos; num stoptime; num followtime; string signal; opnum relation; num checkvalue; ENDRECORD", "How a stop point ends: kind, program sync, in-position, stop or follow time."),
    type_decl("RECORD progdisp pose pdisp; extjoint eoffs; ENDRECORD", "Active program displacement and external axis offsets."),
    type_decl("RECORD veldata num oride; num max; ENDRECORD", "Velocity part of motsetdata: override percent and TCP speed limit."),
    type_decl("RECORD accdata num acc; num ramp; num finepramp; ENDRECORD", "Acceleration part of motsetdata, as set by AccSet."),
    type_decl("RECORD singdata bool wrist; bool lockaxis4; bool arm; bool base; ENDRECORD", "Singularity handling part of motsetdata, as set by SingArea."),
    type_decl("RECORD confsupdata bool jsup; bool lsup; num ax1; num ax4; num ax6; ENDRECORD", "Configuration supervision part of motsetdata, as set by ConfJ and ConfL."),
    // uncertain: component list taken from a public clone of the RW6 layout; later RW6 releases may add more.
    type_decl("RECORD motsetdata veldata vel; accdata acc; singdata sing; confsupdata conf; num pathresol; bool motionsup; num tunevalue; bool acclim; num accmax; bool decellim; num decelmax; num cirpathreori; bool worldacclim; num worldaccmax; bool evtbufferact; ENDRECORD", "All current motion settings except displacement; read through C_MOTSET."),
    type_decl("RECORD restartdata bool restartstop; bool stoponpath; dionum predo1val; dionum postdo1val; num prego1val; num postgo1val; num prego2val; num postgo2val; num prego3val; num postgo3val; num prego4val; num postgo4val; dionum preshadowval; dionum shadowflanks; dionum postshadowval; ENDRECORD", "Process signal values before and after a stop, filled by TriggStopProc."),
    type_decl("RECORD triggios bool used; num distance; bool start; num equiplag; string signalname; num setvalue; num xxx; ENDRECORD", "One I/O trigger for TriggJIOs and TriggLIOs with a num value."),
    type_decl("RECORD triggstrgo bool used; num distance; bool start; num equiplag; string signalname; stringdig setvalue; num xxx; ENDRECORD", "One group-output trigger for TriggJIOs and TriggLIOs with a digit-string value."),
    type_decl("RECORD triggiosdnum bool used; num distance; bool start; num equiplag; string signalname; dnum setvalue; num xxx; ENDRECORD", "One I/O trigger for TriggJIOs and TriggLIOs with a dnum value."),
    type_decl("RECORD wztemporary num wz; ENDRECORD", "Identity of a temporary world zone."),
    type_decl("RECORD wzstationary num wz; ENDRECORD", "Identity of a stationary world zone, defined at power-on."),

    // ---- Other value records ------------------------------------------------------------
    type_decl("RECORD listitem string image; string text; ENDRECORD", "One menu line for UIListView: icon path and text."),
    type_decl("RECORD rmqheader string datatype; num ndim; num dim1; num dim2; num dim3; ENDRECORD", "Describes the data inside an RMQ message: type name and array shape."),
    type_decl("RECORD tasks string taskname; ENDRECORD", "Name of a program task; arrays of it list tasks to synchronize."),

    // ---- Non-value (opaque) types -------------------------------------------------------
    non_value("clock", "Stopwatch for timing, in seconds."),
    non_value("iodev", "Reference to an open file or serial channel."),
    non_value("rawbytes", "Container of up to 1024 raw bytes for binary I/O."),
    non_value("socketdev", "Reference to a network socket."),
    non_value("trapdata", "Information about the interrupt that started the current trap routine."),
    non_value("triggdata", "A defined trigger condition and action for the Trigg move instructions."),
    non_value("dir", "Reference to an open directory, used to walk a directory."),
    non_value("loadsession", "Reference to a module load started with StartLoad."),
    non_value("mecunit", "Reference to a mechanical unit (robot or external axes)."),
    non_value("taskid", "Reference to a program task."),
    non_value("syncident", "Name of a synchronization point shared by several tasks."),
    non_value("pathrecid", "Marker on the path recorded by the path recorder."),
    non_value("corrdescr", "Descriptor of a connected path correction generator."),
    non_value("shapedata", "Geometry of a world zone."),
    non_value("rmqslot", "Identity of a RAPID message queue client or task."),
    non_value("rmqmessage", "Container holding one received RAPID message queue message."),
    non_value("datapos", "Enclosing block of a data object found by GetNextSym."),
    // uncertain: indcnvdata (Indexing conveyor option) is really a record whose components we could not find.
    non_value("indcnvdata", "Settings of the indexing conveyor function."),

    // ---- Semi-value signal types --------------------------------------------------------
    semi_value("signalai num", "Analog input signal; reads as its current value."),
    semi_value("signalao num", "Analog output signal; reads as its current value."),
    semi_value("signaldi dionum", "Digital input signal; reads as 0 or 1."),
    semi_value("signaldo dionum", "Digital output signal; reads as 0 or 1."),
    semi_value("signalgi num", "Group of digital inputs; reads as an integer."),
    semi_value("signalgo num", "Group of digital outputs; reads as an integer."),
];
