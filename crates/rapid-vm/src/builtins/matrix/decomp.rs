//! Matrix decompositions (§1.15, RobotWare 6.15): MatrixInverse, MatrixSolve,
//! MatrixSolveQR and MatrixSVD, on nalgebra's LU, Householder QR and SVD.
//!
//! Numerical rules, chosen here and stated so that tests can rely on them:
//! - A matrix is singular (rank deficient) when its smallest singular value is at most
//!   `max(m, n) * eps * largest` (eps = 2.2e-16), the usual rank tolerance; MatrixInverse
//!   and MatrixSolve then raise ERR_CALC_DIVZERO (uncertain: the controller's errno).
//! - MatrixSolveQR returns the full factorisation A = Q R, Q m x m orthogonal, R m x n
//!   upper triangular, with the diagonal of R made non-negative (this makes Q and R
//!   unique for a matrix of full column rank).
//! - MatrixSVD returns the singular values in descending order; U and V are completed to
//!   full orthogonal matrices (U only to n columns with \Econ when m > n).
//! - The SVD iteration is bounded; a matrix on which it does not converge raises
//!   ERR_CALC_DIVZERO rather than hanging.

use nalgebra::{DMatrix, DVector, SVD};

use super::{read_matrix, read_vector, store_matrix, store_vector, Res};
use crate::builtins::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// At most this many QR sweeps in the SVD (far more than any matrix a program holds needs).
const SVD_MAX_ITERATIONS: usize = 100_000;

crate::builtins::signature::layout! {
    static INVERSE: InverseArgs = "MatrixInverse" { a_n: "A_n", a_inv: "AInv" }
    static SOLVE: SolveArgs = "MatrixSolve" { a_m: "A_m", a_n: "A_n", b: "b", x: "x" }
    static SOLVE_QR: SolveQrArgs = "MatrixSolveQR" { a_m: "A_m", a_n: "A_n", q: "Q", r: "R" }
    static SVD_ARGS: SvdArgs = "MatrixSVD" { a_m: "A_m", a_n: "A_n", u: "U", s: "S", v: "V", econ: "Econ" }
}

/// `MatrixInverse A [\A_n] AInv`: AInv := the inverse of the square matrix A (or of its
/// top-left n x n block).
pub(super) fn matrix_inverse(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *INVERSE;
    // \A_n gives both sides of the square block.
    let a = read_matrix(ctx, &args[0], args.get(at.a_n), args.get(at.a_n), "A")?;
    if !present(args.get(at.a_n)) && a.nrows() != a.ncols() {
        let (m, n) = (a.nrows(), a.ncols());
        return Err(ctx.error(Err::ArraySize, format!("MatrixInverse needs a square matrix, A is {m}x{n}")));
    }
    check_full_rank(ctx, &a)?;
    let Some(inverse) = a.full_piv_lu().try_inverse() else {
        return Err(singular(ctx));
    };
    store_matrix(ctx, &args[at.a_inv], &inverse, "AInv")?;
    Ok(None)
}

/// `MatrixSolve A [\A_m] [\A_n] b x`: solves A x = b; for m > n the least-squares
/// solution (smallest |A x - b|).
pub(super) fn matrix_solve(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SOLVE;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    let (m, n) = (a.nrows(), a.ncols());
    if m < n {
        return Err(ctx.error(Err::ArraySize, format!("MatrixSolve needs m >= n, A is {m}x{n}")));
    }
    let b = DVector::from_vec(read_vector(ctx, &args[at.b], m, "b")?);
    check_full_rank(ctx, &a)?;
    let x = if m == n { a.full_piv_lu().solve(&b) } else { least_squares(a, b) };
    let Some(x) = x else { return Err(singular(ctx)) };
    store_vector(ctx, &args[at.x], x.as_slice(), "x")?;
    Ok(None)
}

/// The least-squares solution of an m x n system (m > n, full column rank) through QR:
/// R x = (Q^T b) restricted to the first n rows.
fn least_squares(a: DMatrix<f64>, mut b: DVector<f64>) -> Option<DVector<f64>> {
    let n = a.ncols();
    let qr = a.qr();
    qr.q_tr_mul(&mut b);
    let r = qr.r();
    r.solve_upper_triangular(&b.rows(0, n).into_owned())
}

/// `MatrixSolveQR A [\A_m] [\A_n] Q R`: A = Q R.
pub(super) fn matrix_solve_qr(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SOLVE_QR;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    let (q, r) = full_qr(&a);
    store_matrix(ctx, &args[at.q], &q, "Q")?;
    store_matrix(ctx, &args[at.r], &r, "R")?;
    Ok(None)
}

/// The full QR factorisation (Q m x m, R m x n) with a non-negative diagonal in R.
fn full_qr(a: &DMatrix<f64>) -> (DMatrix<f64>, DMatrix<f64>) {
    let (m, n) = (a.nrows(), a.ncols());
    let qr = a.clone().qr();
    let mut q_t = DMatrix::identity(m, m);
    qr.q_tr_mul(&mut q_t);
    let mut q = q_t.transpose();
    let mut r = a.clone();
    qr.q_tr_mul(&mut r);
    for j in 0..n {
        for i in (j + 1)..m {
            r[(i, j)] = 0.0;
        }
    }
    for k in 0..m.min(n) {
        if r[(k, k)] < 0.0 {
            r.row_mut(k).neg_mut();
            q.column_mut(k).neg_mut();
        }
    }
    (q, r)
}

/// `MatrixSVD A [\A_m] [\A_n] U S V [\Econ]`: A = U diag(S) V^T.
pub(super) fn matrix_svd(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SVD_ARGS;
    let a = read_matrix(ctx, &args[0], args.get(at.a_m), args.get(at.a_n), "A")?;
    let (m, n) = (a.nrows(), a.ncols());
    let (u, s, v) = thin_svd(ctx, a)?;
    let econ = present(args.get(at.econ));
    let u = if econ && m > n { u } else { complete_basis(&u) };
    let v = complete_basis(&v);
    store_matrix(ctx, &args[at.u], &u, "U")?;
    store_vector(ctx, &args[at.s], s.as_slice(), "S")?;
    store_matrix(ctx, &args[at.v], &v, "V")?;
    Ok(None)
}

/// U, the singular values and V of a thin SVD.
type ThinSvd = (DMatrix<f64>, DVector<f64>, DMatrix<f64>);

/// The thin SVD: U (m x k), singular values (k, descending), V (n x k), k = min(m, n).
fn thin_svd(ctx: &Ctx<'_>, a: DMatrix<f64>) -> Result<ThinSvd, RapidError> {
    let svd = SVD::try_new(a, true, true, f64::EPSILON, SVD_MAX_ITERATIONS).ok_or_else(|| no_convergence(ctx))?;
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else { return Err(no_convergence(ctx)) };
    let s = svd.singular_values;
    // nalgebra sorts, except for its special 2x2/3x3 paths, which sort themselves; sort
    // again so the order never depends on that.
    let mut order: Vec<usize> = (0..s.len()).collect();
    order.sort_by(|&i, &j| s[j].total_cmp(&s[i]));
    let u = DMatrix::from_fn(u.nrows(), order.len(), |i, k| u[(i, order[k])]);
    let v = DMatrix::from_fn(v_t.ncols(), order.len(), |i, k| v_t[(order[k], i)]);
    let s = DVector::from_fn(order.len(), |k, _| s[order[k]]);
    Ok((u, s, v))
}

/// Extends r x k orthonormal columns to an r x r orthogonal matrix: the given columns
/// first, then an orthonormal basis of their complement (from a full QR of them).
fn complete_basis(cols: &DMatrix<f64>) -> DMatrix<f64> {
    let (r, k) = (cols.nrows(), cols.ncols());
    if k >= r {
        return cols.clone();
    }
    let (q, _) = full_qr(cols);
    DMatrix::from_fn(r, r, |i, j| if j < k { cols[(i, j)] } else { q[(i, j)] })
}

/// Raises ERR_CALC_DIVZERO when A's rank is below min(m, n) (see the module header).
fn check_full_rank(ctx: &Ctx<'_>, a: &DMatrix<f64>) -> Result<(), RapidError> {
    let (_, s, _) = thin_svd(ctx, a.clone())?;
    let largest = s.iter().copied().fold(0.0, f64::max);
    let smallest = s.iter().copied().fold(f64::INFINITY, f64::min);
    let tolerance = a.nrows().max(a.ncols()) as f64 * f64::EPSILON * largest;
    if largest == 0.0 || smallest <= tolerance {
        return Err(singular(ctx));
    }
    Ok(())
}

fn singular(ctx: &Ctx<'_>) -> RapidError {
    ctx.error(Err::CalcDivZero, "the matrix is singular")
}

fn no_convergence(ctx: &Ctx<'_>) -> RapidError {
    ctx.error(Err::CalcDivZero, "the singular value decomposition did not converge")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: &DMatrix<f64>, b: &DMatrix<f64>) -> bool {
        (a - b).abs().max() < 1e-12
    }

    #[test]
    fn full_qr_is_orthogonal_and_reproduces_a() {
        let a = DMatrix::from_row_slice(3, 2, &[3.0, 0.0, 4.0, 5.0, 0.0, 12.0]);
        let (q, r) = full_qr(&a);
        assert!(close(&(q.transpose() * &q), &DMatrix::identity(3, 3)));
        assert!(close(&(&q * &r), &a));
        assert!(r[(0, 0)] >= 0.0 && r[(1, 1)] >= 0.0 && r[(1, 0)] == 0.0 && r[(2, 1)] == 0.0);
    }

    #[test]
    fn complete_basis_adds_orthonormal_columns() {
        let u = DMatrix::from_row_slice(3, 1, &[0.6, 0.8, 0.0]);
        let full = complete_basis(&u);
        assert_eq!(full.column(0), u.column(0));
        assert!(close(&(full.transpose() * &full), &DMatrix::identity(3, 3)));
    }
}
