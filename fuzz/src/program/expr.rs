//! The generator's typed expressions: data it may read or write (scalars, array
//! elements, record components), literals, and expressions of each type built from
//! operators and built-in functions, each typed as it is written.

use arbitrary::Result;

use super::{Data, Gen, Kind, Mode, Routine, Ty, MAX_EXPR_DEPTH, TYPES};

impl Gen<'_, '_> {
    /// A data object the program may write, of type `ty` when given: a scalar or an
    /// array element.
    pub(super) fn writable(&mut self, ty: Option<Ty>) -> Result<Option<(String, Ty)>> {
        let all: Vec<Data> = self
            .locals
            .iter()
            .chain(&self.globals)
            .filter(|d| d.writable && ty.is_none_or(|t| t == d.ty))
            .cloned()
            .collect();
        if all.is_empty() {
            return Ok(None);
        }
        let data = self.u.choose(&all)?.clone();
        let place = match data.len {
            Some(len) => format!("{}{{{}}}{}", data.name, self.index(len, 0)?, data.field),
            None => format!("{}{}", data.name, data.field),
        };
        Ok(Some((place, data.ty)))
    }

    /// A reference for an INOUT argument: a variable (or its element) or a whole
    /// persistent.
    pub(super) fn reference(&mut self, ty: Ty) -> Result<Option<String>> {
        let all: Vec<Data> = self
            .locals
            .iter()
            .chain(&self.globals)
            .filter(|d| d.writable && d.ty == ty && !(d.persistent && (d.len.is_some() || !d.field.is_empty())))
            .cloned()
            .collect();
        if all.is_empty() {
            return Ok(None);
        }
        let data = self.u.choose(&all)?.clone();
        Ok(Some(match data.len {
            Some(len) if !data.persistent => format!("{}{{{}}}{}", data.name, self.index(len, 0)?, data.field),
            _ => format!("{}{}", data.name, data.field),
        }))
    }

    /// A reference of a type StrToVal reads: num, bool, pos or string.
    pub(super) fn reference_of_some_type(&mut self) -> Result<Option<String>> {
        let ty = *self.u.choose(&[Ty::Num, Ty::Bool, Ty::Pos, Ty::Str])?;
        self.reference(ty)
    }

    /// A dnum expression whose type is dnum on its own (a literal alone is a num).
    pub(super) fn typed_dnum(&mut self, depth: u32) -> Result<String> {
        match self.readable(Ty::Dnum, depth + 1)? {
            Some(name) if self.u.ratio(1, 2)? => Ok(name),
            _ => Ok(format!("NumToDnum({})", self.expr(Ty::Num, depth + 1)?)),
        }
    }

    /// An index: mostly within `1..=len`, sometimes an expression that may miss. Only
    /// a literal at the deepest level: an index expression may index again.
    pub(super) fn index(&mut self, len: u32, depth: u32) -> Result<String> {
        if depth < MAX_EXPR_DEPTH && self.u.ratio(1, 8)? {
            return self.expr(Ty::Num, MAX_EXPR_DEPTH);
        }
        Ok(self.u.int_in_range(1..=len)?.to_string())
    }

    pub(super) fn literal(&mut self, ty: Ty) -> Result<String> {
        Ok(match ty {
            Ty::Num => {
                (*self.u.choose(&["0", "1", "2", "-1", "0.5", "10", "3.25", "1E6", "-7", "8388608"])?).to_owned()
            }
            Ty::Dnum => (*self.u.choose(&["0", "1", "4294967295", "-2", "0.125", "1E15"])?).to_owned(),
            Ty::Bool => (*self.u.choose(&["TRUE", "FALSE"])?).to_owned(),
            Ty::Str => format!("\"{}\"", self.u.choose(&["", "a", "abc", "x y", "1.5", "\\\\", "\"\""])?),
            Ty::Pos => (*self.u.choose(&["[0,0,0]", "[1,2,3]", "[100,-50,0.5]", "[9E9,0,-1]"])?).to_owned(),
        })
    }

    /// A constant in an expression: a literal, or for a record type (whose aggregate
    /// needs a type from its context, which an operand does not give) a component of
    /// the `home` constant.
    pub(super) fn leaf(&mut self, ty: Ty) -> Result<String> {
        match ty {
            Ty::Pos => Ok("home.trans".to_owned()),
            _ => self.literal(ty),
        }
    }

    /// A data object readable as `ty`: a scalar, an array element, or none.
    pub(super) fn readable(&mut self, ty: Ty, depth: u32) -> Result<Option<String>> {
        let all: Vec<Data> = self.locals.iter().chain(&self.globals).filter(|d| d.ty == ty).cloned().collect();
        if all.is_empty() {
            return Ok(None);
        }
        let data = self.u.choose(&all)?.clone();
        Ok(Some(match data.len {
            Some(len) => format!("{}{{{}}}{}", data.name, self.index(len, depth)?, data.field),
            None => format!("{}{}", data.name, data.field),
        }))
    }

    pub(super) fn expr(&mut self, ty: Ty, depth: u32) -> Result<String> {
        if depth >= MAX_EXPR_DEPTH || self.u.ratio(1, 3)? {
            return match self.readable(ty, depth)? {
                Some(name) if self.u.ratio(2, 3)? => Ok(name),
                _ => self.leaf(ty),
            };
        }
        let d = depth + 1;
        Ok(match ty {
            Ty::Num => match self.u.int_in_range(0..=16)? {
                0 => format!(
                    "({} {} {})",
                    self.expr(Ty::Num, d)?,
                    self.u.choose(&["+", "-", "*", "/"])?,
                    self.expr(Ty::Num, d)?
                ),
                1 => format!(
                    "({} {} {})",
                    self.expr(Ty::Num, d)?,
                    self.u.choose(&["DIV", "MOD"])?,
                    self.expr(Ty::Num, d)?
                ),
                2 => format!("-{}", self.expr(Ty::Num, d)?),
                3 => format!(
                    "{}({})",
                    self.u.choose(&["Abs", "Sqrt", "Trunc", "Sin", "Cos", "Tan", "ATan", "ASin", "ACos", "Exp"])?,
                    self.expr(Ty::Num, d)?
                ),
                4 => format!("Round({} \\Dec:={})", self.expr(Ty::Num, d)?, self.u.int_in_range(0..=3)?),
                5 => format!("StrLen({})", self.expr(Ty::Str, d)?),
                6 => format!("Pow({}, {})", self.expr(Ty::Num, d)?, self.expr(Ty::Num, d)?),
                7 => self.func_call(Ty::Num, d)?,
                8 => match self.globals.iter().find(|g| g.len.is_some()).cloned() {
                    Some(array) => format!("Dim({}, 1)", array.name),
                    None => "ERRNO".to_owned(),
                },
                9 => format!("DnumToNum({})", self.typed_dnum(d)?),
                10 => match self.readable(Ty::Pos, d)? {
                    Some(name) if !name.contains('{') => format!("{name}.{}", self.u.choose(&["x", "y", "z"])?),
                    _ => format!("VectMagn({})", self.expr(Ty::Pos, d)?),
                },
                11 => format!("DotProd({}, {})", self.expr(Ty::Pos, d)?, self.expr(Ty::Pos, d)?),
                12 => format!("ATan2({}, {})", self.expr(Ty::Num, d)?, self.expr(Ty::Num, d)?),
                13 => format!("StrFind({}, {}, STR_DIGIT)", self.expr(Ty::Str, d)?, self.expr(Ty::Num, d)?),
                14 => format!(
                    "StrMatch({}, {}, {})",
                    self.expr(Ty::Str, d)?,
                    self.expr(Ty::Num, d)?,
                    self.expr(Ty::Str, d)?
                ),
                15 => "RemainingRetries()".to_owned(),
                _ => "ClkRead(clk)".to_owned(),
            },
            Ty::Pos => match self.u.int_in_range(0..=5)? {
                0 => format!("({} {} {})", self.expr(Ty::Pos, d)?, self.u.choose(&["+", "-"])?, self.expr(Ty::Pos, d)?),
                1 => format!("({} * {})", self.expr(Ty::Pos, d)?, self.expr(Ty::Num, d)?),
                2 => self.func_call(Ty::Pos, d)?,
                3 => "CPos(\\Tool:=tool0)".to_owned(),
                4 => format!("PoseVect([[10, 0, 0], [0.7071068, 0, 0.7071068, 0]], {})", self.expr(Ty::Pos, d)?),
                _ => format!("CrossProd({}, {})", self.expr(Ty::Pos, d)?, self.expr(Ty::Pos, d)?),
            },
            Ty::Dnum => match self.u.int_in_range(0..=3)? {
                0 => format!(
                    "({} {} {})",
                    self.typed_dnum(d)?,
                    self.u.choose(&["+", "-", "*", "/", "DIV", "MOD"])?,
                    self.expr(Ty::Dnum, d)?
                ),
                1 => format!("NumToDnum({})", self.expr(Ty::Num, d)?),
                2 => self.func_call(Ty::Dnum, d)?,
                _ => format!("AbsDnum({})", self.typed_dnum(d)?),
            },
            Ty::Bool => match self.u.int_in_range(0..=7)? {
                0 => format!(
                    "({} {} {})",
                    self.expr(Ty::Num, d)?,
                    self.u.choose(&["<", "<=", "=", "<>", ">", ">="])?,
                    self.expr(Ty::Num, d)?
                ),
                1 => format!(
                    "({} {} {})",
                    self.expr(Ty::Bool, d)?,
                    self.u.choose(&["AND", "OR", "XOR"])?,
                    self.expr(Ty::Bool, d)?
                ),
                2 => format!("NOT {}", self.expr(Ty::Bool, d)?),
                3 => format!("({} = {})", self.expr(Ty::Str, d)?, self.expr(Ty::Str, d)?),
                4 => format!("({} < {})", self.typed_dnum(d)?, self.expr(Ty::Dnum, d)?),
                5 => format!("StrMemb({}, {}, STR_DIGIT)", self.expr(Ty::Str, d)?, self.expr(Ty::Num, d)?),
                6 => format!("StrOrder({}, {}, STR_UPPER + STR_LOWER)", self.expr(Ty::Str, d)?, self.expr(Ty::Str, d)?),
                _ => self.func_call(Ty::Bool, d)?,
            },
            Ty::Str => match self.u.int_in_range(0..=9)? {
                0 => format!("{} + {}", self.expr(Ty::Str, d)?, self.expr(Ty::Str, d)?),
                1 => format!("NumToStr({}, {})", self.expr(Ty::Num, d)?, self.u.int_in_range(0..=4)?),
                2 => {
                    let of = *self.u.choose(&TYPES)?;
                    format!("ValToStr({})", self.expr(of, d)?)
                }
                3 => format!(
                    "StrPart({}, {}, {})",
                    self.expr(Ty::Str, d)?,
                    self.expr(Ty::Num, d)?,
                    self.expr(Ty::Num, d)?
                ),
                4 => format!("DnumToStr({}, {})", self.expr(Ty::Dnum, d)?, self.u.int_in_range(0..=4)?),
                5 => format!("StrMap({}, \"abc\", \"xyz\")", self.expr(Ty::Str, d)?),
                6 => format!("CTime() + CDate() + StrPart(\"abc\", 1, {})", self.u.int_in_range(0..=4)?),
                7 => format!(
                    "ByteToStr({} {})",
                    self.u.choose(&["0", "65", "255", "256", "-1"])?,
                    self.u.choose(&["", "\\Hex", "\\Okt", "\\Bin", "\\Char"])?
                ),
                8 => format!("{}({})", self.u.choose(&["DecToHex", "HexToDec"])?, self.expr(Ty::Str, d)?),
                _ => self.func_call(Ty::Str, d)?,
            },
        })
    }

    /// A call of a user FUNC returning `ty`, or a literal when there is none.
    pub(super) fn func_call(&mut self, ty: Ty, depth: u32) -> Result<String> {
        let funcs: Vec<Routine> = self.routines.iter().filter(|r| r.kind == Kind::Func(ty)).cloned().collect();
        if funcs.is_empty() {
            return self.leaf(ty);
        }
        let func = self.u.choose(&funcs)?.clone();
        let mut args = Vec::new();
        for p in &func.params {
            match p.mode {
                Mode::In | Mode::InOut => args.push(self.expr(p.ty, depth + 1)?),
                Mode::Optional if self.u.ratio(1, 2)? => {
                    args.push(format!("\\{}:={}", p.name, self.expr(p.ty, depth + 1)?));
                }
                Mode::Switch if self.u.ratio(1, 2)? => args.push(format!("\\{}", p.name)),
                _ => {}
            }
        }
        Ok(format!("{}({})", func.name, join_args(&args)))
    }
}

/// Arguments as RAPID writes them: a required one after a comma, an optional one
/// (`\Name:=value`, `\Switch`) after a blank.
pub(super) fn join_args(args: &[String]) -> String {
    let mut out = String::new();
    for (idx, arg) in args.iter().enumerate() {
        if idx > 0 {
            out.push_str(if arg.starts_with('\\') { " " } else { ", " });
        }
        out.push_str(arg);
    }
    out
}
