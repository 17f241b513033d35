//! What a debugger shows of a stopped task besides its call stack: values as trees
//! (a record's components by name, an array's elements by index, each with its
//! type), and a RAPID expression evaluated in a frame of the task.
//!
//! An expression is parsed by the real parser (as the right-hand side of an
//! assignment in a throw-away module) and evaluated with the VM's own operators
//! (`rapid_vm::ops`, §1.3.1), names resolved as the frame sees them: the routine's
//! parameters and data first, then the task's data (LOCAL data of the routine's
//! module before global data). Evaluating never changes the program's state: a
//! function call is evaluated only when the function is a built-in with a pure form
//! (its result depends on its arguments alone); a user FUNC and other built-ins are
//! refused with the reason. Aggregates are refused as not supported yet.

use rapid_sema::bind::{ArgBinder, Binding};
use rapid_syntax::ast::{Arena, ArgKind, ExprId, ExprKind, Item, StmtKind};
use rapid_vm::builtins::symsearch::SymData;
use rapid_vm::value::Value;

use super::{ApiError, Session};

/// A value as a debugger shows it: its RAPID literal text, its type, and its parts
/// (a record's components, an array's elements; none for an atomic value).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValueTree {
    /// The datum's name, a component's name, or an element's indices (`{2}`).
    pub name: String,
    /// `num`, `pos`, `robtarget{5}`…; empty when unknown.
    pub type_name: String,
    /// RAPID literal text, or `<not present>`, `<present>`, `<no literal>`.
    pub value: String,
    pub children: Vec<ValueTree>,
}

impl Session {
    /// The parameters and routine data of frame `frame` of task `task` (0: the
    /// innermost), as trees.
    pub fn frame_trees(&self, task: &str, frame: usize) -> Result<Vec<ValueTree>, ApiError> {
        let idx = self.task_index(task)?;
        let vm = &self.controller.tasks[idx].loaded.vm;
        let locals = vm
            .depth()
            .checked_sub(frame + 1)
            .and_then(|at| vm.frame_locals(at))
            .ok_or_else(|| ApiError::NotFound(format!("task {task} has no frame {frame}")))?;
        Ok(locals.into_iter().map(|(name, value)| self.tree(idx, name, &value)).collect())
    }

    /// Module datum `name` of module `module` of task `task` as a tree (a shared
    /// persistent as it stands now).
    pub fn data_tree(&mut self, task: &str, module: &str, name: &str) -> Result<ValueTree, ApiError> {
        let idx = self.task_index(task)?;
        let datum = self.datum_in(idx, Some(module), name)?;
        let value = self.global_value(idx, &datum)?;
        let mut tree = self.tree(idx, datum.name.clone(), &value);
        tree.type_name.clone_from(&datum.ty);
        Ok(tree)
    }

    /// Evaluates the RAPID expression `text` in frame `frame` of task `task` (0: the
    /// innermost) and returns its value as a tree named by the text.
    pub fn evaluate(&mut self, task: &str, frame: usize, text: &str) -> Result<ValueTree, ApiError> {
        let idx = self.task_index(task)?;
        let parsed = parse_expression(text)?;
        let (arena, expr) = parsed.expression()?;
        let locals = {
            let vm = &self.controller.tasks[idx].loaded.vm;
            vm.depth().checked_sub(frame + 1).and_then(|at| vm.frame_locals(at)).unwrap_or_default()
        };
        let module = self.frame_module(idx, frame);
        let mut scope = Scope { session: self, idx, locals, module, parsed: &parsed };
        let value = scope.eval(arena, expr)?;
        Ok(self.tree(idx, text.trim().to_owned(), &value))
    }

    /// `value` as a tree named `name`, typed by task `idx`'s program.
    fn tree(&self, idx: usize, name: String, value: &Value) -> ValueTree {
        let program = self.controller.tasks[idx].loaded.analysis.as_deref();
        let text = match value {
            Value::Array(array) if array.rank() > 1 => nested_literal(array),
            Value::Absent => "<not present>".to_owned(),
            Value::SwitchOn => "<present>".to_owned(),
            other => rapid_vm::builtins::value_literal(other).unwrap_or_else(|| "<no literal>".to_owned()),
        };
        let (type_name, children) = match value {
            Value::Num(_) => ("num".to_owned(), Vec::new()),
            Value::Dnum(_) => ("dnum".to_owned(), Vec::new()),
            Value::Bool(_) => ("bool".to_owned(), Vec::new()),
            Value::Str(_) => ("string".to_owned(), Vec::new()),
            Value::Record(record) => {
                let fields = program.and_then(|p| p.types.record_fields(record.ty));
                let children = record
                    .fields
                    .iter()
                    .enumerate()
                    .map(|(at, field)| {
                        let name = fields
                            .and_then(|f| f.get(at))
                            .map_or_else(|| format!("#{}", at + 1), |f| f.display.clone());
                        self.tree(idx, name, field)
                    })
                    .collect();
                (program.map_or_else(String::new, |p| p.types.name(record.ty).to_owned()), children)
            }
            Value::Array(array) => {
                let children: Vec<ValueTree> = array
                    .elems
                    .iter()
                    .enumerate()
                    .map(|(at, elem)| self.tree(idx, element_name(array.dims, at), elem))
                    .collect();
                let elem = children.first().map_or("", |c| c.type_name.as_str());
                let dims: Vec<String> = array.dims.iter().take_while(|&&d| d > 0).map(u32::to_string).collect();
                (format!("{elem}{{{}}}", dims.join(",")), children)
            }
            Value::Opaque(opaque) => {
                (program.map_or_else(String::new, |p| p.types.name(opaque.ty).to_owned()), Vec::new())
            }
            Value::Absent | Value::SwitchOn | Value::Ref(_) => (String::new(), Vec::new()),
        };
        ValueTree { name, type_name, value: text, children }
    }

    /// Task `idx`'s datum `name`: in `module` when given, else (for an expression)
    /// none is given and a global one is taken.
    fn datum_in(&self, idx: usize, module: Option<&str>, name: &str) -> Result<SymData, ApiError> {
        let symbols = &self.controller.tasks[idx].loaded.vm.resources().symsearch;
        let module_idx = module.and_then(|m| symbols.modules().iter().position(|n| n.eq_ignore_ascii_case(m)));
        let named = |d: &&SymData| d.name.eq_ignore_ascii_case(name);
        let found = match module_idx {
            // LOCAL data of the module first, then the task's global data.
            Some(m) => symbols
                .data()
                .iter()
                .filter(named)
                .find(|d| d.module as usize == m)
                .or_else(|| symbols.data().iter().filter(named).find(|d| !d.local)),
            None => symbols.data().iter().filter(named).find(|d| !d.local),
        };
        found.cloned().ok_or_else(|| ApiError::NotFound(format!("no data `{name}` in scope")))
    }

    /// The value of task `idx`'s datum now (a shared persistent brought in first).
    fn global_value(&mut self, idx: usize, datum: &SymData) -> Result<Value, ApiError> {
        let global = datum.global;
        self.controller
            .with_task(idx, &mut self.pendant, |vm, _| vm.global(global).cloned())
            .ok_or_else(|| ApiError::NotFound(format!("no value for `{}`", datum.name)))
    }

    /// The name of the module holding frame `frame`'s routine (0: innermost): the
    /// module of the task whose declaration `MODULE name` its file holds.
    fn frame_module(&self, idx: usize, frame: usize) -> Option<String> {
        let vm = &self.controller.tasks[idx].loaded.vm;
        let stack = vm.call_stack();
        let at = stack.len().checked_sub(frame + 1)?;
        let source = vm.program_source(stack.get(at)?.file)?;
        let symbols = &vm.resources().symsearch;
        symbols.modules().iter().find(|m| declares_module(&source.text, m)).cloned()
    }
}

/// Whether `text` holds the declaration `MODULE name` (any letter case).
fn declares_module(text: &str, name: &str) -> bool {
    text.lines().any(|line| {
        let mut words = line.split(|c: char| c.is_whitespace() || c == '(').filter(|w| !w.is_empty());
        words.next().is_some_and(|w| w.eq_ignore_ascii_case("MODULE"))
            && words.next().is_some_and(|w| w.eq_ignore_ascii_case(name))
    })
}

/// A multi-dimensional array as RAPID writes its aggregate: one bracket per
/// dimension, `[[1,2],[3,4]]` for a 2×2 array (`value_literal` writes the elements
/// in one flat list).
fn nested_literal(array: &rapid_vm::value::Array) -> String {
    let texts: Option<Vec<String>> = array.elems.iter().map(rapid_vm::builtins::value_literal).collect();
    let Some(texts) = texts else { return "<no literal>".to_owned() };
    let dims: Vec<usize> = array.dims.iter().take_while(|&&d| d > 0).map(|&d| d as usize).collect();
    nest(&texts, &dims)
}

/// `texts` (row-major) grouped by `dims`, outermost first.
fn nest(texts: &[String], dims: &[usize]) -> String {
    let Some((&first, rest)) = dims.split_first() else { return texts.first().cloned().unwrap_or_default() };
    if rest.is_empty() {
        return format!("[{}]", texts.join(","));
    }
    let size = texts.len() / first.max(1);
    let rows: Vec<String> = texts.chunks(size.max(1)).map(|row| nest(row, rest)).collect();
    format!("[{}]", rows.join(","))
}

/// How a debugger names element `at` of an array of sizes `dims`: `{i}`, `{i,j}`…
fn element_name(dims: [u32; 3], at: usize) -> String {
    let rank = dims.iter().take_while(|&&d| d > 0).count();
    let mut rest = at;
    let mut indices = vec![0; rank];
    for d in (0..rank).rev() {
        let size = dims[d].max(1) as usize;
        indices[d] = rest % size + 1;
        rest /= size;
    }
    let indices: Vec<String> = indices.iter().map(usize::to_string).collect();
    format!("{{{}}}", indices.join(","))
}

/// An expression parsed inside a throw-away module, with the names it interned.
struct Parsed {
    parse: rapid_syntax::Parse,
    interner: rapid_syntax::Interner,
    /// The throw-away module's text (the spans index it).
    source: String,
}

/// Parses `text` as a RAPID expression (the right-hand side of an assignment).
fn parse_expression(text: &str) -> Result<Parsed, ApiError> {
    if text.contains(['\n', '\r', ';', '!']) {
        return Err(ApiError::BadLiteral(format!("`{text}` is not one RAPID expression")));
    }
    let source = format!("MODULE DebugEval\nPROC DebugEval()\nDebugValue := {text};\nENDPROC\nENDMODULE\n");
    let mut interner = rapid_syntax::Interner::default();
    let parse = rapid_syntax::parse(&source, &mut interner);
    if let Some(error) = parse.errors.first() {
        return Err(ApiError::BadLiteral(format!("`{text}` is not a RAPID expression: {}", error.message)));
    }
    Ok(Parsed { parse, interner, source })
}

impl Parsed {
    /// The arena and the expression parsed.
    fn expression(&self) -> Result<(&Arena, ExprId), ApiError> {
        let routine = self.parse.file.modules.first().and_then(|m| {
            m.items.iter().find_map(|item| match item {
                Item::Routine(r) => r.body.as_deref(),
                _ => None,
            })
        });
        let found = routine.and_then(|body| match body.stmts.as_slice() {
            [stmt] => match stmt.kind {
                StmtKind::Assign { value, .. } => Some((&body.arena, value)),
                _ => None,
            },
            _ => None,
        });
        found.ok_or_else(|| ApiError::BadLiteral("not one RAPID expression".into()))
    }

    /// The source text of expression `id`.
    fn text_of(&self, arena: &Arena, id: ExprId) -> &str {
        let span = arena.expr(id).span;
        self.source.get(span.start as usize..span.end as usize).unwrap_or_default()
    }
}

/// Names as a frame sees them, while an expression is evaluated.
struct Scope<'s> {
    session: &'s mut Session,
    idx: usize,
    locals: Vec<(String, Value)>,
    module: Option<String>,
    parsed: &'s Parsed,
}

impl Scope<'_> {
    fn eval(&mut self, arena: &Arena, id: ExprId) -> Result<Value, ApiError> {
        let parsed = self.parsed;
        let literal = parsed.text_of(arena, id);
        match arena.expr(id).kind {
            ExprKind::Num => rapid_syntax::literal::num_value(literal)
                .map(|n| Value::Num(n as f32))
                .ok_or_else(|| ApiError::BadLiteral(format!("`{literal}` is no num"))),
            ExprKind::Str => Ok(Value::Str(rapid_syntax::literal::string_value(literal).into())),
            ExprKind::Bool(b) => Ok(Value::Bool(b)),
            ExprKind::Name(name) => self.name(parsed.interner.resolve(name)),
            ExprKind::Paren(inner) => self.eval(arena, inner),
            ExprKind::Field { base, field } => {
                let value = self.eval(arena, base)?;
                self.component(value, parsed.interner.resolve(field))
            }
            ExprKind::Index { base, indices } => {
                let value = self.eval(arena, base)?;
                let mut at = Vec::new();
                for &index in arena.list(indices) {
                    match self.eval(arena, index)? {
                        Value::Num(n) => at.push(f64::from(n)),
                        Value::Dnum(n) => at.push(n),
                        _ => return Err(ApiError::Refused("an array index must be a number".into())),
                    }
                }
                let Value::Array(array) = value else {
                    return Err(ApiError::Refused("an index of a value that is no array".into()));
                };
                let at = rapid_vm::exec::storage::element_index(array.dims, &at)
                    .map_err(|(_, why)| ApiError::Refused(why))?;
                array.elems.get(at as usize).cloned().ok_or_else(|| ApiError::Refused("index out of bounds".into()))
            }
            ExprKind::Unary { op, operand } => {
                let value = self.eval(arena, operand)?;
                rapid_vm::ops::unary(op, value, self.op_types()?).map_err(|(_, why)| ApiError::Refused(why))
            }
            ExprKind::Binary { op, lhs, rhs } => {
                let a = self.eval(arena, lhs)?;
                let b = self.eval(arena, rhs)?;
                rapid_vm::ops::binary(op, a, b, self.op_types()?).map_err(|(_, why)| ApiError::Refused(why))
            }
            ExprKind::Call { name, args } => self.call(arena, parsed.interner.resolve(name), args),
            _ => Err(ApiError::Unsupported(format!("`{literal}` in a debugger expression"))),
        }
    }

    /// A function call. Evaluating must never change the program's state, so only a
    /// built-in with a pure form (`rapid_vm::builtins::pure`: its result depends on its
    /// arguments alone and it touches nothing) is called. A user FUNC is refused: it
    /// may write data or persistents, do I/O or move the robot, and running it on a
    /// copy of the task would still reach the shared persistents, the I/O and the
    /// motion the copy shares with the real one.
    fn call(&mut self, arena: &Arena, name: &str, args: rapid_syntax::ast::ArgList) -> Result<Value, ApiError> {
        let user_func = self.session.controller.tasks[self.idx]
            .loaded
            .vm
            .codes()
            .any(|code| code.is_func && code.name.eq_ignore_ascii_case(name));
        if user_func {
            return Err(ApiError::Refused(format!(
                "`{name}` is a function of the program: the debugger does not run it, since it could change \
                 data, do I/O or move the robot"
            )));
        }
        let set = crate::builtin_set::standard();
        let pure = set.lookup(name).and_then(|id| set.pure_form(id)).ok_or_else(|| {
            ApiError::Refused(format!(
                "`{name}` is not evaluated by the debugger: only built-in functions without side effects are"
            ))
        })?;
        let values = self.pure_args(arena, name, args)?;
        // A pure form answers None where the built-in would raise an error (or takes
        // arguments of another kind): the debugger says so rather than raise it.
        pure(&values).ok_or_else(|| {
            ApiError::Refused(format!(
                "`{name}` cannot be evaluated with these arguments (it would raise an error, or the debugger \
                 does not evaluate this form of it)"
            ))
        })
    }

    /// The arguments of a call of built-in `name` as its pure form takes them: bound
    /// to the parameters as the compiler binds them (by name, positional ones to the
    /// next free required parameter, §1.5), their values in parameter order, a switch
    /// as present. Like the fast loop (which alone calls pure forms in a program), only
    /// a leading run of parameters may be given: one left out before one given would
    /// need the built-in's general form, which the debugger does not run.
    fn pure_args(
        &mut self,
        arena: &Arena,
        name: &str,
        args: rapid_syntax::ast::ArgList,
    ) -> Result<Vec<Value>, ApiError> {
        let program = self.session.controller.tasks[self.idx].loaded.analysis.as_deref();
        let Some(routine) = program
            .and_then(|p| p.routines.iter().find(|r| r.chapter.is_some() && r.display.eq_ignore_ascii_case(name)))
        else {
            return Err(ApiError::Unsupported(format!("`{name}` without the task's checked program")));
        };
        // Messages name the built-in and its parameters as the catalogue spells them.
        let name = routine.display.clone();
        let name = name.as_str();
        let (params, groups) = (routine.params.clone(), routine.groups.clone());
        let types = program.map(|p| &p.types);
        let kinds = ["num", "dnum", "string", "bool"].map(|kind| types.and_then(|t| t.find(kind)));
        // The expression was parsed with an interner of its own: its argument names are
        // spelled in the program's symbols, which the parameters are declared in.
        let mut written = Vec::new();
        for arg in arena.args(args).iter().filter(|a| a.kind != ArgKind::Placeholder) {
            let mut arg = *arg;
            if let Some(mut named) = arg.name {
                let text =
                    self.parsed.source.get(named.span.start as usize..named.span.end as usize).unwrap_or_default();
                named.sym = program
                    .and_then(|p| p.interner.get(text))
                    .ok_or_else(|| ApiError::Refused(format!("`{name}` has no parameter `{text}`")))?;
                arg.name = Some(named);
            }
            written.push(arg);
        }
        let mut binder = ArgBinder::new(&params, &groups, Vec::new());
        let mut bound: Vec<Option<Value>> = vec![None; params.len()];
        for arg in &written {
            let Some(value) = self.arg_value(arena, name, arg)? else { continue };
            let value_ty = match value {
                Value::Num(_) => kinds[0],
                Value::Dnum(_) => kinds[1],
                Value::Str(_) => kinds[2],
                Value::Bool(_) => kinds[3],
                _ => None,
            };
            let at = match binder.bind(arg, |_, param| value_ty == Some(param.ty)) {
                Binding::Param { param, previous: None, .. } => param,
                Binding::Param { param, .. } => {
                    return Err(ApiError::Refused(format!("`{}` of `{name}` is given twice", params[param].display)))
                }
                Binding::UnknownName => return Err(ApiError::Refused(format!("`{name}` has no such parameter"))),
                Binding::TooMany | Binding::NoValue => {
                    return Err(ApiError::Refused(format!("too many arguments for `{name}`")))
                }
            };
            bound[at] = Some(value);
        }
        let given = bound.iter().rposition(Option::is_some).map_or(0, |last| last + 1);
        if let Some(gap) = bound[..given].iter().position(Option::is_none) {
            return Err(ApiError::Unsupported(format!(
                "`{name}` without `{}` but with a later argument in a debugger call",
                params[gap].display
            )));
        }
        Ok(bound.into_iter().take(given).flatten().collect())
    }

    /// An argument's value: its expression's, a switch's presence, or for a
    /// conditional argument `\P?Q` the value of the frame's optional parameter Q
    /// (`None`: Q was not passed, so neither is P, §1.5).
    fn arg_value(
        &mut self,
        arena: &Arena,
        name: &str,
        arg: &rapid_syntax::ast::Arg,
    ) -> Result<Option<Value>, ApiError> {
        match (arg.kind, arg.value) {
            (ArgKind::Required, Some(value)) => self.eval(arena, value).map(Some),
            (ArgKind::Optional, None) => Ok(Some(Value::SwitchOn)),
            (ArgKind::Optional, Some(value)) => self.eval(arena, value).map(Some),
            (ArgKind::Conditional, Some(value)) => match arena.expr(value).kind {
                ExprKind::Name(sym) => {
                    let param = self.parsed.interner.resolve(sym);
                    let local = self.locals.iter().find(|(n, _)| n.eq_ignore_ascii_case(param));
                    match local {
                        Some((_, Value::Absent)) => Ok(None),
                        Some((_, value)) => Ok(Some(value.clone())),
                        None => Err(ApiError::Refused(format!("`{param}` is no optional parameter of this frame"))),
                    }
                }
                _ => Err(ApiError::Refused("a conditional argument must name an optional parameter".into())),
            },
            _ => Err(ApiError::Unsupported(format!("this kind of argument in a debugger call of `{name}`"))),
        }
    }

    /// A name: the frame's parameters and data, then the task's data.
    fn name(&mut self, name: &str) -> Result<Value, ApiError> {
        if let Some((_, value)) = self.locals.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)) {
            return Ok(value.clone());
        }
        let datum = self.session.datum_in(self.idx, self.module.as_deref(), name)?;
        self.session.global_value(self.idx, &datum)
    }

    /// Component `field` of record `value`.
    fn component(&self, value: Value, field: &str) -> Result<Value, ApiError> {
        let Value::Record(record) = value else {
            return Err(ApiError::Refused(format!("`.{field}` of a value that is no record")));
        };
        let program = self.session.controller.tasks[self.idx].loaded.analysis.as_deref();
        let fields = program
            .and_then(|p| p.types.record_fields(record.ty))
            .ok_or_else(|| ApiError::Unsupported("record components need the task's checked program".into()))?;
        let at = fields
            .iter()
            .position(|f| f.display.eq_ignore_ascii_case(field))
            .ok_or_else(|| ApiError::NotFound(format!("the record has no component `{field}`")))?;
        record.fields.get(at).cloned().ok_or_else(|| ApiError::NotFound(format!("no component `{field}`")))
    }

    /// The types pos and orient, which the operators compute on.
    fn op_types(&self) -> Result<rapid_vm::ops::OpTypes, ApiError> {
        let types = &self.session.controller.tasks[self.idx].loaded.types_by_name;
        match (types.get("pos"), types.get("orient")) {
            (Some(&pos), Some(&orient)) => Ok(rapid_vm::ops::OpTypes { pos, orient }),
            _ => Err(ApiError::Unsupported("the task's program has no types table".into())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{declares_module, element_name, nest, parse_expression};

    #[test]
    fn elements_are_named_by_their_indices() {
        assert_eq!(element_name([3, 0, 0], 0), "{1}");
        assert_eq!(element_name([3, 0, 0], 2), "{3}");
        // Row-major: element 4 of a 2×3 array is row 2, column 2.
        assert_eq!(element_name([2, 3, 0], 4), "{2,2}");
    }

    #[test]
    fn arrays_nest_by_dimension() {
        let texts: Vec<String> = (1..=6).map(|n| n.to_string()).collect();
        assert_eq!(nest(&texts, &[2, 3]), "[[1,2,3],[4,5,6]]");
        assert_eq!(nest(&texts, &[3, 2]), "[[1,2],[3,4],[5,6]]");
        assert_eq!(nest(&texts[..2], &[2]), "[1,2]");
    }

    #[test]
    fn module_declarations_are_found() {
        assert!(declares_module("%%%\nMODULE Main (SYSMODULE)\n", "main"));
        assert!(!declares_module("MODULE Mainly\n", "Main"));
    }

    #[test]
    fn only_one_expression_is_parsed() {
        assert!(parse_expression("a + 1").is_ok());
        assert!(parse_expression("a + ").is_err());
        assert!(parse_expression("a; b := 2").is_err());
    }
}
