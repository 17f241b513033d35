//! Fuzz target `cfg`: arbitrary bytes as a `.cfg` file through the parser and every
//! typed view (EIO, SYS, MOC) and the editor. Nothing may panic; every finding's span
//! lies in the text on the line it names; rewriting a value keeps the file readable.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rapid_config::{eio, find_named, moc, parse, sys, CfgError};

fn check_findings(text: &str, errors: &[CfgError]) {
    for error in errors {
        assert!(error.span.start <= error.span.end && error.span.end <= text.len(), "span {:?}", error.span);
        let line = text.as_bytes()[..error.span.start].iter().filter(|&&b| b == b'\n').count() + 1;
        assert_eq!(error.line as usize, line, "finding `{}` on the wrong line", error.message);
    }
}

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let file = parse(&text);
    check_findings(&text, &file.errors);
    for section in &file.sections {
        for inst in &section.instances {
            assert!(inst.span.start <= inst.span.end && inst.span.end <= text.len());
        }
    }
    check_findings(&text, &eio::read(&file).errors);
    check_findings(&text, &sys::read(&file).errors);
    let _ = moc::robots(&file);
    let _ = moc::mechanical_units(&file);
    let _ = moc::external_units(&file);
    if let Some((section, instance)) =
        file.sections.iter().enumerate().find_map(|(s, sec)| (!sec.instances.is_empty()).then_some((s, 0)))
    {
        if let Ok(rewritten) = file.with_value(section, instance, "Name", "fuzz") {
            let again = parse(&rewritten);
            assert_eq!(again.sections.len(), file.sections.len(), "a rewrite changed the sections:\n{rewritten}");
        }
    }
    let _ = find_named(&file, "EIO_SIGNAL", "fuzz");
});
