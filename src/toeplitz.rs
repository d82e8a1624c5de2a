//! Toeplitz matrices (plus a constant per column) and their products by FFT.
//!
//! On a uniform grid the half-plane's influence matrices are Toeplitz up to one term: the entry (i, j) is a function
//! of i − j (a strip's influence depends on the distance to the collocation point) plus the displacement of the datum
//! point under strip j, which is the same for every row (`crate::source::half_plane`: displacements are relative to
//! a datum at depth D below the contact centre). So K = T + 1 cᵀ, also with an elastic counter-body on the same grid.
//! A Toeplitz product is a convolution; embedded in a circulant of length L ≥ 2n − 1 it takes two real FFTs and an
//! inverse (O(n log n)) instead of the dense product's 2n² operations, and 1 (cᵀx) adds O(n). The structure is
//! detected, not assumed: [`Toeplitz::detect`] fits t and c and checks every entry, so a BEM wheel's flexibility
//! (not of this form) keeps the dense product.
//!
//! **Where it pays.** Everywhere it was measured. `cargo bench --bench physics -- toeplitz` (criterion medians, one
//! K x, this 2-core machine, 2026-11-27, faer sequential):
//!
//! | n | 16 | 32 | 48 | 64 | 96 | 128 | 192 | 256 | 512 | 841 | 1600 |
//! |---|---|---|---|---|---|---|---|---|---|---|---|
//! | FFT (µs) | 0.19 | 0.27 | 0.39 | 0.47 | 0.72 | 1.30 | 2.25 | 1.77 | 3.54 | 11.1 | 21.7 |
//! | dense (µs) | 0.28 | 0.39 | 0.52 | 0.76 | 1.67 | 2.64 | 6.51 | 11.4 | 39.4 | 143 | 1293 |
//! | dense ÷ FFT | 1.5 | 1.5 | 1.3 | 1.6 | 2.3 | 2.0 | 2.9 | 6.4 | 11 | 13 | 60 |
//!
//! There is no crossover above 16 rows: the dense product's fixed cost (faer's dispatch) exceeds three short FFTs even
//! there. [`FFT_ABOVE`] = 16, the smallest size measured; smaller matrices keep the dense product (not measured).
//! Transform lengths matter (192 rows, L = 384 = 2⁷·3, is slower than 256, L = 512).
//!
//! The products are exact up to round-off relative to ‖T‖·‖x‖ (tested against the dense product to 1e-13 of the
//! product's largest entry),
//! not entry by entry: they serve the iterations (GMRES applies, the active sets' gaps and slips); every final answer
//! is solved by a factorisation and certified by the dense residuals.

use crate::error::ArgumentError;
use faer::Mat;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use std::sync::Arc;

/// Matrices of at least this many rows use the FFT product (the smallest size measured; module docs).
pub const FFT_ABOVE: usize = 16;

/// How closely a matrix must fit T + 1 cᵀ, relative to its largest entry, for [`Toeplitz::detect`]: the round-off
/// of the fit's subtractions (the FFT product itself is accurate to about 1e-15 of ‖T‖‖x‖).
pub const DETECT_TOLERANCE: f64 = 1e-14;

/// A square Toeplitz matrix plus a constant per column, T + 1 cᵀ, ready for FFT products.
#[derive(Clone)]
pub struct Toeplitz {
    n: usize,
    /// c: the constant added to each column (`None`: zero).
    column_shift: Option<Vec<f64>>,
    len: usize,
    /// FFT of the circulant's first column, divided by `len` (the inverse FFT's scale).
    spectrum: Vec<Complex<f64>>,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
}

impl std::fmt::Debug for Toeplitz {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Toeplitz").field("n", &self.n).field("len", &self.len).finish()
    }
}

/// The smallest length ≥ `min` of the form 2^a 3^b (fast FFT sizes).
pub(crate) fn fast_length(min: usize) -> usize {
    let mut best = min.next_power_of_two();
    let mut p3 = 1;
    while p3 < best {
        let mut v = p3;
        while v < min {
            v *= 2;
        }
        best = best.min(v);
        p3 *= 3;
    }
    best
}

/// The outcome of a transform whose buffers the same plan made (`make_output_vec`, or a vector of the plan's length):
/// realfft checks only their lengths and, for the inverse, that the imaginary parts at 0 and len/2 are zero, which
/// [`Toeplitz::apply`] sets just before. No input reaches a failure; one would be a bug in this file, never a wrong
/// product returned.
fn transformed(result: Result<(), realfft::FftError>) {
    result.expect("a realfft transform on buffers made by its own plan");
}

impl Toeplitz {
    /// The Toeplitz matrix with first column `col` (T[k, 0]) and first row `row` (T[0, k]); `col[0]` is the diagonal
    /// (`row[0]` is ignored). Both of length n ≥ 1: other lengths are refused, naming the argument.
    pub fn from_parts(col: &[f64], row: &[f64]) -> Result<Toeplitz, ArgumentError> {
        const F: &str = "Toeplitz::from_parts";
        let n = col.len();
        if n == 0 {
            return Err(ArgumentError::new(F, "col", "is empty: a Toeplitz matrix has n ≥ 1 rows"));
        }
        if row.len() != n {
            return Err(ArgumentError::new(F, "row", format!("has {} entries, `col` {n}", row.len())));
        }
        let Some(len) = n.checked_mul(2).map(fast_length) else {
            return Err(ArgumentError::new(F, "col", format!("{n} rows: the FFT length 2n overflows")));
        };
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(len);
        let inverse = planner.plan_fft_inverse(len);
        let mut c = vec![0.0; len];
        c[..n].copy_from_slice(col);
        for k in 1..n {
            c[len - k] = row[k];
        }
        let mut spectrum = forward.make_output_vec();
        transformed(forward.process(&mut c, &mut spectrum));
        let scale = 1.0 / len as f64;
        spectrum.iter_mut().for_each(|v| *v *= scale);
        Ok(Toeplitz { n, column_shift: None, len, spectrum, forward, inverse })
    }

    /// `Some` when `m` is square, has at least [`FFT_ABOVE`] rows and is T + 1 cᵀ (T Toeplitz, c a constant per
    /// column) to [`DETECT_TOLERANCE`] of its largest entry at every entry; `None` otherwise (the dense product is then
    /// the faster or the only one). The gauge c₀ = 0: t(k) = m[k, 0] for k ≥ 0, c_j = m[j, j] − m[0, 0],
    /// t(−j) = m[0, j] − c_j.
    pub fn detect(m: &Mat<f64>) -> Option<Toeplitz> {
        let n = m.nrows();
        if n < FFT_ABOVE || m.ncols() != n {
            return None;
        }
        let c: Vec<f64> = (0..n).map(|j| m[(j, j)] - m[(0, 0)]).collect();
        let col: Vec<f64> = (0..n).map(|i| m[(i, 0)]).collect();
        let row: Vec<f64> = (0..n).map(|j| m[(0, j)] - c[j]).collect();
        let scale = (0..n).map(|j| (0..n).fold(0.0_f64, |a, i| a.max(m[(i, j)].abs()))).fold(0.0_f64, f64::max);
        let tol = DETECT_TOLERANCE * scale;
        let fits = (0..n).all(|j| {
            (0..n).all(|i| {
                let t = if i >= j { col[i - j] } else { row[j - i] };
                (m[(i, j)] - (t + c[j])).abs() <= tol
            })
        });
        if !fits || !scale.is_finite() {
            return None;
        }
        let mut op = Toeplitz::from_parts(&col, &row).ok()?;
        op.column_shift = c.iter().any(|v| *v != 0.0).then_some(c);
        Some(op)
    }

    /// Number of rows (and columns).
    pub fn n(&self) -> usize {
        self.n
    }

    /// T x (plus 1 cᵀx with a column constant); `x` of another length than n is refused.
    pub fn apply(&self, x: &[f64]) -> Result<Vec<f64>, ArgumentError> {
        if x.len() != self.n {
            return Err(ArgumentError::new(
                "Toeplitz::apply",
                "x",
                format!("has {} entries, the matrix {}", x.len(), self.n),
            ));
        }
        let mut buf = vec![0.0; self.len];
        buf[..self.n].copy_from_slice(x);
        let mut spec = self.forward.make_output_vec();
        transformed(self.forward.process(&mut buf, &mut spec));
        spec.iter_mut().zip(&self.spectrum).for_each(|(a, b)| *a *= b);
        // The inverse of a real signal's spectrum: the imaginary parts at 0 and len/2 are round-off.
        spec[0].im = 0.0;
        if self.len % 2 == 0 {
            spec[self.len / 2].im = 0.0;
        }
        transformed(self.inverse.process(&mut spec, &mut buf));
        buf.truncate(self.n);
        if let Some(c) = &self.column_shift {
            let cx: f64 = c.iter().zip(x).map(|(a, b)| a * b).sum();
            buf.iter_mut().for_each(|v| *v += cx);
        }
        Ok(buf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT product against the dense product (an independent computation) on a non-symmetric Toeplitz matrix
    /// with a logarithmic kernel like the half-plane's, at sizes that hit power-of-two and 2^a·3^b lengths.
    #[test]
    fn fft_product_matches_the_dense_product() {
        for n in [1usize, 2, 5, 96, 200, 301] {
            let t = |k: i64| if k >= 0 { -(1.0 + k as f64).ln() + 0.3 } else { -(1.0 - k as f64).ln() - 0.2 };
            let m = Mat::<f64>::from_fn(n, n, |i, j| t(i as i64 - j as i64));
            let col: Vec<f64> = (0..n).map(|i| m[(i, 0)]).collect();
            let row: Vec<f64> = (0..n).map(|j| m[(0, j)]).collect();
            let op = Toeplitz::from_parts(&col, &row).unwrap();
            let x: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin() + 0.1).collect();
            let dense: Vec<f64> = (0..n).map(|i| (0..n).map(|j| m[(i, j)] * x[j]).sum()).collect();
            let scale = dense.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            for (a, b) in dense.iter().zip(op.apply(&x).unwrap()) {
                assert!((a - b).abs() <= 1e-13 * scale, "n = {n}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn detect_takes_toeplitz_plus_column_constants_of_fft_size_only() {
        let n = FFT_ABOVE;
        let m = Mat::<f64>::from_fn(n, n, |i, j| 1.0 / (1.0 + (i as f64 - j as f64).abs()) + (0.3 * j as f64).cos());
        let op = Toeplitz::detect(&m).expect("T + 1 c^T");
        let x: Vec<f64> = (0..n).map(|i| (i as f64 * 0.21).cos()).collect();
        let dense: Vec<f64> = (0..n).map(|i| (0..n).map(|j| m[(i, j)] * x[j]).sum()).collect();
        let scale = dense.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        for (a, b) in dense.iter().zip(op.apply(&x).unwrap()) {
            assert!((a - b).abs() <= 1e-13 * scale);
        }
        let mut bent = m.clone();
        bent[(7, 3)] += 1e-9;
        assert!(Toeplitz::detect(&bent).is_none(), "one entry off its diagonal's value");
        let small = Mat::<f64>::from_fn(n - 1, n - 1, |i, j| 1.0 / (1.0 + (i as f64 - j as f64).abs()));
        assert!(Toeplitz::detect(&small).is_none(), "below FFT_ABOVE the dense product is used");
    }

    #[test]
    fn fast_lengths_are_smooth_and_large_enough() {
        assert_eq!(fast_length(1682), 1728); // 2^6·3^3, for the 841-element grid
        assert_eq!(fast_length(222), 243);
        assert_eq!(fast_length(256), 256);
    }
}
