//! Where the grid's elements are ([`ContactGrid`]) and the FFT operators of its influence ([`Influence`]).

use super::kernel::{Coefficients, Compliance, KernelTable, UniformGrid};
use crate::error::ArgumentError;
use crate::toeplitz2d::{BlockScratch, Scratch, Toeplitz2d};

/// The largest grid (elements) for which a dense influence matrix may be formed ([`Influence::dense`]): 4 096
/// elements, a 128 MiB matrix of one component. Dense matrices serve cross-checks by Lemke and clarabel on small
/// grids; production paths use the FFT products.
pub const DENSE_LIMIT: usize = 4096;

/// A uniform grid of `mx × my` rectangular elements `dx × dy` whose first element `(0, 0)` has its centre at
/// `(x0, y0)`: element `(ix, iy)` is centred at `(x0 + ix·dx, y0 + iy·dy)` and covers that point ± `dx/2`, `dy/2`.
/// Lengths in any one unit (the scene's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactGrid {
    mx: usize,
    my: usize,
    dx: f64,
    dy: f64,
    x0: f64,
    y0: f64,
}

impl ContactGrid {
    /// The grid of `mx × my` elements (`≥ 1` each, at most 2²⁶ per side and 2³² in all) of sides `dx`, `dy`
    /// (finite, `> 0`) with the first centre at `(x0, y0)` (finite).
    ///
    /// # Errors
    /// An [`ArgumentError`] naming the argument out of range.
    pub fn new(mx: usize, my: usize, dx: f64, dy: f64, x0: f64, y0: f64) -> Result<ContactGrid, ArgumentError> {
        const F: &str = "ContactGrid::new";
        for (name, m) in [("mx", mx), ("my", my)] {
            if m == 0 || m > 1 << 26 {
                return Err(ArgumentError::new(F, name, format!("(elements) must be 1 ..= 2^26, got {m}")));
            }
        }
        if mx * my > 1 << 32 {
            return Err(ArgumentError::new(F, "my", format!("{mx} × {my} elements exceed 2^32")));
        }
        for (name, h) in [("dx", dx), ("dy", dy)] {
            if !(h > 0.0 && h.is_finite()) {
                return Err(ArgumentError::new(F, name, format!("(element side) must be finite and > 0, got {h}")));
            }
        }
        for (name, v) in [("x0", x0), ("y0", y0)] {
            if !v.is_finite() {
                return Err(ArgumentError::new(F, name, format!("must be finite, got {v}")));
            }
        }
        Ok(ContactGrid { mx, my, dx, dy, x0, y0 })
    }

    /// The grid of `mx × my` elements covering the rectangle `[x_lo, x_hi] × [y_lo, y_hi]` exactly (CONTACT's
    /// potential contact area given by its extent).
    ///
    /// # Errors
    /// An [`ArgumentError`] when a bound is not finite, a range is empty or reversed, or a count is out of range.
    pub fn covering(
        mx: usize,
        my: usize,
        x_lo: f64,
        x_hi: f64,
        y_lo: f64,
        y_hi: f64,
    ) -> Result<ContactGrid, ArgumentError> {
        const F: &str = "ContactGrid::covering";
        for (name, lo, hi) in [("x_hi", x_lo, x_hi), ("y_hi", y_lo, y_hi)] {
            if !(lo.is_finite() && hi.is_finite() && hi > lo) {
                return Err(ArgumentError::new(
                    F,
                    name,
                    format!("the range {lo} .. {hi} must be finite and non-empty"),
                ));
            }
        }
        if mx == 0 || my == 0 {
            return Err(ArgumentError::new(F, "mx", format!("a grid of at least 1 × 1 elements, got {mx} × {my}")));
        }
        let (dx, dy) = ((x_hi - x_lo) / mx as f64, (y_hi - y_lo) / my as f64);
        ContactGrid::new(mx, my, dx, dy, x_lo + 0.5 * dx, y_lo + 0.5 * dy)
    }

    /// Elements along `x`.
    pub fn mx(&self) -> usize {
        self.mx
    }

    /// Elements along `y`.
    pub fn my(&self) -> usize {
        self.my
    }

    /// Number of elements `mx · my`.
    pub fn len(&self) -> usize {
        self.mx * self.my
    }

    /// Always false: a grid has at least one element.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Element side along `x` (length).
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// Element side along `y` (length).
    pub fn dy(&self) -> f64 {
        self.dy
    }

    /// One element's area `dx · dy`.
    pub fn area(&self) -> f64 {
        self.dx * self.dy
    }

    /// The centre of element `(ix, iy)` (not range-checked: any index gives the lattice point).
    pub fn centre(&self, ix: usize, iy: usize) -> (f64, f64) {
        (self.x0 + ix as f64 * self.dx, self.y0 + iy as f64 * self.dy)
    }

    /// The element centres in grid order (`ix + mx·iy`).
    pub fn centres(&self) -> Vec<(f64, f64)> {
        (0..self.my).flat_map(|iy| (0..self.mx).map(move |ix| self.centre(ix, iy))).collect()
    }

    /// The function `f(x, y)` sampled at the element centres, in grid order (e.g. an initial separation
    /// `A x² + B y²`).
    pub fn sample(&self, f: impl Fn(f64, f64) -> f64) -> Vec<f64> {
        self.centres().into_iter().map(|(x, y)| f(x, y)).collect()
    }

    /// The uniform-grid kernel of this grid with the material constants `compliance`.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the grid's kernel cannot be held ([`UniformGrid::new`]).
    pub fn kernel(&self, compliance: Compliance) -> Result<UniformGrid, ArgumentError> {
        UniformGrid::new(compliance, self.mx, self.my, self.dx, self.dy)
    }
}

/// Which kernels an [`Influence`] holds: the effects a problem pays for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Kernels {
    /// `C_zz` only: the frictionless normal problem.
    Normal,
    /// `C_zz` and the tangential `C_xx`, `C_xy`, `C_yy`; the coupling `C_zx`, `C_zy` too when the pair's coupling
    /// constant is non-zero (dissimilar materials), never for an identical pair (they vanish identically).
    Full,
}

/// The floor of the circulant spectra inverted by [`Influence::normal_preconditioner`] and
/// [`Influence::tangential_preconditioner`]: this factor times `1/max(Lx, Ly)` of the largest value (`Lx × Ly` the
/// preconditioner's periodic grid). A guard only.
///
/// The preconditioners invert compact circulants of the kernels' nearest periodic images
/// ([`Toeplitz2d::circulant_even_compact`]), whose spectra, like the 1/|k| of the half-space, stay positive: the
/// smallest value of `C_zz`'s was at least `0.51/max(Lx, Ly)` of the largest on every grid measured (1 × 9, 2 × 2,
/// 7 × 5, 15 × 15 to 575 × 647, square and 1 : 3 elements, 101 × 37; ν = 0, 0.28, 0.3), and of `C_xx`'s and
/// `C_yy`'s at least `0.41/max(Lx, Ly)` (ν up to 0.5), so this floor is never reached there (test
/// `the_compact_circulants_stay_above_the_floor`). (The zero-padded embedding of [`Toeplitz2d::new`] is not positive on every grid — e.g. 101 × 37 — and
/// inverting it took up to 423 iterations against 19 on a Hertz ellipse of a/b = 3.)
///
/// Why the compact circulant: it holds the grid once (`Lx ≥ mx`), not twice, so each preconditioner product costs
/// a quarter of the FFT work of the embedding of all images on the products' grid (`Lx ≥ 2mx − 1`,
/// [`Toeplitz2d::circulant_even`]), and it preconditions as well: the normal PCG's iterations on Hertz's circle and
/// the 8 : 1 ellipse at 10 … 160 elements across were 10 12 14 17 19 and 15 17 19 22 24 against 9 12 14 16 19 and
/// 15 17 19 21 24; the tangential CG's on CONTACT's `tang_problm_1s`, `2s`, `4s` 47, 70, 150 against 47, 70, 140 (with the CG's
/// step criterion alone, before its stop also asked for a small fresh residual).
pub const PRECONDITIONER_FLOOR: f64 = 0.001;

/// The inverse of the compact circulant of an even kernel given on one quadrant ([`PRECONDITIONER_FLOOR`]).
fn compact_inverse(mx: usize, my: usize, kernel: impl Fn(usize, usize) -> f64) -> Result<Toeplitz2d, ArgumentError> {
    let c = Toeplitz2d::circulant_even_compact(mx, my, kernel)?;
    let (lx, ly) = c.periodic_size();
    Ok(c.circulant_inverse(PRECONDITIONER_FLOOR / lx.max(ly) as f64)?.0)
}

/// The influence operators of a grid: `u_z = C_zz p`, and on demand `u_t = C_tt q` and the coupling `C_zt`, `C_tz`,
/// each a two-level Toeplitz operator applied by FFT ([`crate::toeplitz2d`]). Per unit traction; displacements as
/// in [`super::kernel`] (body 1 relative to body 2 for a pair).
#[derive(Clone, Debug)]
pub struct Influence {
    grid: ContactGrid,
    kernel: UniformGrid,
    table: KernelTable,
    zz: Toeplitz2d,
    tangential: Option<[Toeplitz2d; 3]>,
    coupling: Option<[Toeplitz2d; 2]>,
    /// The inverse of `C_zz`'s circulant embedding, built on first use ([`Influence::normal_preconditioner`]).
    normal_inverse: std::sync::OnceLock<Toeplitz2d>,
    /// The inverses of `C_xx`'s and `C_yy`'s circulant embeddings, built on first use
    /// ([`Influence::tangential_preconditioner`]).
    tangential_inverse: std::sync::OnceLock<[Toeplitz2d; 2]>,
}

impl Influence {
    /// The operators of `grid` with the constants `compliance` ([`super::HalfSpace::compliance`] or
    /// [`super::HalfSpace::pair`]), holding the kernels `kernels` says.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the grid's kernel cannot be built (too large; a non-finite coefficient, which the
    /// constants of two [`super::HalfSpace`]s cannot produce).
    pub fn new(grid: ContactGrid, compliance: Compliance, kernels: Kernels) -> Result<Influence, ArgumentError> {
        let kernel = grid.kernel(compliance)?;
        // Only what the kernels asked for: a frictionless problem never computes the tangential integrals.
        let table = match kernels {
            Kernels::Normal => kernel.normal_table(),
            Kernels::Full => kernel.kernel_table(),
        };
        let op = |f: fn(&Coefficients) -> f64| {
            Toeplitz2d::new(grid.mx, grid.my, |di, dj| table.get(di, dj).map_or(f64::NAN, |c| f(&c)))
        };
        let zz = op(|c| c.zz)?;
        let (tangential, coupling) = match kernels {
            Kernels::Normal => (None, None),
            Kernels::Full => {
                let t = [op(|c| c.xx)?, op(|c| c.xy)?, op(|c| c.yy)?];
                let c = if compliance.coupling() != 0.0 { Some([op(|c| c.zx)?, op(|c| c.zy)?]) } else { None };
                (Some(t), c)
            }
        };
        let (normal_inverse, tangential_inverse) = (std::sync::OnceLock::new(), std::sync::OnceLock::new());
        Ok(Influence { grid, kernel, table, zz, tangential, coupling, normal_inverse, tangential_inverse })
    }

    /// The grid.
    pub fn grid(&self) -> &ContactGrid {
        &self.grid
    }

    /// The material constants.
    pub fn compliance(&self) -> Compliance {
        self.kernel.compliance()
    }

    /// The kernel's quadrant table (every coefficient at every offset, by parity: [`KernelTable::get`]).
    pub fn kernel_table(&self) -> &KernelTable {
        &self.table
    }

    /// Whether the tangential kernels were built.
    pub fn has_tangential(&self) -> bool {
        self.tangential.is_some()
    }

    /// Whether the coupling kernels were built (a pair of dissimilar materials with [`Kernels::Full`]).
    pub fn has_coupling(&self) -> bool {
        self.coupling.is_some()
    }

    /// The normal operator `C_zz` (for solvers that apply it themselves).
    pub fn normal_operator(&self) -> &Toeplitz2d {
        &self.zz
    }

    /// The FFT preconditioner of the normal problem: the inverse of `C_zz`'s compact circulant (Strang's: the
    /// kernel's nearest periodic images on the smallest fast periodic grid that holds the grid once,
    /// [`Toeplitz2d::circulant_even_compact`]; [`Toeplitz2d::circulant_inverse`], spectral values floored as
    /// [`PRECONDITIONER_FLOOR`] says), built on first use and kept.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the spectrum has no positive value (not for the kernels of [`super::HalfSpace`]s).
    pub fn normal_preconditioner(&self) -> Result<&Toeplitz2d, ArgumentError> {
        if let Some(m) = self.normal_inverse.get() {
            return Ok(m);
        }
        let zz = |i: usize, j: usize| match self.table.get(i as isize, j as isize) {
            Some(c) => c.zz,
            None => self.kernel.normal_at(i, j),
        };
        let m = compact_inverse(self.grid.mx, self.grid.my, zz)?;
        Ok(self.normal_inverse.get_or_init(|| m))
    }

    /// The FFT preconditioner of the tangential problem: the inverses of the compact circulants of the diagonal
    /// blocks `C_xx` and `C_yy` (as [`Influence::normal_preconditioner`]), `[M_xx, M_yy]`, built on first use and
    /// kept. The off-diagonal block `C_xy` (odd, and zero for ν = 0) is left out, as in Vollebregt's TangCG.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the tangential kernels were not built ([`Kernels::Normal`]), or a spectrum has no
    /// positive value (not for the kernels of [`super::HalfSpace`]s).
    pub fn tangential_preconditioner(&self) -> Result<&[Toeplitz2d; 2], ArgumentError> {
        if let Some(m) = self.tangential_inverse.get() {
            return Ok(m);
        }
        if self.tangential.is_none() {
            let msg = "built with Kernels::Normal: no tangential kernels";
            return Err(ArgumentError::new("Influence::tangential_preconditioner", "self", msg));
        }
        let (mx, my) = (self.grid.mx, self.grid.my);
        let both = |i: usize, j: usize| match self.table.get(i as isize, j as isize) {
            Some(c) => (c.xx, c.yy),
            None => self.kernel.tangential_at(i, j),
        };
        let m = [compact_inverse(mx, my, |i, j| both(i, j).0)?, compact_inverse(mx, my, |i, j| both(i, j).1)?];
        Ok(self.tangential_inverse.get_or_init(|| m))
    }

    /// `u_z = C_zz p` into `uz`.
    ///
    /// # Errors
    /// An [`ArgumentError`] when a vector is not one value per element.
    pub fn apply_normal(&self, p: &[f64], uz: &mut [f64], scratch: &mut Scratch) -> Result<(), ArgumentError> {
        self.zz.apply_into(p, uz, scratch)
    }

    /// The tangential displacements (slips, for a pair) of the shears: `u_x = C_xx q_x + C_xy q_y`,
    /// `u_y = C_xy q_x + C_yy q_y` into `ux`, `uy` (one 2 × 2 block product: [`Toeplitz2d::apply_block_into`]).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the tangential kernels were not built ([`Kernels::Normal`]) or a vector is not one
    /// value per element.
    pub fn apply_tangential(
        &self,
        q: (&[f64], &[f64]),
        u: (&mut [f64], &mut [f64]),
        scratch: &mut BlockScratch,
    ) -> Result<(), ArgumentError> {
        let [xx, xy, yy] = self.tangential.as_ref().ok_or_else(|| {
            ArgumentError::new(
                "Influence::apply_tangential",
                "self",
                "built with Kernels::Normal: no tangential kernels",
            )
        })?;
        Toeplitz2d::apply_block_into([xx, xy, yy], q, u, scratch)
    }

    /// The gap change of the shears through the coupling: `u_z = C_zx q_x + C_zy q_y` into `uz` (zero when the
    /// coupling kernels were not built).
    ///
    /// # Errors
    /// An [`ArgumentError`] when a vector is not one value per element.
    pub fn coupling_gap(
        &self,
        q: (&[f64], &[f64]),
        uz: &mut [f64],
        scratch: &mut Scratch,
    ) -> Result<(), ArgumentError> {
        uz.iter_mut().for_each(|v| *v = 0.0);
        let Some([zx, zy]) = self.coupling.as_ref() else { return Ok(()) };
        let mut tmp = vec![0.0; uz.len()];
        for (op, qt) in [(zx, q.0), (zy, q.1)] {
            op.apply_into(qt, &mut tmp, scratch)?;
            uz.iter_mut().zip(&tmp).for_each(|(a, b)| *a += b);
        }
        Ok(())
    }

    /// The slip of the pressures through the coupling: `u_x = C_xz p`, `u_y = C_yz p` (`C_xz = −C_zx` per offset)
    /// into `ux`, `uy` (zero when the coupling kernels were not built).
    ///
    /// # Errors
    /// An [`ArgumentError`] when a vector is not one value per element.
    pub fn coupling_slip(
        &self,
        p: &[f64],
        u: (&mut [f64], &mut [f64]),
        scratch: &mut Scratch,
    ) -> Result<(), ArgumentError> {
        let (ux, uy) = u;
        ux.iter_mut().chain(uy.iter_mut()).for_each(|v| *v = 0.0);
        let Some([zx, zy]) = self.coupling.as_ref() else { return Ok(()) };
        zx.apply_into(p, ux, scratch)?;
        zy.apply_into(p, uy, scratch)?;
        ux.iter_mut().chain(uy.iter_mut()).for_each(|v| *v = -*v);
        Ok(())
    }

    /// One component of the influence as a dense row-major `N × N` matrix (`N` the grid's elements, entry
    /// `[i·N + j]` the displacement at centre `i` per unit traction on element `j`), for cross-checks on small grids.
    /// `pick` selects the component from the [`Coefficients`] (e.g. `|c| c.zz`).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the grid has more than [`DENSE_LIMIT`] elements, or when `pick` reads a
    /// coefficient this operator did not compute (a tangential one of [`Kernels::Normal`]).
    pub fn dense(&self, pick: impl Fn(&Coefficients) -> f64) -> Result<Vec<f64>, ArgumentError> {
        let m = dense(&self.grid, &self.table, pick)?;
        if m.iter().any(|v| v.is_nan()) {
            let msg = "reads a coefficient these operators were not built with (Kernels::Normal holds C_zz only)";
            return Err(ArgumentError::new("Influence::dense", "pick", msg.to_string()));
        }
        Ok(m)
    }
}

/// The dense matrix of one component ([`Influence::dense`]).
fn dense(
    grid: &ContactGrid,
    table: &KernelTable,
    pick: impl Fn(&Coefficients) -> f64,
) -> Result<Vec<f64>, ArgumentError> {
    let n = grid.len();
    if n > DENSE_LIMIT {
        let msg = format!("{n} elements: a dense matrix is formed only up to {DENSE_LIMIT} (use the FFT products)");
        return Err(ArgumentError::new("Influence::dense", "grid", msg));
    }
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        let (ix, iy) = ((i % grid.mx) as isize, (i / grid.mx) as isize);
        for j in 0..n {
            let (jx, jy) = ((j % grid.mx) as isize, (j / grid.mx) as isize);
            m[i * n + j] = table.get(ix - jx, iy - jy).map_or(f64::NAN, |c| pick(&c));
        }
    }
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::super::HalfSpace;
    use super::*;

    fn mat_vec(m: &[f64], v: &[f64]) -> Vec<f64> {
        let n = v.len();
        (0..n).map(|i| (0..n).map(|j| m[i * n + j] * v[j]).sum()).collect()
    }

    /// The compact circulants the preconditioners invert ([`PRECONDITIONER_FLOOR`]) stay positive: for `C_zz`,
    /// `C_xx` and `C_yy` of ν = 0, 0.28 and 0.5 on grids from 1 × 9 to 287 × 323 with square and 1 : 3 elements, no
    /// spectral value reaches the floor (the claim "a guard only"; the smallest measured was 0.41/max(Lx, Ly) of
    /// the largest, `C_xx` at ν = 0.5). Expected from theory: the half-space kernels' Fourier transforms are
    /// positive (`C_zz`: ∝ 1/|k|; `C_xx`: ∝ (1 − ν k_y²/|k|²)/|k| with the axes as in `kernel`, ≥ (1 − ν)/|k|).
    #[test]
    fn the_compact_circulants_stay_above_the_floor() {
        let grids = [(1, 9, 1.0), (9, 1, 1.0), (2, 2, 1.0), (7, 5, 1.0), (15, 15, 1.0), (101, 37, 1.0), (60, 20, 3.0)];
        let grids = [grids.as_slice(), &[(20, 60, 3.0), (143, 163, 1.0), (287, 323, 1.0)]].concat();
        for nu in [0.0, 0.28, 0.5] {
            let body = HalfSpace::new(1.0, nu).unwrap();
            for &(mx, my, dy) in &grids {
                let g = crate::halfspace::UniformGrid::new(body.pair(&body), mx, my, 1.0, dy).unwrap();
                let kernels: [&dyn Fn(usize, usize) -> f64; 3] =
                    [&|i, j| g.normal_at(i, j), &|i, j| g.tangential_at(i, j).0, &|i, j| g.tangential_at(i, j).1];
                for (k, f) in kernels.iter().enumerate() {
                    let c = Toeplitz2d::circulant_even_compact(mx, my, f).unwrap();
                    let (lx, ly) = c.periodic_size();
                    let (_, floored) = c.circulant_inverse(PRECONDITIONER_FLOOR / lx.max(ly) as f64).unwrap();
                    assert_eq!(floored, 0, "ν = {nu}, {mx} × {my}, kernel {k}");
                }
            }
        }
    }

    /// The FFT operators against the dense matrices of the same kernel (built from the kernel entry by entry, an
    /// independent path through `KernelTable::get`), on a small grid of a dissimilar pair, to 1e-12 of the largest
    /// entry of the product; the identical pair builds no coupling kernels, the normal-only operator no tangential.
    #[test]
    fn fft_products_are_the_dense_products() {
        let pair = HalfSpace::new(210e3, 0.3).unwrap().pair(&HalfSpace::new(70e3, 0.33).unwrap());
        let grid = ContactGrid::new(7, 5, 0.1, 0.15, -0.3, -0.3).unwrap();
        let inf = Influence::new(grid, pair, Kernels::Full).unwrap();
        assert!(inf.has_tangential() && inf.has_coupling());
        let n = grid.len();
        let v = |s: f64| (0..n).map(|i| ((i as f64 + s) * 0.7).sin()).collect::<Vec<f64>>();
        let (p, qx, qy) = (v(0.0), v(1.0), v(2.0));
        let (mut ux, mut uy, mut uz) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let (mut s, mut bs) = (Scratch::default(), BlockScratch::default());
        inf.apply_normal(&p, &mut uz, &mut s).unwrap();
        inf.apply_tangential((&qx, &qy), (&mut ux, &mut uy), &mut bs).unwrap();
        let (mut cz, mut cx, mut cy) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        inf.coupling_gap((&qx, &qy), &mut cz, &mut s).unwrap();
        inf.coupling_slip(&p, (&mut cx, &mut cy), &mut s).unwrap();
        for (u, c) in [(&mut uz, &cz), (&mut ux, &cx), (&mut uy, &cy)] {
            u.iter_mut().zip(c).for_each(|(a, b)| *a += b);
        }
        let d = |f: fn(&Coefficients) -> f64| inf.dense(f).unwrap();
        let add = |a: Vec<f64>, b: Vec<f64>, c: Vec<f64>| -> Vec<f64> {
            a.iter().zip(&b).zip(&c).map(|((x, y), z)| x + y + z).collect()
        };
        let ex = add(mat_vec(&d(|c| c.xx), &qx), mat_vec(&d(|c| c.xy), &qy), mat_vec(&d(|c| c.xz), &p));
        let ey = add(mat_vec(&d(|c| c.yx), &qx), mat_vec(&d(|c| c.yy), &qy), mat_vec(&d(|c| c.yz), &p));
        let ez = add(mat_vec(&d(|c| c.zx), &qx), mat_vec(&d(|c| c.zy), &qy), mat_vec(&d(|c| c.zz), &p));
        for (got, exp) in [(&ux, &ex), (&uy, &ey), (&uz, &ez)] {
            let scale = exp.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let err = got.iter().zip(exp.iter()).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(err <= 1e-12 * scale, "FFT vs dense: {err:e} of {scale:e}");
        }
        let same = HalfSpace::new(210e3, 0.3).unwrap();
        let inf = Influence::new(grid, same.pair(&same), Kernels::Full).unwrap();
        assert!(inf.has_tangential() && !inf.has_coupling());
        let inf = Influence::new(grid, same.compliance(), Kernels::Normal).unwrap();
        assert!(!inf.has_tangential() && !inf.has_coupling());
        let err = inf.apply_tangential((&qx, &qy), (&mut ux, &mut uy), &mut bs).unwrap_err();
        assert!(err.to_string().contains("Kernels::Normal"), "{err}");
        // The normal-only operator computed C_zz alone: bit for bit the full table's, and a dense tangential matrix
        // of it is refused rather than filled with what was never computed.
        let full = Influence::new(grid, same.compliance(), Kernels::Full).unwrap();
        assert!(!inf.kernel_table().has_tangential() && full.kernel_table().has_tangential());
        assert_eq!(inf.kernel_table().zz(), full.kernel_table().zz());
        assert_eq!(inf.dense(|c| c.zz).unwrap(), full.dense(|c| c.zz).unwrap());
        assert!(inf.dense(|c| c.xx).unwrap_err().to_string().contains("pick"));
    }

    /// Grid placement: `covering` puts the element edges on the given bounds; bad sizes are refused by name.
    #[test]
    fn grid_placement_and_refusals() {
        let g = ContactGrid::covering(4, 2, -1.0, 1.0, 0.0, 3.0).unwrap();
        assert_eq!(g.centre(0, 0), (-0.75, 0.75));
        assert_eq!(g.centre(3, 1), (0.75, 2.25));
        assert_eq!((g.len(), g.area()), (8, 0.75));
        assert!(ContactGrid::new(0, 3, 1.0, 1.0, 0.0, 0.0).unwrap_err().to_string().contains("mx"));
        assert!(ContactGrid::new(3, 3, f64::NAN, 1.0, 0.0, 0.0).unwrap_err().to_string().contains("dx"));
        assert!(ContactGrid::covering(3, 3, 1.0, 1.0, 0.0, 1.0).unwrap_err().to_string().contains("x_hi"));
        let big = ContactGrid::new(65, 64, 1.0, 1.0, 0.0, 0.0).unwrap();
        let inf = Influence::new(big, HalfSpace::new(1.0, 0.3).unwrap().compliance(), Kernels::Normal).unwrap();
        assert!(inf.dense(|c| c.zz).unwrap_err().to_string().contains("4096"));
    }
}
