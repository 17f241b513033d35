//! Catalogue chapter: flow, various, error recovery, pendant/UI, RAPID support, calibration and
//! multitasking routines (manual §1.5, §1.6, §1.10 pendant part, §1.12, §1.17, §1.18, §1.20).

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- §1.5 Program flow (routines, not keywords) ----------------------------------------------
    routine(
        r#"PROC CallByVar(string Name, num Number)"#,
        "Calls the procedure whose name is Name followed by the digits of Number.",
    ),
    routine(
        r#"PROC Stop(\switch NoRegain | switch AllMoveTasks)"#,
        "Stops program execution; a restart continues with the next instruction.",
    ),
    routine(
        r#"PROC Break()"#,
        "Halts execution at once for debugging (the 6.15 overview also lists it as a loop exit).",
    ),
    // uncertain: listed only in the RW 6.15 overview (§1.5) as a loop control; no signature found.
    routine(r#"PROC Continue()"#, "Skips the rest of the current loop pass and starts the next one."),
    routine(r#"PROC ExitCycle()"#, "Ends the current cycle and moves the program pointer to the start of main."),
    routine(
        r#"PROC SystemStopAction(\switch Stop | switch StopBlock | switch Halt)"#,
        "Stops program and robot motion in all motion tasks, more or less severely.",
    ),
    // --- §1.6 Waiting -------------------------------------------------------------------------------
    routine(
        r#"PROC WaitTime(\switch InPos, num Time)"#,
        "Waits the given number of seconds, optionally after the robot has stopped.",
    ),
    routine(
        r#"PROC WaitUntil(\switch InPos, bool Cond \num MaxTime \VAR bool TimeFlag \num PollRate \switch Visualize \string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon \string Image \num VisualizeTime \signaldo UIActiveSignal)"#,
        "Waits until a condition is TRUE, polling it, with an optional time limit.",
    ),
    // --- §1.6 Loading and saving program modules ----------------------------------------------------
    routine(
        r#"PROC Load(\switch Dynamic, string FilePath \string File \switch CheckRef)"#,
        "Loads a program module into program memory during execution.",
    ),
    routine(
        r#"PROC UnLoad(\switch ErrIfChanged | switch Save, string FilePath \string File)"#,
        "Removes a module loaded with Load or StartLoad from program memory.",
    ),
    routine(
        r#"PROC StartLoad(\switch Dynamic, string FilePath \string File, VAR loadsession LoadNo)"#,
        "Starts loading a program module in the background.",
    ),
    routine(
        r#"PROC WaitLoad(\string UnloadPath \string UnloadFile, VAR loadsession LoadNo \switch CheckRef)"#,
        "Waits for a StartLoad to finish and links the loaded module into the task.",
    ),
    routine(r#"PROC CancelLoad(VAR loadsession LoadNo)"#, "Cancels a module load begun with StartLoad."),
    routine(r#"PROC CheckProgRef()"#, "Checks the task's program for unresolved references."),
    routine(
        r#"PROC Save(\taskid TaskRef | string TaskName, string ModuleName \string FilePath \string File)"#,
        "Saves a program module to a file.",
    ),
    routine(r#"PROC EraseModule(string ModuleName)"#, "Removes a module from program memory during execution."),
    // --- §1.6 Various functions -------------------------------------------------------------------------
    routine(
        r#"PROC TryInt(num DataObj | dnum DataObj2)"#,
        "Raises an error unless the given num or dnum holds a valid integer.",
    ),
    routine(
        r#"FUNC symnum OpMode()"#,
        "Returns the controller's current operating mode (auto, manual reduced, manual full).",
    ),
    routine(
        r#"FUNC symnum RunMode(\switch Main)"#,
        "Returns the task's current running mode (continuous, cycle, step...).",
    ),
    routine(r#"FUNC bool NonMotionMode(\switch Main)"#, "Tells whether the task runs in non-motion execution mode."),
    routine(
        r#"FUNC num Dim(anytype ArrPar{*}, num DimNo)"#,
        "Returns the number of elements of an array in dimension DimNo (1-3).",
    ),
    routine(
        r#"FUNC bool Present(anytype OptPar)"#,
        "Tells whether an optional parameter was given an argument in the call.",
    ),
    routine(
        r#"FUNC string Type(anytype Data \switch BaseName)"#,
        "Returns the data type name of a data object (its base type with BaseName).",
    ),
    routine(r#"FUNC bool IsPers(INOUT anytype DatObj)"#, "Tells whether an INOUT parameter refers to a persistent."),
    routine(r#"FUNC bool IsVar(INOUT anytype DatObj)"#, "Tells whether an INOUT parameter refers to a variable."),
    // --- §1.10 FlexPendant TP functions --------------------------------------------------------------------
    routine(r#"PROC TPErase()"#, "Clears the operator window of the FlexPendant."),
    routine(
        r#"PROC TPWrite(string TPText \num Num | bool Bool | pos Pos | orient Orient | dnum Dnum)"#,
        "Writes a text, optionally followed by a value, on the FlexPendant.",
    ),
    routine(
        r#"PROC ErrWrite(\switch W | switch I, string Header, string Reason \string RL2 \string RL3 \string RL4)"#,
        "Writes a user error, warning or information message to the event log.",
    ),
    routine(
        r#"PROC TPReadFK(INOUT num TPAnswer, string TPText, string TPFK1, string TPFK2, string TPFK3, string TPFK4, string TPFK5 \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag)"#,
        "Shows texts on the function keys and returns which key (1-5) was pressed.",
    ),
    routine(
        r#"PROC TPReadNum(INOUT num TPAnswer, string TPText \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag)"#,
        "Asks the operator for a num on the FlexPendant.",
    ),
    routine(
        r#"PROC TPReadDnum(INOUT dnum TPAnswer, string TPText \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag)"#,
        "Asks the operator for a dnum on the FlexPendant.",
    ),
    routine(r#"PROC TPShow(tpnum Window)"#, "Brings the given FlexPendant window to the front."),
    // --- §1.10 FlexPendant UI functions ----------------------------------------------------------------------
    routine(
        r#"PROC UIMsgBox(\string Header, string MsgLine1 \string MsgLine2 \string MsgLine3 \string MsgLine4 \string MsgLine5 \switch Wrap \buttondata Buttons \icondata Icon \string Image \INOUT btnres Result \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Shows a message box with up to five lines and standard buttons.",
    ),
    routine(
        r#"FUNC btnres UIMessageBox(\string Header \string Message | string MsgArray{*} \switch Wrap \buttondata Buttons | string BtnArray{*} \btnres DefaultBtn \icondata Icon \string Image \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Shows a message box with standard or own buttons and returns the one chosen.",
    ),
    routine(
        r#"FUNC num UINumEntry(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon \num InitValue \num MinValue \num MaxValue \switch AsInteger \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Lets the operator enter a num on a number pad and returns it.",
    ),
    routine(
        r#"FUNC dnum UIDnumEntry(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon \dnum InitValue \dnum MinValue \dnum MaxValue \switch AsInteger \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Lets the operator enter a dnum on a number pad and returns it.",
    ),
    routine(
        r#"FUNC num UINumTune(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon, num InitValue, num Increment \num MinValue \num MaxValue \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Lets the operator step a num up or down by Increment and returns the result.",
    ),
    routine(
        r#"FUNC dnum UIDnumTune(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon, dnum InitValue, dnum Increment \dnum MinValue \dnum MaxValue \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Lets the operator step a dnum up or down by Increment and returns the result.",
    ),
    routine(
        r#"FUNC string UIAlphaEntry(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon \string InitString \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Lets the operator type a string on a keyboard and returns it.",
    ),
    routine(
        r#"FUNC num UIListView(\INOUT btnres Result \string Header, listitem ListItems{*} \buttondata Buttons | string BtnArray{*} \icondata Icon \num DefaultIndex \num MaxTime \signaldi DIBreak \switch DIPassive \signaldo DOBreak \switch DOPassive \PERS bool PersBoolBreak \switch PersBoolPassive \VAR errnum BreakFlag \signaldo UIActiveSignal)"#,
        "Shows a list menu and returns the index of the item the operator picked.",
    ),
    routine(r#"FUNC bool UIClientExist()"#, "Tells whether a user device such as the FlexPendant is connected."),
    routine(
        r#"PROC UIMsgWrite(\string Header \string Message | string MsgArray{*} \switch Wrap \icondata Icon \string Image \PERS bool PersBool | string PersBoolName \bool AbortValue \signaldo UIActiveSignal)"#,
        "Shows a message box without buttons and continues at once.",
    ),
    routine(r#"PROC UIMsgWriteAbort()"#, "Removes a message box shown by UIMsgWrite."),
    routine(
        r#"PROC UIShow(string AssemblyName, string TypeName \string InitCmd \INOUT uishownum InstanceId \VAR num Status \switch NoCloseBtn)"#,
        "Opens a custom FlexPendant view from the given assembly and type.",
    ),
    // --- §1.12 Error recovery ---------------------------------------------------------------------------------
    routine(
        r#"PROC BookErrNo(VAR errnum ErrorName)"#,
        "Books a new, unused system error number into an errnum variable.",
    ),
    routine(
        r#"PROC RaiseToUser(\switch Continue | switch BreakOff \errnum ErrorNumber)"#,
        "From a NOSTEPIN routine, passes the error on to the handler at user level.",
    ),
    routine(r#"PROC SkipWarn()"#, "Keeps the latest warning out of the event log."),
    routine(r#"PROC ResetRetryCount()"#, "Resets the count of RETRY attempts made from the error handler."),
    routine(r#"FUNC num RemainingRetries()"#, "Returns how many RETRY attempts are left before the limit."),
    routine(
        r#"PROC ErrLog(num ErrorId \switch W | switch I, errstr Argument1, errstr Argument2, errstr Argument3, errstr Argument4, errstr Argument5)"#,
        "Writes a user message with five arguments to the event log and FlexPendant.",
    ),
    routine(
        r#"PROC ErrRaise(string ErrorName, num ErrorId, errstr Argument1, errstr Argument2, errstr Argument3, errstr Argument4, errstr Argument5)"#,
        "Raises a booked error with an event-log message and calls the error handler.",
    ),
    routine(
        r#"PROC ProcerrRecovery(\switch SyncOrgMoveInst | switch SyncLastMoveInst \signaldo ProcSignal)"#,
        "Raises a process error during robot motion so an error handler can recover.",
    ),
    // --- §1.17 System data and system information -----------------------------------------------------------------
    routine(
        r#"PROC GetSysData(\taskid TaskRef | string TaskName, PERS anytype DestObject \INOUT string ObjectName)"#,
        "Copies the active system data (e.g. tool, work object) into a persistent.",
    ).names_data(),
    routine(
        r#"PROC SetSysData(PERS anytype SourceObject \string ObjectName)"#,
        "Makes the given persistent the active system data of its type.",
    ).names_data(),
    routine(r#"PROC ResetPPMoved()"#, "Clears the flag telling that the program pointer was moved in manual mode."),
    routine(r#"FUNC bool IsSysId(string SystemId)"#, "Tells whether the controller's serial number equals SystemId."),
    routine(
        r#"FUNC bool IsStopStateEvent(\switch PPMoved | switch PPToMain)"#,
        "Tells whether the program pointer was moved (or moved to main) while stopped.",
    ),
    routine(
        r#"FUNC bool PPMovedInManMode()"#,
        "Tells whether the program pointer was moved by the user in manual mode.",
    ),
    routine(r#"FUNC bool RobOS()"#, "Tells whether execution runs on a real controller rather than a virtual one."),
    // uncertain: added in RW 6.15.03; arguments modelled on GetNextMechUnit, not confirmed.
    routine(
        r#"FUNC bool GetNextOption(INOUT num ListNumber, VAR string Name)"#,
        "Steps through the installed options, returning the next option name.",
    ),
    // uncertain: arguments (and the optional version output) not confirmed.
    routine(
        r#"FUNC bool GetNextProduct(INOUT num ListNumber, VAR string Name \VAR string Version)"#,
        "Steps through the installed products, returning the next product name.",
    ),
    // uncertain: ABB's StateMachine add-in calls it; signature from the instruction list
    // of RobotWare 6 (no argument, returns the ModalPayLoadMode system parameter).
    routine(r#"FUNC num GetModalPayLoadMode()"#, "Returns the ModalPayLoadMode system parameter (1 = payload modal)."),
    routine(
        r#"FUNC string GetSysInfo(\switch SerialNo | switch SWVersion | switch SWVersionName | switch RobotType | switch CtrlId | switch LanIp | switch CtrlLang | switch SystemName)"#,
        "Returns one item of system information, such as serial number or software version.",
    ),
    routine(r#"FUNC string GetUASUserName()"#, "Returns the name of the user logged in on the FlexPendant."),
    // --- §1.17 Configuration data, restart and text tables -----------------------------------------------------------
    routine(
        r#"PROC ReadCfgData(string InstancePath, string Attribute, VAR anytype CfgData \VAR num ListNo)"#,
        "Reads one attribute of a system parameter into a variable.",
    ),
    routine(
        r#"PROC WriteCfgData(string InstancePath, string Attribute, anytype CfgData \VAR num ListNo)"#,
        "Writes one attribute of a system parameter.",
    ),
    routine(
        r#"PROC SaveCfgData(string FilePath \string File, cfgdomain Domain)"#,
        "Saves the system parameters of one configuration domain to a file.",
    ),
    routine(r#"PROC WarmStart()"#, "Restarts the controller."),
    routine(r#"PROC TextTabInstall(string File)"#, "Installs a user text table from a file."),
    routine(r#"FUNC num TextTabGet(string TableName)"#, "Returns the number of an installed user text table."),
    routine(
        r#"FUNC string TextGet(num Table, num Index \string Arg1 \string Arg2)"#,
        "Returns a text from a text table, filling in {1} and {2} placeholders.",
    ),
    routine(
        r#"FUNC bool TextTabFreeToUse(string TableName)"#,
        "Tells whether a text table name is still free (not yet installed).",
    ),
    // --- §1.17 Object names, task information, execution context ------------------------------------------------------
    routine(
        r#"FUNC string ArgName(anytype Parameter \VAR errnum ErrorNumber)"#,
        "Returns the name of the original data object behind a parameter or datum.",
    ),
    // uncertain: the extract lists no arguments; the optional number outputs are from memory.
    routine(
        r#"FUNC string GetTaskName(\VAR num TaskNo | VAR num MecTaskNo)"#,
        "Returns the name of the current (or connected motion) task, optionally its number.",
    ),
    routine(r#"FUNC num MotionPlannerNo()"#, "Returns the number of the motion planner connected to the task."),
    // note: the Chinese overview spells this TasksExecuting.
    routine(
        r#"FUNC bool TaskIsExecuting(taskid TaskRef | string TaskName)"#,
        "Tells whether the given program task is executing.",
    ).names_data(),
    // note: the Chinese overview spells this TasksActive.
    routine(
        r#"FUNC bool TaskIsActive(taskid TaskRef | string TaskName)"#,
        "Tells whether a normal task is selected in the Task Selection Panel.",
    ).names_data(),
    routine(
        r#"FUNC tsp_status GetTSPStatus(taskid TaskRef | string TaskName)"#,
        "Returns the Task Selection Panel status of a task.",
    ).names_data(),
    routine(r#"FUNC event_type EventType()"#, "Returns the type of the event routine being executed, if any."),
    routine(
        r#"FUNC handler_type ExecHandler()"#,
        "Returns which kind of handler (error, backward, undo, none) is executing.",
    ),
    routine(r#"FUNC exec_level ExecLevel()"#, "Returns the execution level (normal, trap, user or system routine)."),
    // --- §1.17 Searching symbols -------------------------------------------------------------------------------------
    routine(
        r#"PROC SetDataSearch(string Type \string TypeMod \string Object \switch PersSym \switch VarSym \switch ConstSym \switch InTask | string InMod \string InRout \switch GlobalSym | switch LocalSym)"#,
        "Starts a search for data objects of a type, to be stepped with GetNextSym.",
    ),
    routine(
        r#"FUNC bool GetNextSym(INOUT string Object, VAR datapos Block \switch Recursive)"#,
        "Returns the next data object found by SetDataSearch; FALSE when done.",
    ),
    routine(
        r#"PROC GetDataVal(string Object \VAR datapos Block | taskid TaskRef | string TaskName, VAR anytype Value)"#,
        "Reads the value of a data object named by a string.",
    ).names_data(),
    routine(
        r#"PROC SetDataVal(string Object \VAR datapos Block | taskid TaskRef | string TaskName, anytype Value)"#,
        "Sets the value of a data object named by a string.",
    ).names_data(),
    routine(
        r#"PROC SetAllDataVal(string Type \string TypeMod \string Object \switch Hidden, anytype Value)"#,
        "Sets every data object of a type (optionally matching a name pattern) to a value.",
    ),
    // --- §1.17 Service information ---------------------------------------------------------------------------------------
    routine(
        r#"FUNC string GetServiceInfo(mecunit MechUnit \switch DutyTimeCnt)"#,
        "Returns service information, such as the duty time counter, of a mechanical unit.",
    ).names_data(),
    // --- §1.18 Calibration and service -------------------------------------------------------------------------------------
    routine(
        r#"PROC MToolRotCalib(jointtarget RefTip, jointtarget ZPos \jointtarget XPos, PERS tooldata Tool)"#,
        "Calibrates the orientation of a robot-held tool.",
    ),
    routine(
        r#"PROC MToolTCPCalib(jointtarget Pos1, jointtarget Pos2, jointtarget Pos3, jointtarget Pos4, PERS tooldata Tool, VAR num MaxErr, VAR num MeanErr)"#,
        "Calibrates the TCP of a robot-held tool from four approach positions.",
    ),
    routine(
        r#"PROC SToolRotCalib(robtarget RefTip, robtarget ZPos, robtarget XPos, PERS tooldata Tool)"#,
        "Calibrates TCP and orientation of a stationary tool.",
    ),
    routine(
        r#"PROC SToolTCPCalib(robtarget Pos1, robtarget Pos2, robtarget Pos3, robtarget Pos4, PERS tooldata Tool, VAR num MaxErr, VAR num MeanErr)"#,
        "Calibrates the TCP of a stationary tool from four approach positions.",
    ),
    routine(
        r#"FUNC pose CalcRotAxisFrame(mecunit MechUnit \num AxisNo, robtarget TargetList{*}, num TargetsInList, VAR num MaxErr, VAR num MeanErr)"#,
        "Computes the user frame of a rotational axis from taught points.",
    ).names_data(),
    routine(
        r#"FUNC pose CalcRotAxFrameZ(robtarget TargetList{*}, num TargetsInList, robtarget PositiveZPoint, VAR num MaxErr, VAR num MeanErr)"#,
        "Computes a rotational axis frame from taught points and a positive-Z point.",
    ),
    routine(
        r#"PROC TestSignDefine(num Channel, testsignal SignalId, mecunit MechUnit, num Axis, num SampleTime)"#,
        "Defines a motion-system test signal on a channel (1-12).",
    ).names_data(),
    routine(r#"PROC TestSignReset()"#, "Removes all test signal definitions."),
    routine(r#"FUNC num TestSignRead(num Channel)"#, "Returns the current value of the test signal on a channel."),
    routine(r#"PROC SpyStart(string File)"#, "Starts logging instruction and timing data to a file."),
    routine(r#"PROC SpyStop()"#, "Stops the logging begun with SpyStart."),
    // --- §1.20 Multitasking ------------------------------------------------------------------------------------------------
    routine(
        r#"PROC WaitSyncTask(\switch InPos, VAR syncident SyncID, PERS tasks TaskList{*} \num TimeOut)"#,
        "Waits until all listed tasks reach the same synchronisation point.",
    ).names_data(),
    routine(
        r#"FUNC bool TestAndSet(INOUT bool Object)"#,
        "Takes a bool semaphore if it is free (returns TRUE), else returns FALSE.",
    ),
    routine(r#"PROC WaitTestAndSet(INOUT bool Object)"#, "Waits until a bool semaphore is free and then takes it."),
    routine(r#"FUNC bool TaskRunMec()"#, "Tells whether the task controls any mechanical unit."),
    routine(r#"FUNC bool TaskRunRob()"#, "Tells whether the task controls a robot with a TCP."),
    routine(r#"FUNC string GetMecUnitName(mecunit MechUnit)"#, "Returns the configured name of a mechanical unit.").names_data(),
    routine(
        r#"PROC SyncMoveOn(VAR syncident SyncID, PERS tasks TaskList{*} \num TimeOut)"#,
        "Starts synchronized movement with the listed motion tasks.",
    ).names_data(),
    routine(r#"PROC SyncMoveOff(VAR syncident SyncID \num TimeOut)"#, "Ends synchronized movement at a meeting point.").names_data(),
    routine(r#"PROC SyncMoveUndo()"#, "Forces a return from synchronized to independent movement."),
    routine(r#"FUNC bool IsSyncMoveOn()"#, "Tells whether the motion task is in synchronized movement mode."),
    routine(
        r#"FUNC num TasksInSync(INOUT tasks TaskList{*})"#,
        "Returns how many tasks are synchronized and lists their names.",
    ),
    // --- Cyclic bool (RAPID support, not in the chapter-1 tables) ----------------------------------------------------
    routine(
        r#"PROC SetupCyclicBool(PERS bool Flag, bool Cond \signaldo Signal)"#,
        "Has a logical condition evaluated cyclically into a persistent bool.",
    ),
    routine(r#"PROC RemoveCyclicBool(PERS bool Flag | string Name)"#, "Stops cyclic evaluation of one cyclic bool."),
    routine(
        r#"PROC RemoveAllCyclicBool(\switch AllTasks)"#,
        "Stops cyclic evaluation of all cyclic bools of the task (or of all tasks).",
    ),
    routine(
        r#"FUNC bool IsCyclicBool(PERS bool Flag | string Name \taskid TaskRef | string TaskName)"#,
        "Tells whether a persistent bool is set up as a cyclic bool.",
    ),
    routine(
        r#"FUNC bool GetNextCyclicBool(INOUT num ListNumber, VAR string Name)"#,
        "Steps through the cyclic bools, returning the next name.",
    ),
    routine(r#"FUNC num GetNumberOfCyclicBool()"#, "Returns how many cyclic bool conditions are set up."),
    routine(r#"FUNC num GetMaxNumberOfCyclicBool()"#, "Returns how many cyclic bool conditions may exist at once."),
];
