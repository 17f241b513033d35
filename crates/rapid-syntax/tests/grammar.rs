//! One test per grammar rule of the manual's EBNF (§1.1–§1.5), checked against an
//! S-expression view of the tree worked out by hand from the grammar, plus error
//! recovery and robustness on hostile input.

use rapid_syntax::dump::dump_file;
use rapid_syntax::{parse, Interner, LineIndex, SyntaxErrorKind as K};

/// The dump of a file that must parse without errors.
fn tree(src: &str) -> String {
    let mut interner = Interner::default();
    let parse = parse(src, &mut interner);
    assert!(parse.errors.is_empty(), "unexpected errors: {:?}", parse.errors);
    dump_file(&parse.file, src, &interner)
}

/// The dump of one routine body statement list.
fn body(stmts: &str) -> String {
    let src = format!("MODULE m\nPROC p()\n{stmts}\nENDPROC\nENDMODULE\n");
    let dump = tree(&src);
    let body = dump.lines().skip(1).collect::<Vec<_>>().join("\n");
    let body = body.strip_prefix("(proc p ()").unwrap_or(&body);
    body.strip_suffix(')').unwrap_or(body).trim().to_string()
}

/// The dump of an expression (as the initialiser of a declaration).
fn expr(src: &str) -> String {
    let dump = tree(&format!("MODULE m\nVAR num x := {src};\nENDMODULE"));
    let line = dump.lines().nth(1).unwrap().to_string();
    let line = line.strip_prefix("(var num x := ").unwrap_or(&line);
    line.strip_suffix(')').unwrap_or(line).to_string()
}

/// (kind, 1-based line) of every error.
fn errors(src: &str) -> Vec<(K, u32)> {
    let mut interner = Interner::default();
    let parse = parse(src, &mut interner);
    let index = LineIndex::new(src);
    let mut errs: Vec<(K, u32)> =
        parse.errors.iter().map(|e| (e.kind, index.line_col(src, e.span.start).line)).collect();
    errs.sort_by_key(|&(kind, line)| (line, format!("{kind:?}")));
    errs
}

// ---- expressions: §1.3.5 precedence, §1.3.6 structure ----------------------------------

#[test]
fn multiplication_binds_tighter_than_addition() {
    assert_eq!(expr("a + b * c"), "(+ a (* b c))");
    assert_eq!(expr("a * b + c"), "(+ (* a b) c)");
    assert_eq!(expr("a DIV b MOD c"), "(MOD (DIV a b) c)");
}

#[test]
fn same_level_operators_associate_left() {
    assert_eq!(expr("a + b + c"), "(+ (+ a b) c)");
    assert_eq!(expr("a - b - c"), "(- (- a b) c)");
    assert_eq!(expr("a OR b OR c"), "(OR (OR a b) c)");
    assert_eq!(expr("a OR b XOR c"), "(XOR (OR a b) c)");
}

#[test]
fn and_binds_tighter_than_or_and_relations_tighter_than_and() {
    assert_eq!(expr("a AND b OR c AND d"), "(OR (AND a b) (AND c d))");
    assert_eq!(expr("a < b AND c < d"), "(AND (< a b) (< c d))");
    assert_eq!(expr("a + 1 >= b * 2"), "(>= (+ a 1) (* b 2))");
}

#[test]
fn not_applies_to_a_whole_logical_term() {
    // <expr> ::= [NOT] <logical term> { (OR | XOR) <logical term> }
    assert_eq!(expr("NOT a AND b"), "(not (AND a b))");
    assert_eq!(expr("NOT a OR b"), "(OR (not a) b)");
    assert_eq!(expr("a AND NOT b"), "(AND a (not b))");
}

#[test]
fn leading_sign_covers_the_first_term() {
    assert_eq!(expr("-a * b + c"), "(+ (neg (* a b)) c)");
    assert_eq!(expr("-.002"), "(neg .002)");
    assert_eq!(expr("a * -1"), "(* a (neg 1))");
}

#[test]
fn parentheses_override_precedence() {
    assert_eq!(expr("(a + b) * c"), "(* (+ a b) c)");
}

#[test]
fn comparisons_do_not_chain() {
    let src = "MODULE m\nVAR bool x := a < b < c;\nENDMODULE";
    assert_eq!(errors(src), vec![(K::UnexpectedToken, 2)]);
}

#[test]
fn data_references_elements_and_components() {
    assert_eq!(expr("a{1}"), "(index a 1)");
    assert_eq!(expr("a{i, j + 1}.trans.x"), "(. (. (index a i (+ j 1)) trans) x)");
}

#[test]
fn aggregates_nest() {
    assert_eq!(expr("[[1, 2, 3], [1, 0, 0, 0]]"), "[[1 2 3] [1 0 0 0]]");
}

#[test]
fn literals_of_every_kind() {
    assert_eq!(expr(r#""say ""hi"" \\""#), r#""say ""hi"" \\""#);
    assert_eq!(expr("TRUE XOR FALSE"), "(XOR TRUE FALSE)");
    assert_eq!(expr("0xFF + 0o17 + 0b1 + 3E2 + 9E9"), "(+ (+ (+ (+ 0xFF 0o17) 0b1) 3E2) 9E9)");
}

#[test]
fn function_calls_with_every_argument_form() {
    assert_eq!(expr("Sin(angle)"), "(fn Sin angle)");
    assert_eq!(expr("Polar(Dist:=3.9, Angle:=0.7)"), "(fn Polar (Dist:= 3.9) (Angle:= 0.7))");
    assert_eq!(expr("Cosine(0.78\\Rad)"), "(fn Cosine 0.78 \\Rad)");
    assert_eq!(expr("Dist(\\distance:=pos1, p2)"), "(fn Dist (\\distance pos1) p2)");
    assert_eq!(expr("ReadBin(File \\Time?Maxtime)"), "(fn ReadBin File (\\Time? Maxtime))");
    assert_eq!(expr("CDate()"), "(fn CDate)");
}

#[test]
fn expression_placeholder() {
    assert_eq!(expr("<EXP> + 1"), "(+ Exp 1)");
}

// ---- statements ------------------------------------------------------------------------

#[test]
fn assignment_to_entire_element_and_component() {
    assert_eq!(
        body("x := 1;\na{2} := 3;\np.trans.x := 4;"),
        "(assign x 1)\n  (assign (index a 2) 3)\n  (assign (. (. p trans) x) 4)"
    );
}

#[test]
fn procedure_calls_with_commas_as_the_ebnf_allows() {
    assert_eq!(body("MoveL p1, v100, z10, tool0\\WObj:=wobj0;"), "(call MoveL p1 v100 z10 tool0 (\\WObj wobj0))");
    assert_eq!(body("MoveL p1, v100, z10, tool0, \\WObj:=wobj0;"), "(call MoveL p1 v100 z10 tool0 (\\WObj wobj0))");
    assert_eq!(
        body("MoveL[[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v100,fine,tool0;").lines().count(),
        1
    );
    assert_eq!(body("Stop;"), "(call Stop)");
    assert_eq!(body("TPWrite \"n=\"\\Num:=n;"), "(call TPWrite \"n=\" (\\Num n))");
    assert_eq!(body("routine4 \\on;"), "(call routine4 \\on)");
    assert_eq!(body("proc1 \\x?y;"), "(call proc1 (\\x? y))");
    assert_eq!(body("Polar Dist:=1, Angle:=2;"), "(call Polar (Dist:= 1) (Angle:= 2))");
    assert_eq!(body("proc1 <ARG>;"), "(call proc1 <ARG>)");
}

#[test]
fn required_arguments_need_commas() {
    let src = "MODULE m\nPROC p()\nMoveL p1 v100;\nENDPROC\nENDMODULE";
    assert_eq!(errors(src), vec![(K::UnexpectedToken, 3)]);
}

#[test]
fn late_binding_calls() {
    assert_eq!(body("% \"proc\" + NumToStr(n, 0) % x, y;"), "(late (+ \"proc\" (fn NumToStr n 0)) x y)");
    assert_eq!(body("% names{i} %;"), "(late (index names i))");
}

#[test]
fn if_with_elseif_and_else() {
    let expected = "(if (> a 1)\n    (assign x 1)\n  elseif (< a 0)\n    (assign x 2)\n  else\n    (assign x 3))";
    assert_eq!(body("IF a > 1 THEN\nx := 1;\nELSEIF a < 0 THEN\nx := 2;\nELSE\nx := 3;\nENDIF"), expected);
}

#[test]
fn compact_if_takes_one_simple_statement() {
    assert_eq!(body("IF reg1 > 5 GOTO next;"), "(if1 (> reg1 5) (goto next))");
    assert_eq!(body("IF a = 1 x := 2;"), "(if1 (= a 1) (assign x 2))");
    let src = "MODULE m\nPROC p()\nIF a\nFOR i FROM 1 TO 2 DO\nENDFOR\nENDPROC\nENDMODULE";
    assert_eq!(errors(src), vec![(K::CompoundInCompactIf, 4)]);
}

#[test]
fn for_with_and_without_step() {
    assert_eq!(body("FOR i FROM 1 TO 10 DO\nx := i;\nENDFOR"), "(for i 1 10\n    (assign x i))");
    assert_eq!(body("FOR i FROM 10 TO 1 STEP -2 DO\nENDFOR"), "(for i 10 1 step (neg 2))");
}

#[test]
fn while_loop() {
    assert_eq!(body("WHILE n < 10 DO\nIncr n;\nENDWHILE"), "(while (< n 10)\n    (call Incr n))");
}

#[test]
fn test_with_several_values_per_case_and_default() {
    let expected = "(test n\n  case 1 2 3\n    (call a)\n  case 4\n  default\n    (call c))";
    assert_eq!(body("TEST n\nCASE 1, 2, 3:\na;\nCASE 4:\nDEFAULT:\nc;\nENDTEST"), expected);
}

#[test]
fn goto_labels_and_keyword_statements() {
    assert_eq!(body("start:\nGOTO start;"), "(label start)\n  (goto start)");
    assert_eq!(
        body("RETURN;\nRETURN x + 1;\nRAISE;\nRAISE 5;\nEXIT;"),
        "(return)\n  (return (+ x 1))\n  (raise)\n  (raise 5)\n  (exit)"
    );
    assert_eq!(body("CONNECT intno1 WITH trap1;"), "(connect intno1 trap1)");
}

#[test]
fn instruction_placeholders() {
    assert_eq!(body("<SMT>\n<VAR> := 1;"), "Smt\n  (assign Var 1)");
}

// ---- routines ----------------------------------------------------------------------------

#[test]
fn parameters_of_every_kind() {
    let src = "MODULE m\nPROC r(num a, INOUT num b, VAR num c{*,*}, PERS pos d \\num e | num f, \\switch on | switch off)\nENDPROC\nENDMODULE";
    let dump = tree(src);
    assert_eq!(
        dump.lines().nth(1).unwrap(),
        "(proc r (num a#1 inout num b#2 var num c{2}#3 pers pos d#4 \\num e#5 \\num f#5 \\switch on#6 \\switch off#6))"
    );
}

#[test]
fn parameter_placeholders() {
    let dump = tree("MODULE m\nPROC r(<PAR>, \\<ALT>)\nENDPROC\nENDMODULE");
    assert_eq!(dump.lines().nth(1).unwrap(), "(proc r (Par Alt))");
}

#[test]
fn func_and_trap_declarations() {
    let dump =
        tree("MODULE m\nLOCAL FUNC num vecLen(pos v)\nRETURN Sqrt(v.x);\nENDFUNC\nTRAP t\nRETURN;\nENDTRAP\nENDMODULE");
    assert_eq!(dump.lines().nth(1).unwrap(), "(local func num vecLen (pos v#1)");
    assert!(dump.contains("(trap t ()\n  (return))"));
}

#[test]
fn handlers_in_order_with_error_numbers() {
    let src = "MODULE m\nPROC p()\nx := 1;\nBACKWARD\ny;\nERROR (ERR_DIVZERO, 5)\nRETRY;\nUNDO\nz;\nENDPROC\nENDMODULE";
    let dump = tree(src);
    assert!(
        dump.contains("backward:\n    (call y)\n  error (ERR_DIVZERO 5):\n    (retry)\n  undo:\n    (call z)"),
        "{dump}"
    );
    let wrong = "MODULE m\nPROC p()\nUNDO\nERROR\nENDPROC\nENDMODULE";
    assert_eq!(errors(wrong), vec![(K::UnexpectedToken, 4)]);
}

#[test]
fn routine_data_comes_before_instructions() {
    assert_eq!(body("VAR num n := 1;\nn := 2;"), "(var num n := 1)\n  (assign n 2)");
    let src = "MODULE m\nPROC p()\nn := 2;\nVAR num n;\nENDPROC\nENDMODULE";
    assert_eq!(errors(src), vec![(K::UnexpectedToken, 4)]);
}

// ---- modules and declarations --------------------------------------------------------------

#[test]
fn module_attributes_in_the_manuals_order() {
    assert_eq!(
        tree("MODULE m (SYSMODULE, NOSTEPIN, VIEWONLY)\nENDMODULE").trim(),
        "(module m sysmodule nostepin viewonly)"
    );
    assert_eq!(errors("MODULE m (READONLY, SYSMODULE)\nENDMODULE"), vec![(K::ModuleAttributeOrder, 1)]);
    assert_eq!(errors("MODULE m (NOVIEW, NOSTEPIN)\nENDMODULE"), vec![(K::ModuleAttributeOrder, 1)]);
    assert_eq!(errors("MODULE m (SYSMODULE, NOVIEW)\nENDMODULE"), vec![]);
    assert_eq!(errors("MODULE m (VIEWONLY, VIEWONLY)\nENDMODULE"), vec![(K::DuplicateModuleAttribute, 1)]);
}

#[test]
fn records_and_aliases() {
    let dump = tree("MODULE m\nRECORD part\nstring name;\nnum weight;\nENDRECORD\nLOCAL ALIAS num level;\nENDMODULE");
    assert_eq!(dump.lines().nth(1).unwrap(), "(record part (string name) (num weight))");
    assert_eq!(dump.lines().nth(2).unwrap(), "(local alias num level)");
}

#[test]
fn data_declarations_with_scope_dims_and_init() {
    let dump = tree("MODULE m\nLOCAL VAR num a{2, 3} := [[1,2,3],[4,5,6]];\nTASK PERS num tp := 1;\nCONST pos seq{3} := [[0,0,0],[1,1,1],[2,2,2]];\nPERS num g;\nENDMODULE");
    let lines: Vec<&str> = dump.lines().collect();
    assert_eq!(lines[1], "(local var num a {2 3} := [[1 2 3] [4 5 6]])");
    assert_eq!(lines[2], "(task pers num tp := 1)");
    assert_eq!(lines[3], "(const pos seq {3} := [[0 0 0] [1 1 1] [2 2 2]])");
    assert_eq!(lines[4], "(pers num g)");
    assert_eq!(errors("MODULE m\nVAR num a{1,2,3,4};\nENDMODULE"), vec![(K::TooManyDimensions, 2)]);
}

#[test]
fn module_item_placeholders() {
    assert_eq!(tree("MODULE m\n<TDN>\n<DDN>\n<RDN>\nENDMODULE").lines().count(), 4);
}

#[test]
fn header_case_and_multiple_modules() {
    let src =
        "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\nmodule A\nproc P()\nendproc\nEndModule\nMODULE B\nENDMODULE\n";
    let dump = tree(src);
    assert!(dump.starts_with("(module A)\n(proc P ())\n(module B)"), "{dump}");
}

#[test]
fn reserved_words_are_not_names() {
    assert_eq!(errors("MODULE m\nVAR num IF;\nENDMODULE"), vec![(K::ReservedWordAsName, 2)]);
}

#[test]
fn text_outside_modules_is_reported_once() {
    assert_eq!(errors("junk here\nMODULE m\nENDMODULE\nmore junk"), vec![(K::OutsideModule, 1), (K::OutsideModule, 4)]);
}

// ---- error recovery ---------------------------------------------------------------------------

#[test]
fn one_run_reports_errors_in_every_routine() {
    let src = "MODULE m\nPROC a()\nx := ;\nENDPROC\nPROC b()\nMoveL p1 v1;\nENDPROC\nPROC c()\nIF x THEN\ny;\nENDPROC\nENDMODULE";
    assert_eq!(errors(src), vec![(K::UnexpectedToken, 3), (K::UnexpectedToken, 6), (K::UnclosedBlock, 9)]);
}

#[test]
fn missing_semicolon_is_reported_after_the_last_token() {
    let src = "MODULE m\nPROC a()\nx := 1\ny := 2;\nENDPROC\nENDMODULE";
    assert_eq!(errors(src), vec![(K::UnexpectedToken, 3)]);
}

#[test]
fn unclosed_blocks_are_reported_at_their_opening() {
    assert_eq!(errors("MODULE m\nPROC a()\nWHILE TRUE DO\nENDPROC\nENDMODULE"), vec![(K::UnclosedBlock, 3)]);
    assert_eq!(errors("MODULE m\nPROC a()\n"), vec![(K::UnclosedBlock, 1), (K::UnclosedBlock, 2)]);
    assert_eq!(errors("MODULE m\nRECORD r\nnum x;\nPROC a()\nENDPROC\nENDMODULE"), vec![(K::UnclosedBlock, 2)]);
}

// ---- robustness -------------------------------------------------------------------------------

#[test]
fn ten_thousand_nested_parentheses_are_one_clean_error() {
    let src = format!("MODULE m\nVAR num x := {}1{};\nENDMODULE", "(".repeat(10_000), ")".repeat(10_000));
    assert_eq!(errors(&src), vec![(K::NestingTooDeep, 2)]);
}

#[test]
fn a_thousand_nested_ifs_are_one_clean_error() {
    let mut src = String::from("MODULE m\nPROC p()\n");
    for _ in 0..1000 {
        src.push_str("IF TRUE THEN\n");
    }
    for _ in 0..1000 {
        src.push_str("ENDIF\n");
    }
    src.push_str("ENDPROC\nENDMODULE\n");
    // The 257th IF (line 2 + 257) crosses the limit of 256 nested statements.
    assert_eq!(errors(&src), vec![(K::NestingTooDeep, 259)]);
}

#[test]
fn deep_aggregates_and_signs_are_bounded_too() {
    let src = format!(
        "MODULE m\nVAR num x := {}1{};\nVAR num y := {}1;\nENDMODULE",
        "[".repeat(5000),
        "]".repeat(5000),
        "-".repeat(5000)
    );
    assert_eq!(errors(&src), vec![(K::NestingTooDeep, 2), (K::NestingTooDeep, 3)]);
}

#[test]
fn binary_junk_gives_errors_not_panics() {
    let mut seed = 12345u32;
    let junk: String = (0..20_000)
        .map(|_| {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
            char::from((seed >> 16) as u8)
        })
        .collect();
    let errs = errors(&junk);
    assert!(!errs.is_empty());
    assert!(errs.len() <= 101, "errors are capped per file, got {}", errs.len());
    assert_eq!(errs.last().map(|e| e.0), Some(K::TooManyErrors));
}

#[test]
fn a_ten_megabyte_line_is_linear() {
    let line = "x := x + 1; ".repeat(900_000);
    let src = format!("MODULE m\nPROC p()\n{line}\nENDPROC\nENDMODULE");
    assert!(src.len() > 10_000_000);
    assert_eq!(errors(&src), vec![]);
}

#[test]
fn truncated_files_and_empty_input() {
    assert_eq!(errors(""), vec![(K::OutsideModule, 1)]);
    assert_eq!(errors("MODULE"), vec![(K::UnclosedBlock, 1), (K::UnexpectedToken, 1)]);
    assert_eq!(
        errors("MODULE m\nPROC p()\nx := [1, 2"),
        vec![(K::UnclosedBlock, 1), (K::UnclosedBlock, 2), (K::UnexpectedToken, 3)]
    );
}

#[test]
fn long_operator_chains_are_bounded_too() {
    // Left-nested trees are walked recursively by later passes, so a chain of 10,000
    // additions is one clean error, not a stack overflow further down.
    let src = format!("MODULE m\nPROC p()\nx := {}1;\ny := 2;\nENDPROC\nENDMODULE", "1 + ".repeat(10_000));
    assert_eq!(errors(&src), vec![(K::NestingTooDeep, 3)]);
    let fine = format!("MODULE m\nVAR num x := {}1;\nENDMODULE", "1 + ".repeat(200));
    assert_eq!(errors(&fine), vec![]);
}

#[test]
fn long_component_chains_are_bounded_too() {
    let src = format!("MODULE m\nPROC p()\nx := a{};\nENDPROC\nENDMODULE", ".b{1}".repeat(5_000));
    assert_eq!(errors(&src), vec![(K::NestingTooDeep, 3)]);
}

#[test]
fn a_component_of_a_function_result_is_refused_plainly_and_the_statement_goes_on() {
    // §1.3: components and elements are selected of data, not of a function call.
    let src = "MODULE m\nPROC p()\n  x := f(1).a{2}.b + 1;\n  y := 2;\nENDPROC\nENDMODULE\n";
    let mut interner = Interner::default();
    let parse = parse(src, &mut interner);
    let messages: Vec<&str> = parse.errors.iter().map(|e| e.message.as_str()).collect();
    assert_eq!(
        messages,
        ["a component or element of a function's result cannot be selected: assign the result to a variable first"]
    );
    // The selectors are read over: the rest of the expression and the next statement parse.
    assert!(dump_file(&parse.file, src, &interner).contains("(assign y 2)"), "{:?}", parse.errors);
}
