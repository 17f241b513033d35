//! What the checker hands a body sink with each item (`rapid_sema::ItemFacts`): the
//! declaration each name and call denotes, the routine's own data numbered in the
//! order it is declared, the parameter each argument was bound to and the type of
//! each expression.

use rapid_sema::symbols::Def;
use rapid_sema::{analyze_with, BodySink, Denotes, ExprType, ItemFacts, Options, SourceInput, Tables};
use rapid_syntax::ast::{Arena, ArgList, BodyItem, ExprKind, Routine, Stmt, StmtKind};

/// Writes down, for each item, what the facts say of its names, calls and arguments.
struct Recorder<'t> {
    text: &'t str,
    seen: Vec<String>,
}

impl Recorder<'_> {
    fn denotes(&self, tables: Tables<'_>, denotes: Option<Denotes>) -> String {
        match denotes {
            None => "unknown".into(),
            Some(Denotes::Nothing) => "nothing".into(),
            Some(Denotes::Local(n)) => format!("own data {n}"),
            Some(Denotes::Decl(Def::Data(idx))) => format!("data {}", tables.datas[idx as usize].display),
            Some(Denotes::Decl(Def::Routine(idx))) => format!("routine {}", tables.routines[idx as usize].display),
            Some(Denotes::Decl(Def::Type(_))) => "a type".into(),
        }
    }

    /// `param=argument` for each bound parameter of the call of `routine`.
    fn bindings(&self, tables: Tables<'_>, facts: &ItemFacts, arena: &Arena, args: ArgList, routine: u32) -> String {
        let info = &tables.routines[routine as usize];
        let Some(bound) = facts.bound(args, info.params.len()) else { return "not bound".into() };
        let shown: Vec<String> = bound
            .iter()
            .zip(info.params.iter())
            .filter_map(|(arg, param)| {
                let arg = &arena.args[(*arg)? as usize];
                Some(format!("{}={}", param.display, arg.value.map_or("", |v| arena.expr(v).span.text(self.text))))
            })
            .collect();
        shown.join(" ")
    }

    fn stmt(&mut self, tables: Tables<'_>, facts: &ItemFacts, arena: &Arena, stmt: &Stmt) {
        match &stmt.kind {
            StmtKind::Call { name, args } => {
                let denotes = facts.procedure(name.span.start);
                let mut line = format!("call {}: {}", name.span.text(self.text), self.denotes(tables, denotes));
                if let Some(Denotes::Decl(Def::Routine(idx))) = denotes {
                    line = format!("{line} ({})", self.bindings(tables, facts, arena, *args, idx));
                }
                self.seen.push(line);
            }
            StmtKind::For { body, .. } => {
                for stmt in body {
                    self.stmt(tables, facts, arena, stmt);
                }
            }
            _ => {}
        }
    }
}

impl BodySink for Recorder<'_> {
    fn begin(&mut self, _: Tables<'_>, _: usize, _: usize, _: usize, routine: &Routine) {
        self.seen.push(format!("begin {}", routine.name.span.text(self.text)));
    }

    fn item(&mut self, tables: Tables<'_>, item: &BodyItem, arena: &Arena, facts: &ItemFacts) {
        for (idx, expr) in arena.exprs.iter().enumerate() {
            let id = rapid_syntax::ast::ExprId(idx as u32);
            let text = expr.span.text(self.text);
            match expr.kind {
                ExprKind::Name(_) => {
                    let line = format!("{text}: {}", self.denotes(tables, facts.name(id)));
                    self.seen.push(line);
                }
                ExprKind::Call { args, .. } => {
                    let denotes = facts.name(id);
                    let mut line = format!("{text}: {}", self.denotes(tables, denotes));
                    if let Some(Denotes::Decl(Def::Routine(idx))) = denotes {
                        line = format!("{line} ({})", self.bindings(tables, facts, arena, args, idx));
                    }
                    self.seen.push(line);
                }
                _ => {}
            }
        }
        if let BodyItem::Stmt(stmt) = item {
            self.stmt(tables, facts, arena, stmt);
        }
    }

    fn end(&mut self, _: Tables<'_>, clean: bool) {
        self.seen.push(format!("end clean={clean}"));
    }
}

fn record(text: &str) -> Vec<String> {
    let files = [SourceInput::from_text("m.mod", text)];
    let mut recorder = Recorder { text, seen: Vec::new() };
    let analysis = analyze_with(&files, &Options::default(), Some(&mut recorder));
    assert!(!rapid_sema::Program::has_errors(&analysis.diagnostics), "{:?}", analysis.diagnostics);
    recorder.seen
}

#[test]
fn names_calls_and_arguments_are_resolved_once_per_item() {
    let text = "MODULE M
  VAR num g := 1;
  VAR signalgo go1;
  PROC main(num a)
    VAR num x;
    VAR dnum d;
    FOR i FROM 1 TO 2 DO
      x := i + g;
    ENDFOR
    SetGO go1, x + d;
    x := GetTSPStatus(\"T_ROB1\");
    p x, \\Opt:=a;
    x := Abs(x);
    Nowhere;
  ENDPROC
  PROC p(num b, \\num Opt)
  ENDPROC
ENDMODULE
";
    let seen = record(text);
    let expected = [
        "begin main",
        // The parameter is own data 0, then x, d and the FOR variable in order.
        // `x := i + g;` inside the loop: x, i and g.
        "x: own data 1",
        "i: own data 3",
        "g: data g",
        // SetGO's `num Value | dnum Dvalue`: `num + dnum` is a dnum (manual §1.3.5's
        // operator table), so the argument stands for Dvalue.
        "go1: data go1",
        "x: own data 1",
        "d: own data 2",
        "call SetGO: routine SetGO (Signal=go1 Dvalue=x + d)",
        // `taskid TaskRef | string TaskName`: a string literal is a TaskName.
        "x: own data 1",
        "GetTSPStatus(\"T_ROB1\"): routine GetTSPStatus (TaskName=\"T_ROB1\")",
        "x: own data 1",
        "a: own data 0",
        "call p: routine p (b=x Opt=a)",
        "x: own data 1",
        "x: own data 1",
        "Abs(x): routine Abs (Value=x)",
        // A procedure defined nowhere: a late error, ERR_REFUNKPRC, when it runs.
        "call Nowhere: nothing",
        "end clean=true",
        "begin p",
        "end clean=true",
    ];
    assert_eq!(seen, expected);
}

#[test]
fn a_late_bound_call_forwards_a_parameter_the_checker_resolved() {
    let text = "MODULE M
  PROC relay(string name \\num opt)
    % name % 9 \\opt?opt;
  ENDPROC
ENDMODULE
";
    // The callee is matched only when the call runs, but the forwarded parameter is
    // this routine's own: its second parameter.
    let expected = ["begin relay", "name: own data 0", "opt: own data 1", "end clean=true"];
    assert_eq!(record(text), expected);
}

/// Writes down the type the facts give each literal and operator expression.
struct TypeRecorder<'t> {
    text: &'t str,
    seen: Vec<String>,
}

impl BodySink for TypeRecorder<'_> {
    fn begin(&mut self, _: Tables<'_>, _: usize, _: usize, _: usize, _: &Routine) {}

    fn item(&mut self, tables: Tables<'_>, _: &BodyItem, arena: &Arena, facts: &ItemFacts) {
        for (idx, expr) in arena.exprs.iter().enumerate() {
            let operator = matches!(
                expr.kind,
                ExprKind::Num | ExprKind::Binary { .. } | ExprKind::Unary { .. } | ExprKind::Paren(_)
            );
            // Items of one body may share an arena: an earlier item's facts are reset.
            let Some(ty) = facts.ty(rapid_syntax::ast::ExprId(idx as u32)).filter(|_| operator) else { continue };
            let ty = match ty {
                ExprType::Numeric => "numeric".to_string(),
                ExprType::Of { ty, rank } => format!("{}/{rank}", tables.types.name(ty)),
            };
            self.seen.push(format!("{}: {ty}", expr.span.text(self.text)));
        }
    }

    fn end(&mut self, _: Tables<'_>, _: bool) {}
}

#[test]
fn literals_and_their_arithmetic_are_typed_by_context_and_aliases_by_their_base() {
    let text = "MODULE M
  ALIAS num distance;
  VAR distance d := 1;
  PROC main()
    VAR dnum x := 2 * 0.1;
    VAR num n;
    VAR bool b;
    n := d * 2;
    n := -(7 DIV 2) + n;
    x := n * 0.5 + x;
    b := d > 0.5;
  ENDPROC
ENDMODULE
";
    let files = [SourceInput::from_text("m.mod", text)];
    let mut recorder = TypeRecorder { text, seen: Vec::new() };
    let analysis = analyze_with(&files, &Options::default(), Some(&mut recorder));
    assert!(!rapid_sema::Program::has_errors(&analysis.diagnostics), "{:?}", analysis.diagnostics);
    let mut seen = recorder.seen;
    let mut expected = vec![
        // A literal and arithmetic of literals only take the context's type: here
        // dnum, so 2 * 0.1 is computed in double precision.
        "2: numeric",
        "0.1: numeric",
        "2 * 0.1: numeric",
        // Arithmetic on an alias gives its base type (§1.3.5, footnote ii).
        "2: numeric",
        "d * 2: num/0",
        "7: numeric",
        "2: numeric",
        "7 DIV 2: numeric",
        "(7 DIV 2): numeric",
        "-(7 DIV 2): numeric",
        "-(7 DIV 2) + n: num/0",
        // num * literal is a num; num + dnum a dnum.
        "0.5: numeric",
        "n * 0.5: num/0",
        "n * 0.5 + x: dnum/0",
        "0.5: numeric",
        "d > 0.5: bool/0",
    ];
    seen.sort();
    expected.sort();
    assert_eq!(seen, expected);
}
