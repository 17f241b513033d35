//! Tests of `exec::modules`: the stand-in that keeps an unloaded module's numbering.

use super::*;

/// Types, data and routines a program declares (the checker's numbering).
fn counts(text: &str) -> (rapid_sema::types::TypeId, usize, usize) {
    let mut checked = check(vec![SourceInput::from_text("m.mod", text)], &Options::default(), None)
        .unwrap_or_else(|_| panic!("no program"));
    let errors = checked.diagnostics.iter().filter(|d| d.severity() == Severity::Error).count();
    assert_eq!(errors, 0, "{:?}", checked.diagnostics);
    let (routines, datas) = members(&checked.prog, 0);
    // The next type's number tells how many there are.
    let info = rapid_sema::types::TypeInfo {
        display: String::new(),
        kind: rapid_sema::types::TypeKind::Pending,
        span: Default::default(),
    };
    (checked.prog.types.add(info), datas.len(), routines.len())
}

#[test]
fn a_stand_in_declares_as_much_as_the_module_it_replaces() {
    let text = "MODULE m\nRECORD r num a; num b; ENDRECORD\nALIAS num n2;\nVAR r v1;\nPERS num p := 1;\n\
                CONST num c := 2;\nPROC p1(num x) VAR num l; ENDPROC\nFUNC num f1() RETURN 1; ENDFUNC\n\
                TRAP t1 ENDTRAP\nENDMODULE\n";
    let mut interner = rapid_syntax::Interner::default();
    let parse = rapid_syntax::parse(text, &mut interner);
    let replacement = stand_in(&parse.file.modules[0], 3);
    assert_eq!(counts(text), counts(&replacement));
}
