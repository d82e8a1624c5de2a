//! Two-level Toeplitz operators and their products by 2D FFT: the influence matrix of a uniform MX × MY grid of
//! elements on a half-space (Kalker's 3D discretisation, issue 32) maps the tractions of element j to the displacement
//! at element i through a kernel of the index offset only, `(K v)_i = Σ_j k(i − j) v_j` with `i = (ix, iy)`,
//! `j = (jx, jy)` and `k` given for offsets `(dx, dy) ∈ [−(mx−1), mx−1] × [−(my−1), my−1]` (block Toeplitz with
//! Toeplitz blocks). A dense matrix would hold (MX·MY)² numbers — 10¹⁰ at 100 000 elements; this operator holds the
//! kernel's spectrum, O(MX·MY), and a product costs O(MX·MY log(MX·MY)).
//!
//! **Method.** The kernel is placed on a periodic `Lx × Ly` grid (`Lx ≥ 2mx − 1`, `Ly ≥ 2my − 1`, fast lengths
//! 2^a 3^b): offset `(dx, dy)` at `(dx mod Lx, dy mod Ly)`. With `v` zero-padded to the same grid, the circular
//! convolution of the two equals `K v` on the original `mx × my` indices, since no offset that occurs wraps onto
//! another. The convolution is a product of 2D spectra: a real-to-complex FFT along x for each of the `Ly` rows
//! (realfft), a complex FFT along y for each of the `Lx/2 + 1` columns (rustfft), the product with the kernel's
//! spectrum (computed once, scaled by `1/(Lx Ly)` for the inverse), and the two inverse transforms.
//!
//! **Layout.** Grid vectors are `ix + mx · iy` (x fastest).
//!
//! **Accuracy.** The product is exact up to the FFT's round-off relative to `‖k‖₁ ‖v‖∞` (tested against the dense
//! product to 1e-13 of the product's largest entry), not entry by entry: like [`crate::toeplitz`], it serves
//! iterations, whose answers are certified by residuals.

use crate::error::ArgumentError;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// A two-level Toeplitz operator on an `mx × my` grid, ready for FFT products (module docs).
#[derive(Clone)]
pub struct Toeplitz2d {
    mx: usize,
    my: usize,
    lx: usize,
    ly: usize,
    /// The kernel's 2D spectrum, `(lx/2 + 1) × ly` (column kx of length ly contiguous), scaled by 1/(lx ly).
    spectrum: Vec<Complex<f64>>,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    fft_y: Arc<dyn Fft<f64>>,
    ifft_y: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for Toeplitz2d {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Toeplitz2d").field("mx", &self.mx).field("my", &self.my).field("lx", &self.lx).finish()
    }
}

/// Buffers of a block product (reused by [`Toeplitz2d::apply_block_into`]).
#[derive(Debug, Default, Clone)]
pub struct BlockScratch {
    one: Scratch,
    other: Vec<Complex<f64>>,
}

/// Buffers of one product (reused by [`Toeplitz2d::apply_into`]).
#[derive(Debug, Default, Clone)]
pub struct Scratch {
    real: Vec<f64>,
    half: Vec<Complex<f64>>,
    spectrum: Vec<Complex<f64>>,
}

impl Toeplitz2d {
    /// The operator of `kernel(dx, dy)` (offsets as in the module docs) on an `mx × my` grid.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the grid is empty or larger than 2²⁶ elements in either direction, or when the
    /// kernel has a non-finite value.
    pub fn new(mx: usize, my: usize, kernel: impl Fn(isize, isize) -> f64) -> Result<Toeplitz2d, ArgumentError> {
        let bad = |arg: &'static str, msg: String| ArgumentError::new("Toeplitz2d::new", arg, msg);
        Toeplitz2d::check_size("Toeplitz2d::new", mx, my)?;
        let mut op = Toeplitz2d::plan(mx, my);
        let (lx, ly) = (op.lx, op.ly);
        let mut grid = vec![0.0; lx * ly];
        let (mxi, myi) = (mx as isize, my as isize);
        for dy in -(myi - 1)..myi {
            for dx in -(mxi - 1)..mxi {
                let v = kernel(dx, dy);
                if !v.is_finite() {
                    return Err(bad("kernel", format!("k({dx}, {dy}) = {v} is not finite")));
                }
                grid[dx.rem_euclid(lx as isize) as usize + lx * dy.rem_euclid(ly as isize) as usize] = v;
            }
        }
        op.set_spectrum(grid);
        Ok(op)
    }

    /// A grid of 1 to 2²⁶ elements a side, or an [`ArgumentError`] of `function` naming `mx, my`.
    fn check_size(function: &'static str, mx: usize, my: usize) -> Result<(), ArgumentError> {
        const LIMIT: usize = 1 << 26;
        if mx == 0 || my == 0 || mx > LIMIT || my > LIMIT {
            let msg = format!("a grid of 1 to {LIMIT} elements a side (got {mx} × {my})");
            return Err(ArgumentError::new(function, "mx, my", msg));
        }
        Ok(())
    }

    /// The FFT plans of an `mx × my` grid (sizes checked by [`Toeplitz2d::check_size`]), with no kernel yet.
    fn plan(mx: usize, my: usize) -> Toeplitz2d {
        let (lx, ly) = (crate::toeplitz::fast_length(2 * mx - 1), crate::toeplitz::fast_length(2 * my - 1));
        Toeplitz2d::plan_periodic(mx, my, lx, ly)
    }

    /// The FFT plans of an `mx × my` grid on the periodic `lx × ly` grid (`lx ≥ mx`, `ly ≥ my`), with no kernel.
    fn plan_periodic(mx: usize, my: usize, lx: usize, ly: usize) -> Toeplitz2d {
        let mut planner = RealFftPlanner::<f64>::new();
        let (r2c, c2r) = (planner.plan_fft_forward(lx), planner.plan_fft_inverse(lx));
        let mut cplanner = FftPlanner::<f64>::new();
        let (fft_y, ifft_y) = (cplanner.plan_fft_forward(ly), cplanner.plan_fft_inverse(ly));
        Toeplitz2d { mx, my, lx, ly, spectrum: Vec::new(), r2c, c2r, fft_y, ifft_y }
    }

    /// The kernel's spectrum from its values on the periodic grid (destroyed), scaled for the inverse transform.
    fn set_spectrum(&mut self, mut grid: Vec<f64>) {
        let mut scratch = Scratch::default();
        self.forward(&mut grid, &mut scratch);
        let scale = 1.0 / (self.lx * self.ly) as f64;
        self.spectrum = scratch.spectrum.iter().map(|c| c * scale).collect();
    }

    /// The circulant operator of an even kernel on the periodic grid an `mx × my` operator uses: `k(|dx|, |dy|)`
    /// at every nearest-image offset (`|dx| ≤ Lx/2`, `|dy| ≤ Ly/2`), not only the offsets of the grid, with no
    /// zero padding. Its products cut to the `mx × my` grid are `K v` again (every offset within the grid is its own
    /// nearest image, `Lx ≥ 2mx − 1`); what differs from [`Toeplitz2d::new`] is the embedding, hence its inverse
    /// ([`Toeplitz2d::circulant_inverse`]), the preconditioner of `K`: for a kernel whose Fourier transform is
    /// positive (as the half-space's), the embedding of all images stays positive where the zero-padded one dips
    /// below zero (tests). `kernel` is called once per offset of one quadrant.
    ///
    /// # Errors
    /// As [`Toeplitz2d::new`].
    pub fn circulant_even(
        mx: usize,
        my: usize,
        kernel: impl Fn(usize, usize) -> f64,
    ) -> Result<Toeplitz2d, ArgumentError> {
        Toeplitz2d::check_size("Toeplitz2d::circulant_even", mx, my)?;
        let op = Toeplitz2d::plan(mx, my);
        Toeplitz2d::circulant_even_periodic(op, kernel)
    }

    /// As [`Toeplitz2d::circulant_even`] on the smallest fast periodic grid that holds the `mx × my` grid once
    /// (`Lx ≥ mx`, `Ly ≥ my`, not `2mx − 1`): Strang's circulant, whose products cut to the grid are NOT `K v` (the
    /// far offsets wrap onto near images), but whose inverse is a cheaper preconditioner — a quarter of the FFT work.
    ///
    /// # Errors
    /// As [`Toeplitz2d::new`].
    pub fn circulant_even_compact(
        mx: usize,
        my: usize,
        kernel: impl Fn(usize, usize) -> f64,
    ) -> Result<Toeplitz2d, ArgumentError> {
        Toeplitz2d::check_size("Toeplitz2d::circulant_even_compact", mx, my)?;
        let (lx, ly) = (crate::toeplitz::fast_length(mx), crate::toeplitz::fast_length(my));
        Toeplitz2d::circulant_even_periodic(Toeplitz2d::plan_periodic(mx, my, lx, ly), kernel)
    }

    /// The circulant of the even `kernel` on `op`'s periodic grid (nearest images), as its spectrum.
    fn circulant_even_periodic(
        mut op: Toeplitz2d,
        kernel: impl Fn(usize, usize) -> f64,
    ) -> Result<Toeplitz2d, ArgumentError> {
        let (lx, ly) = (op.lx, op.ly);
        let (hx, hy) = (lx / 2 + 1, ly / 2 + 1);
        let mut quadrant = Vec::with_capacity(hx * hy);
        for j in 0..hy {
            for i in 0..hx {
                let v = kernel(i, j);
                if !v.is_finite() {
                    let msg = format!("k({i}, {j}) = {v} is not finite");
                    return Err(ArgumentError::new("Toeplitz2d::circulant_even", "kernel", msg));
                }
                quadrant.push(v);
            }
        }
        let mut grid = vec![0.0; lx * ly];
        for jy in 0..ly {
            let j = jy.min(ly - jy);
            for jx in 0..lx {
                grid[jx + lx * jy] = quadrant[jx.min(lx - jx) + hx * j];
            }
        }
        op.set_spectrum(grid);
        Ok(op)
    }

    /// The grid's size (mx, my).
    pub fn size(&self) -> (usize, usize) {
        (self.mx, self.my)
    }

    /// The periodic grid's size (Lx, Ly) the products use (module docs, "Method").
    pub fn periodic_size(&self) -> (usize, usize) {
        (self.lx, self.ly)
    }

    /// `K v` (`v` of length `mx · my`, index `ix + mx · iy`).
    ///
    /// # Errors
    /// An [`ArgumentError`] when `v` has another length.
    pub fn apply(&self, v: &[f64]) -> Result<Vec<f64>, ArgumentError> {
        let mut out = vec![0.0; v.len()];
        self.apply_into(v, &mut out, &mut Scratch::default())?;
        Ok(out)
    }

    /// `K v` into `out`, with reusable buffers.
    ///
    /// # Errors
    /// An [`ArgumentError`] when `v` or `out` is not `mx · my` long.
    pub fn apply_into(&self, v: &[f64], out: &mut [f64], scratch: &mut Scratch) -> Result<(), ArgumentError> {
        let n = self.mx * self.my;
        if v.len() != n || out.len() != n {
            let msg = format!("v and out of {n} entries (got {} and {})", v.len(), out.len());
            return Err(ArgumentError::new("Toeplitz2d::apply_into", "v", msg));
        }
        self.load(v, scratch);
        for (s, k) in scratch.spectrum.iter_mut().zip(&self.spectrum) {
            *s *= k;
        }
        let mut spectrum = std::mem::take(&mut scratch.spectrum);
        self.inverse(&mut spectrum, out, scratch);
        scratch.spectrum = spectrum;
        Ok(())
    }

    /// The symmetric 2 × 2 block product `[u_x; u_y] = [A B; B C] [v_x; v_y]` of three operators of one grid
    /// (`blocks = [A, B, C]`), with two forward and two inverse transforms instead of the eight of four separate
    /// products (the spectra are combined before transforming back).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the three operators are not of one grid, or a vector is not `mx · my` long.
    pub fn apply_block_into(
        blocks: [&Toeplitz2d; 3],
        v: (&[f64], &[f64]),
        out: (&mut [f64], &mut [f64]),
        scratch: &mut BlockScratch,
    ) -> Result<(), ArgumentError> {
        let [a, b, c] = blocks;
        let n = a.mx * a.my;
        if [b, c].iter().any(|o| (o.mx, o.my, o.lx, o.ly) != (a.mx, a.my, a.lx, a.ly)) {
            let msg = "the three operators must be of one grid".to_string();
            return Err(ArgumentError::new("Toeplitz2d::apply_block_into", "blocks", msg));
        }
        if [v.0.len(), v.1.len(), out.0.len(), out.1.len()].iter().any(|&l| l != n) {
            let msg = format!("vectors of {n} entries");
            return Err(ArgumentError::new("Toeplitz2d::apply_block_into", "v", msg));
        }
        let s = &mut scratch.one;
        a.load(v.0, s);
        let mut sx = std::mem::take(&mut scratch.other);
        std::mem::swap(&mut sx, &mut s.spectrum);
        a.load(v.1, s);
        let sy = &mut s.spectrum;
        // sx ← A x̂ + B ŷ, sy ← B x̂ + C ŷ (per frequency).
        for k in 0..sx.len() {
            let (x, y) = (sx[k], sy[k]);
            sx[k] = a.spectrum[k] * x + b.spectrum[k] * y;
            sy[k] = b.spectrum[k] * x + c.spectrum[k] * y;
        }
        let mut sy = std::mem::take(&mut s.spectrum);
        a.inverse(&mut sx, out.0, s);
        a.inverse(&mut sy, out.1, s);
        s.spectrum = sy;
        scratch.other = sx;
        Ok(())
    }

    /// `v` zero-padded onto the periodic grid and transformed: its spectrum in `scratch.spectrum`.
    fn load(&self, v: &[f64], scratch: &mut Scratch) {
        let lx = self.lx;
        let mut grid = std::mem::take(&mut scratch.real);
        grid.clear();
        grid.resize(lx * self.ly, 0.0);
        for (iy, row) in v.chunks_exact(self.mx).enumerate() {
            grid[lx * iy..lx * iy + self.mx].copy_from_slice(row);
        }
        self.forward(&mut grid, scratch);
        scratch.real = grid;
    }

    /// The inverse transform of a spectrum (destroyed), cut to the `mx × my` grid, into `out`.
    fn inverse(&self, spectrum: &mut [Complex<f64>], out: &mut [f64], scratch: &mut Scratch) {
        let (lx, ly, hx) = (self.lx, self.ly, self.lx / 2 + 1);
        // Inverse along y (column by column), then along x (row by row).
        for kx in 0..hx {
            self.ifft_y.process(&mut spectrum[kx * ly..(kx + 1) * ly]);
        }
        scratch.half.resize(hx, Complex::default());
        let mut row = std::mem::take(&mut scratch.real);
        row.resize(lx, 0.0);
        for iy in 0..self.my {
            for kx in 0..hx {
                scratch.half[kx] = spectrum[kx * ly + iy];
            }
            // The imaginary parts at 0 and lx/2 are round-off of a real signal's transform: zero them, as c2r needs.
            scratch.half[0].im = 0.0;
            if lx % 2 == 0 {
                scratch.half[hx - 1].im = 0.0;
            }
            // Lengths come from this plan: the transform cannot fail (module docs of crate::toeplitz).
            let _ = self.c2r.process(&mut scratch.half, &mut row[..lx]);
            out[self.mx * iy..self.mx * (iy + 1)].copy_from_slice(&row[..self.mx]);
        }
        scratch.real = row;
    }

    /// The inverse of this operator's circulant embedding (module docs, "Method"), as an operator of the same grid:
    /// `M v` is `v` zero-padded to the periodic `Lx × Ly` grid, divided by the kernel's spectrum, transformed back
    /// and cut to the `mx × my` grid. For a kernel even in both offsets (`k(−dx, dy) = k(dx, −dy) = k(dx, dy)`, as
    /// every symmetric influence kernel), the spectrum is real; its values are floored at `floor` times the largest
    /// one before they are inverted, so that `M` is symmetric positive definite whatever the embedding's smallest
    /// eigenvalues: the FFT preconditioner of a conjugate-gradient method on a subset of the grid (Vollebregt, J.
    /// Comput. Phys. 257, 2014: the pressures that give unit displacement at one element). Returns the operator and
    /// the number of spectral values that were floored.
    ///
    /// # Errors
    /// An [`ArgumentError`] when `floor` is not in (0, 1) or the spectrum's largest value is not positive.
    pub fn circulant_inverse(&self, floor: f64) -> Result<(Toeplitz2d, usize), ArgumentError> {
        let bad = |msg: String| ArgumentError::new("Toeplitz2d::circulant_inverse", "floor", msg);
        if !(floor > 0.0 && floor < 1.0) {
            return Err(bad(format!("in (0, 1) (got {floor})")));
        }
        let top = self.spectrum.iter().fold(0.0_f64, |m, c| m.max(c.re));
        if !(top > 0.0 && top.is_finite()) {
            return Err(bad(format!("the kernel's spectrum has no positive value (largest {top:e})")));
        }
        // `spectrum` holds s = k̂ / L (L = lx·ly); the inverse wants (1 / k̂) / L = 1 / (s L²).
        let l2 = ((self.lx * self.ly) as f64).powi(2);
        let mut floored = 0;
        let spectrum = self
            .spectrum
            .iter()
            .map(|c| {
                let s = if c.re < floor * top {
                    floored += 1;
                    floor * top
                } else {
                    c.re
                };
                Complex::new(1.0 / (s * l2), 0.0)
            })
            .collect();
        Ok((Toeplitz2d { spectrum, ..self.clone() }, floored))
    }

    /// The 2D spectrum of a real `lx × ly` grid (destroyed) into `scratch.spectrum`, column-major in kx.
    fn forward(&self, grid: &mut [f64], scratch: &mut Scratch) {
        let (lx, ly, hx) = (self.lx, self.ly, self.lx / 2 + 1);
        scratch.half.resize(hx, Complex::default());
        scratch.spectrum.clear();
        scratch.spectrum.resize(hx * ly, Complex::default());
        for iy in 0..ly {
            let row = &mut grid[lx * iy..lx * (iy + 1)];
            if row.iter().all(|v| *v == 0.0) {
                continue;
            }
            let _ = self.r2c.process(row, &mut scratch.half);
            for kx in 0..hx {
                scratch.spectrum[kx * ly + iy] = scratch.half[kx];
            }
        }
        for kx in 0..hx {
            self.fft_y.process(&mut scratch.spectrum[kx * ly..(kx + 1) * ly]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Toeplitz2d;

    /// A kernel with no symmetry (so that a transposed or mirrored embedding is caught), smooth plus a peak.
    fn kernel(dx: isize, dy: isize) -> f64 {
        let (x, y) = (dx as f64, dy as f64);
        1.0 / (1.0 + x * x + 0.5 * y * y).sqrt() + 0.01 * x - 0.02 * y + 0.001 * x * y
    }

    /// The dense product Σ_j k(i − j) v_j, computed directly (the reference).
    fn dense(mx: usize, my: usize, v: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; mx * my];
        for iy in 0..my {
            for ix in 0..mx {
                let mut s = 0.0;
                for jy in 0..my {
                    for jx in 0..mx {
                        s += kernel(ix as isize - jx as isize, iy as isize - jy as isize) * v[jx + mx * jy];
                    }
                }
                out[ix + mx * iy] = s;
            }
        }
        out
    }

    #[test]
    fn the_fft_product_is_the_dense_product() {
        for (mx, my) in [(1, 1), (1, 7), (9, 1), (2, 3), (13, 11), (16, 16), (31, 5), (40, 27)] {
            let v: Vec<f64> = (0..mx * my).map(|k| ((k * 7919) % 101) as f64 / 50.0 - 1.0).collect();
            let op = Toeplitz2d::new(mx, my, kernel).unwrap();
            let fast = op.apply(&v).unwrap();
            let slow = dense(mx, my, &v);
            let scale = slow.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
            let err = fast.iter().zip(&slow).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(err <= 1e-13 * scale, "{mx}×{my}: {err:e} of {scale:e}");
            // Reused buffers give the same product.
            let mut out = vec![0.0; mx * my];
            let mut scratch = super::Scratch::default();
            op.apply_into(&v, &mut out, &mut scratch).unwrap();
            op.apply_into(&v, &mut out, &mut scratch).unwrap();
            assert_eq!(out, fast);
        }
    }

    /// The circulant inverse's spectrum is the reciprocal of the kernel's (`s s' L² = 1` with the stored scaling
    /// `s = k̂/L`), real for a kernel even in both offsets; refusals name the floor.
    #[test]
    fn the_circulant_inverse_inverts_the_spectrum() {
        let sym = |dx: isize, dy: isize| {
            let (x, y) = (dx as f64, dy as f64);
            1.0 / (0.3 + x * x + 0.5 * y * y).sqrt()
        };
        let op = Toeplitz2d::new(12, 9, sym).unwrap();
        let floor = 1e-3;
        let (inv, floored) = op.circulant_inverse(floor).unwrap();
        let top = op.spectrum.iter().fold(0.0_f64, |m, c| m.max(c.norm()));
        let l = (op.lx * op.ly) as f64;
        let mut low = 0;
        for (a, b) in op.spectrum.iter().zip(&inv.spectrum) {
            // s = k̂/L and s' = (1/k̂)/L: s s' L² = 1; below the floor, s' = 1/(floor · top · L²).
            let s = if a.re < floor * top {
                low += 1;
                floor * top
            } else {
                a.re
            };
            assert!((s * b.re * l * l - 1.0).abs() < 1e-12 && b.im == 0.0);
        }
        // The zero-padded embedding of this 1/r kernel is not positive definite: some values are floored, and
        // counted as such.
        assert!(low > 0 && floored == low);
        assert!(op.spectrum.iter().all(|c| c.im.abs() <= 1e-13 * top), "an even kernel's spectrum is real");
        assert!(op.circulant_inverse(0.0).is_err() && op.circulant_inverse(1.0).is_err());
        // A kernel with no positive spectral value is refused.
        let neg = Toeplitz2d::new(4, 4, |dx, dy| if dx == 0 && dy == 0 { -1.0 } else { 0.0 }).unwrap();
        assert!(neg.circulant_inverse(1e-3).is_err());
    }

    /// The embedding of all periodic images: cut to the grid, its product is the Toeplitz product (to 1e-13 of the
    /// largest entry); for the 1/r-like kernel above, the zero-padded embedding of a 101 × 37 grid (periodic grid
    /// 216 × 81: padding) has values ≤ 0 that the embedding of all images does not have.
    #[test]
    fn the_embedding_of_all_images_keeps_the_product_and_stays_positive() {
        let sym = |dx: f64, dy: f64| 1.0 / (0.3 + dx * dx + 0.5 * dy * dy).sqrt();
        let (mx, my) = (101, 37);
        let padded = Toeplitz2d::new(mx, my, |dx, dy| sym(dx as f64, dy as f64)).unwrap();
        let images = Toeplitz2d::circulant_even(mx, my, |i, j| sym(i as f64, j as f64)).unwrap();
        assert_eq!(padded.periodic_size(), images.periodic_size());
        let v: Vec<f64> = (0..mx * my).map(|k| ((k * 7919) % 101) as f64 / 50.0 - 1.0).collect();
        let (a, b) = (padded.apply(&v).unwrap(), images.apply(&v).unwrap());
        let scale = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-13 * scale));
        let tiny = 1e-15;
        assert!(padded.circulant_inverse(tiny).unwrap().1 > 0, "the zero-padded embedding dips below zero");
        assert_eq!(images.circulant_inverse(tiny).unwrap().1, 0, "the embedding of all images does not");
        assert!(Toeplitz2d::circulant_even(3, 3, |_, _| f64::NAN).is_err());
    }

    /// The 2 × 2 block product equals the four separate products (to 1e-13 of the largest entry), with the block
    /// scratch reused; operators of different grids and wrong lengths are refused.
    #[test]
    fn the_block_product_is_the_four_products() {
        let (mx, my) = (13, 8);
        let a = Toeplitz2d::new(mx, my, kernel).unwrap();
        let b = Toeplitz2d::new(mx, my, |dx, dy| 0.3 * kernel(dy, dx)).unwrap();
        let c = Toeplitz2d::new(mx, my, |dx, dy| kernel(-dx, dy) + 0.5).unwrap();
        let vx: Vec<f64> = (0..mx * my).map(|k| ((k * 7919) % 101) as f64 / 50.0 - 1.0).collect();
        let vy: Vec<f64> = (0..mx * my).map(|k| ((k * 104729) % 97) as f64 / 40.0 - 1.2).collect();
        let add = |p: Vec<f64>, q: Vec<f64>| p.iter().zip(&q).map(|(x, y)| x + y).collect::<Vec<f64>>();
        let ex = add(a.apply(&vx).unwrap(), b.apply(&vy).unwrap());
        let ey = add(b.apply(&vx).unwrap(), c.apply(&vy).unwrap());
        let (mut ux, mut uy) = (vec![0.0; mx * my], vec![0.0; mx * my]);
        let mut scratch = super::BlockScratch::default();
        for _ in 0..2 {
            Toeplitz2d::apply_block_into([&a, &b, &c], (&vx, &vy), (&mut ux, &mut uy), &mut scratch).unwrap();
            for (got, exp) in [(&ux, &ex), (&uy, &ey)] {
                let scale = exp.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
                assert!(got.iter().zip(exp.iter()).all(|(g, e)| (g - e).abs() <= 1e-13 * scale));
            }
        }
        let other = Toeplitz2d::new(mx, my + 1, kernel).unwrap();
        let r = Toeplitz2d::apply_block_into([&a, &other, &c], (&vx, &vy), (&mut ux, &mut uy), &mut scratch);
        assert!(r.unwrap_err().to_string().contains("blocks"));
        let r = Toeplitz2d::apply_block_into([&a, &b, &c], (&vx[1..], &vy), (&mut ux, &mut uy), &mut scratch);
        assert!(r.is_err());
    }

    #[test]
    fn bad_arguments_are_errors_not_panics() {
        assert!(Toeplitz2d::new(0, 3, kernel).is_err());
        assert!(Toeplitz2d::new(3, 3, |_, _| f64::NAN).is_err());
        let op = Toeplitz2d::new(3, 2, kernel).unwrap();
        assert!(op.apply(&[1.0; 5]).is_err());
        assert_eq!(op.size(), (3, 2));
    }
}
