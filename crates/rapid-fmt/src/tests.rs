//! Layout rules, each shown by an input and the output worked out by hand from the
//! rules in docs/fmt.md.

use super::*;
use crate::layout::Threads;

fn fmt(text: &str) -> String {
    fmt_with(text, &Config::default())
}

fn fmt_with(text: &str, config: &Config) -> String {
    let out = format(text, config).unwrap_or_else(|refusal| panic!("refused: {refusal:?}"));
    // Every case is also idempotent.
    assert_eq!(format(&out, config).as_ref(), Ok(&out), "formatting again changed the output");
    out
}

#[test]
fn blocks_are_indented_four_spaces_per_level() {
    let input = "module m\nproc main()\nif a=1 then\nb:=2;\nelseif a=2 then\nb:=3;\nelse\nwhile b<3 do\nb:=b+1;\nendwhile\nendif\nendproc\nendmodule\n";
    let expected = "\
MODULE m
    PROC main()
        IF a = 1 THEN
            b := 2;
        ELSEIF a = 2 THEN
            b := 3;
        ELSE
            WHILE b < 3 DO
                b := b + 1;
            ENDWHILE
        ENDIF
    ENDPROC
ENDMODULE
";
    assert_eq!(fmt(input), expected);
}

#[test]
fn one_statement_per_line_and_compact_if_stays_one() {
    let input = "MODULE m\n  PROC main()\n    a:=1; b:=2;\n    IF a>0 b:=0;\n  ENDPROC\nENDMODULE";
    let expected = "MODULE m\n    PROC main()\n        a := 1;\n        b := 2;\n        IF a > 0 b := 0;\n    ENDPROC\nENDMODULE\n";
    assert_eq!(fmt(input), expected);
}

#[test]
fn test_case_and_handlers_stand_one_level_out() {
    let input =
        "MODULE m\nPROC p()\nTEST n\nCASE 1,2:\nx:=1;\nDEFAULT:\nx:=0;\nENDTEST\nERROR\nRETRY;\nENDPROC\nENDMODULE\n";
    let expected = "\
MODULE m
    PROC p()
        TEST n
        CASE 1, 2:
            x := 1;
        DEFAULT:
            x := 0;
        ENDTEST
    ERROR
        RETRY;
    ENDPROC
ENDMODULE
";
    assert_eq!(fmt(input), expected);
}

#[test]
fn keywords_upper_built_ins_as_declared_user_names_kept() {
    let input = "module Cell\nvar NUM Counter:=0;\nproc Main()\nmovel p10,V1000,z50,TOOL0\\wobj:=wobj0;\ncounter:=counter+1;\ntpwrite \"n\"\\num:=Counter;\nendproc\nendmodule\n";
    let expected = "\
MODULE Cell
    VAR num Counter:=0;
    PROC Main()
        MoveL p10, v1000, z50, tool0\\WObj:=wobj0;
        counter := counter + 1;
        TPWrite \"n\"\\Num:=Counter;
    ENDPROC
ENDMODULE
";
    assert_eq!(fmt(input), expected);
}

#[test]
fn a_user_declaration_hides_the_built_in_spelling() {
    // The module declares its own `movel`: calls keep the user's spelling.
    let input =
        "MODULE m\nPROC movel(num x)\nENDPROC\nPROC main()\nmovel 1;\nMOVEJ p, v10, fine, tool0;\nENDPROC\nENDMODULE\n";
    let out = fmt(input);
    assert!(out.contains("        movel 1;"), "{out}");
    assert!(out.contains("        MoveJ p, v10, fine, tool0;"), "{out}");
}

#[test]
fn comments_are_kept_where_they_are() {
    let input = "! file comment\nMODULE m\n! about main\nPROC main()\n  x := 1;   ! trailing, spaces kept\n! inside\nENDPROC\nENDMODULE ! end\n";
    let expected = "\
! file comment
MODULE m
    ! about main
    PROC main()
        x := 1;   ! trailing, spaces kept
        ! inside
    ENDPROC
ENDMODULE ! end
";
    assert_eq!(fmt(input), expected);
}

#[test]
fn blank_lines_are_kept_up_to_the_limit() {
    let input = "MODULE m\n\n\n\n\nVAR num a;\n\nVAR num b;\nENDMODULE\n";
    assert_eq!(fmt(input), "MODULE m\n\n\n    VAR num a;\n\n    VAR num b;\nENDMODULE\n");
    let config = Config { max_blank_lines: 0, ..Config::default() };
    assert_eq!(fmt_with(input, &config), "MODULE m\n    VAR num a;\n    VAR num b;\nENDMODULE\n");
}

#[test]
fn crlf_line_ends_and_header_are_kept() {
    let input = "%%%\r\n  VERSION:1\r\n  LANGUAGE:ENGLISH\r\n%%%\r\nMODULE m\r\nVAR num a;\r\nENDMODULE\r\n";
    let expected = "%%%\r\n  VERSION:1\r\n  LANGUAGE:ENGLISH\r\n%%%\r\nMODULE m\r\n    VAR num a;\r\nENDMODULE\r\n";
    assert_eq!(fmt(input), expected);
}

#[test]
fn module_attributes_records_traps_and_labels() {
    let input = "MODULE lib(SYSMODULE,NOSTEPIN)\nRECORD pair\nnum a;\nnum b;\nENDRECORD\nTRAP t\nlbl:\nRETURN;\nENDTRAP\nENDMODULE\n";
    let expected = "\
MODULE lib (SYSMODULE, NOSTEPIN)
    RECORD pair
        num a;
        num b;
    ENDRECORD
    TRAP t
        lbl:
        RETURN;
    ENDTRAP
ENDMODULE
";
    assert_eq!(fmt(input), expected);
}

#[test]
fn long_argument_lists_wrap_after_the_instruction_name() {
    let config = Config { max_width: 40, ..Config::default() };
    let input =
        "MODULE m\nPROC p()\nTPReadFK reg1,\"More?\",stEmpty,stEmpty,stEmpty,\"Yes\",\"No\";\nENDPROC\nENDMODULE\n";
    // 8 spaces + `TPReadFK ` puts continuation lines at column 17; the first line is
    // 40 wide; `stEmpty, stEmpty,` ends at column 34 and ` "Yes",` would make it 41.
    let expected = "\
MODULE m
    PROC p()
        TPReadFK reg1, \"More?\", stEmpty,
                 stEmpty, stEmpty,
                 \"Yes\", \"No\";
    ENDPROC
ENDMODULE
";
    assert_eq!(fmt_with(input, &config), expected);
}

#[test]
fn long_aggregates_wrap_inside_their_bracket() {
    let config = Config { max_width: 60, ..Config::default() };
    let input =
        "MODULE m\nPERS tooldata t:=[TRUE,[[0,0,0],[1,0,0,0]],[0.001,[0,0,0.001],[1,0,0,0],0,0,0]];\nENDMODULE\n";
    // The commas at depth 1 are the outermost; continuation under the `T` of TRUE.
    let expected = "\
MODULE m
    PERS tooldata t:=[TRUE,[[0,0,0],[1,0,0,0]],
                      [0.001,[0,0,0.001],[1,0,0,0],0,0,0]];
ENDMODULE
";
    assert_eq!(fmt_with(input, &config), expected);
}

#[test]
fn a_comment_inside_a_statement_ends_its_line() {
    let input = "MODULE m\nCONST num a{3}:=[1, ! first\n2,\n! the rest\n3];\nENDMODULE\n";
    let expected = "MODULE m\n    CONST num a{3}:=[1, ! first\n                     2,\n                     ! the rest\n                     3];\nENDMODULE\n";
    assert_eq!(fmt(input), expected);
}

#[test]
fn aggregate_spaces_option() {
    let config = Config { aggregate_spaces: true, indent_width: 2, ..Config::default() };
    let out = fmt_with("MODULE m\nCONST pos p:=[1,2,3];\nENDMODULE\n", &config);
    assert_eq!(out, "MODULE m\n  CONST pos p:=[1, 2, 3];\nENDMODULE\n");
}

#[test]
fn syntax_errors_are_refused() {
    let refusal = format("MODULE m\nPROC p()\n  x := ;\nENDPROC\nENDMODULE\n", &Config::default()).unwrap_err();
    assert!(matches!(refusal, Refusal::SyntaxErrors(errors) if !errors.is_empty()));
}

#[test]
fn placeholders_stay_statements() {
    let input = "MODULE m\nPROC p()\n<SMT>\nx:=1;\nENDPROC\nENDMODULE\n";
    assert_eq!(fmt(input), "MODULE m\n    PROC p()\n        <SMT>\n        x := 1;\n    ENDPROC\nENDMODULE\n");
}

#[test]
fn long_files_are_parsed_while_laid_out() {
    // Over 1 MB: the bodies are parsed on a second thread.
    let body = "x:=x+1;\n".repeat(140_000);
    let good = format!("MODULE m\nVAR num x;\nPROC p()\nVAR num movel;\n{body}movel:=1;\nENDPROC\nENDMODULE\n");
    assert!(good.len() > super::PARALLEL_THRESHOLD);
    let out = format(&good, &Config::default()).unwrap();
    assert!(out.starts_with("MODULE m\n    VAR num x;\n    PROC p()\n        VAR num movel;\n        x := x + 1;\n"));
    // The local `movel` keeps its spelling.
    assert!(out.ends_with("        x := x + 1;\n        movel := 1;\n    ENDPROC\nENDMODULE\n"));
    let bad = good.replace("movel:=1;", "movel:=;");
    assert!(matches!(format(&bad, &Config::default()), Err(Refusal::SyntaxErrors(errors)) if errors.len() == 1));
}

#[test]
fn long_files_lay_out_on_threads_as_short_ones_do() {
    // Over 1 MB: verified on a second thread in chunks, and lexed on a third in
    // batches, whose edges fall anywhere in the file; the result must be what one
    // thread writes, comments, blank lines and wrapped lines included.
    let mut body = String::new();
    for i in 0..9_000 {
        body.push_str(&format!("! step {i}\n\n\n\nmovel [[{i}.5,0,1],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,z1,tool0\\wobj:=wobj0;\n"));
        body.push_str("IF x>1 THEN ! check\nx:=x+1; ! count\nendif\n");
        body.push_str(&format!(
            "TPWrite \"a long text to make the line wrap at the width\"+NumToStr(x,0)+\"{i}\", ! why\n\\Num:=x;\n"
        ));
    }
    let text = format!("MODULE m\nVAR num x;\nPROC p()\n{body}ENDPROC\nENDMODULE\n");
    assert!(text.len() > super::PARALLEL_THRESHOLD);
    let config = Config::default();
    let declared = || syntax::outline(&text).map_err(|_| "outline").unwrap().declared;
    let on_one = layout::format(&text, &config, declared(), Threads::One).unwrap();
    let on_two = layout::format(&text, &config, declared(), Threads::Verifier).unwrap();
    assert!(on_two == on_one, "the layout verified on a thread differs");
    let on_three = layout::format(&text, &config, declared(), Threads::LexerAndVerifier).unwrap();
    assert!(on_three == on_one, "the layout lexed and verified on threads differs");
    // Spot checks worked out by hand from the rules.
    assert!(on_one.contains("        ! step 8999\n\n\n        MoveL [[8999.5,0,1],"));
    assert!(on_one.contains("        IF x > 1 THEN ! check\n            x := x + 1; ! count\n        ENDIF\n"));
}

/// A long module whose outline declares `movel` (a routine of its own, after the
/// statements that call it): every `movel` keeps its spelling, `moveJ` does not.
fn long_module_declaring_movel() -> String {
    let body = "movel;\nmoveJ p,v100,z1,tool0;\n".repeat(45_000);
    format!("MODULE m\nPROC main()\n{body}ENDPROC\nPROC movel()\nENDPROC\nENDMODULE\n")
}

#[test]
fn long_files_keep_names_their_outline_declares() {
    // The layout starts before the outline is parsed: whatever it respelled meanwhile
    // must come out as if it had known the outline's names from the start.
    let text = long_module_declaring_movel();
    assert!(text.len() > super::PARALLEL_THRESHOLD);
    let out = format(&text, &Config::default()).unwrap();
    assert!(out.starts_with("MODULE m\n    PROC main()\n        movel;\n        MoveJ p, v100, z1, tool0;\n"));
    assert!(out.ends_with("        MoveJ p, v100, z1, tool0;\n    ENDPROC\n    PROC movel()\n    ENDPROC\nENDMODULE\n"));
    assert!(!out.contains("MoveL"));
}

#[test]
fn a_layout_that_respelled_a_declared_name_starts_again() {
    // The outline comes late (after the layout respelled `movel` as `MoveL`, as the
    // first statement calls it): the layout must answer that it starts again, with the
    // outline's names, and never give the text it wrote.
    let text = long_module_declaring_movel();
    let declared = syntax::outline(&text).map_err(|_| "outline").unwrap().declared;
    let (send, names) = std::sync::mpsc::sync_channel(1);
    let late = std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(300));
        let _ = send.send(declared);
    });
    let laid = layout::format_before_outline(&text, &Config::default(), names, Threads::Verifier);
    late.join().unwrap();
    let layout::Laid::Again(declared) = laid else { panic!("the layout did not start again") };
    let again = layout::format(&text, &Config::default(), declared, Threads::LexerAndVerifier).unwrap();
    assert_eq!(again, format(&text, &Config::default()).unwrap());
    assert!(again.contains("        movel;\n") && !again.contains("MoveL"));
}

#[test]
fn long_files_with_outline_errors_are_refused_for_them() {
    // The layout runs while the outline is parsed; the outline's errors still refuse
    // the file, as they do a short one.
    let text = long_module_declaring_movel().replace("PROC movel()", "PROC movel(");
    assert!(matches!(format(&text, &Config::default()), Err(Refusal::SyntaxErrors(errors)) if !errors.is_empty()));
}

#[test]
fn a_name_declared_after_it_was_respelled_keeps_its_spelling_from_there() {
    // `movel` in `a` is the instruction; `b` declares a local `movel`, which keeps its
    // spelling from its declaration on (the layout notes locals as they go by, and the
    // spellings it remembers between statements must not outlive that).
    let input = "MODULE m\nPROC a()\nmovel p,v100,z1,tool0;\nENDPROC\nPROC b()\nVAR num movel;\nmovel:=1;\nENDPROC\nPROC c()\nmovel p,v100,z1,tool0;\nENDPROC\nENDMODULE\n";
    let expected = "\
MODULE m
    PROC a()
        MoveL p, v100, z1, tool0;
    ENDPROC
    PROC b()
        VAR num movel;
        movel := 1;
    ENDPROC
    PROC c()
        movel p, v100, z1, tool0;
    ENDPROC
ENDMODULE
";
    assert_eq!(fmt(input), expected);
}
