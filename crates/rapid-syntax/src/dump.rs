//! A compact S-expression view of a syntax tree, for tests and `rapid parse`.

use crate::ast::*;
use crate::intern::Interner;

/// Renders every module of `file` as S-expressions, one item per line.
pub fn dump_file(file: &SourceFile, text: &str, interner: &Interner) -> String {
    let printer = Printer { text, interner };
    let mut out = String::new();
    for module in &file.modules {
        printer.module(&mut out, module);
    }
    out
}

struct Printer<'a> {
    text: &'a str,
    interner: &'a Interner,
}

impl Printer<'_> {
    fn name(&self, name: Name) -> &str {
        name.span.text(self.text)
    }

    fn module(&self, out: &mut String, module: &Module) {
        out.push_str(&format!("(module {}", self.name(module.name)));
        for (attr, _) in &module.attrs {
            out.push_str(&format!(" {attr:?}").to_lowercase());
        }
        out.push_str(")\n");
        for item in &module.items {
            match item {
                Item::Type(def) => out.push_str(&self.type_def(def)),
                Item::Data(decl) => out.push_str(&self.data_decl(decl, &module.arena)),
                Item::Routine(routine) => out.push_str(&self.routine(routine)),
                Item::Placeholder(ph, _) => out.push_str(&format!("(placeholder {ph:?})")),
            }
            out.push('\n');
        }
    }

    fn type_def(&self, def: &TypeDef) -> String {
        let local = if def.local { "local " } else { "" };
        match &def.kind {
            TypeDefKind::Alias { base, name } => format!("({local}alias {} {})", self.name(*base), self.name(*name)),
            TypeDefKind::Record { name, components } => {
                let comps: Vec<String> =
                    components.iter().map(|c| format!("({} {})", self.name(c.ty), self.name(c.name))).collect();
                format!("({local}record {} {})", self.name(*name), comps.join(" "))
            }
        }
    }

    fn data_decl(&self, decl: &DataDecl, arena: &Arena) -> String {
        let scope = match decl.scope {
            DeclScope::Global => "",
            DeclScope::Local => "local ",
            DeclScope::Task => "task ",
        };
        let storage = format!("{:?}", decl.storage).to_lowercase();
        let mut out = format!("({scope}{storage} {} {}", self.name(decl.ty), self.name(decl.name));
        if !decl.dims.is_empty() {
            let dims: Vec<String> = decl.dims.iter().map(|&d| self.expr(arena, d)).collect();
            out.push_str(&format!(" {{{}}}", dims.join(" ")));
        }
        if let Some(init) = decl.init {
            out.push_str(&format!(" := {}", self.expr(arena, init)));
        }
        out.push(')');
        out
    }

    fn routine(&self, routine: &Routine) -> String {
        let kind = format!("{:?}", routine.kind).to_lowercase();
        let local = if routine.local { "local " } else { "" };
        let ret = routine.ret_ty.map(|t| format!(" {}", self.name(t))).unwrap_or_default();
        let params: Vec<String> = routine.params.iter().map(|p| self.param(p)).collect();
        let mut out = format!("({local}{kind}{ret} {} ({})", self.name(routine.name), params.join(" "));
        if let Some(body) = &routine.body {
            for decl in &body.decls {
                out.push_str(&format!("\n  {}", self.data_decl(decl, &body.arena)));
            }
            self.stmts(&mut out, &body.stmts, &body.arena, 1);
            for (word, handler) in [("backward", &body.backward), ("error", &body.error), ("undo", &body.undo)] {
                if let Some(handler) = handler {
                    let numbers: Vec<String> =
                        handler.error_numbers.iter().map(|&n| self.expr(&body.arena, n)).collect();
                    let numbers = if numbers.is_empty() { String::new() } else { format!(" ({})", numbers.join(" ")) };
                    out.push_str(&format!("\n  {word}{numbers}:"));
                    self.stmts(&mut out, &handler.stmts, &body.arena, 2);
                }
            }
        }
        out.push(')');
        out
    }

    fn param(&self, param: &Param) -> String {
        if let Some(ph) = param.placeholder {
            return format!("{ph:?}");
        }
        let opt = if param.optional { "\\" } else { "" };
        let mode = match param.mode {
            ParamMode::In => "",
            ParamMode::Var => "var ",
            ParamMode::Pers => "pers ",
            ParamMode::Inout => "inout ",
        };
        let rank = if param.rank > 0 { format!("{{{}}}", param.rank) } else { String::new() };
        format!("{opt}{mode}{} {}{rank}#{}", self.name(param.ty), self.name(param.name), param.group)
    }

    fn stmts(&self, out: &mut String, stmts: &[Stmt], arena: &Arena, depth: usize) {
        for stmt in stmts {
            out.push('\n');
            out.push_str(&"  ".repeat(depth));
            out.push_str(&self.stmt(stmt, arena, depth));
        }
    }

    fn stmt(&self, stmt: &Stmt, arena: &Arena, depth: usize) -> String {
        let mut out = String::new();
        match &stmt.kind {
            StmtKind::Assign { target, value } => {
                out = format!("(assign {} {})", self.expr(arena, *target), self.expr(arena, *value))
            }
            StmtKind::Call { name, args } => out = format!("(call {}{})", self.name(*name), self.args(arena, *args)),
            StmtKind::LateCall { callee, args } => {
                out = format!("(late {}{})", self.expr(arena, *callee), self.args(arena, *args))
            }
            StmtKind::If { cond, then, elifs, els } => {
                out.push_str(&format!("(if {}", self.expr(arena, *cond)));
                self.stmts(&mut out, then, arena, depth + 1);
                for elif in elifs {
                    let cond = elif.cond.map_or("<EIT>".to_string(), |c| self.expr(arena, c));
                    out.push_str(&format!("\n{}elseif {cond}", "  ".repeat(depth)));
                    self.stmts(&mut out, &elif.body, arena, depth + 1);
                }
                if let Some(els) = els {
                    out.push_str(&format!("\n{}else", "  ".repeat(depth)));
                    self.stmts(&mut out, els, arena, depth + 1);
                }
                out.push(')');
            }
            StmtKind::CompactIf { cond, stmt } => {
                out = format!("(if1 {} {})", self.expr(arena, *cond), self.stmt(stmt, arena, depth))
            }
            StmtKind::For { var, from, to, step, body } => {
                let step = step.map(|s| format!(" step {}", self.expr(arena, s))).unwrap_or_default();
                out.push_str(&format!(
                    "(for {} {} {}{step}",
                    self.name(*var),
                    self.expr(arena, *from),
                    self.expr(arena, *to)
                ));
                self.stmts(&mut out, body, arena, depth + 1);
                out.push(')');
            }
            StmtKind::While { cond, body } => {
                out.push_str(&format!("(while {}", self.expr(arena, *cond)));
                self.stmts(&mut out, body, arena, depth + 1);
                out.push(')');
            }
            StmtKind::Test { subject, cases, default } => {
                out.push_str(&format!("(test {}", self.expr(arena, *subject)));
                for case in cases {
                    let values: Vec<String> = case.values.iter().map(|&v| self.expr(arena, v)).collect();
                    out.push_str(&format!("\n{}case {}", "  ".repeat(depth), values.join(" ")));
                    self.stmts(&mut out, &case.body, arena, depth + 1);
                }
                if let Some(default) = default {
                    out.push_str(&format!("\n{}default", "  ".repeat(depth)));
                    self.stmts(&mut out, default, arena, depth + 1);
                }
                out.push(')');
            }
            StmtKind::Goto(label) => out = format!("(goto {})", self.name(*label)),
            StmtKind::Label(label) => out = format!("(label {})", self.name(*label)),
            StmtKind::Return(value) => {
                out = format!("(return{})", value.map(|v| format!(" {}", self.expr(arena, v))).unwrap_or_default())
            }
            StmtKind::Raise(value) => {
                out = format!("(raise{})", value.map(|v| format!(" {}", self.expr(arena, v))).unwrap_or_default())
            }
            StmtKind::Retry => out.push_str("(retry)"),
            StmtKind::TryNext => out.push_str("(trynext)"),
            StmtKind::Exit => out.push_str("(exit)"),
            StmtKind::Connect { target, trap } => {
                out = format!("(connect {} {})", self.expr(arena, *target), self.name(*trap))
            }
            StmtKind::Placeholder(ph) => out = format!("{ph:?}"),
            StmtKind::Error => out.push_str("(error)"),
        }
        out
    }

    fn args(&self, arena: &Arena, args: ArgList) -> String {
        let mut out = String::new();
        for arg in arena.args(args) {
            let value = arg.value.map(|v| self.expr(arena, v));
            let name = arg.name.map(|n| self.name(n).to_string());
            out.push(' ');
            out.push_str(&match (arg.kind, name, value) {
                (ArgKind::Required, None, Some(v)) => v,
                (ArgKind::Required, Some(n), Some(v)) => format!("({n}:= {v})"),
                (ArgKind::Optional, Some(n), None) => format!("\\{n}"),
                (ArgKind::Optional, Some(n), Some(v)) => format!("(\\{n} {v})"),
                (ArgKind::Conditional, Some(n), Some(v)) => format!("(\\{n}? {v})"),
                (ArgKind::Placeholder, _, _) => "<ARG>".into(),
                _ => "?".into(),
            });
        }
        out
    }

    fn expr(&self, arena: &Arena, id: ExprId) -> String {
        let expr = arena.expr(id);
        match expr.kind {
            ExprKind::Num | ExprKind::Str => expr.span.text(self.text).to_string(),
            ExprKind::Bool(b) => if b { "TRUE" } else { "FALSE" }.into(),
            ExprKind::Name(_) => expr.span.text(self.text).to_string(),
            ExprKind::Index { base, indices } => {
                let idx: Vec<String> = arena.list(indices).iter().map(|&i| self.expr(arena, i)).collect();
                format!("(index {} {})", self.expr(arena, base), idx.join(" "))
            }
            ExprKind::Field { base, field } => {
                format!("(. {} {})", self.expr(arena, base), self.interner.resolve(field))
            }
            ExprKind::Call { args, .. } => {
                let name = expr.span.text(self.text).split('(').next().unwrap_or("").trim();
                format!("(fn {name}{})", self.args(arena, args))
            }
            ExprKind::Unary { op, operand } => {
                format!("({} {})", format!("{op:?}").to_lowercase(), self.expr(arena, operand))
            }
            ExprKind::Binary { op, lhs, rhs } => {
                format!("({} {} {})", op.text(), self.expr(arena, lhs), self.expr(arena, rhs))
            }
            ExprKind::Paren(inner) => self.expr(arena, inner),
            ExprKind::Aggregate(items) => {
                let items: Vec<String> = arena.list(items).iter().map(|&i| self.expr(arena, i)).collect();
                format!("[{}]", items.join(" "))
            }
            ExprKind::Placeholder(ph) => format!("{ph:?}"),
            ExprKind::Error => "(error)".into(),
        }
    }
}
