//! Matrix instructions and FitCircle (§1.15, RobotWare 6.15): MatrixAdd, MatrixSub,
//! MatrixMult, MatrixTranspose, MatrixReset here; the decompositions (MatrixInverse,
//! MatrixSolve, MatrixSolveQR, MatrixSVD) in `decomp`, the circle fit in `fit`.
//!
//! A matrix is a two-dimensional dnum array, row by row (`A{i,j}` is row i, column j).
//! The optional `\A_m` / `\A_n` select the top-left m x n block of A, so a program can
//! keep large arrays and use part of them. Every other operand and every result array
//! must be at least as large as the block the operation needs; results go into its
//! top-left corner and the rest of the array is left as it was.
//!
//! uncertain: ABB's manual (3HAC050917, RW 6.15) is not public for MatrixAdd, MatrixSub,
//! MatrixMult, MatrixTranspose, MatrixInverse and MatrixReset; their arguments follow the
//! documented pattern of MatrixSolve (`A [\A_m] [\A_n] ...`). Errors, also uncertain:
//! ERR_ARRAY_SIZE for a bad `\A_m`/`\A_n` or a shape A itself may not have (not square,
//! fewer rows than columns), ERR_INVDIM when two operands do not fit each other,
//! ERR_NOTEQDIM when a result array is too small, ERR_CALC_DIVZERO for a singular matrix.

mod decomp;
mod fit;

use nalgebra::DMatrix;

use super::{native, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Array, Value};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("MatrixAdd", matrix_add),
        native("MatrixSub", matrix_sub),
        native("MatrixMult", matrix_mult),
        native("MatrixTranspose", matrix_transpose),
        native("MatrixReset", matrix_reset),
        native("MatrixInverse", decomp::matrix_inverse),
        native("MatrixSolve", decomp::matrix_solve),
        native("MatrixSolveQR", decomp::matrix_solve_qr),
        native("MatrixSVD", decomp::matrix_svd),
        native("FitCircle", fit::fit_circle),
    ],
};

super::signature::layout! {
    static ELEMENTWISE: ElementwiseArgs = "MatrixAdd" | "MatrixSub" { a_m: "A_m", a_n: "A_n", b: "B", c: "C" }
    static MULT: MultArgs = "MatrixMult" { a_m: "A_m", a_n: "A_n", b: "B", scalar: "Scalar", c: "C" }
    static TRANSPOSE: TransposeArgs = "MatrixTranspose" { a_m: "A_m", a_n: "A_n", a_t: "AT" }
    static RESET: ResetArgs = "MatrixReset" { a_m: "A_m", a_n: "A_n" }
}

/// `MatrixAdd A [\A_m] [\A_n] B C`: C := A + B, element by element.
fn matrix_add(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    elementwise(ctx, args, |a, b| a + b)
}

/// `MatrixSub A [\A_m] [\A_n] B C`: C := A - B, element by element.
fn matrix_sub(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    elementwise(ctx, args, |a, b| a - b)
}

fn elementwise(ctx: &mut Ctx<'_>, args: &[Value], op: fn(f64, f64) -> f64) -> Res {
    let at = *ELEMENTWISE;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    let b = read_block(ctx, &args[at.b], a.nrows(), a.ncols(), "B")?;
    let c = a.zip_map(&b, op);
    store_matrix(ctx, &args[at.c], &c, "C")?;
    Ok(None)
}

/// `MatrixMult A [\A_m] [\A_n] B | Scalar C`: C := A * B (B has as many rows as the
/// block of A has columns; all of B's columns are used), or C := Scalar * A.
fn matrix_mult(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *MULT;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    // B and Scalar are alternatives: whichever was passed (the compiler binds a
    // positional argument by its type and rank; a value of unknown shape goes to B).
    let operand = if super::present(args.get(at.scalar)) { &args[at.scalar] } else { &args[at.b] };
    let c = match ctx.value(operand)? {
        Value::Array(b) => {
            let (rows, cols) = (a.ncols(), b.dims[1] as usize);
            a * block_of(ctx, &b, rows, cols, "B")?
        }
        _ => a * ctx.num(operand)?,
    };
    store_matrix(ctx, &args[at.c], &c, "C")?;
    Ok(None)
}

/// `MatrixTranspose A [\A_m] [\A_n] AT`: AT := the transpose of A.
fn matrix_transpose(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TRANSPOSE;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    store_matrix(ctx, &args[at.a_t], &a.transpose(), "AT")?;
    Ok(None)
}

/// `MatrixReset A [\A_m] [\A_n]`: sets the block of A to zero.
fn matrix_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *RESET;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    store_matrix(ctx, &args[0], &DMatrix::zeros(a.nrows(), a.ncols()), "A")?;
    Ok(None)
}

// --- Reading and writing arrays -----------------------------------------------------

/// The array an argument holds, which must have `rank` dimensions.
fn array(ctx: &Ctx<'_>, arg: &Value, rank: u8, what: &str) -> Result<Array, RapidError> {
    match ctx.value(arg)? {
        Value::Array(a) if a.rank() == rank => Ok(*a),
        _ => Err(ctx.error(Err::InvalidDim, format!("{what} must be an array of {rank} dimension(s)"))),
    }
}

/// How much of a dimension of `full` elements to use: all, or `\A_m` / `\A_n`.
fn used_size(ctx: &Ctx<'_>, arg: Option<&Value>, full: u32, what: &str) -> Result<usize, RapidError> {
    match ctx.opt_num(arg)? {
        None => Ok(full as usize),
        Some(n) if n.fract() == 0.0 && n >= 1.0 && n <= f64::from(full) => Ok(n as usize),
        Some(n) => Err(ctx.error(Err::ArraySize, format!("{what} is {n}, outside 1 to {full}"))),
    }
}

/// Matrix A, or its top-left block of `\A_m` rows and `\A_n` columns.
fn read_matrix(
    ctx: &Ctx<'_>,
    arg: &Value,
    m: Option<&Value>,
    n: Option<&Value>,
    what: &str,
) -> Result<DMatrix<f64>, RapidError> {
    let a = array(ctx, arg, 2, what)?;
    let rows = used_size(ctx, m, a.dims[0], &format!("the row count of {what}"))?;
    let cols = used_size(ctx, n, a.dims[1], &format!("the column count of {what}"))?;
    Ok(block(&a, rows, cols))
}

/// The top-left `rows` x `cols` block of a matrix operand that must be at least that large.
fn read_block(ctx: &Ctx<'_>, arg: &Value, rows: usize, cols: usize, what: &str) -> Result<DMatrix<f64>, RapidError> {
    block_of(ctx, &array(ctx, arg, 2, what)?, rows, cols, what)
}

/// The top-left `rows` x `cols` block of `a`, which must be at least that large.
fn block_of(ctx: &Ctx<'_>, a: &Array, rows: usize, cols: usize, what: &str) -> Result<DMatrix<f64>, RapidError> {
    if a.rank() != 2 {
        return Err(ctx.error(Err::InvalidDim, format!("{what} must be an array of 2 dimension(s)")));
    }
    if (a.dims[0] as usize) < rows || (a.dims[1] as usize) < cols {
        let (r, c) = (a.dims[0], a.dims[1]);
        return Err(ctx.error(Err::InvalidDim, format!("{what} is {r}x{c}, the operation needs {rows}x{cols}")));
    }
    Ok(block(a, rows, cols))
}

fn block(a: &Array, rows: usize, cols: usize) -> DMatrix<f64> {
    let stride = a.dims[1] as usize;
    DMatrix::from_fn(rows, cols, |i, j| a.elems.get(i * stride + j).and_then(Value::as_f64).unwrap_or(0.0))
}

/// The first `len` elements of a one-dimensional operand that must be at least that long.
fn read_vector(ctx: &Ctx<'_>, arg: &Value, len: usize, what: &str) -> Result<Vec<f64>, RapidError> {
    let a = array(ctx, arg, 1, what)?;
    if (a.dims[0] as usize) < len {
        let have = a.dims[0];
        return Err(ctx.error(Err::InvalidDim, format!("{what} has {have} elements, the operation needs {len}")));
    }
    Ok(a.elems.iter().take(len).map(|v| v.as_f64().unwrap_or(0.0)).collect())
}

/// A dnum result; -0 is stored as 0 and a result outside dnum's range is an error.
fn dnum(ctx: &Ctx<'_>, x: f64) -> Result<Value, RapidError> {
    if !x.is_finite() {
        return Err(ctx.error(Err::NumLimit, "a matrix result is outside the range of dnum"));
    }
    Ok(Value::Dnum(x + 0.0))
}

/// Writes `m` into the top-left corner of the matrix argument `arg`.
fn store_matrix(ctx: &mut Ctx<'_>, arg: &Value, m: &DMatrix<f64>, what: &str) -> Result<(), RapidError> {
    let mut a = array(ctx, arg, 2, what)?;
    let (rows, cols) = (a.dims[0] as usize, a.dims[1] as usize);
    if rows < m.nrows() || cols < m.ncols() {
        let (r, c) = (m.nrows(), m.ncols());
        return Err(ctx.error(Err::NotEqualDim, format!("{what} is {rows}x{cols}, the result is {r}x{c}")));
    }
    for i in 0..m.nrows() {
        for j in 0..m.ncols() {
            a.elems[i * cols + j] = dnum(ctx, m[(i, j)])?;
        }
    }
    ctx.store(arg, Value::Array(Box::new(a)))
}

/// Writes `v` into the first elements of the one-dimensional argument `arg`.
fn store_vector(ctx: &mut Ctx<'_>, arg: &Value, v: &[f64], what: &str) -> Result<(), RapidError> {
    let mut a = array(ctx, arg, 1, what)?;
    if (a.dims[0] as usize) < v.len() {
        let (have, need) = (a.dims[0], v.len());
        return Err(ctx.error(Err::NotEqualDim, format!("{what} has {have} elements, the result has {need}")));
    }
    for (slot, &x) in a.elems.iter_mut().zip(v) {
        *slot = dnum(ctx, x)?;
    }
    ctx.store(arg, Value::Array(Box::new(a)))
}
