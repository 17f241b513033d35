//! Catalogue chapter: motion settings and motion (manual §1.7 "运动设置" and §1.8 "运动").
//!
//! Includes the position functions of §1.8 (CRobT, Offs, RelTool, CalcJointT, ...). Tool,
//! work object and total load arguments are persistents, as ABB requires; mechanical units,
//! task references and other non-value arguments are passed as VAR.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // ==== §1.7 Motion settings =============================================================
    routine("FUNC num MaxRobSpeed()", "Returns the highest TCP speed, in mm/s, of the robot type in this task."),
    routine("FUNC num MaxRobReorientSpeed()", "Returns the highest TCP reorientation speed, in deg/s, of the robot."),
    routine("FUNC num MaxExtLinearSpeed()", "Returns the highest speed, in mm/s, of the linear external axes in this task."),
    routine("FUNC num MaxExtReorientSpeed()", "Returns the highest speed, in deg/s, of the rotating external axes in this task."),
    routine("PROC VelSet(num Override, num Max)", "Scales programmed speeds by Override percent and caps the TCP speed at Max mm/s."),
    routine("PROC SpeedRefresh(num Override)", "Changes the speed override of the ongoing movement, 0..100 percent."),
    routine("PROC SpeedLimAxis(VAR mecunit MechUnit, num AxisNo, num AxisSpeed)", "Sets a speed limit for one axis, applied when the limiting system input is set.").names_data(),
    routine("PROC SpeedLimCheckPoint(num RobSpeed)", "Sets a speed limit for the robot check points, applied by a system input."),
    routine(r#"PROC AccSet(num Acc, num Ramp, \num FinePointRamp)"#, "Limits acceleration and its rate of change to percentages of normal."),
    routine(r#"PROC WorldAccLim(\num On | switch Off)"#, "Limits tool acceleration in the world frame to On m/s2, or removes the limit."),
    routine(r#"PROC PathAccLim(bool AccLim, \num AccMax, bool DecelLim, \num DecelMax)"#, "Sets or clears limits on TCP acceleration and deceleration along the path."),
    routine(r#"PROC ConfJ(\switch On | switch Off)"#, "Turns configuration control of joint moves on (default) or off."),
    routine(r#"PROC ConfL(\switch On | switch Off)"#, "Turns configuration monitoring of linear and circular moves on (default) or off."),
    routine("PROC GripLoad(PERS loaddata Load)", "Declares the payload now held in the gripper.").names_data(),
    routine(r#"PROC SingArea(\switch Wrist | switch LockAxis4 | switch Off)"#, "Chooses how the robot passes near singular points."),
    routine("PROC ActEventBuffer()", "Activates the configured event buffer for this motion task."),
    routine("PROC DeactEventBuffer()", "Deactivates the event buffer for this motion task."),
    routine("PROC CornerPathWarning(bool Active)", "Turns corner path failure warnings on or off for the following moves."),
    routine("PROC MotionProcessModeSet(motionprocessmode Mode)", "Selects the motion process mode (cycle time versus accuracy) for the robot."),

    // ---- Program displacement and external axis offsets ---------------------------------
    routine(r#"PROC PDispOn(\switch Rot, \robtarget ExeP, robtarget ProgPoint, PERS tooldata Tool, \PERS wobjdata WObj)"#, "Turns on program displacement from the difference between two positions."),
    routine("PROC PDispSet(pose DispFrame)", "Turns on program displacement with a given frame."),
    routine("PROC PDispOff()", "Turns program displacement off."),
    routine(r#"PROC EOffsOn(\robtarget ExeP, robtarget ProgPoint)"#, "Turns on external axis offsets from the difference between two positions."),
    routine("PROC EOffsSet(extjoint EAxOffs)", "Turns on external axis offsets with given values."),
    routine("PROC EOffsOff()", "Turns external axis offsets off."),
    routine("FUNC pose DefDFrame(robtarget OldP1, robtarget OldP2, robtarget OldP3, robtarget NewP1, robtarget NewP2, robtarget NewP3)", "Computes a displacement frame from three original and three moved positions."),
    routine(r#"FUNC pose DefFrame(robtarget NewP1, robtarget NewP2, robtarget NewP3, \num Origin)"#, "Computes a frame from three points: origin, x direction and xy plane."),
    routine("FUNC pose DefAccFrame(robtarget TargetListOne{*}, robtarget TargetListTwo{*}, num TargetsInList, VAR num MaxErr, VAR num MeanErr)", "Fits a frame to 3..10 pairs of original and moved positions; reports the errors."),
    routine(r#"FUNC robtarget ORobT(robtarget OrgPoint, \switch InPDisp | switch InEOffs)"#, "Removes program displacement and/or external axis offsets from a position."),

    // ---- Soft servo and tuning ----------------------------------------------------------
    routine(r#"PROC SoftAct(\VAR mecunit MechUnit, num Axis, num Softness, \num Ramp)"#, "Makes one axis compliant (soft servo), Softness 0..100 percent.").names_data(),
    routine(r#"PROC SoftDeact(\num Ramp)"#, "Turns soft servo off for all axes."),
    routine(r#"PROC TuneServo(VAR mecunit MecUnit, num Axis, num TuneValue, \tunetype Type)"#, "Tunes one servo parameter of an axis, in percent of normal.").names_data(),
    routine("PROC TuneReset()", "Resets all servo tuning to normal."),
    routine("PROC PathResol(num PathSampleTime)", "Changes the geometric path sample time, in percent of the configured value."),
    routine(r#"PROC CirPathMode(\switch PathFrame | switch ObjectFrame | switch CirPointOri | switch Wrist45 | switch Wrist46 | switch Wrist56)"#, "Chooses how the tool is reoriented during circular moves."),

    // ---- World zones --------------------------------------------------------------------
    // uncertain: a public extract lists LowPoint before Shape; the other WZ*Def put Shape first, as here.
    routine(r#"PROC WZBoxDef(\switch Inside | switch Outside, VAR shapedata Shape, pos LowPoint, pos HighPoint)"#, "Defines a box-shaped world zone with sides parallel to the world axes."),
    routine(r#"PROC WZCylDef(\switch Inside | switch Outside, VAR shapedata Shape, pos CentrePoint, num Radius, num Height)"#, "Defines a cylinder-shaped world zone along the world z axis."),
    routine(r#"PROC WZSphDef(\switch Inside | switch Outside, VAR shapedata Shape, pos CentrePoint, num Radius)"#, "Defines a sphere-shaped world zone."),
    routine(r#"PROC WZHomeJointDef(\switch Inside | switch Outside, VAR shapedata Shape, jointtarget MiddleJointVal, jointtarget DeltaJointVal)"#, "Defines a world zone in joint space around a home position."),
    routine(r#"PROC WZLimJointDef(\switch Inside | switch Outside, VAR shapedata Shape, jointtarget LowJointVal, jointtarget HighJointVal)"#, "Defines a joint-space world zone that limits the working range."),
    // uncertain: WorldZone is wztemporary with \Temp and wzstationary with \Stat; anytype used.
    routine(r#"PROC WZLimSup(\switch Temp | switch Stat, INOUT anytype WorldZone, VAR shapedata Shape)"#, "Activates a world zone that stops the robot before it enters the zone."),
    // uncertain: WorldZone typed as anytype for the same reason as WZLimSup.
    routine(r#"PROC WZDOSet(\switch Temp | switch Stat, INOUT anytype WorldZone, \switch Inside | switch Before, VAR shapedata Shape, signaldo Signal, dionum SetValue)"#, "Activates a world zone that sets a digital output when the TCP is in or near it."),
    routine("PROC WZDisable(INOUT wztemporary WorldZone)", "Suspends supervision of a temporary world zone."),
    routine("PROC WZEnable(INOUT wztemporary WorldZone)", "Resumes supervision of a temporary world zone."),
    routine("PROC WZFree(INOUT wztemporary WorldZone)", "Removes a temporary world zone."),

    // ---- Miscellaneous motion settings --------------------------------------------------
    routine(r#"PROC WaitRob(\switch InPos | switch ZeroSpeed)"#, "Waits until the robot and external axes are in position or at zero speed."),

    // ==== §1.8 Motion ======================================================================
    // ---- Positioning instructions -------------------------------------------------------
    routine(r#"PROC MoveC(\switch Conc, robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num V | num T, zonedata Zone, \num Z, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Moves the TCP along a circle through CirPoint to ToPoint.").names_data(),
    routine(r#"PROC MoveJ(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num V | num T, zonedata Zone, \num Z, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#, "Moves the robot to ToPoint with all axes interpolated together (joint move).").names_data(),
    routine(r#"PROC MoveL(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num V | num T, zonedata Zone, \num Z, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Moves the TCP in a straight line to ToPoint.").names_data(),
    routine(r#"PROC MoveAbsJ(\switch Conc, jointtarget ToJointPos, \identno ID, \switch NoEOffs, speeddata Speed, \num V | num T, zonedata Zone, \num Z, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#, "Moves robot and external axes to absolute axis positions; no displacement applies.").names_data(),
    routine(r#"PROC MoveExtJ(\switch Conc, jointtarget ToJointPos, \identno ID, \switch UseEOffs, speeddata Speed, \num T, zonedata Zone, \stoppointdata Inpos)"#, "Moves only external axes, without a TCP, to absolute positions."),
    routine(r#"PROC MoveCAO(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalao Signal, num Value, \PERS loaddata TLoad)"#, "Circular move that sets an analog output at the middle of the corner path."),
    routine(r#"PROC MoveCDO(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signaldo Signal, dionum Value, \PERS loaddata TLoad)"#, "Circular move that sets a digital output at the middle of the corner path."),
    routine(r#"PROC MoveCGO(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalgo Signal, \num Value | dnum Dvalue, \PERS loaddata TLoad)"#, "Circular move that sets a group output at the middle of the corner path."),
    routine(r#"PROC MoveJAO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalao Signal, num Value, \PERS loaddata TLoad)"#, "Joint move that sets an analog output at the middle of the corner path."),
    routine(r#"PROC MoveJDO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signaldo Signal, dionum Value, \PERS loaddata TLoad)"#, "Joint move that sets a digital output at the middle of the corner path."),
    routine(r#"PROC MoveJGO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalgo Signal, \num Value | dnum Dvalue, \PERS loaddata TLoad)"#, "Joint move that sets a group output at the middle of the corner path."),
    routine(r#"PROC MoveLAO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalao Signal, num Value, \PERS loaddata TLoad)"#, "Linear move that sets an analog output at the middle of the corner path."),
    routine(r#"PROC MoveLDO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signaldo Signal, dionum Value, \PERS loaddata TLoad)"#, "Linear move that sets a digital output at the middle of the corner path."),
    routine(r#"PROC MoveLGO(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, signalgo Signal, \num Value | dnum Dvalue, \PERS loaddata TLoad)"#, "Linear move that sets a group output at the middle of the corner path."),
    routine(r#"PROC MoveCSync(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, string ProcName, \PERS loaddata TLoad)"#, "Circular move that runs a named procedure at the middle of the corner path."),
    routine(r#"PROC MoveJSync(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, string ProcName, \PERS loaddata TLoad)"#, "Joint move that runs a named procedure at the middle of the corner path."),
    routine(r#"PROC MoveLSync(robtarget ToPoint, \identno ID, speeddata Speed, \num T, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, string ProcName, \PERS loaddata TLoad)"#, "Linear move that runs a named procedure at the middle of the corner path."),

    // ---- Search -------------------------------------------------------------------------
    routine(r#"PROC SearchC(\switch Stop | switch PStop | switch SStop | switch Sup, signaldi Signal | PERS bool PersBool, \switch Flanks | switch PosFlank | switch NegFlank | switch HighLevel | switch LowLevel, INOUT robtarget SearchPoint, robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num V | num T, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Circular move that records the position where a signal or persistent changes."),
    routine(r#"PROC SearchL(\switch Stop | switch PStop | switch SStop | switch Sup, signaldi Signal | PERS bool PersBool, \switch Flanks | switch PosFlank | switch NegFlank | switch HighLevel | switch LowLevel, INOUT robtarget SearchPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num V | num T, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Linear move that records the position where a signal or persistent changes."),
    routine(r#"PROC SearchExtJ(\switch Stop | switch PStop | switch SStop | switch Sup, signaldi Signal | PERS bool PersBool, \switch Flanks | switch PosFlank | switch NegFlank | switch HighLevel | switch LowLevel, INOUT jointtarget SearchJointPos, jointtarget ToJointPos, \identno ID, \switch UseEOffs, speeddata Speed, \num T)"#, "External-axis move that records the axis positions where a signal changes."),

    // ---- Actions at positions (triggers) ------------------------------------------------
    // uncertain: TriggAbsJ is missing from the public extract; arguments modelled on MoveAbsJ and TriggJ.
    routine(r#"PROC TriggAbsJ(\switch Conc, jointtarget ToJointPos, \identno ID, \switch NoEOffs, speeddata Speed, \num T, VAR triggdata Trigg_1 | VAR triggdata TriggArray{*}, \VAR triggdata T2, \VAR triggdata T3, \VAR triggdata T4, \VAR triggdata T5, \VAR triggdata T6, \VAR triggdata T7, \VAR triggdata T8, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#, "Absolute joint move that fires defined triggers along the way."),
    routine(r#"PROC TriggC(\switch Conc, robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, \num T, VAR triggdata Trigg_1 | VAR triggdata TriggArray{*}, \VAR triggdata T2, \VAR triggdata T3, \VAR triggdata T4, \VAR triggdata T5, \VAR triggdata T6, \VAR triggdata T7, \VAR triggdata T8, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Circular move that fires defined triggers (outputs, interrupts) at positions."),
    routine(r#"PROC TriggJ(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num T, VAR triggdata Trigg_1 | VAR triggdata TriggArray{*}, \VAR triggdata T2, \VAR triggdata T3, \VAR triggdata T4, \VAR triggdata T5, \VAR triggdata T6, \VAR triggdata T7, \VAR triggdata T8, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#, "Joint move that fires defined triggers (outputs, interrupts) at positions."),
    routine(r#"PROC TriggL(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num T, VAR triggdata Trigg_1 | VAR triggdata TriggArray{*}, \VAR triggdata T2, \VAR triggdata T3, \VAR triggdata T4, \VAR triggdata T5, \VAR triggdata T6, \VAR triggdata T7, \VAR triggdata T8, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Linear move that fires defined triggers (outputs, interrupts) at positions."),
    routine(r#"PROC TriggJIOs(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num T, \triggios TriggData1{*}, \triggstrgo TriggData2{*}, \triggiosdnum TriggData3{*}, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#, "Joint move that sets outputs at positions listed in triggios arrays."),
    routine(r#"PROC TriggLIOs(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed, \num T, \triggios TriggData1{*}, \triggstrgo TriggData2{*}, \triggiosdnum TriggData3{*}, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \switch Corr, \PERS loaddata TLoad)"#, "Linear move that sets outputs at positions listed in triggios arrays."),
    routine(r#"PROC TriggIO(VAR triggdata TriggData, num Distance, \switch Start | switch Time, \signaldo DOp | signalgo GOp | signalao AOp | num ProcID, num SetValue | dnum SetDvalue, \num DODelay, \PERS bool Inhib, \PERS anytype InhibSetValue, \triggmode Mode)"#, "Defines a trigger that sets an output at a distance or time along the next path."),
    routine(r#"PROC TriggEquip(VAR triggdata TriggData, num Distance, \switch Start | switch Next, num EquipLag, \signaldo DOp | signalgo GOp | signalao AOp | num ProcID, num SetValue | dnum SetDvalue, \PERS bool Inhib, \PERS anytype InhibSetValue, \triggmode Mode)"#, "Defines a trigger that sets an output early to make up for equipment lag."),
    routine(r#"PROC TriggInt(VAR triggdata TriggData, num Distance, \switch Start | switch Next | switch Time, VAR intnum Interrupt, \PERS bool Inhib, \triggmode Mode)"#, "Defines a trigger that raises an interrupt at a position on the next path."),
    routine(r#"PROC TriggCheckIO(VAR triggdata TriggData, num Distance, \switch Start | switch Next | switch Time, anytype Signal, opnum Relation, num CheckValue | dnum CheckDvalue, \switch StopMove, VAR intnum Interrupt, \PERS bool Inhib, \triggmode Mode)"#, "Defines a trigger that checks a signal at a position and interrupts if it fails.").takes_signals(),
    routine(r#"PROC TriggRampAO(VAR triggdata TriggData, num Distance, \switch Start | switch Next, num EquipLag, signalao AOutput, num SetValue, num RampLength, \switch Time, \PERS bool Inhib, \PERS anytype InhibSetValue, \triggmode Mode)"#, "Defines a trigger that ramps an analog output up or down along the path."),
    routine(r#"PROC TriggSpeed(VAR triggdata TriggData, num Distance, \switch Start | switch Next, num ScaleLag, signalao AOp, num ScaleValue, \num DipLag, \signaldo ErrDO, \PERS bool Inhib, \PERS anytype InhibSetValue, \triggmode Mode)"#, "Defines a trigger that drives an analog output in proportion to TCP speed."),
    routine("PROC TriggDataCopy(VAR triggdata Source, VAR triggdata Destination)", "Copies the contents of one triggdata variable into another."),
    routine("PROC TriggDataReset(VAR triggdata TriggData)", "Clears the contents of a triggdata variable."),
    routine("FUNC bool TriggDataValid(VAR triggdata TriggData)", "TRUE when a triggdata variable holds a valid trigger definition."),
    routine(r#"PROC TriggStopProc(PERS restartdata RestartRef, \signaldo DO1, \signalgo GO1, \signalgo GO2, \signalgo GO3, \signalgo GO4, signaldo ShadowDO)"#, "Sets up supervision that zeroes process signals at a stop and records restart data."),
    routine("PROC StepBwdPath(num StepLength, num StepTime)", "From a RESTART event routine, moves the TCP StepLength mm back along the path."),

    // ---- Motion control on errors and interrupts ----------------------------------------
    routine(r#"PROC StopMove(\switch Quick, \switch AllMotionTasks)"#, "Stops robot and external axis movement for now, keeping the path."),
    routine(r#"PROC StartMove(\switch AllMotionTasks)"#, "Resumes movement stopped by StopMove."),
    routine("PROC StartMoveRetry()", "Resumes movement and retries the failed instruction, like StartMove plus RETRY."),
    routine(r#"PROC StopMoveReset(\switch AllMotionTasks)"#, "Clears the stop-move state without starting to move."),
    routine(r#"PROC StorePath(\switch KeepSync)"#, "Saves the current path and starts a new path level, e.g. in a trap."),
    routine("PROC RestoPath()", "Restores the path saved by StorePath."),
    routine("PROC ClearPath()", "Removes the whole motion path on the current path level."),
    routine("FUNC num PathLevel()", "Returns the current path level: 1 for base level, 2 after StorePath."),
    routine("PROC SyncMoveSuspend()", "Suspends synchronized movement at the StorePath level."),
    routine("PROC SyncMoveResume()", "Resumes synchronized movement at the StorePath level."),
    routine(r#"FUNC bool IsStopMoveAct(\switch FromMoveTask | switch FromNonMoveTask)"#, "TRUE when a stop-move flag of the given kind is set."),

    // ---- Robot information in MultiMove -------------------------------------------------
    routine("FUNC string RobName()", "Returns the name of the TCP robot controlled by this task, or an empty string."),

    // ---- External axes ------------------------------------------------------------------
    routine("PROC ActUnit(VAR mecunit MechUnit)", "Activates a mechanical unit.").names_data(),
    routine("PROC DeactUnit(VAR mecunit MechUnit)", "Deactivates a mechanical unit.").names_data(),
    routine("PROC MechUnitLoad(VAR mecunit MechUnit, num AxisNo, PERS loaddata Load)", "Declares the payload carried by an axis of an external mechanical unit.").names_data(),
    // uncertain: the public extract shows only the two optionals; an output argument for the margin is assumed.
    routine(r#"PROC GetTorqueMargin(\VAR mecunit MechUnit, \num AxisNo, INOUT num TorqueMargin)"#, "Reads the smallest torque margin of an axis since ResetTorqueMargin."),
    routine(r#"PROC ResetTorqueMargin(\VAR mecunit MechUnit, \num AxisNo)"#, "Restarts the measurement of the smallest torque margin."),
    routine(r#"FUNC num GetMotorTorque(\VAR mecunit MecUnit, num AxisNo)"#, "Returns the current motor torque of a robot or external axis.").names_data(),
    // uncertain: access modes of the output arguments assumed INOUT, MecRef VAR.
    routine(r#"FUNC bool GetNextMechUnit(INOUT num ListNumber, INOUT string UnitName, \VAR mecunit MecRef, \INOUT bool TCPRob, \INOUT num NoOfAxes, \INOUT num MecTaskNo, \INOUT num MotPlanNo, \INOUT bool Active, \INOUT num DriveModule, \INOUT bool OKToDeact)"#, "Steps through the mechanical units of the system, returning name and data."),
    routine("FUNC bool IsMechUnitActive(VAR mecunit MechUnit)", "TRUE when a mechanical unit is active.").names_data(),

    // ---- Independent axes ---------------------------------------------------------------
    routine(r#"PROC IndAMove(VAR mecunit MecUnit, num Axis, \robtarget ToAbsPos | num ToAbsNum, num Speed, \num Ramp)"#, "Puts an axis in independent mode and moves it to an absolute position.").names_data(),
    routine(r#"PROC IndCMove(VAR mecunit MecUnit, num Axis, num Speed, \num Ramp)"#, "Puts an axis in independent mode and starts it rotating continuously.").names_data(),
    routine(r#"PROC IndDMove(VAR mecunit MecUnit, num Axis, num Delta, num Speed, \num Ramp)"#, "Puts an axis in independent mode and moves it by a distance.").names_data(),
    routine(r#"PROC IndRMove(VAR mecunit MecUnit, num Axis, \robtarget ToRelPos | num ToRelNum, \switch Short | switch Fwd | switch Bwd, num Speed, \num Ramp)"#, "Puts a rotating axis in independent mode and moves it within one turn.").names_data(),
    routine(r#"PROC IndReset(VAR mecunit MecUnit, num Axis, \robtarget RefPos | num RefNum, \switch Short | switch Fwd | switch Bwd | switch Old)"#, "Returns an independent axis to normal mode, optionally moving its range.").names_data(),
    routine("PROC HollowWristReset()", "Resets the wrist axis position on hollow-wrist robots (IRB 5402/5403)."),
    routine("FUNC bool IndInpos(VAR mecunit MecUnit, num Axis)", "TRUE when an independent axis has reached its position.").names_data(),
    routine(r#"FUNC bool IndSpeed(VAR mecunit MecUnit, num Axis, \switch InSpeed | switch ZeroSpeed)"#, "TRUE when an independent axis has reached its set speed or zero speed.").names_data(),

    // ---- Path correction ----------------------------------------------------------------
    routine("PROC CorrCon(VAR corrdescr Descr)", "Connects a path correction generator."),
    routine("PROC CorrWrite(VAR corrdescr Descr, pos Data)", "Writes a path-frame offset to a connected correction generator."),
    routine("PROC CorrDiscon(VAR corrdescr Descr)", "Disconnects a path correction generator."),
    routine("PROC CorrClear()", "Removes all connected correction generators."),
    routine("FUNC pos CorrRead()", "Returns the total correction delivered by all correction generators."),

    // ---- Path recorder ------------------------------------------------------------------
    routine("PROC PathRecStart(VAR pathrecid ID)", "Starts recording the robot path, marking the start with ID."),
    routine(r#"PROC PathRecStop(\switch Clear)"#, "Stops recording the robot path, optionally discarding it."),
    routine(r#"PROC PathRecMoveBwd(\VAR pathrecid ID, \pos ToolOffs, \speeddata Speed)"#, "Moves the robot backwards along the recorded path."),
    routine(r#"PROC PathRecMoveFwd(\VAR pathrecid ID, \pos ToolOffs, \speeddata Speed)"#, "Moves the robot forward again to where PathRecMoveBwd started."),
    routine(r#"FUNC bool PathRecValidBwd(\VAR pathrecid ID)"#, "TRUE when the recorder is active and a backward path exists."),
    routine(r#"FUNC bool PathRecValidFwd(\VAR pathrecid ID)"#, "TRUE when the recorder can move forward again."),

    // ---- Conveyor tracking --------------------------------------------------------------
    // uncertain: the public extract lists only WObj; \RelDist, \MaxTime and \TimeFlag recalled.
    routine(r#"PROC WaitWObj(PERS wobjdata WObj, \num RelDist, \num MaxTime, \VAR bool TimeFlag)"#, "Connects to the next object on the conveyor, waiting for it if needed."),
    routine("PROC DropWObj(PERS wobjdata WObj)", "Disconnects from the current conveyor object."),
    // uncertain: indexing conveyor arguments not found in public sources; modelled as a mechanical unit.
    routine("PROC IndCnvInit(VAR mecunit MechUnit, VAR indcnvdata IndCnvData)", "Sets up the indexing conveyor function."),
    // uncertain: see IndCnvInit.
    routine("PROC IndCnvEnable(VAR mecunit MechUnit)", "Starts watching the input that triggers the indexing conveyor."),
    // uncertain: see IndCnvInit.
    routine("PROC IndCnvDisable(VAR mecunit MechUnit)", "Stops watching the input that triggers the indexing conveyor."),
    // uncertain: see IndCnvInit.
    routine("PROC IndCnvReset(VAR mecunit MechUnit)", "Returns the indexing conveyor to normal mode."),
    // uncertain: see IndCnvInit.
    routine("PROC IndCnvAddObject(VAR mecunit MechUnit)", "Adds an object to the indexing conveyor's object queue by hand."),

    // ---- Sensor synchronization ---------------------------------------------------------
    routine(r#"PROC WaitSensor(VAR mecunit MechUnit, \num RelDist, \num PredTime, \num MaxTime, \VAR bool TimeFlag)"#, "Connects to an object in the start window of a sensor unit."),
    routine(r#"PROC SyncToSensor(VAR mecunit MechUnit, \switch On | switch Off)"#, "Starts or stops synchronizing robot motion to a sensor unit."),
    routine("PROC DropSensor(VAR mecunit MechUnit)", "Disconnects from the current sensor object."),

    // ---- Load identification and collision detection ------------------------------------
    routine(r#"PROC MotionSup(\switch On | switch Off, \num TuneValue, \switch NoBackoff)"#, "Turns motion supervision (collision detection) on or off and tunes it."),
    // uncertain: Pos and AxValid access modes assumed VAR.
    routine(r#"FUNC bool ParIdPosValid(paridnum ParIdType, VAR jointtarget Pos, VAR bool AxValid{*}, \num ConfAngle)"#, "Checks whether the robot position suits a parameter identification."),
    routine(r#"FUNC paridvalidnum ParIdRobValid(paridnum ParIdType, \VAR mecunit MechUnit, \num AxisNo)"#, "Checks whether the robot or manipulator type supports the identification.").names_data(),
    // uncertain: argument list after ParIdType recalled from the manual, not in the public extract.
    routine(r#"PROC LoadId(paridnum ParIdType, loadidnum LoadIdType, PERS tooldata Tool, \PERS loaddata PayLoad, \PERS wobjdata WObj, \num ConfAngle, \switch SlowTest, \INOUT num Accuracy)"#, "Identifies the load of a tool or payload by running test moves."),
    routine(r#"PROC ManLoadIdProc(\paridnum ParIdType, \VAR mecunit MechUnit | string MechUnitName, \num AxisNumber, \PERS loaddata PayLoad, \num ConfigAngle, \switch DeactAll | switch AlreadyActive, \INOUT bool DefinedFlag, \bool DoExit)"#, "Identifies the payload of an external manipulator."),

    // ---- Position functions -------------------------------------------------------------
    routine("FUNC robtarget Offs(robtarget Point, num XOffset, num YOffset, num ZOffset)", "Returns Point moved by the given offsets in the object frame."),
    routine(r#"FUNC robtarget RelTool(robtarget Point, num Dx, num Dy, num Dz, \num Rx, \num Ry, \num Rz)"#, "Returns Point moved and rotated (deg) in the tool frame."),
    routine(r#"FUNC robtarget CalcRobT(jointtarget Joint_target, PERS tooldata Tool, \PERS wobjdata WObj)"#, "Computes the robtarget reached at given axis positions (forward kinematics)."),
    routine(r#"FUNC jointtarget CalcJointT(\switch UseCurWObjPos, robtarget Rob_target, PERS tooldata Tool, \PERS wobjdata WObj, \INOUT errnum ErrorNumber)"#, "Computes the axis positions that reach a robtarget (inverse kinematics)."),
    routine(r#"FUNC pos CPos(\PERS tooldata Tool, \PERS wobjdata WObj)"#, "Returns the current TCP position (x, y, z only)."),
    routine(r#"FUNC robtarget CRobT(\VAR taskid TaskRef | string TaskName, \PERS tooldata Tool, \PERS wobjdata WObj)"#, "Returns the current robot and external axis position as a robtarget.").names_data(),
    routine(r#"FUNC jointtarget CJointT(\VAR taskid TaskRef | string TaskName)"#, "Returns the current robot and external axis angles.").names_data(),
    routine(r#"FUNC num ReadMotor(\VAR mecunit MecUnit, num Axis)"#, "Returns the current motor angle of an axis, in radians.").names_data(),
    routine(r#"FUNC tooldata CTool(\VAR taskid TaskRef | string TaskName)"#, "Returns the data of the tool now in use."),
    routine(r#"FUNC wobjdata CWObj(\VAR taskid TaskRef | string TaskName)"#, "Returns the data of the work object now in use."),
    routine(r#"FUNC robtarget MirPos(robtarget Point, wobjdata MirPlane, \wobjdata WObj, \switch MirY)"#, "Returns Point mirrored in the xy plane of MirPlane."),
    routine("FUNC num Distance(pos Point1, pos Point2)", "Returns the straight-line distance between two points."),

    // ---- Path interrupted at power failure, status --------------------------------------
    routine(r#"FUNC bool PFRestart(\switch Base | switch Irpt)"#, "TRUE when a path was interrupted by a power failure."),
    routine(r#"FUNC num CSpeedOverride(\switch CTask)"#, "Returns the speed override percent set by the operator."),
];
