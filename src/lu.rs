//! LU with partial pivoting that factorises its matrix in place: one n × n array. faer's `PartialPivLu` copies the
//! matrix and stores L and U apart (three n × n arrays at its peak), which on the 841-element creep curve was a
//! fifth of the peak memory. The factorisation and the solves are faer's own kernels
//! (`linalg::lu::partial_pivoting`), with the same parameters and parallelism as `PartialPivLu`; only the storage
//! differs (L's unit diagonal and U share one array).

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::perm::PermRef;
use faer::Mat;

/// P A = L U of a square matrix, L (unit lower) and U stored in the one array that held A.
#[derive(Debug, Clone)]
pub struct InPlaceLu {
    lu: Mat<f64>,
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
}

impl InPlaceLu {
    /// Factorise `a` (square), consuming it. A singular matrix gives a zero pivot (solves then give non-finite
    /// values, as with `PartialPivLu`).
    pub fn new(mut a: Mat<f64>) -> InPlaceLu {
        assert_eq!(a.nrows(), a.ncols(), "LU of a square matrix");
        let n = a.nrows();
        let par = faer::get_global_parallelism();
        let (mut perm, mut perm_inv) = (vec![0usize; n], vec![0usize; n]);
        let scratch = factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default());
        factor::lu_in_place(
            a.as_mut(),
            &mut perm,
            &mut perm_inv,
            par,
            MemStack::new(&mut MemBuffer::new(scratch)),
            Default::default(),
        );
        InPlaceLu { lu: a, perm, perm_inv }
    }

    /// Its size n.
    pub fn n(&self) -> usize {
        self.lu.nrows()
    }

    /// A⁻¹ b for b with n rows (any number of columns).
    pub fn solve(&self, b: &Mat<f64>) -> Mat<f64> {
        self.solve_either(b, false)
    }

    /// A⁻ᵀ b.
    pub fn solve_transpose(&self, b: &Mat<f64>) -> Mat<f64> {
        self.solve_either(b, true)
    }

    /// A⁻¹ b or A⁻ᵀ b: faer's in-place solves with L and U read from the one array.
    fn solve_either(&self, b: &Mat<f64>, transpose: bool) -> Mat<f64> {
        let mut x = b.clone();
        let (n, k) = (self.n(), x.ncols());
        let par = faer::get_global_parallelism();
        let perm = PermRef::new_checked(&self.perm, &self.perm_inv, n);
        let lu = self.lu.as_ref();
        if transpose {
            let scratch = solve::solve_transpose_in_place_scratch::<usize, f64>(n, k, par);
            solve::solve_transpose_in_place(lu, lu, perm, x.as_mut(), par, MemStack::new(&mut MemBuffer::new(scratch)));
        } else {
            let scratch = solve::solve_in_place_scratch::<usize, f64>(n, k, par);
            solve::solve_in_place(lu, lu, perm, x.as_mut(), par, MemStack::new(&mut MemBuffer::new(scratch)));
        }
        x
    }
}

/// The solves of an LU factorisation ([`InPlaceLu`] or faer's `PartialPivLu`), for code that takes either.
pub trait LuSolve {
    /// A⁻¹ b.
    fn solve_mat(&self, b: &Mat<f64>) -> Mat<f64>;
    /// A⁻ᵀ b.
    fn solve_transpose_mat(&self, b: &Mat<f64>) -> Mat<f64>;
}

impl LuSolve for InPlaceLu {
    fn solve_mat(&self, b: &Mat<f64>) -> Mat<f64> {
        self.solve(b)
    }
    fn solve_transpose_mat(&self, b: &Mat<f64>) -> Mat<f64> {
        self.solve_transpose(b)
    }
}

impl LuSolve for faer::linalg::solvers::PartialPivLu<f64> {
    fn solve_mat(&self, b: &Mat<f64>) -> Mat<f64> {
        faer::linalg::solvers::Solve::solve(self, b)
    }
    fn solve_transpose_mat(&self, b: &Mat<f64>) -> Mat<f64> {
        faer::linalg::solvers::Solve::solve_transpose(self, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use faer::linalg::solvers::Solve;

    /// Against faer's `PartialPivLu` (the same kernels, another storage): the solutions agree bit for bit on a
    /// nonsymmetric matrix that needs pivoting, and solve the system to round-off.
    #[test]
    fn solves_like_faers_partial_piv_lu() {
        let n = 37;
        let a = Mat::<f64>::from_fn(n, n, |i, j| ((i * 13 + j * 7) % 17) as f64 - 8.0 + if i == j { 0.5 } else { 0.0 });
        let b = Mat::<f64>::from_fn(n, 3, |i, j| (i as f64 * 0.3 + j as f64).sin());
        let lu = InPlaceLu::new(a.clone());
        let faer_lu = a.partial_piv_lu();
        for (ours, faers) in [(lu.solve(&b), faer_lu.solve(&b)), (lu.solve_transpose(&b), faer_lu.solve_transpose(&b))]
        {
            for j in 0..3 {
                for i in 0..n {
                    assert_eq!(ours[(i, j)].to_bits(), faers[(i, j)].to_bits(), "({i}, {j})");
                }
            }
        }
        let ours = lu.solve(&b);
        let r = &a * &ours - &b;
        let worst =
            r.col_iter().flat_map(|c| c.iter().copied().collect::<Vec<_>>()).fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(worst < 1e-10, "{worst:e}");
    }
}
