//! Rules that need several modules checked together as one task (§1.1.3, §1.1.5,
//! §1.2.2): global names across modules, LOCAL hiding, shared persistents, module
//! names, and the diagnostics' messages as users read them.

use rapid_sema::{check, Code, Options, SourceInput};
use rapid_syntax::LineIndex;

fn codes(files: &[(&str, &str)]) -> Vec<(String, &'static str, u32)> {
    let inputs: Vec<SourceInput> = files.iter().map(|(path, text)| SourceInput::from_text(*path, *text)).collect();
    check(&inputs, &Options::default())
        .iter()
        .map(|d| {
            let text = &inputs[d.file].text;
            let line = LineIndex::new(text).line_col(text, d.span.start).line;
            (inputs[d.file].path.clone(), d.code.as_str(), line)
        })
        .collect()
}

#[test]
fn a_global_routine_is_visible_from_other_modules() {
    let main = "MODULE MainModule\nPROC main()\n  grip_open;\n  reg1 := part_count();\nENDPROC\nENDMODULE";
    let lib = "MODULE Lib\nPROC grip_open()\nENDPROC\nFUNC num part_count()\n  RETURN 3;\nENDFUNC\nENDMODULE";
    assert_eq!(codes(&[("main.mod", main), ("lib.mod", lib)]), vec![]);
}

#[test]
fn a_local_routine_is_invisible_from_other_modules() {
    let main = "MODULE MainModule\nPROC main()\n  helper;\nENDPROC\nENDMODULE";
    let lib = "MODULE Lib\nLOCAL PROC helper()\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("main.mod", main), ("lib.mod", lib)]), vec![("main.mod".into(), "W0202", 3)]);
}

#[test]
fn local_data_hides_a_global_of_another_module() {
    let a = "MODULE A\nLOCAL VAR string n := \"a\";\nPROC pa()\n  n := \"x\";\nENDPROC\nENDMODULE";
    let b = "MODULE B\nVAR num n := 1;\nPROC pb()\n  n := 2;\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("a.mod", a), ("b.mod", b)]), vec![]);
}

#[test]
fn one_global_name_in_two_modules_is_ambiguous() {
    let a = "MODULE A\nVAR num counter;\nENDMODULE";
    let b = "MODULE B\nPROC counter()\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("a.mod", a), ("b.mod", b)]), vec![("b.mod".into(), "E0208", 2)]);
}

#[test]
fn a_persistent_declared_in_two_modules_is_one_object() {
    let a = "MODULE A\nPERS num shared := 0;\nENDMODULE";
    let b = "MODULE B\nPERS num shared := 0;\nPROC p()\n  shared := 1;\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("a.mod", a), ("b.mod", b)]), vec![]);
}

#[test]
fn two_modules_of_one_name() {
    let a = "MODULE Same\nENDMODULE";
    let b = "MODULE same\nENDMODULE";
    assert_eq!(codes(&[("a.mod", a), ("b.mod", b)]), vec![("b.mod".into(), "E0216", 1)]);
}

#[test]
fn user_declarations_hide_predefined_ones() {
    // A user routine named like a built-in instruction hides it, with its own signature.
    let src = "MODULE m\nPROC MoveL(num speed)\nENDPROC\nPROC main()\n  MoveL 5;\n  VAR num v100;\nENDPROC\nENDMODULE";
    let found = codes(&[("m.mod", src)]);
    // Only the misplaced declaration is reported; `MoveL 5` matches the user's MoveL.
    assert_eq!(found, vec![("m.mod".into(), "E0120", 6)]);
    let hide_data = "MODULE m\nVAR string v100 := \"fast\";\nPROC main()\n  TPWrite v100;\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("m.mod", hide_data)]), vec![]);
}

#[test]
fn encrypted_modules_are_reported_not_parsed() {
    let inputs = vec![SourceInput::from_bytes("enc.mod", vec![0xFC, 0x00, 0x41, 0x42])];
    let diags = check(&inputs, &Options::default());
    assert_eq!(diags.len(), 1);
    assert_eq!(diags[0].code, Code::EncryptedModule);
}

#[test]
fn syntax_only_skips_semantic_checks() {
    let src = "MODULE m\nPROC main()\n  undefined_thing := 1;\n  x := ;\nENDPROC\nENDMODULE";
    let inputs = vec![SourceInput::from_text("m.mod", src)];
    let diags = check(&inputs, &Options { syntax_only: true, ..Options::default() });
    assert_eq!(diags.iter().map(|d| d.code.as_str()).collect::<Vec<_>>(), vec!["E0120"]);
    let all = check(&inputs, &Options::default());
    assert_eq!(all.iter().map(|d| d.code.as_str()).collect::<Vec<_>>(), vec!["E0201", "E0120"]);
}

#[test]
fn every_code_is_documented_and_messages_read_well() {
    // Messages as users see them, for review (insta snapshot of a few typical ones).
    let src = "MODULE m\nVAR num n := \"text\";\nPROC main()\n  MoveL p10, v100, z10;\n  Incr 5;\n  IF n THEN\n  ENDIF\nENDPROC\nENDMODULE";
    let inputs = vec![SourceInput::from_text("m.mod", src)];
    let text: String = check(&inputs, &Options::default())
        .iter()
        .map(|d| {
            let line = LineIndex::new(src).line_col(src, d.span.start).line;
            format!("{}:{line}: {} {}\n", d.code.as_str(), d.severity_word(), d.message)
        })
        .collect();
    insta::assert_snapshot!(text);
    for code in Code::ALL {
        assert!(!code.summary().is_empty());
    }
}

#[test]
fn deepest_accepted_nesting_checks_without_overflow() {
    // 255 nested IFs whose innermost condition nests 255 parentheses: both just under
    // the parser's limits, so the checker walks the deepest tree the parser can build.
    let mut src = String::from("MODULE m\nPROC p()\n");
    for _ in 0..255 {
        src.push_str("IF TRUE THEN\n");
    }
    src.push_str(&format!("reg1 := {}1{};\n", "(".repeat(250), ")".repeat(250)));
    for _ in 0..255 {
        src.push_str("ENDIF\n");
    }
    src.push_str("ENDPROC\nENDMODULE\n");
    assert_eq!(codes(&[("deep.mod", &src)]), vec![]);
}

#[test]
fn long_bodies_checked_on_two_threads_report_like_short_ones() {
    // Over 1 MB of body takes the pipelined path (parser thread + checker thread);
    // its diagnostics must be exactly those of the one-thread path, in order.
    let mut src = String::from(
        "MODULE cam\nPERS tooldata t1 := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];\nPROC main()\n",
    );
    let mut expected = Vec::new();
    for n in 0..12_000 {
        let line = 4 + n;
        match n {
            100 => {
                src.push_str("MoveL [[1,2,3],[1,0,0,0],[0,0,0,0]],v100,z1,t1;\n");
                expected.push(("cam.mod".to_string(), "E0304", line));
            }
            5_000 => {
                src.push_str("MoveL p_missing,v100,z1,t1;\n");
                expected.push(("cam.mod".to_string(), "E0201", line));
            }
            11_999 => {
                src.push_str("MoveL [[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z1;\n");
                expected.push(("cam.mod".to_string(), "E0402", line));
            }
            _ => src.push_str(&format!(
                "MoveL [[{n}.125,-{n}.5,{n}],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z1,t1\\WObj:=wobj0;\n"
            )),
        }
    }
    src.push_str("ENDPROC\nENDMODULE\n");
    assert!(src.len() > 1 << 20, "the body must be long enough to be pipelined");
    assert_eq!(codes(&[("cam.mod", &src)]), expected);
}

#[test]
fn value_components_of_non_value_records_can_be_assigned() {
    // Found in the field (ROS-Industrial driver): a num inside a record that also holds
    // rawbytes is value data (§1.2.1); only the non-value parts cannot be assigned.
    let src = "MODULE m\nRECORD hdr\n  num a;\nENDRECORD\nRECORD msg\n  hdr h;\n  rawbytes data;\nENDRECORD\nPROC p()\n  VAR msg m;\n  VAR msg m2;\n  VAR rawbytes r;\n  m.h.a := 1;\n  m.h := [2];\n  m := m2;\n  m.data := r;\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("m.mod", src)]), vec![("m.mod".into(), "E0307", 15), ("m.mod".into(), "E0307", 16)]);
}

#[test]
fn an_undefined_parameter_type_is_reported_once() {
    let src = "MODULE m\nPROC p(nosuchtype x)\nENDPROC\nENDMODULE";
    assert_eq!(codes(&[("m.mod", src)]), vec![("m.mod".into(), "E0204", 2)]);
}

#[test]
fn mutually_recursive_records_are_found_without_exponential_work() {
    // Found by fuzzing: each record holds the other four times; walking every path
    // (4^depth) never ended. Each record is reported once (E0509), at once.
    let src = "MODULE m\nRECORD ra\n  rb x1;\n  rb x2;\n  rb x3;\n  rb x4;\nENDRECORD\nRECORD rb\n  ra y1;\n  ra y2;\n  ra y3;\n  ra y4;\nENDRECORD\nPROC main()\n  VAR ra v;\nENDPROC\nENDMODULE";
    let found = codes(&[("m.mod", src)]);
    assert_eq!(found, vec![("m.mod".into(), "E0509", 2), ("m.mod".into(), "E0509", 8)]);
}

#[test]
fn configured_data_is_known_like_predefined_data() {
    let main = "MODULE MainModule\nPROC main()\n  IF diPartReady = 1 THEN\n    Set doGrip;\n  ENDIF\n  \
                reg1 := goRecipe;\n  diPartReady := 1;\nENDPROC\nENDMODULE";
    let inputs = [SourceInput::from_text("main.mod", main)];
    let predefined =
        [("diPartReady", "signaldi"), ("DOGRIP", "signaldo"), ("goRecipe", "signalgo"), ("junk", "nosuchtype")]
            .iter()
            .map(|(name, ty)| rapid_sema::PredefinedData { name: (*name).into(), type_name: (*ty).into() })
            .collect();
    let options = Options { predefined, ..Options::default() };
    let found: Vec<(&str, u32)> = check(&inputs, &options)
        .iter()
        .map(|d| (d.code.as_str(), LineIndex::new(main).line_col(main, d.span.start).line))
        .collect();
    // A signal is semi-value data: it is read, never assigned (line 7).
    assert_eq!(found, vec![("E0308", 7)]);
    let without: Vec<&str> = check(&inputs, &Options::default()).iter().map(|d| d.code.as_str()).collect();
    assert!(without.contains(&"E0201"), "{without:?}");
}

#[test]
fn names_of_options_we_do_not_provide_say_which_option() {
    // A spot-welding program: the catalogue does not declare Spot welding, so its
    // names are undefined, and each message names the option they belong to. (Arc
    // and EGM names are declared: `tests/options.rs`.)
    let text = "MODULE Cell\nVAR spotdata spot1;\nPROC main()\n  SpotL p10, v100, spot1, tool0;\n  \
                reg1 := 1;\nENDPROC\nENDMODULE";
    let inputs = [SourceInput::from_text("cell.mod", text)];
    let messages: Vec<String> = check(&inputs, &Options::default()).iter().map(|d| d.message.clone()).collect();
    assert_eq!(
        messages,
        [
            "undefined data type `spotdata` (`spotdata` belongs to ABB's Spot welding option, \
             which OpenRAPID does not provide)",
            "no procedure `SpotL` is defined in this task; calling it raises ERR_REFUNKPRC at run time \
             (`SpotL` belongs to ABB's Spot welding option, which OpenRAPID does not provide)",
            "undefined data `p10`",
        ]
    );
}

/// A module whose `main` calls `n` procedures defined nowhere (W0202 each), then
/// `tail` (a statement of its own).
fn many_warnings(n: usize, tail: &str) -> String {
    let calls: String = (0..n).map(|i| format!("    Missing{i};\n")).collect();
    format!("MODULE m\n  PROC main()\n{calls}{tail}  ENDPROC\nENDMODULE\n")
}

fn count(found: &[(String, &'static str, u32)], code: &str) -> usize {
    found.iter().filter(|d| d.1 == code).count()
}

#[test]
fn a_file_of_many_warnings_stops_reporting_with_a_warning() {
    // 600 W0202: the first 499 are shown, the 500th place says reporting stopped, as
    // a warning (W0112) — no error is among them, so the file does not fail the check.
    let text = many_warnings(600, "");
    let found = codes(&[("m.mod", &text)]);
    assert_eq!(count(&found, "W0202"), 499);
    assert_eq!(count(&found, "W0112"), 1);
    assert_eq!(found.len(), 500, "{:?}", &found[495..]);
    assert!(found.iter().all(|d| d.1.starts_with('W')));
}

#[test]
fn an_error_held_back_by_the_cap_is_still_an_error() {
    // 600 warnings, then an undefined variable (E0201) past the cap: the error itself is
    // not shown, but E0111 says one was held back, so the check fails as it must.
    let text = many_warnings(600, "    undefined_x := 1;\n");
    let found = codes(&[("m.mod", &text)]);
    assert_eq!(count(&found, "W0202"), 499);
    assert_eq!(count(&found, "W0112"), 1);
    assert_eq!(count(&found, "E0111"), 1);
    assert_eq!(count(&found, "E0201"), 0);
    assert_eq!(found.last().map(|d| d.1), Some("E0111"));
}

#[test]
fn a_file_with_an_error_among_many_diagnostics_stops_with_an_error() {
    // An error first, then 600 warnings: the cap at the 500th place is E0111.
    let text = many_warnings(600, "").replace("  PROC main()\n", "  PROC main()\n    undefined_x := 1;\n");
    let found = codes(&[("m.mod", &text)]);
    assert_eq!(count(&found, "E0201"), 1);
    assert_eq!(count(&found, "W0202"), 498);
    assert_eq!(count(&found, "E0111"), 1);
    assert_eq!(count(&found, "W0112"), 0);
    assert_eq!(found.len(), 500);
}

/// W0706: a task's program over `rapid_limits::PROGRAM_MEMORY_BYTES` of source text in
/// all (65 comment lines of 1 MiB in one module, a small main module beside it) is
/// noted at the start of its largest file, and still checks: it is a warning.
#[test]
fn a_program_larger_than_program_memory_is_noted_at_its_largest_file() {
    let line = format!("! {}\n", "x".repeat((1 << 20) - 3));
    let big = format!("MODULE Points\n{}ENDMODULE\n", line.repeat(65));
    let main = "MODULE MainModule\nPROC main()\nENDPROC\nENDMODULE";
    let total = (big.len() + main.len()) as u64;
    assert!(total > rapid_limits::PROGRAM_MEMORY_BYTES && (big.len() as u64) < 66 << 20);
    let found = codes(&[("main.mod", main), ("points.mod", &big)]);
    assert_eq!(found, vec![("points.mod".into(), "W0706", 1)]);
}
