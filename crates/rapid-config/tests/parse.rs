//! The `.cfg` reader on fixtures written in the style of RobotWare's backups.

use rapid_config::{eio, moc, parse, sys, CfgFile};

fn fixture(name: &str) -> CfgFile {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    parse(&text)
}

#[test]
fn header_sections_and_continuations() {
    let file = fixture("eio_rw6.cfg");
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let header = file.header.as_ref().expect("header");
    assert_eq!((header.domain.as_str(), header.format.as_str()), ("EIO", "CFG_1.0"));
    assert_eq!(header.version, ["6", "1"]);
    let names: Vec<&str> = file.sections.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["INDUSTRIAL_NETWORK", "DEVICENET_DEVICE", "EIO_SIGNAL", "EIO_CROSS"]);
    let device = &file.section("devicenet_device").expect("section").instances[0];
    assert_eq!(device.line, 9);
    assert_eq!(device.value("ProductCode"), Some("26"));
    assert_eq!(device.value("InputSize"), Some("2"));
    let ao = file.instances("EIO_SIGNAL").find(|i| i.name() == Some("aoSpeed")).expect("aoSpeed");
    assert_eq!(ao.value("MaxBitVal"), Some("65535"));
    let cross = file.instances("EIO_CROSS").next().expect("cross");
    assert!(cross.has("Act2_invert") && cross.attr("Act2_invert").and_then(|a| a.value.as_ref()).is_none());
}

#[test]
fn flags_bare_values_and_lower_case_names() {
    let file = fixture("sys.cfg");
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let modpos = file.instances("HOTEDIT_MODPOS").next().expect("instance");
    assert_eq!(modpos.name(), Some("modpos"));
    assert!(modpos.has("type") && modpos.value("type").is_none());
    assert!(modpos.has("tuning_in_auto"));
    let limit = file.instances("MANFS_LIMIT").next().expect("instance");
    assert_eq!(limit.value("text_id"), Some("30,82"));
    let regain = file.instances("CAB_REGAIN_DIST").next().expect("instance");
    assert_eq!(regain.value("Tcp_rot"), Some("0.2"));
    assert!(!regain.attr("Tcp_rot").and_then(|a| a.value.as_ref()).expect("value").quoted);
}

#[test]
fn negative_numbers_are_values() {
    let file = parse("EIO:CFG_1.0:5:0::\n#\nEIO_UNIT_TYPE:\n\n  -Name \"G\" -DN_ExplicitMsgEnabled \\\n  -DN_C1OutputSize -1 -DN_C1InputSize -1\n");
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let inst = file.instances("EIO_UNIT_TYPE").next().expect("instance");
    assert!(inst.has("DN_ExplicitMsgEnabled") && inst.value("DN_ExplicitMsgEnabled").is_none());
    assert_eq!(inst.value("DN_C1OutputSize"), Some("-1"));
    assert_eq!(inst.value("DN_C1InputSize"), Some("-1"));
}

#[test]
fn crlf_lines() {
    let file =
        parse("SYS:CFG_1.0:6:0::\r\n#\r\nCAB_TASKS:\r\n\r\n  -Name \"T_ROB1\" -Type \"NORMAL\"\\\r\n  -MotionTask\r\n");
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let inst = file.instances("CAB_TASKS").next().expect("instance");
    assert_eq!(inst.value("Type"), Some("NORMAL"));
    assert!(inst.has("MotionTask"));
}

#[test]
fn malformed_lines_are_errors_and_the_rest_is_kept() {
    let text = "\
  -Name \"early\"
EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"di1\" -SignalType \"DI\" stray

      -Name \"di2\" -SignalType \"DI\" -Name \"again\"

this line is nonsense

      -Name \"di3\" -SignalType \"DI -Device \"x\"
";
    let file = parse(text);
    let found: Vec<(u32, &str)> = file.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(found.len(), 7, "{found:#?}");
    assert_eq!(found[0].0, 1);
    assert!(found[0].1.contains("header"));
    assert_eq!(found[1].0, 1);
    assert!(found[1].1.contains("before any type line"));
    assert_eq!(found[2].0, 2);
    assert!(found[2].1.contains("not the file's first line"));
    assert_eq!((found[3].0, found[3].1), (6, "unexpected `stray`: attributes start with `-` and a name"));
    assert_eq!(found[4].0, 8);
    assert!(found[4].1.contains("given twice"));
    assert_eq!(found[5].0, 10);
    assert!(found[5].1.starts_with("expected a type line"));
    // di3's quotes pair up wrongly: `"DI -Device "` is the type, then `x"` is stray.
    assert_eq!((found[6].0, found[6].1), (12, "unexpected `x\"`: attributes start with `-` and a name"));
    let names: Vec<&str> = file.instances("EIO_SIGNAL").filter_map(|i| i.name()).collect();
    assert_eq!(names, ["di1", "di2", "di3"]);
    assert_eq!(file.instances("EIO_SIGNAL").nth(1).and_then(|i| i.name()), Some("di2"));
}

#[test]
fn unterminated_quote() {
    let file = parse("EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"di1 -SignalType DI\n");
    assert_eq!(file.errors.len(), 1, "{:?}", file.errors);
    assert_eq!(file.errors[0].line, 4);
    assert!(file.errors[0].message.contains("closing"));
}

#[test]
fn editing_changes_one_value_and_nothing_else() {
    let file = fixture("eio_rw6.cfg");
    let (section, instance) = rapid_config::find_named(&file, "EIO_SIGNAL", "DOGRIPCLOSE").expect("signal");
    let edited = file.with_value(section, instance, "Default", "0").expect("edit");
    assert_eq!(edited, file.text.replace("-Access \"All\" -Default 1", "-Access \"All\" -Default 0"));
    let edited = file.with_value(section, instance, "access", "ReadOnly").expect("edit");
    assert_eq!(edited, file.text.replace("-Access \"All\"", "-Access \"ReadOnly\""));
    let (section, instance) = rapid_config::find_named(&file, "EIO_SIGNAL", "diVirtual").expect("signal");
    let edited = file.with_value(section, instance, "Default", "1").expect("edit");
    assert_eq!(edited, file.text.replace("-SignalType \"DI\"\n#", "-SignalType \"DI\" -Default \"1\"\n#"));
    assert_eq!(file.with_value(section, instance, "Label", "a\"b"), Err(rapid_config::EditError::Unquotable));
    assert_eq!(file.with_value(9, 0, "Label", "x"), Err(rapid_config::EditError::NoInstance));
    let reparsed = parse(&edited);
    assert!(reparsed.errors.is_empty());
}

#[test]
fn eio_signals_devices_and_cross_connections() {
    let file = fixture("eio_rw6.cfg");
    let eio = eio::read(&file);
    assert!(eio.errors.is_empty(), "{:?}", eio.errors);
    let types: Vec<(&str, &str)> = eio.signals.iter().map(|s| (s.name.as_str(), s.signal_type.rapid_type())).collect();
    assert_eq!(
        types,
        [
            ("diPartReady", "signaldi"),
            ("doGripClose", "signaldo"),
            ("goRecipe", "signalgo"),
            ("aoSpeed", "signalao"),
            ("diVirtual", "signaldi")
        ]
    );
    let go = eio.signal("gorecipe").expect("goRecipe");
    assert_eq!(go.width(), 8);
    assert_eq!(go.device.as_deref(), Some("d652"));
    let grip = eio.signal("doGripClose").expect("doGripClose");
    assert_eq!((grip.default, grip.access.as_deref()), (Some(1.0), Some("All")));
    let ao = eio.signal("aoSpeed").expect("aoSpeed");
    assert_eq!((ao.analog.max_log, ao.analog.max_bit_val, ao.analog.min_phys), (Some(1000.0), Some(65535.0), None));
    assert_eq!(eio.devices.len(), 1);
    assert_eq!(eio.devices[0].name, "d652");
    let cross = &eio.cross[0];
    assert_eq!(cross.result, "diVirtual");
    assert_eq!(cross.actors.len(), 2);
    assert!(!cross.actors[0].invert && cross.actors[1].invert);
    assert_eq!(cross.operators, [Some("AND".to_owned())]);
}

#[test]
fn eio_robotware_5_units() {
    let file = fixture("eio_rw5.cfg");
    let eio = eio::read(&file);
    assert!(file.errors.is_empty() && eio.errors.is_empty(), "{:?} {:?}", file.errors, eio.errors);
    let gi = eio.signal("gi_job").expect("gi_job");
    assert_eq!((gi.device.as_deref(), gi.width()), (Some("board10"), 4));
    assert_eq!(eio.devices[0].network.as_deref(), Some("DeviceNet1"));
}

#[test]
fn eio_findings() {
    let text = "\
EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"a\" -SignalType \"DX\"

      -Name \"b\" -SignalType \"DI\" -DeviceMap \"0-1\"

      -Name \"c\" -SignalType \"GO\" -DeviceMap \"0-32\"

      -Name \"d\" -SignalType \"DO\"\\
      -Default \"high\"

      -Name \"B\" -SignalType \"DO\"

      -Name \"e\" -SignalType \"GI\" -DeviceMap \"3-x\"

      -SignalType \"DI\"
#
EIO_CROSS:

      -Res \"d\" -Act1 \"nosuch\" -Oper1 \"XOR\" -Act2 \"b\"
";
    let file = parse(text);
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let eio = eio::read(&file);
    let found: Vec<(u32, &str)> = eio.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(
        found,
        [
            (5, "signal `a`: unknown signal type `DX` (DI, DO, AI, AO, GI or GO)"),
            (7, "signal `b`: a digital signal maps one bit, this map names 2"),
            (9, "signal `c`: a group signal has at most 32 bits, this map names 33"),
            (12, "signal `d`: `-Default` is not a number: `high`"),
            (14, "signal `B` is configured twice"),
            (16, "signal `e`: the map `3-x` is not bits such as `0`, `0-7` or `0-3,8-11`"),
            (18, "a signal without `-Name`"),
            (22, "cross-connection names `nosuch`, which is not a configured signal"),
            (22, "cross-connection operator `XOR` is neither AND nor OR"),
        ]
    );
}

#[test]
fn maps() {
    assert_eq!(eio::parse_map("7-4"), Ok(vec![7, 6, 5, 4]));
    assert_eq!(eio::parse_map("0-1,8"), Ok(vec![0, 1, 8]));
    assert!(eio::parse_map("").is_err());
}

#[test]
fn sys_tasks_and_modules() {
    let file = fixture("sys.cfg");
    let sys = sys::read(&file);
    assert!(sys.errors.is_empty(), "{:?}", sys.errors);
    let rob = sys.task("t_rob1").expect("T_ROB1");
    assert_eq!((rob.task_type, rob.entry.as_str(), rob.motion_task), (sys::TaskType::Normal, "main", true));
    let logger = sys.task("T_LOGGER").expect("T_LOGGER");
    assert_eq!(logger.task_type, sys::TaskType::SemiStatic);
    assert_eq!((logger.entry.as_str(), logger.trust_level.as_deref()), ("log_main", Some("None")));
    assert!(!logger.motion_task);
    assert_eq!((logger.foreground.as_deref(), rob.foreground.as_deref()), (Some("T_ROB1"), None));
    assert_eq!(sys.modules.len(), 2);
    assert!(sys.modules[0].shared && !sys.modules[0].all_tasks);
    assert_eq!(sys.modules[1].module.as_deref(), Some("user"));
    assert!(sys.modules[1].all_tasks);
}

#[test]
fn sys_findings() {
    let file = parse(
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T1\" -Type \"DYNAMIC\"\n\n  -Name \"t1\"\n\n  -Type \"NORMAL\"\n\n  \
         -Name \"T2\" -TaskInForeground \"T9\"\n\n  -Name \"T3\" -TrustLevel \"Bogus\"\n\n  -Name \"T4\" -TrustLevel \"None\"\n",
    );
    let sys = sys::read(&file);
    let found: Vec<(u32, &str)> = sys.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(
        found,
        [
            (5, "task `T1`: unknown type `DYNAMIC` (NORMAL, STATIC or SEMISTATIC)"),
            (7, "task `t1` is configured twice"),
            (9, "a task without `-Name`"),
            (13, "task `T3`: unknown -TrustLevel `Bogus` (SysFail, SysHalt, SysStop, NoSafety)"),
            (11, "task `T2` runs in the background of `T9`, which is not a task"),
        ]
    );
}

#[test]
fn sys_entry_and_event_routine_spans() {
    // The entry routine and an event routine's name are kept with their places, so that
    // a routine a task lacks can be reported where the configuration names it.
    let text =
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T1\"\n\n  -Name \"T2\" -Entry \"go\"\n#\nCAB_EXEC_HOOKS:\n\n  \
                -Routine \"on_power\" -Shelf \"POWER_ON\" -AllTask\n";
    let file = parse(text);
    let sys = sys::read(&file);
    assert!(sys.errors.is_empty(), "{:?}", sys.errors);
    assert_eq!(sys.task("T1").map(|t| t.entry_span.clone()), Some(None));
    let entry = sys.task("T2").and_then(|t| t.entry_span.clone()).expect("T2's -Entry");
    assert_eq!((file.line_of(entry.start), text[entry].trim_matches('"')), (7, "go"));
    let routine = sys.hooks[0].routine_span.clone();
    assert_eq!((file.line_of(routine.start), text[routine].trim_matches('"')), (11, "on_power"));
}

#[test]
fn foreground_tasks_in_either_spelling_and_no_cycles() {
    // `-Task_in_forground` is how SYS.cfg files controllers write spell the attribute;
    // a cycle of tasks in each other's background could never run. T_SELF naming
    // itself was an error here too; issue 20 decided otherwise on evidence (a SYS.cfg a
    // controller wrote, in a public backup, has it): it is a warning, T_SELF has no
    // foreground task (`a_task_naming_itself_as_its_foreground_has_none`).
    let file = parse(
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_ROB1\" -Type \"NORMAL\"\n\n  \
         -Name \"T_BG\" -Task_in_forground \"T_ROB1\"\n\n  -Name \"T_SELF\" -TaskInForeground \"T_SELF\"\n\n  \
         -Name \"T_A\" -TaskInForeground \"T_B\"\n\n  -Name \"T_B\" -Task_in_forground \"T_A\"\n",
    );
    let sys = sys::read(&file);
    assert_eq!(sys.task("T_BG").and_then(|t| t.foreground.as_deref()), Some("T_ROB1"));
    let found: Vec<(u32, &str)> = sys.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(
        found,
        [
            (
                11,
                "task `T_A` runs in the background of `T_B`, which runs (through its foreground tasks) in the \
                 background of `T_A`: none of them could run"
            ),
            (
                13,
                "task `T_B` runs in the background of `T_A`, which runs (through its foreground tasks) in the \
                 background of `T_B`: none of them could run"
            ),
        ]
    );
}

#[test]
fn a_task_naming_itself_as_its_foreground_has_none() {
    // T_UI names itself (line 7, either spelling): a warning at its line, no foreground
    // task; T_BG behind it runs in its background as usual, and nothing is an error.
    let file = parse(
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_ROB1\" -Type \"NORMAL\"\n\n  \
         -Name \"T_UI\" -Type \"STATIC\" -Task_in_forground \"t_ui\"\n\n  -Name \"T_BG\" -TaskInForeground \"T_UI\"\n",
    );
    let sys = sys::read(&file);
    assert!(sys.errors.is_empty(), "{:?}", sys.errors);
    assert_eq!(sys.task("T_UI").map(|t| t.foreground.clone()), Some(None));
    assert_eq!(sys.task("T_BG").and_then(|t| t.foreground.as_deref()), Some("T_UI"));
    let warned: Vec<(u32, &str)> = sys.warnings.iter().map(|w| (w.line, w.message.as_str())).collect();
    assert_eq!(
        warned,
        [(7, "task `T_UI` names itself as its foreground task: it has none (it runs at the top level)")]
    );
}

#[test]
fn moc_robots() {
    let file =
        parse("MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n  -name \"ROB_1\" -use_robot_type \"ROB1\" -base_frame_pos_z 0.5\n");
    let robots = moc::robots(&file);
    assert_eq!(robots.len(), 1);
    assert_eq!((robots[0].name.as_str(), robots[0].robot_type.as_deref()), ("ROB_1", Some("ROB1")));
}

#[test]
fn moc_external_units_are_the_mechanical_units_no_robot_names() {
    let file = parse(
        "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT:\n\n  -name \"ROB_1\"\n\n  -name \"TRACK\" -activate_at_start_up\n\n  \
         -name \"STN1\"\n#\nROBOT:\n\n  -name \"ROB_1\" -use_robot_type \"ROB1\"\n",
    );
    assert_eq!(moc::external_units(&file), ["TRACK", "STN1"]);
}

#[test]
fn moc_a_group_without_a_robot_is_a_positioners() {
    let file = parse(
        "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT_GROUP:\n\n  -name \"rob1\" -robot \"ROB_1\"\n\n  \
         -name \"stn1\" -mech_unit_1 \"STN1\"\n",
    );
    assert_eq!(moc::group_robot(&file, "ROB1"), Some(Some("ROB_1".to_owned())));
    assert_eq!(moc::group_robot(&file, "stn1"), Some(None));
    assert_eq!(moc::group_robot(&file, "stn2"), None);
}

#[test]
fn removing_a_flag_keeps_the_rest() {
    let file = fixture("sys.cfg");
    let (section, instance) = rapid_config::find_named(&file, "CAB_TASKS", "T_ROB1").expect("task");
    let edited = file.with_value(section, instance, "Entry", "go").expect("edit");
    let file = parse(&edited);
    let edited = file.without_attr(section, instance, "MotionTask").expect("edit").expect("present");
    assert_eq!(edited, file.text.replace(" -MotionTask", ""));
    assert_eq!(file.without_attr(section, instance, "Hidden"), Ok(None));
}

#[test]
fn an_empty_file_lacks_its_header() {
    for text in ["", "\n\n   \n"] {
        let file = parse(text);
        assert_eq!(file.errors.len(), 1, "{text:?}");
        assert_eq!(file.errors[0].line, 1);
        assert!(file.errors[0].message.contains("header"));
    }
}

#[test]
fn never_panics_on_prefixes_or_odd_text() {
    let mut texts: Vec<String> =
        ["-", "\"", "\\", "-a\\", "#\n-\n", "X:\n-a \"", "EIO:\n-\\\n\\\n", ":::\n-1 -2", "É:\n -é \"é\"\\\n"]
            .iter()
            .map(|t| t.to_string())
            .collect();
    for name in ["eio_rw6.cfg", "eio_rw5.cfg", "sys.cfg"] {
        let text = fixture(name).text;
        texts.extend(text.char_indices().map(|(i, _)| text[..i].to_owned()));
    }
    for text in &texts {
        let file = parse(text);
        let _ = (eio::read(&file), sys::read(&file), moc::robots(&file));
        for (si, section) in file.sections.iter().enumerate() {
            for ii in 0..section.instances.len() {
                let _ = file.with_value(si, ii, "Name", "x y");
                let _ = file.with_flag(si, ii, "Flag");
                let _ = file.without_attr(si, ii, "Name");
            }
        }
        for error in &file.errors {
            assert!(error.span.start <= error.span.end && error.span.end <= text.len(), "{text:?}: {error:?}");
        }
    }
}

#[test]
fn cross_connection_loops() {
    let text = "\
EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"a\" -SignalType \"DI\"

      -Name \"b\" -SignalType \"DI\"

      -Name \"c\" -SignalType \"DI\"

      -Name \"d\" -SignalType \"DI\"
#
EIO_CROSS:

      -Res \"b\" -Act1 \"a\"

      -Res \"c\" -Act1 \"b\" -Oper1 \"OR\" -Act2 \"d\"

      -Res \"a\" -Act1 \"c\"

      -Res \"d\" -Act1 \"a\" -Act1_invert
";
    let eio = eio::read(&parse(text));
    let found: Vec<(u32, &str)> = eio.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(
        found,
        [
            (15, "cross-connections loop: `b` is driven, through them, by itself"),
            (17, "cross-connections loop: `c` is driven, through them, by itself"),
            (19, "cross-connections loop: `a` is driven, through them, by itself"),
            (21, "cross-connections loop: `d` is driven, through them, by itself"),
        ]
    );
    // A chain without a loop is fine.
    let chain = text
        .replace("-Res \"a\" -Act1 \"c\"", "-Res \"a\" -Act1 \"d\" -Act1_invert")
        .replace("-Res \"d\" -Act1 \"a\" -Act1_invert", "");
    let eio = eio::read(&parse(&chain));
    assert!(eio.errors.is_empty(), "{:?}", eio.errors);
}

/// Line numbers come from a table of line starts, not a count from the top for every
/// instance (quadratic: a SYS.cfg of a thousand tasks took minutes to check). Each
/// instance here is a blank line and its `-Name` line, after the 3-line header, so
/// instance i (from 0) is on line 5 + 2i; a duplicate at the end is found, on its line.
#[test]
fn many_instances_keep_their_lines_and_duplicates() {
    let mut text = String::from("SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n");
    for i in 0..5000 {
        text.push_str(&format!("\n      -Name \"T_{i}\" -Type \"NORMAL\"\n"));
    }
    text.push_str("\n      -Name \"t_7\" -Type \"NORMAL\"\n");
    let file = rapid_config::parse(&text);
    let section = &file.sections[0];
    assert_eq!(section.instances.len(), 5001);
    assert_eq!(section.instances[0].line, 5);
    assert_eq!(section.instances[4999].line, 5 + 2 * 4999);
    let sys = rapid_config::sys::read(&file);
    let duplicate: Vec<_> = sys.errors.iter().filter(|e| e.message.contains("configured twice")).collect();
    assert_eq!(duplicate.len(), 1, "{:?}", sys.errors);
    assert_eq!(duplicate[0].line, 5 + 2 * 5000);
    // Over the task limit: that one finding, and no foreground checks past it.
    assert!(sys.errors.iter().any(|e| e.message == "at most 20 tasks; 4980 more are configured"), "{:?}", sys.errors);
}

/// MMC.cfg names its instruction palettes: `NAME = TYPE:` starts a section of the type
/// with a name of its own, and its instances belong to it. RobotWare writes the line
/// with a blank on each side of `=` and a CR LF line end.
#[test]
fn a_named_section_is_a_section_of_its_type() {
    let text =
        "MMC:CFG_1.0:6:0::\r\n#\r\nMMC_PAL_A = MMC_PALETTE:\r\n\r\n      -name \"MoveJ\" -only_mec_task \r\n\r\n      \
                -name \"Set\"\r\n#\r\nMMC_PAL_B=MMC_PALETTE:\r\n\r\n      -name \"WaitTime\"\r\n";
    let file = parse(text);
    assert!(file.errors.is_empty(), "{:?}", file.errors);
    let sections: Vec<(&str, Option<&str>, usize)> =
        file.sections.iter().map(|s| (s.name.as_str(), s.label.as_deref(), s.instances.len())).collect();
    assert_eq!(sections, [("MMC_PALETTE", Some("MMC_PAL_A"), 2), ("MMC_PALETTE", Some("MMC_PAL_B"), 1)]);
    let names: Vec<&str> = file.instances("MMC_PALETTE").filter_map(|i| i.value("name")).collect();
    assert_eq!(names, ["MoveJ", "Set", "WaitTime"]);
    // `A = B = C:` and `= T:` name no section: still errors.
    let bad = parse("MMC:CFG_1.0:6:0::\n#\nA = B = C:\n#\n= T:\n");
    let lines: Vec<u32> = bad.errors.iter().map(|e| e.line).collect();
    assert_eq!(lines, [3, 5]);
}

/// `-Task` given twice in a CAB_TASK_MODULES instance loads the module into each task
/// it names (and no other); any other attribute given twice stays a finding.
#[test]
fn a_task_module_of_two_tasks() {
    let text = "SYS:CFG_1.0:6:0::\n#\nCAB_TASK_MODULES:\n\n      -File \"HOME:/both.mod\" -Task \"T_ROB1\" \
                -Task \"T_ROB2\"\n\n      -File \"HOME:/a.mod\" -File \"HOME:/b.mod\" -Task \"T_ROB1\"\n";
    let file = parse(text);
    let found: Vec<(u32, &str)> = file.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(found, [(7, "attribute `-File` given twice in one instance; the first is kept")]);
    let sys = sys::read(&file);
    assert_eq!(sys.modules[0].tasks, ["T_ROB1", "T_ROB2"]);
    assert!(sys.modules[0].loads_into("t_rob2") && !sys.modules[0].loads_into("T_ROB3"));
    assert_eq!(sys.modules[1].file, "HOME:/a.mod");
}

/// A cross-connection may read the drive module's internal signals (DRV1BRAKE), which
/// RobotWare configures itself: each is accepted with a warning at its line.
#[test]
fn a_cross_connection_reads_a_drive_module_signal() {
    let text =
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"doBrakeOff\" -SignalType \"DO\"\n#\nEIO_CROSS:\n\n      \
                -Name \"brake\" -Res \"doBrakeOff\"\\\n      -Act1 \"DRV1BRAKE\" -Act1_invert\n\n      \
                -Name \"other\" -Res \"doBrakeOff\" -Act1 \"DRVX\"\n";
    let eio = eio::read(&parse(text));
    // `DRVX` has no drive module number: an unknown signal as before.
    let errors: Vec<(u32, &str)> = eio.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
    assert_eq!(errors, [(12, "cross-connection names `DRVX`, which is not a configured signal")]);
    let warnings: Vec<u32> = eio.warnings.iter().map(|w| w.line).collect();
    assert_eq!(warnings, [10]);
    assert!(eio.warnings[0].message.contains("`DRV1BRAKE` is an internal signal of the drive module"));
    let brake = eio.signal("drv1brake").expect("the drive module's signal");
    assert_eq!((brake.signal_type, brake.access.as_deref()), (eio::SignalType::Do, Some("ReadOnly")));
}

/// `-AllMotionTask` on an event routine: it runs in every motion task (and in the task
/// `-Task` names), not in a task that moves nothing.
#[test]
fn an_event_routine_of_every_motion_task() {
    let text = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n\n      \
                -Name \"T_ROB2\" -Type \"NORMAL\" -MotionTask\n\n      -Name \"T_IO\" -Type \"STATIC\"\n#\n\
                CAB_EXEC_HOOKS:\n\n      -Routine \"on_start\" -Shelf \"START\" -Task \"T_ROB1\" -AllMotionTask\n";
    let sys = sys::read(&parse(text));
    assert!(sys.errors.is_empty(), "{:?}", sys.errors);
    let runs: Vec<usize> = ["T_ROB1", "T_ROB2", "T_IO"].iter().map(|t| sys.hooks_for(t, "START").len()).collect();
    assert_eq!(runs, [1, 1, 0]);
}
