//! A structure-aware generator of RAPID programs: fuzzer bytes choose, through
//! `arbitrary::Unstructured`, among declarations (VAR, PERS, CONST, arrays, intnum),
//! routines (PROC, FUNC, TRAP; IN, INOUT, optional and switch parameters), statements
//! (assignments, IF, WHILE, FOR, TEST, calls, late-bound calls, RAISE, RETURN, waits,
//! interrupts), typed expressions (num, dnum, bool, string; built-in functions) and
//! ERROR and UNDO handlers (RETRY, TRYNEXT, RAISE), spread over several modules.
//!
//! Programs are typed as they are written, so most of them check clean and reach the
//! interpreter: the byte-level fuzzer rarely gets past the parser's first error. When
//! the bytes run out every choice takes its first option, so every input gives a
//! finite, small program.

use std::fmt::Write as _;

use arbitrary::{Result, Unstructured};

mod expr;
use expr::join_args;

/// The value types the generator writes.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Ty {
    Num,
    Dnum,
    Bool,
    Str,
    Pos,
}

const TYPES: [Ty; 5] = [Ty::Num, Ty::Dnum, Ty::Bool, Ty::Str, Ty::Pos];

impl Ty {
    fn name(self) -> &'static str {
        match self {
            Ty::Num => "num",
            Ty::Dnum => "dnum",
            Ty::Bool => "bool",
            Ty::Str => "string",
            Ty::Pos => "pos",
        }
    }
}

/// A data object in scope: its name, type, length when a 1-D array, and whether the
/// program may write it.
#[derive(Clone, Debug)]
struct Data {
    name: String,
    ty: Ty,
    len: Option<u32>,
    writable: bool,
    /// A PERS: passed to INOUT whole only.
    persistent: bool,
    /// A record component read or written through the data (`.a`), or empty.
    field: &'static str,
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Mode {
    In,
    InOut,
    Optional,
    Switch,
}

#[derive(Clone, Debug)]
struct Param {
    name: String,
    ty: Ty,
    mode: Mode,
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Proc,
    Func(Ty),
    Trap,
}

#[derive(Clone, Debug)]
struct Routine {
    name: String,
    kind: Kind,
    params: Vec<Param>,
    module: usize,
}

/// Limits that keep a program small enough to run many times a second.
const MAX_MODULES: usize = 3;
const MAX_GLOBALS: usize = 8;
const MAX_ROUTINES: usize = 6;
const MAX_BLOCK: usize = 6;
const MAX_STMT_DEPTH: u32 = 3;
const MAX_EXPR_DEPTH: u32 = 3;

/// The generated program: one text per module; module 0 holds `main`.
pub struct Program {
    pub modules: Vec<String>,
}

/// Writes a program from the fuzzer's bytes.
pub fn generate(u: &mut Unstructured<'_>) -> Result<Program> {
    let mut gen = Gen {
        u,
        globals: Vec::new(),
        routines: Vec::new(),
        locals: Vec::new(),
        interrupts: 0,
        fresh: 0,
        in_undo: false,
        records: Vec::new(),
    };
    gen.program()
}

struct Gen<'a, 'b> {
    u: &'a mut Unstructured<'b>,
    globals: Vec<Data>,
    routines: Vec<Routine>,
    /// The data of the routine being written: its parameters and routine data.
    locals: Vec<Data>,
    /// How many `intnum` globals there are (`ir0`, `ir1`, …).
    interrupts: usize,
    fresh: u32,
    /// Writing an UNDO handler: no motion there.
    in_undo: bool,
    /// The `rec` globals: name and array length.
    records: Vec<(String, Option<u32>)>,
}

impl Gen<'_, '_> {
    fn program(&mut self) -> Result<Program> {
        let n_modules = self.u.int_in_range(1..=MAX_MODULES)?;
        self.interrupts = self.u.int_in_range(0..=2)?;
        let mut decls = vec![String::new(); n_modules];
        let n_globals = self.u.int_in_range(0..=MAX_GLOBALS)?;
        for idx in 0..n_globals {
            let module = self.u.choose_index(n_modules)?;
            let decl = self.global(idx)?;
            decls[module].push_str(&decl);
        }
        for idx in 0..self.interrupts {
            decls[0].push_str(&format!("  VAR intnum ir{idx};\n"));
        }
        // A record type of the program's own, and data of it: its components are
        // read and written as data of their types, whole records assigned.
        decls[0].push_str("  RECORD rec\n    num a;\n    string b;\n    pos c;\n  ENDRECORD\n");
        for idx in 0..self.u.int_in_range(0..=2)? {
            let module = self.u.choose_index(n_modules)?;
            let decl = self.record_global(idx)?;
            decls[module].push_str(&decl);
        }
        // An error number booked at run time (BookErrNo), raised and handled.
        decls[0].push_str("  VAR errnum ERR_MINE := -1;\n");
        // A point the default robot reaches, for moves relative to it (Offs).
        decls[0].push_str("  CONST robtarget home := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n");
        decls[0].push_str("  VAR clock clk;\n");
        let n_routines = self.u.int_in_range(0..=MAX_ROUTINES)?;
        for idx in 0..n_routines {
            let routine = self.signature(idx, n_modules)?;
            self.routines.push(routine);
        }
        let mut bodies = vec![String::new(); n_modules];
        let main = Routine { name: "main".into(), kind: Kind::Proc, params: Vec::new(), module: 0 };
        bodies[0].push_str(&self.routine(&main)?);
        for idx in 0..self.routines.len() {
            let routine = self.routines[idx].clone();
            let text = self.routine(&routine)?;
            bodies[routine.module].push_str(&text);
        }
        let modules = (0..n_modules).map(|m| format!("MODULE M{m}\n{}{}ENDMODULE\n", decls[m], bodies[m])).collect();
        Ok(Program { modules })
    }

    fn name(&mut self, prefix: &str) -> String {
        self.fresh += 1;
        format!("{prefix}{}", self.fresh)
    }

    fn global(&mut self, idx: usize) -> Result<String> {
        let ty = *self.u.choose(&TYPES)?;
        let name = format!("g{idx}");
        let storage = *self.u.choose(&["VAR", "VAR", "PERS", "CONST"])?;
        let len = if storage != "CONST" && self.u.ratio(1, 4)? { Some(self.u.int_in_range(1..=5)?) } else { None };
        let init = match len {
            Some(n) => {
                let items: Vec<String> = (0..n).map(|_| self.literal(ty)).collect::<Result<_>>()?;
                format!("[{}]", items.join(", "))
            }
            None => self.literal(ty)?,
        };
        let dims = len.map_or(String::new(), |n| format!("{{{n}}}"));
        // PERS and CONST need a value; a VAR may go without.
        let init = if storage == "VAR" && self.u.ratio(1, 3)? { String::new() } else { format!(" := {init}") };
        let persistent = storage == "PERS";
        self.globals.push(Data { name: name.clone(), ty, len, writable: storage != "CONST", persistent, field: "" });
        Ok(format!("  {storage} {} {name}{dims}{init};\n", ty.name()))
    }

    /// A global of the record type `rec`: a VAR, a PERS (with a value) or a VAR
    /// array, offered as data of each component's type.
    fn record_global(&mut self, idx: usize) -> Result<String> {
        let name = format!("rc{idx}");
        let storage = *self.u.choose(&["VAR", "PERS", "VAR"])?;
        let len = if storage == "VAR" && self.u.ratio(1, 3)? { Some(self.u.int_in_range(1..=3)?) } else { None };
        let one = format!("[{}, {}, {}]", self.literal(Ty::Num)?, self.literal(Ty::Str)?, self.literal(Ty::Pos)?);
        let init = match (storage, len) {
            ("PERS", _) => format!(" := {one}"),
            (_, Some(n)) if self.u.ratio(1, 2)? => format!(" := [{}]", vec![one; n as usize].join(", ")),
            (_, None) if self.u.ratio(1, 2)? => format!(" := {one}"),
            _ => String::new(),
        };
        let persistent = storage == "PERS";
        for (field, ty) in [(".a", Ty::Num), (".b", Ty::Str), (".c", Ty::Pos)] {
            self.globals.push(Data { name: name.clone(), ty, len, writable: true, persistent, field });
        }
        self.records.push((name.clone(), len));
        let dims = len.map_or(String::new(), |n| format!("{{{n}}}"));
        Ok(format!("  {storage} rec {name}{dims}{init};\n"))
    }

    fn signature(&mut self, idx: usize, n_modules: usize) -> Result<Routine> {
        let kind = match self.u.int_in_range(0..=5)? {
            0..=2 => Kind::Proc,
            3 | 4 => Kind::Func(*self.u.choose(&TYPES)?),
            _ => Kind::Trap,
        };
        let mut params = Vec::new();
        if kind != Kind::Trap {
            for p in 0..self.u.int_in_range(0..=3)? {
                let mode = *self.u.choose(&[Mode::In, Mode::In, Mode::InOut, Mode::Optional, Mode::Switch])?;
                // FUNC parameters cannot be INOUT... they can, but keep calls in
                // expressions free of side effects on arbitrary data: IN only there.
                let mode = if matches!(kind, Kind::Func(_)) && mode == Mode::InOut { Mode::In } else { mode };
                params.push(Param { name: format!("p{p}"), ty: *self.u.choose(&TYPES)?, mode });
            }
        }
        Ok(Routine { name: format!("r{idx}"), kind, params, module: self.u.choose_index(n_modules)? })
    }

    fn routine(&mut self, routine: &Routine) -> Result<String> {
        self.locals.clear();
        let params: Vec<String> = routine
            .params
            .iter()
            .map(|p| match p.mode {
                Mode::In => format!("{} {}", p.ty.name(), p.name),
                Mode::InOut => format!("INOUT {} {}", p.ty.name(), p.name),
                Mode::Optional => format!("\\{} {}", p.ty.name(), p.name),
                Mode::Switch => format!("\\switch {}", p.name),
            })
            .collect();
        for p in &routine.params {
            // Optional parameters may be absent: read them only under Present (below),
            // so they are not offered as plain data. IN parameters are read-only here.
            if matches!(p.mode, Mode::In | Mode::InOut) {
                let writable = p.mode == Mode::InOut;
                self.locals.push(Data {
                    name: p.name.clone(),
                    ty: p.ty,
                    len: None,
                    writable,
                    persistent: false,
                    field: "",
                });
            }
        }
        let mut out = match routine.kind {
            Kind::Proc => format!("  PROC {}({})\n", routine.name, params.join(", ")),
            Kind::Func(ty) => format!("  FUNC {} {}({})\n", ty.name(), routine.name, params.join(", ")),
            Kind::Trap => format!("  TRAP {}\n", routine.name),
        };
        for _ in 0..self.u.int_in_range(0..=2)? {
            let ty = *self.u.choose(&TYPES)?;
            let name = self.name("l");
            let init = self.literal(ty)?;
            out.push_str(&format!("    VAR {} {name} := {init};\n", ty.name()));
            self.locals.push(Data { name, ty, len: None, writable: true, persistent: false, field: "" });
        }
        for p in routine.params.iter().filter(|p| p.mode == Mode::Optional) {
            let value = self.expr(p.ty, 0)?;
            out.push_str(&format!("    IF Present({}) TPWrite ValToStr({} = {value});\n", p.name, p.name));
        }
        out.push_str(&self.block(routine.kind, 0, 2)?);
        if let Kind::Func(ty) = routine.kind {
            out.push_str(&format!("    RETURN {};\n", self.expr(ty, 0)?));
        }
        if routine.kind != Kind::Trap && self.u.ratio(1, 3)? {
            out.push_str("  ERROR\n");
            out.push_str(&self.handler(routine.kind)?);
        }
        if routine.kind == Kind::Proc && self.u.ratio(1, 6)? {
            out.push_str("  UNDO\n");
            self.in_undo = true;
            let undo = self.block(Kind::Trap, MAX_STMT_DEPTH, 2);
            self.in_undo = false;
            out.push_str(&undo?);
        }
        out.push_str(match routine.kind {
            Kind::Proc => "  ENDPROC\n",
            Kind::Func(_) => "  ENDFUNC\n",
            Kind::Trap => "  ENDTRAP\n",
        });
        Ok(out)
    }

    fn handler(&mut self, kind: Kind) -> Result<String> {
        let mut out = self.block(kind, MAX_STMT_DEPTH, 2)?;
        let end = match self.u.int_in_range(0..=7)? {
            0 => "RETRY;".to_owned(),
            1 => "TRYNEXT;".to_owned(),
            2 => "RAISE;".to_owned(),
            3 => match kind {
                Kind::Func(ty) => format!("RETURN {};", self.expr(ty, 0)?),
                _ => "RETURN;".to_owned(),
            },
            4 => "IF ERRNO = ERR_DIVZERO TRYNEXT;".to_owned(),
            5 => "IF RemainingRetries() > 0 RETRY;".to_owned(),
            6 => "IF ERRNO = ERR_MINE RETRY;".to_owned(),
            _ => "SkipWarn;".to_owned(),
        };
        out.push_str(&format!("    {end}\n"));
        Ok(out)
    }

    /// A block of statements at nesting `depth`, indented by `indent` levels.
    fn block(&mut self, kind: Kind, depth: u32, indent: usize) -> Result<String> {
        let mut out = String::new();
        for _ in 0..self.u.int_in_range(0..=MAX_BLOCK)? {
            let stmt = self.statement(kind, depth, indent)?;
            let _ = writeln!(out, "{}{stmt}", "  ".repeat(indent));
        }
        Ok(out)
    }

    fn statement(&mut self, kind: Kind, depth: u32, indent: usize) -> Result<String> {
        let nested = depth < MAX_STMT_DEPTH;
        let pad = "  ".repeat(indent);
        Ok(match self.u.int_in_range(0..=26)? {
            0..=3 => match self.writable(None)? {
                Some(target) => {
                    let value = self.expr(target.1, 0)?;
                    format!("{} := {value};", target.0)
                }
                None => format!("TPWrite {};", self.expr(Ty::Str, 0)?),
            },
            4 => format!("TPWrite {} \\Num:={};", self.expr(Ty::Str, 0)?, self.expr(Ty::Num, 0)?),
            5 if nested => {
                let cond = self.expr(Ty::Bool, 0)?;
                let then = self.block(kind, depth + 1, indent + 1)?;
                let other = if self.u.ratio(1, 2)? {
                    format!("{pad}ELSE\n{}", self.block(kind, depth + 1, indent + 1)?)
                } else {
                    String::new()
                };
                format!("IF {cond} THEN\n{then}{other}{pad}ENDIF")
            }
            6 if nested => {
                let cond = self.expr(Ty::Bool, 0)?;
                let body = self.block(kind, depth + 1, indent + 1)?;
                format!("WHILE {cond} DO\n{body}{pad}ENDWHILE")
            }
            7 if nested => {
                let var = self.name("i");
                let (from, to) = (self.expr(Ty::Num, 1)?, self.expr(Ty::Num, 1)?);
                let step =
                    if self.u.ratio(1, 4)? { format!(" STEP {}", self.expr(Ty::Num, 2)?) } else { String::new() };
                self.locals.push(Data {
                    name: var.clone(),
                    ty: Ty::Num,
                    len: None,
                    writable: false,
                    persistent: false,
                    field: "",
                });
                let body = self.block(kind, depth + 1, indent + 1)?;
                self.locals.retain(|d| d.name != var);
                format!("FOR {var} FROM {from} TO {to}{step} DO\n{body}{pad}ENDFOR")
            }
            8 if nested => {
                let subject = self.expr(Ty::Num, 1)?;
                let mut out = format!("TEST {subject}\n");
                for _ in 0..self.u.int_in_range(1..=3)? {
                    let value = self.u.int_in_range(0..=4)?;
                    let _ = write!(out, "{pad}CASE {value}:\n{}", self.block(kind, depth + 1, indent + 1)?);
                }
                if self.u.ratio(1, 2)? {
                    let _ = write!(out, "{pad}DEFAULT:\n{}", self.block(kind, depth + 1, indent + 1)?);
                }
                out.push_str(&format!("{pad}ENDTEST"));
                out
            }
            9 => self.call()?,
            10 => match kind {
                Kind::Func(ty) => format!("RETURN {};", self.expr(ty, 0)?),
                _ => "RETURN;".to_owned(),
            },
            11 => format!("RAISE {};", self.u.int_in_range(1..=90)?),
            12 => format!("WaitTime {};", self.u.choose(&["0", "0.01", "0.1", "0.5"])?),
            13 if self.interrupts > 0 => self.interrupt()?,
            14 => match self.writable(Some(Ty::Num))? {
                Some((name, _)) => format!("{} {name};", self.u.choose(&["Incr", "Decr"])?),
                None => "Stop \\NoRegain;".to_owned(),
            },
            15 => {
                // Late binding: a procedure named at run time, perhaps one that is not there.
                let procs: Vec<String> = self
                    .routines
                    .iter()
                    .filter(|r| {
                        r.kind == Kind::Proc && r.params.iter().all(|p| p.mode != Mode::In && p.mode != Mode::InOut)
                    })
                    .map(|r| r.name.clone())
                    .collect();
                let target = if procs.is_empty() || self.u.ratio(1, 4)? {
                    "nowhere".to_owned()
                } else {
                    self.u.choose(&procs)?.clone()
                };
                format!("%\"{target}\"%;")
            }
            16 if !self.in_undo => {
                let instr = self.u.choose(&["MoveL", "MoveJ"])?;
                let to = self.offs()?;
                let speed = self.u.choose(&["v100", "v1000", "vmax"])?;
                let zone = self.u.choose(&["fine", "z10", "z50"])?;
                format!("{instr} {to}, {speed}, {zone}, tool0;")
            }
            17 => (*self.u.choose(&["ClkStart clk;", "ClkStop clk;", "ClkReset clk;"])?).to_owned(),
            18 => format!("WaitUntil {} \\MaxTime:=0.1;", self.expr(Ty::Bool, 1)?),
            19 if !self.records.is_empty() => self.record_assignment()?,
            20 => (*self.u.choose(&[
                "BookErrNo ERR_MINE;",
                "RAISE ERR_MINE;",
                "BookErrNo ERR_MINE;\n    RAISE ERR_MINE;",
            ])?)
            .to_owned(),
            21 => {
                // Late binding by number: `r0` to `r5` are the routines, perhaps not
                // procedures, perhaps with parameters, perhaps not there.
                format!("CallByVar \"r\", {};", self.u.int_in_range(0..=MAX_ROUTINES)?)
            }
            22 => self.data_by_name()?,
            23 => match self.reference_of_some_type()? {
                Some(target) => {
                    let text = *self.u.choose(&["\"1.5\"", "\"[1,2,3]\"", "\"TRUE\"", "\"x\"", "\"\""])?;
                    let text = if self.u.ratio(1, 4)? { self.expr(Ty::Str, 1)? } else { text.to_owned() };
                    format!("IF StrToVal({text}, {target}) TPWrite \"parsed\";")
                }
                None => "ResetRetryCount;".to_owned(),
            },
            24 if !self.in_undo => {
                let to = self.offs()?;
                match self.u.int_in_range(0..=2)? {
                    0 => format!("MoveAbsJ CalcJointT({to}, tool0), v100, fine, tool0;"),
                    1 => format!("MoveC {}, {to}, v100, z10, tool0;", self.offs()?),
                    _ => "WaitRob \\InPos;".to_owned(),
                }
            }
            25 => (*self.u.choose(&[
                "IEnable;",
                "IDisable;",
                "ResetRetryCount;",
                "TPWrite \"retries \" \\Num:=RemainingRetries();",
            ])?)
            .to_owned(),
            _ => format!("ErrWrite \\W, {}, {};", self.expr(Ty::Str, 1)?, self.expr(Ty::Str, 1)?),
        })
    }

    /// A point near `home`: `Offs(home, dx, dy, dz)`.
    fn offs(&mut self) -> Result<String> {
        let (dx, dy, dz) = (self.expr(Ty::Num, 2)?, self.expr(Ty::Num, 2)?, self.expr(Ty::Num, 2)?);
        Ok(format!("Offs(home, {dx}, {dy}, {dz})"))
    }

    /// A whole record assigned: an aggregate, or another record (an element of an
    /// array of records as well).
    fn record_assignment(&mut self) -> Result<String> {
        let records = self.records.clone();
        let (name, len) = self.u.choose(&records)?.clone();
        let target = match len {
            Some(n) => format!("{name}{{{}}}", self.index(n, 0)?),
            None => name,
        };
        let value = match self.u.ratio(1, 3)? {
            true => {
                let (other, len) = self.u.choose(&records)?.clone();
                match len {
                    Some(n) => format!("{other}{{{}}}", self.index(n, 0)?),
                    None => other,
                }
            }
            false => format!("[{}, {}, {}]", self.expr(Ty::Num, 1)?, self.expr(Ty::Str, 1)?, self.expr(Ty::Pos, 1)?),
        };
        Ok(format!("{target} := {value};\n    TPWrite ValToStr({target});"))
    }

    /// Data reached by its name at run time (GetDataVal, SetDataVal): a global
    /// scalar, read into a variable of its type or written with a value of it (a
    /// CONST written is the program's error, raised).
    fn data_by_name(&mut self) -> Result<String> {
        let globals: Vec<Data> =
            self.globals.iter().filter(|g| g.len.is_none() && g.field.is_empty()).cloned().collect();
        if globals.is_empty() {
            return Ok("GetDataVal \"nowhere\", ERR_MINE;".to_owned());
        }
        let data = self.u.choose(&globals)?.clone();
        let name = if self.u.ratio(1, 8)? { data.name.to_uppercase() } else { data.name.clone() };
        if self.u.ratio(1, 2)? {
            return Ok(format!("SetDataVal \"{name}\", {};", self.expr(data.ty, 1)?));
        }
        // A VAR of the routine or the module (parameters and persistents are no VAR).
        let vars: Vec<Data> = self
            .locals
            .iter()
            .chain(&self.globals)
            .filter(|d| d.writable && !d.persistent && d.ty == data.ty && d.len.is_none() && d.field.is_empty())
            .filter(|d| !d.name.starts_with('p'))
            .cloned()
            .collect();
        match vars.is_empty() {
            true => Ok(format!("SetDataVal \"{name}\", {};", self.expr(data.ty, 1)?)),
            false => Ok(format!("GetDataVal \"{name}\", {};", self.u.choose(&vars)?.name)),
        }
    }

    /// A call of a user procedure with arguments matching its parameters.
    fn call(&mut self) -> Result<String> {
        let procs: Vec<Routine> = self.routines.iter().filter(|r| r.kind == Kind::Proc).cloned().collect();
        if procs.is_empty() {
            return Ok(format!("TPWrite {};", self.expr(Ty::Str, 0)?));
        }
        let routine = self.u.choose(&procs)?.clone();
        let mut args = Vec::new();
        for p in &routine.params {
            match p.mode {
                Mode::In => args.push(self.expr(p.ty, 1)?),
                Mode::InOut => match self.reference(p.ty)? {
                    Some(name) => args.push(name),
                    // No variable to pass: no call.
                    None => return Ok(format!("TPWrite {};", self.expr(Ty::Str, 0)?)),
                },
                Mode::Optional => {
                    if self.u.ratio(1, 2)? {
                        args.push(format!("\\{}:={}", p.name, self.expr(p.ty, 1)?));
                    }
                }
                Mode::Switch => {
                    if self.u.ratio(1, 2)? {
                        args.push(format!("\\{}", p.name));
                    }
                }
            }
        }
        Ok(if args.is_empty() {
            format!("{};", routine.name)
        } else {
            format!("{} {};", routine.name, join_args(&args))
        })
    }

    fn interrupt(&mut self) -> Result<String> {
        let ir = format!("ir{}", self.u.choose_index(self.interrupts)?);
        let traps: Vec<String> =
            self.routines.iter().filter(|r| r.kind == Kind::Trap).map(|r| r.name.clone()).collect();
        Ok(match self.u.int_in_range(0..=4)? {
            0 if !traps.is_empty() => format!("CONNECT {ir} WITH {};", self.u.choose(&traps)?),
            1 => format!("ITimer \\Single, {}, {ir};", self.u.choose(&["0.01", "0.05", "0.2"])?),
            2 => format!("IDelete {ir};"),
            3 => format!("ISleep {ir};"),
            _ => format!("IWatch {ir};"),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_bytes_give_a_small_program() {
        let mut u = Unstructured::new(&[]);
        let program = generate(&mut u).expect("generate");
        assert_eq!(program.modules.len(), 1);
        assert!(program.modules[0].contains("PROC main()"));
    }

    /// Found by the `program` target (a silent stack overflow): an index expression
    /// could index again, without end, once the bytes ran out.
    #[test]
    fn index_expressions_end() {
        let mut bytes = vec![0x00, 0xfd];
        bytes.extend([0x28; 51]);
        bytes.push(0x0a);
        let program = generate(&mut Unstructured::new(&bytes)).expect("generate");
        assert!(program.modules[0].contains("g0{g0{1}}"), "{}", program.modules[0]);
    }
}

#[cfg(test)]
mod quality {
    use super::*;
    use rapid_sema::{check, Options, SourceInput};

    /// Most generated programs must check clean, or the generator only feeds the
    /// checker's error paths. Bytes from a fixed xorshift sequence.
    #[test]
    fn most_programs_check_clean() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut clean = 0;
        let total = 300;
        for _ in 0..total {
            let bytes: Vec<u8> = (0..4000)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    state as u8
                })
                .collect();
            let program = generate(&mut Unstructured::new(&bytes)).expect("generate");
            let files: Vec<SourceInput> = program
                .modules
                .iter()
                .enumerate()
                .map(|(i, m)| SourceInput::from_bytes(format!("m{i}.mod"), m.clone().into_bytes()))
                .collect();
            let errors: Vec<_> = check(&files, &Options::default())
                .into_iter()
                .filter(|d| d.severity() == rapid_sema::Severity::Error)
                .collect();
            if errors.is_empty() {
                clean += 1;
            } else if std::env::var_os("SHOW").is_some() {
                for d in &errors {
                    let text = &files[d.file].text;
                    eprintln!("{:?} {} `{}`", d.code, d.message, &text[d.span.start as usize..d.span.end as usize]);
                }
            }
        }
        eprintln!("{clean} of {total} check clean");
        assert!(clean * 2 > total, "{clean} of {total} check clean");
    }
}
