//! # The tangential problem on a half-space grid: a shift step with the Coulomb law on the disc
//!
//! One quasi-static step of Kalker's "shift" problem at a given pressure (the tangential problem with memory: the
//! Cattaneo–Mindlin loading, a load path of shifts, fretting). Given the element pressures `p` (stress), the friction
//! coefficient `μ`, the shears `q′` at the end of the previous step (zero from rest) and either the rigid shift
//! increment `w = (w_x, w_y)` of body 1 relative to body 2 in this step (length) or the total tangential force
//! `F = A Σ q` at its end (force; `A` one element's area), find the shears `q_i = (q_x, q_y)_i` (stress, on body 1)
//! with the slip of each element in the step
//!
//! ```text
//!   s_i = w + [C_tt (q − q′)]_i                    (length; body 1 relative to body 2)
//!   |q_i| ≤ g_i = μ p_i,    |q_i| < g_i ⇒ s_i = 0,    s_i ≠ 0 ⇒ q_i = −g_i s_i / |s_i|
//! ```
//!
//! — Coulomb's law on the DISC `|q| ≤ μp`, exactly: the shear opposes the slip and is at the bound wherever the
//! element slips. `C_tt` is the 2 × 2-block tangential influence ([`super::Influence::apply_tangential`]). The
//! normal–tangential coupling is left out: exact for a pair of identical materials (Dundurs' β = 0, the coupling
//! kernels vanish identically) and for ν = 0 on both bodies; for a dissimilar pair this is the decoupled
//! approximation, and the caller alternates with the normal problem for the coupled one.
//!
//! ## The convex program and the method
//!
//! These are the optimality conditions of `min f(q) = ½ (q − q′)ᵀ C_tt (q − q′) + wᵀ Σ_i q_i` over the product of
//! discs `|q_i| ≤ g_i`: `∇_i f = s_i`, and `−s_i` in the disc's normal cone at `q_i` is the law above (Kalker's
//! principle of minimum complementary energy). With the force prescribed, `w` is the multiplier of the constraint
//! `Σ_i q_i = F/A` and is found with `q`.
//!
//! Solved by the accelerated projected gradient method (FISTA, Beck & Teboulle 2009) with adaptive restart
//! (O'Donoghue & Candès 2015): `q ← P(y − ∇f(y)/L)` with `L` a bound on the largest eigenvalue of `C_tt` (the
//! largest absolute row sum of its blocks, Gershgorin; measured 1.16× the eigenvalue found by power iteration on
//! the Cattaneo test grids of 20 and 40 elements across, ν = 0). `P` is the Euclidean projection onto the product of discs — and, with the force prescribed, onto
//! its intersection with the affine set `Σ q = F/A`: `P(z)_i = Π_i(z_i − ν)` (`Π_i` the projection onto disc `i`)
//! with the 2-vector `ν` the root of `Σ_i Π_i(z_i − ν) = F/A`, the gradient of a concave function of `ν`, found by
//! Newton's method with backtracking. At the fixed point `ν·L` is the rigid shift `w`. Each iteration costs one
//! tangential product (four 2D FFT products), O(N log N).
//!
//! ## The default: a preconditioned conjugate-gradient method
//!
//! FISTA's iterations grow with the grid (313, 393, 885 on CONTACT's `tang_problm_1s`, `2s`, `4s`: 1 730 to 28 260
//! slipping elements), since `C_tt`'s condition number does. The default [`TangentialMethod::ConjugateGradient`]
//! (`tangential/cg.rs`, after Vollebregt's TangCG) solves the stick and slip equations by a nonlinear
//! conjugate-gradient method with the inverse circulants of `C_xx` and `C_yy` as preconditioner
//! ([`super::Influence::tangential_preconditioner`]): 50, 77 and 170 iterations on those cases at tolerance 1e-7
//! (CONTACT's TangCG: 51, 71, 154, with its looser rms stop; ours certify the disc law's residual to 6e-9, 6e-9,
//! 2e-10 against FISTA's 1e-6, 5e-6), two FFT passes each (the product and the preconditioner, a quarter of one),
//! the same stick and slip counts as CONTACT's and FISTA's; 240 on `8s` (111 191 slipping; CONTACT 190). A prescribed force is kept by projecting the steps onto `Σ v = 0`, the shift
//! found as its multiplier: Cattaneo's circle at 20 and 40 elements across in 22 and 27 iterations against FISTA's
//! 156 and 212, the same answer. Should the method lose every stick element under a prescribed force, FISTA solves
//! the step ([`TangentialSolution::method`] says which ran). Tests hold both methods, and clarabel's cones, to one
//! answer.
//!
//! ## What `converged` certifies
//!
//! Either iteration stops when the largest change of a shear in an iteration is below `tolerance · max g` (the
//! conjugate-gradient method also needs a check of the constraints that changes neither set). The answer
//! is then checked from the final shears with a fresh product: [`TangentialSolution::residual`] is the natural
//! residual of the disc law, `max_i |q_i − Π_i(q_i − s_i · L_d)| / max g` with `L_d` the diagonal compliance —
//! zero exactly at a solution of the conditions above, whatever the method.
//!
//! A force beyond the friction's capacity `|F| > μ A Σ p` (or equal to it: then the shift is not determined) has no
//! quasi-static solution: the outcome [`TangentialStop::GrossSliding`], with every element at its bound along `F`
//! and no shift, not an error.

use super::operator::Influence;
use crate::cancel::Cancel;

pub(crate) mod cg;
use crate::error::ArgumentError;
use crate::toeplitz2d::BlockScratch;

/// What is prescribed tangentially in a shift step.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum TangentialDrive {
    /// The rigid shift increment `(w_x, w_y)` of body 1 relative to body 2 in this step (length).
    Shift(f64, f64),
    /// The total tangential force `(F_x, F_y) = A Σ q` on body 1 at the end of the step (force).
    Force(f64, f64),
}

/// Why the tangential iteration stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum TangentialStop {
    /// The largest shear change fell below the tolerance.
    Converged,
    /// The iteration limit was reached first.
    IterationLimit,
    /// The caller's [`Cancel`] token was raised.
    Cancelled,
    /// The prescribed force is at or beyond the friction's capacity `μ A Σ p`: gross sliding, no quasi-static
    /// solution (the shears are at their bounds along the force; the shift is not determined).
    GrossSliding,
}

/// The method of [`solve`] (named in scenes as `tangential_method = "conjugate_gradient" | "fista"`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum TangentialMethod {
    /// The preconditioned nonlinear conjugate-gradient method on the stick and slip sets (after Vollebregt's
    /// TangCG; `tangential/cg.rs`), the default. Under a prescribed force with no stick element left during the
    /// iteration it hands the step to [`TangentialMethod::Fista`] (the solution's `method` says which ran).
    ConjugateGradient,
    /// The accelerated projected gradient method (module docs), for either drive.
    Fista,
}

/// Settings of [`solve`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct TangentialSettings {
    /// Largest shear change per iteration relative to `max μp` to stop at, in (0, 1).
    pub tolerance: f64,
    /// Largest number of iterations (≥ 1).
    pub max_iterations: usize,
    /// The method.
    pub method: TangentialMethod,
}

impl Default for TangentialSettings {
    /// `tolerance` 1e-10, `max_iterations` 100 000, [`TangentialMethod::ConjugateGradient`].
    fn default() -> Self {
        TangentialSettings { tolerance: 1e-10, max_iterations: 100_000, method: TangentialMethod::ConjugateGradient }
    }
}

impl TangentialSettings {
    /// Settings with a tolerance and an iteration limit (checked by [`solve`]), the default method.
    pub fn new(tolerance: f64, max_iterations: usize) -> TangentialSettings {
        TangentialSettings { tolerance, max_iterations, ..TangentialSettings::default() }
    }

    /// The same settings with the method `method`.
    pub fn with_method(mut self, method: TangentialMethod) -> TangentialSettings {
        self.method = method;
        self
    }
}

/// The state of one element after a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ElementState {
    /// No pressure: outside the contact.
    Exterior,
    /// In contact, below the friction bound: no slip.
    Stick,
    /// In contact, at the friction bound.
    Slip,
}

/// The answer of one shift step.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct TangentialSolution {
    /// Shear `q_x` per element (stress, on body 1), grid order.
    pub qx: Vec<f64>,
    /// Shear `q_y` per element.
    pub qy: Vec<f64>,
    /// Slip `s_x` per element in the step (length, body 1 relative to body 2).
    pub sx: Vec<f64>,
    /// Slip `s_y` per element.
    pub sy: Vec<f64>,
    /// Each element's state.
    pub state: Vec<ElementState>,
    /// The rigid shift increment `(w_x, w_y)` (length): prescribed, or found from the force (NaN under gross
    /// sliding).
    pub shift: (f64, f64),
    /// The total force `A Σ q` (force).
    pub force: (f64, f64),
    /// Elements in stick.
    pub stick: usize,
    /// Elements in slip.
    pub slip: usize,
    /// Iterations done: FISTA's (one tangential product each, plus one), or the conjugate-gradient steps (two FFT
    /// passes each, plus one product per check of the constraints and one).
    pub iterations: usize,
    /// The method that ran ([`TangentialMethod::ConjugateGradient`] may hand a prescribed force to FISTA).
    pub method: TangentialMethod,
    /// Why the iteration stopped.
    pub stop: TangentialStop,
    /// The natural residual of the disc law relative to `max μp` (module docs), from the final shears.
    pub residual: f64,
}

/// One shift step's data (module docs).
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct ShiftStep<'a> {
    /// Pressure per element at the end of the step (stress, ≥ 0), grid order.
    pub pressure: &'a [f64],
    /// Friction coefficient μ (≥ 0).
    pub friction: f64,
    /// The shears `(q′_x, q′_y)` at the end of the previous step (`None`: from rest, zero). They may exceed this
    /// step's bound (the pressure fell, or the traction was carried in from upstream in transient rolling): only
    /// the displacement they leave, `C_tt q′`, enters the step; the iteration starts from their projection.
    pub previous: Option<(&'a [f64], &'a [f64])>,
    /// A slip offset per element added to `s` (length; `None`: zero) — the change in the step of the tangential
    /// displacement that the pressures cause, `C_tz (p − p′)`, when the caller couples the normal and tangential
    /// problems of a dissimilar pair.
    pub offset: Option<(&'a [f64], &'a [f64])>,
    /// What is prescribed.
    pub drive: TangentialDrive,
}

impl<'a> ShiftStep<'a> {
    /// A step from rest (`previous` and `offset` none) at the pressures `pressure` with friction `friction`.
    pub fn new(pressure: &'a [f64], friction: f64, drive: TangentialDrive) -> ShiftStep<'a> {
        ShiftStep { pressure, friction, previous: None, offset: None, drive }
    }

    /// The same step from the previous shears `(q′_x, q′_y)`.
    pub fn after(mut self, qx: &'a [f64], qy: &'a [f64]) -> ShiftStep<'a> {
        self.previous = Some((qx, qy));
        self
    }

    /// The same step with the slip offset `(o_x, o_y)` per element.
    pub fn with_offset(mut self, ox: &'a [f64], oy: &'a [f64]) -> ShiftStep<'a> {
        self.offset = Some((ox, oy));
        self
    }
}

/// Solve one shift step (module docs) with `settings`; `cancel` is checked at every iteration.
///
/// # Errors
/// An [`ArgumentError`] naming the argument when the operator has no tangential kernels, a vector is not one finite
/// value per element, a pressure is negative, the friction coefficient or a drive component is not finite (or μ
/// negative), `previous` is not finite, or a setting is out of range.
pub fn solve(
    influence: &Influence,
    step: &ShiftStep<'_>,
    settings: &TangentialSettings,
    cancel: &Cancel,
) -> Result<TangentialSolution, ArgumentError> {
    let (pressure, friction, previous, drive) = (step.pressure, step.friction, step.previous, step.drive);
    check(influence, step, settings)?;
    let n = pressure.len();
    let area = influence.grid().area();
    let bound: Vec<f64> = pressure.iter().map(|&p| friction * p).collect();
    let zeros = vec![0.0; n];
    let (px, py) = previous.unwrap_or((&zeros, &zeros));
    let offset = step.offset.unwrap_or((&zeros, &zeros));
    let mut fista = Fista::new(influence, &bound, (px, py), offset, drive, area);
    if let TangentialDrive::Force(fx, fy) = drive {
        let capacity = area * bound.iter().sum::<f64>();
        if fx.hypot(fy) >= capacity {
            return fista.gross_sliding(fx, fy);
        }
    }
    if settings.method == TangentialMethod::ConjugateGradient {
        let drive = match drive {
            TangentialDrive::Shift(wx, wy) => cg::Drive::Shift(wx, wy),
            TangentialDrive::Force(fx, fy) => cg::Drive::Force(fx / area, fy / area),
        };
        let problem = cg::Problem { op: influence, bound: &bound, prev: (px, py), offset, drive };
        // `None`: a prescribed force with no stick element left to carry it; FISTA solves the step instead.
        if let Some(out) = cg::run(&problem, settings.tolerance, settings.max_iterations, cancel)? {
            (fista.q, fista.iterations, fista.method) = (out.q, out.iterations, TangentialMethod::ConjugateGradient);
            fista.found = Some(out.shift);
            return fista.finish(out.stop);
        }
    }
    let stop = fista.run(settings, cancel)?;
    fista.finish(stop)
}

/// The FISTA iteration's state.
struct Fista<'a> {
    op: &'a Influence,
    bound: &'a [f64],
    prev: (&'a [f64], &'a [f64]),
    offset: (&'a [f64], &'a [f64]),
    drive: TangentialDrive,
    area: f64,
    /// Gershgorin bound on the largest eigenvalue of `C_tt`.
    lipschitz: f64,
    /// The diagonal compliance `C_xx(0, 0)` (for the natural residual).
    diagonal: f64,
    q: (Vec<f64>, Vec<f64>),
    /// The last projection's multiplier `ν` (force drive).
    nu: (f64, f64),
    bufs: Buffers,
    iterations: usize,
    /// The method that produced `q`.
    method: TangentialMethod,
    /// The shift the conjugate-gradient method found (force drive) or was given.
    found: Option<(f64, f64)>,
}

/// Work vectors of one product.
struct Buffers {
    dx: Vec<f64>,
    dy: Vec<f64>,
    ux: Vec<f64>,
    uy: Vec<f64>,
    scratch: BlockScratch,
}

impl<'a> Fista<'a> {
    fn new(
        op: &'a Influence,
        bound: &'a [f64],
        prev: (&'a [f64], &'a [f64]),
        offset: (&'a [f64], &'a [f64]),
        drive: TangentialDrive,
        area: f64,
    ) -> Fista<'a> {
        let n = bound.len();
        let (lipschitz, diagonal) = lipschitz(op);
        let z = || vec![0.0; n];
        let bufs = Buffers { dx: z(), dy: z(), ux: z(), uy: z(), scratch: BlockScratch::default() };
        let q = (prev.0.to_vec(), prev.1.to_vec());
        let method = TangentialMethod::Fista;
        Fista {
            op,
            bound,
            prev,
            offset,
            drive,
            area,
            lipschitz,
            diagonal,
            q,
            nu: (0.0, 0.0),
            bufs,
            iterations: 0,
            method,
            found: None,
        }
    }

    /// The slip `w + o + C_tt (q − q′)` of the shears `(x, y)` into `bufs.ux`, `bufs.uy` (without `w` when `with_w` is
    /// false: the force drive's gradient, whose `w` is the projection's multiplier).
    fn slip(&mut self, x: &[f64], y: &[f64], with_w: bool) -> Result<(), ArgumentError> {
        let b = &mut self.bufs;
        for i in 0..x.len() {
            b.dx[i] = x[i] - self.prev.0[i];
            b.dy[i] = y[i] - self.prev.1[i];
        }
        self.op.apply_tangential((&b.dx, &b.dy), (&mut b.ux, &mut b.uy), &mut b.scratch)?;
        b.ux.iter_mut().zip(self.offset.0).for_each(|(v, o)| *v += o);
        b.uy.iter_mut().zip(self.offset.1).for_each(|(v, o)| *v += o);
        if let (TangentialDrive::Shift(wx, wy), true) = (self.drive, with_w) {
            b.ux.iter_mut().for_each(|v| *v += wx);
            b.uy.iter_mut().for_each(|v| *v += wy);
        }
        Ok(())
    }

    /// FISTA with adaptive restart (module docs).
    fn run(&mut self, settings: &TangentialSettings, cancel: &Cancel) -> Result<TangentialStop, ArgumentError> {
        let n = self.bound.len();
        let gmax = self.bound.iter().fold(0.0_f64, |m, &g| m.max(g));
        let step = 1.0 / self.lipschitz;
        // Start from the previous shears projected onto this step's set.
        let (mut yx, mut yy) = self.q.clone();
        self.project(&mut yx, &mut yy);
        self.q = (yx.clone(), yy.clone());
        let mut t = 1.0_f64;
        let (mut zx, mut zy) = (vec![0.0; n], vec![0.0; n]);
        while self.iterations < settings.max_iterations {
            if cancel.is_cancelled() {
                return Ok(TangentialStop::Cancelled);
            }
            self.iterations += 1;
            self.slip(&yx, &yy, true)?;
            for i in 0..n {
                zx[i] = yx[i] - step * self.bufs.ux[i];
                zy[i] = yy[i] - step * self.bufs.uy[i];
            }
            self.project(&mut zx, &mut zy);
            // z is the new iterate; q the old one.
            let (mut change, mut restart) = (0.0_f64, 0.0);
            for i in 0..n {
                let (ddx, ddy) = (zx[i] - self.q.0[i], zy[i] - self.q.1[i]);
                change = change.max(ddx.hypot(ddy));
                restart += (yx[i] - zx[i]) * ddx + (yy[i] - zy[i]) * ddy;
            }
            let t_next = 0.5 * (1.0 + (1.0 + 4.0 * t * t).sqrt());
            let momentum = if restart > 0.0 { 0.0 } else { (t - 1.0) / t_next };
            t = if restart > 0.0 { 1.0 } else { t_next };
            for i in 0..n {
                yx[i] = zx[i] + momentum * (zx[i] - self.q.0[i]);
                yy[i] = zy[i] + momentum * (zy[i] - self.q.1[i]);
            }
            std::mem::swap(&mut self.q.0, &mut zx);
            std::mem::swap(&mut self.q.1, &mut zy);
            if change <= settings.tolerance * gmax {
                return Ok(TangentialStop::Converged);
            }
        }
        Ok(TangentialStop::IterationLimit)
    }

    /// The projection `P` (module docs) in place: onto the discs, and onto `Σ q = F/A` with the force drive.
    fn project(&mut self, x: &mut [f64], y: &mut [f64]) {
        match self.drive {
            TangentialDrive::Shift(..) => {
                for i in 0..x.len() {
                    (x[i], y[i]) = disc(x[i], y[i], self.bound[i]);
                }
            }
            TangentialDrive::Force(fx, fy) => {
                let target = (fx / self.area, fy / self.area);
                self.nu = multiplier(x, y, self.bound, target, self.nu);
                for i in 0..x.len() {
                    (x[i], y[i]) = disc(x[i] - self.nu.0, y[i] - self.nu.1, self.bound[i]);
                }
            }
        }
    }

    /// Every element at its bound along the force: the gross-sliding outcome.
    fn gross_sliding(mut self, fx: f64, fy: f64) -> Result<TangentialSolution, ArgumentError> {
        let f = fx.hypot(fy);
        let (ex, ey) = if f > 0.0 { (fx / f, fy / f) } else { (0.0, 0.0) };
        for i in 0..self.bound.len() {
            self.q.0[i] = self.bound[i] * ex;
            self.q.1[i] = self.bound[i] * ey;
        }
        let mut s = self.finish(TangentialStop::GrossSliding)?;
        s.shift = (f64::NAN, f64::NAN);
        Ok(s)
    }

    /// The solution from the final shears with a fresh product (module docs).
    fn finish(mut self, stop: TangentialStop) -> Result<TangentialSolution, ArgumentError> {
        let n = self.bound.len();
        let (qx, qy) = std::mem::take(&mut self.q);
        self.slip(&qx, &qy, true)?;
        let shift = match self.drive {
            TangentialDrive::Shift(wx, wy) => (wx, wy),
            TangentialDrive::Force(..) => {
                self.found.unwrap_or((self.nu.0 * self.lipschitz, self.nu.1 * self.lipschitz))
            }
        };
        let (mut sx, mut sy) = (std::mem::take(&mut self.bufs.ux), std::mem::take(&mut self.bufs.uy));
        if let TangentialDrive::Force(..) = self.drive {
            sx.iter_mut().for_each(|v| *v += shift.0);
            sy.iter_mut().for_each(|v| *v += shift.1);
        }
        let gmax = self.bound.iter().fold(0.0_f64, |m, &g| m.max(g)).max(f64::MIN_POSITIVE);
        let mut residual = 0.0_f64;
        let mut state = Vec::with_capacity(n);
        for i in 0..n {
            let g = self.bound[i];
            residual = residual.max(disc_law_residual((qx[i], qy[i]), (sx[i], sy[i]), g, self.diagonal) / gmax);
            state.push(if g <= 0.0 {
                ElementState::Exterior
            } else if g - qx[i].hypot(qy[i]) <= 1e-9 * g {
                ElementState::Slip
            } else {
                ElementState::Stick
            });
        }
        let count = |s: ElementState| state.iter().filter(|&&e| e == s).count();
        let force = (self.area * qx.iter().sum::<f64>(), self.area * qy.iter().sum::<f64>());
        Ok(TangentialSolution {
            stick: count(ElementState::Stick),
            slip: count(ElementState::Slip),
            qx,
            qy,
            sx,
            sy,
            state,
            shift,
            force,
            iterations: self.iterations,
            method: self.method,
            stop,
            residual,
        })
    }
}

/// The natural residual of Coulomb's law on the disc at one element: `|q − Π(q − s/c₀)|` (stress), with `Π` the
/// projection onto the disc of radius `bound = μp`, `s` the element's slip (length) and `c₀ > 0` a compliance
/// (length per stress) that makes the two commensurable. Zero exactly when `q` and `s` satisfy the law.
pub(crate) fn disc_law_residual(q: (f64, f64), s: (f64, f64), bound: f64, c0: f64) -> f64 {
    let (rx, ry) = disc(q.0 - s.0 / c0, q.1 - s.1 / c0, bound);
    (q.0 - rx).hypot(q.1 - ry)
}

/// The projection of `(x, y)` onto the disc of radius `g ≥ 0`.
fn disc(x: f64, y: f64, g: f64) -> (f64, f64) {
    let r = x.hypot(y);
    if r <= g {
        (x, y)
    } else if g > 0.0 {
        (x * (g / r), y * (g / r))
    } else {
        (0.0, 0.0)
    }
}

/// The multiplier `ν` of the projection onto the discs and `Σ q = target` (module docs): the root of
/// `φ(ν) = Σ_i Π_i(z_i − ν) − target`, the gradient of the concave `Θ(ν) = −Σ_i h(z_i − ν) − νᵀ target` with
/// `h(y) = ½|y|² − ½ dist(y, disc)²`; Newton's method from `start` with backtracking on `Θ`. The caller has checked
/// `|target| < Σ g` (a strictly feasible target), so the root exists.
fn multiplier(x: &[f64], y: &[f64], g: &[f64], target: (f64, f64), start: (f64, f64)) -> (f64, f64) {
    let theta_grad = |nu: (f64, f64)| {
        let (mut val, mut fx, mut fy) = (0.0, -target.0, -target.1);
        let (mut jxx, mut jxy, mut jyy) = (0.0, 0.0, 0.0);
        for i in 0..x.len() {
            let (yx, yy) = (x[i] - nu.0, y[i] - nu.1);
            let r = yx.hypot(yy);
            let (px, py) = disc(yx, yy, g[i]);
            fx += px;
            fy += py;
            let dist2 = (yx - px).powi(2) + (yy - py).powi(2);
            val -= 0.5 * (r * r - dist2);
            if r <= g[i] {
                jxx += 1.0;
                jyy += 1.0;
            } else if g[i] > 0.0 {
                let (ux, uy, c) = (yx / r, yy / r, g[i] / r);
                jxx += c * (1.0 - ux * ux);
                jxy -= c * ux * uy;
                jyy += c * (1.0 - uy * uy);
            }
        }
        val -= nu.0 * target.0 + nu.1 * target.1;
        (val, (fx, fy), (jxx, jxy, jyy))
    };
    let scale = g.iter().fold(0.0_f64, |m, &v| m.max(v)).max(f64::MIN_POSITIVE);
    let mut nu = start;
    for _ in 0..100 {
        let (val, (fx, fy), (jxx, jxy, jyy)) = theta_grad(nu);
        if fx.hypot(fy) <= 1e-14 * scale * (x.len() as f64).sqrt() {
            break;
        }
        // Newton's step for the maximum of Θ (∇Θ = φ, ∇²Θ = −Σ J): ν ← ν + d with (Σ J) d = φ, regularised where
        // Σ J is singular (every element outside its disc along one direction), steepest ascent if it fails.
        let reg = 1e-12 * (jxx + jyy).max(1.0);
        let (a, b, c) = (jxx + reg, jxy, jyy + reg);
        let det = a * c - b * b;
        let (dx, dy) = if det > 0.0 { ((c * fx - b * fy) / det, (a * fy - b * fx) / det) } else { (fx, fy) };
        // Backtracking until Θ does not decrease.
        let mut step = 1.0;
        let mut next = (nu.0 + dx, nu.1 + dy);
        while step > 1e-12 && theta_grad(next).0 < val {
            step *= 0.5;
            next = (nu.0 + step * dx, nu.1 + step * dy);
        }
        if next == nu {
            break;
        }
        nu = next;
    }
    nu
}

/// `(L, L_d)`: the Gershgorin bound on the largest eigenvalue of `C_tt` (largest absolute row sum over both block
/// rows, from the kernel table) and the diagonal compliance `C_xx(0, 0)`.
fn lipschitz(op: &Influence) -> (f64, f64) {
    let grid = op.grid();
    let table = op.kernel_table();
    let (mx, my) = (grid.mx() as isize, grid.my() as isize);
    let mut rows: f64 = 0.0;
    // The row sums of the corner, edge-centre and centre elements: for these decaying positive kernels the largest
    // is at the centre; the others are taken as well (each is an exact sum, and the bound only needs the largest).
    let sites = [(0, 0), (mx - 1, my - 1), (0, my - 1), (mx - 1, 0), (mx / 2, my / 2), (mx / 2, 0), (0, my / 2)];
    for (ix, iy) in sites {
        let (mut rx, mut ry) = (0.0, 0.0);
        for jy in 0..my {
            for jx in 0..mx {
                if let Some(c) = table.get(ix - jx, iy - jy) {
                    rx += c.xx.abs() + c.xy.abs();
                    ry += c.xy.abs() + c.yy.abs();
                }
            }
        }
        rows = rows.max(rx).max(ry);
    }
    let diagonal = table.get(0, 0).map_or(1.0, |c| c.xx);
    (rows.max(f64::MIN_POSITIVE), diagonal.max(f64::MIN_POSITIVE))
}

/// The arguments' ranges ([`solve`]).
fn check(op: &Influence, step: &ShiftStep<'_>, s: &TangentialSettings) -> Result<(), ArgumentError> {
    let (pressure, friction, previous, drive) = (step.pressure, step.friction, step.previous, step.drive);
    let bad = |arg: &'static str, msg: String| Err(ArgumentError::new("halfspace::tangential::solve", arg, msg));
    let n = op.grid().len();
    if !op.has_tangential() {
        return bad("influence", "built with Kernels::Normal: no tangential kernels (use Kernels::Full)".into());
    }
    if pressure.len() != n {
        return bad("pressure", format!("one value per element ({n}), got {}", pressure.len()));
    }
    if let Some(i) = pressure.iter().position(|p| !(p.is_finite() && *p >= 0.0)) {
        return bad("pressure", format!("pressure[{i}] = {} must be finite and ≥ 0", pressure[i]));
    }
    if !(friction.is_finite() && friction >= 0.0) {
        return bad("friction", format!("a finite coefficient ≥ 0 (got {friction})"));
    }
    if let Some((qx, qy)) = previous {
        if qx.len() != n || qy.len() != n {
            return bad("previous", format!("two vectors of {n} values (got {} and {})", qx.len(), qy.len()));
        }
        if let Some(i) = (0..n).find(|&i| !(qx[i].is_finite() && qy[i].is_finite())) {
            return bad("previous", format!("element {i}: q′ = ({}, {}) is not finite", qx[i], qy[i]));
        }
    }
    if let Some((ox, oy)) = step.offset {
        if ox.len() != n || oy.len() != n || !ox.iter().chain(oy).all(|v| v.is_finite()) {
            return bad("offset", format!("two vectors of {n} finite values"));
        }
    }
    let (a, b) = match drive {
        TangentialDrive::Shift(a, b) | TangentialDrive::Force(a, b) => (a, b),
    };
    if !(a.is_finite() && b.is_finite()) {
        return bad("drive", format!("finite components (got {a}, {b})"));
    }
    if !(s.tolerance > 0.0 && s.tolerance < 1.0) {
        return bad("settings.tolerance", format!("in (0, 1) (got {})", s.tolerance));
    }
    if s.max_iterations == 0 {
        return bad("settings.max_iterations", "at least 1".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::normal::{self, Drive, NormalSettings};
    use super::super::{ContactGrid, HalfSpace, Kernels};
    use super::*;
    use crate::theory::Hertz3D;

    /// A sphere pair of identical materials with ν = 0 (Cattaneo–Mindlin is then exact: no normal–tangential
    /// coupling, no Poisson term in C_tt), `per_diameter` elements across the Hertz contact, its discrete pressure.
    struct Case {
        inf: Influence,
        p: Vec<f64>,
        hz: Hertz3D,
        g: f64,
        mu: f64,
    }

    fn case(per_diameter: usize) -> Case {
        let (e, nu, load, r_star) = (210e3, 0.0, 1.0e4, 50.0);
        let body = HalfSpace::new(e, nu).unwrap();
        let e_star = e / (2.0 * (1.0 - nu * nu));
        let hz = Hertz3D::from_load(0.5 / r_star, 0.5 / r_star, e_star, load).unwrap();
        let h_el = 2.0 * hz.a_x / per_diameter as f64;
        let m = ((1.2 * hz.a_x / h_el).ceil() as usize) * 2 + 1;
        let o = -((m / 2) as f64) * h_el;
        let grid = ContactGrid::new(m, m, h_el, h_el, o, o).unwrap();
        let inf = Influence::new(grid, body.pair(&body), Kernels::Full).unwrap();
        assert!(!inf.has_coupling());
        let h = grid.sample(|x, y| (x * x + y * y) / (2.0 * r_star));
        let ns = normal::solve(&inf, &h, Drive::Load(load), &NormalSettings::default(), &Cancel::never()).unwrap();
        Case { inf, p: ns.pressure, hz, g: e / (2.0 * (1.0 + nu)), mu: 0.3 }
    }

    /// Johnson §7.2: the traction of Cattaneo's loading to Q, `μp₀/a (√(a² − r²) − √(c² − r²))` (the second term
    /// inside the stick circle of radius c only), c/a = (1 − Q/μP)^(1/3).
    fn cattaneo(r: f64, a: f64, c: f64, mu_p0: f64) -> f64 {
        let root = |s: f64| if r < s { (s * s - r * r).sqrt() } else { 0.0 };
        mu_p0 / a * (root(a) - root(c))
    }

    /// Max over the elements of |q_x − expected|, and the largest |q_y|, relative to μp₀.
    fn traction_error(c: &Case, s: &TangentialSolution, expected: impl Fn(f64) -> f64) -> (f64, f64) {
        let mu_p0 = c.mu * c.hz.p0;
        let (mut ex, mut ey) = (0.0_f64, 0.0_f64);
        for (i, (x, y)) in c.inf.grid().centres().into_iter().enumerate() {
            ex = ex.max((s.qx[i] - expected(x.hypot(y))).abs() / mu_p0);
            ey = ey.max(s.qy[i].abs() / mu_p0);
        }
        (ex, ey)
    }

    /// Cattaneo–Mindlin on the circle (ν = 0, exact): loading from rest to Q = 0.5 μP, force prescribed. Expected
    /// values from Johnson §7.2 (eqs. 7.38–7.42): the stick radius c/a = (1 − Q/μP)^(1/3) (from the stick area,
    /// √(N_stick A/π)), the traction, and the rigid shift δ = 3μP/(16a)·Σ(2−ν)/G·[1 − (1 − Q/μP)^(2/3)] (body 1
    /// moves by −δ relative to body 2 for a force +Q on it). Errors measured at 20, 40 elements across the contact
    /// (each falling by a quarter at least: a discretisation error, not a wrong law) and bounded at 40 by 2 % (c;
    /// measured 1.8e-2 → 3.4e-3), 7 % of μp₀ (the largest element error of the traction, at the √ edges of the
    /// stick and contact circles that the grid cannot resolve: measured 8.0 % → 5.5 %, order ½) and 1 % (δ;
    /// measured 5.3e-4 → 9.3e-6).
    #[test]
    fn cattaneo_mindlin_circle() {
        let mut errors = Vec::new();
        for n in [20, 40] {
            let c = case(n);
            let (mu, load) = (c.mu, c.hz.load);
            let q = 0.5 * mu * load;
            let set = TangentialSettings::default();
            let s = solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Force(q, 0.0)), &set, &Cancel::never())
                .unwrap();
            assert_eq!(s.stop, TangentialStop::Converged, "{} iterations, residual {}", s.iterations, s.residual);
            assert!(s.residual <= 1e-8, "residual {}", s.residual);
            assert!((s.force.0 - q).abs() <= 1e-10 * q && s.force.1.abs() <= 1e-10 * q, "{:?}", s.force);
            let a = c.hz.a_x;
            let c_exact = a * (1.0 - q / (mu * load)).cbrt();
            let c_num = (s.stick as f64 * c.inf.grid().area() / std::f64::consts::PI).sqrt();
            let (eq, ey) = traction_error(&c, &s, |r| cattaneo(r, a, c_exact, mu * c.hz.p0));
            let delta = 3.0 * mu * load / (16.0 * a) * (4.0 / c.g) * (1.0 - (1.0 - q / (mu * load)).powf(2.0 / 3.0));
            let errs = [(c_num - c_exact).abs() / c_exact, eq, (s.shift.0 + delta).abs() / delta];
            println!(
                "n {n}: c {:.3e} q {:.3e} delta {:.3e} ({} its, {} stick)",
                errs[0], errs[1], errs[2], s.iterations, s.stick
            );
            assert!(ey <= 1e-12, "q_y must vanish for ν = 0 and a force along x: {ey:e}");
            assert!(s.shift.1.abs() <= 1e-12 * delta);
            errors.push(errs);
        }
        assert!(errors[1][0] <= 0.02 && errors[1][1] <= 0.07 && errors[1][2] <= 0.01, "{errors:?}");
        for k in 0..3 {
            assert!(errors[1][k] <= 0.75 * errors[0][k], "quantity {k} does not converge: {errors:?}");
        }
    }

    /// Memory: unloading from Q* = 0.6 μP to Q = 0.2 μP in one step from the loaded state (force prescribed,
    /// `previous` the loaded shears). Johnson §7.3 (Mindlin & Deresiewicz): a new stick circle
    /// c′/a = (1 − (Q* − Q)/(2μP))^(1/3), the traction q* − 2(q_a − q_c′) = μp₀/a[−√(a² − r²) + 2√(c′² − r²) −
    /// √(c*² − r²)] (`q_s = μp₀/a √(s² − r²)` inside radius s only; the annulus c′ < r < a slips back at −μp), and
    /// the shift of the step
    /// +2·3μP/(16a)·Σ(2−ν)/G·[1 − (1 − (Q* − Q)/(2μP))^(2/3)]. The same answers, at 40 elements across, to the
    /// bounds of the loading test.
    #[test]
    fn mindlin_deresiewicz_unloading_remembers_the_loaded_state() {
        let c = case(40);
        let (mu, load) = (c.mu, c.hz.load);
        let (q_star, q) = (0.6 * mu * load, 0.2 * mu * load);
        let set = TangentialSettings::default();
        let never = Cancel::never();
        let up = solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Force(q_star, 0.0)), &set, &never).unwrap();
        let down = solve(
            &c.inf,
            &ShiftStep::new(&c.p, mu, TangentialDrive::Force(q, 0.0)).after(&up.qx, &up.qy),
            &set,
            &never,
        )
        .unwrap();
        assert_eq!(down.stop, TangentialStop::Converged);
        assert!(down.residual <= 1e-8, "{}", down.residual);
        let a = c.hz.a_x;
        let c_star = a * (1.0 - q_star / (mu * load)).cbrt();
        let c_new = a * (1.0 - (q_star - q) / (2.0 * mu * load)).cbrt();
        let mu_p0 = mu * c.hz.p0;
        let expected = |r: f64| {
            let root = |s: f64| if r < s { (s * s - r * r).sqrt() } else { 0.0 };
            mu_p0 / a * (-root(a) + 2.0 * root(c_new) - root(c_star))
        };
        let (eq, ey) = traction_error(&c, &down, expected);
        let delta_step = 2.0 * 3.0 * mu * load / (16.0 * a)
            * (4.0 / c.g)
            * (1.0 - (1.0 - (q_star - q) / (2.0 * mu * load)).powf(2.0 / 3.0));
        // The loaded stick circle c* lies inside the new one: the new stick area is c′'s.
        let c_num = (down.stick as f64 * c.inf.grid().area() / std::f64::consts::PI).sqrt();
        let errs = [(c_num - c_new).abs() / c_new, eq, (down.shift.0 - delta_step).abs() / delta_step];
        assert!(errs[0] <= 0.02 && errs[1] <= 0.07 && errs[2] <= 0.01 && ey <= 1e-12, "{errs:?}, q_y {ey:e}");
    }

    /// The shift drive is the same discrete problem: prescribing the shift the force-driven step found gives back
    /// its force (to 1e-7) and shears (to 1e-7 of μp₀); a force at or above μP is `GrossSliding` with every element
    /// at its bound along the force, not an error; a raised cancel token stops at once.
    #[test]
    fn shift_drive_inverts_the_force_drive_and_gross_sliding_is_a_status() {
        let c = case(20);
        let (mu, load) = (c.mu, c.hz.load);
        let set = TangentialSettings::default();
        let never = Cancel::never();
        let f = (0.3 * mu * load, -0.4 * mu * load);
        let by_force =
            solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Force(f.0, f.1)), &set, &never).unwrap();
        let w = by_force.shift;
        let by_shift =
            solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Shift(w.0, w.1)), &set, &never).unwrap();
        assert_eq!(by_shift.stop, TangentialStop::Converged);
        let fmag = f.0.hypot(f.1);
        assert!((by_shift.force.0 - f.0).hypot(by_shift.force.1 - f.1) <= 1e-7 * fmag, "{:?} vs {f:?}", by_shift.force);
        let mu_p0 = mu * c.hz.p0;
        let dq = (0..c.p.len())
            .fold(0.0_f64, |m, i| m.max((by_shift.qx[i] - by_force.qx[i]).hypot(by_shift.qy[i] - by_force.qy[i])));
        assert!(dq <= 1e-7 * mu_p0, "{dq:e}");
        let over =
            solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Force(0.0, 1.01 * mu * load)), &set, &never)
                .unwrap();
        assert_eq!(over.stop, TangentialStop::GrossSliding);
        assert!(over.shift.0.is_nan() && over.stick == 0);
        assert!((over.force.1 - mu * load).abs() <= 1e-9 * mu * load && over.force.0 == 0.0);
        let cancel = Cancel::new();
        cancel.cancel();
        let s = solve(&c.inf, &ShiftStep::new(&c.p, mu, TangentialDrive::Force(f.0, f.1)), &set, &cancel).unwrap();
        assert_eq!((s.stop, s.iterations), (TangentialStop::Cancelled, 0));
    }

    /// Refusals by name: an operator without tangential kernels, a negative pressure, a previous state beyond
    /// this step's bound, a non-finite drive, a zero tolerance.
    #[test]
    fn refusals() {
        let body = HalfSpace::new(1.0, 0.3).unwrap();
        let grid = ContactGrid::new(3, 3, 1.0, 1.0, -1.0, -1.0).unwrap();
        let normal_only = Influence::new(grid, body.compliance(), Kernels::Normal).unwrap();
        let full = Influence::new(grid, body.compliance(), Kernels::Full).unwrap();
        let p = vec![1.0; 9];
        let set = TangentialSettings::default();
        let never = Cancel::never();
        let d = TangentialDrive::Force(1.0, 0.0);
        let e = |r: Result<TangentialSolution, ArgumentError>| r.unwrap_err().to_string();
        assert!(e(solve(&normal_only, &ShiftStep::new(&p, 0.3, d), &set, &never)).contains("Kernels::Full"));
        let mut neg = p.clone();
        neg[4] = -1.0;
        assert!(e(solve(&full, &ShiftStep::new(&neg, 0.3, d), &set, &never)).contains("pressure[4]"));
        let mut nan = vec![0.5; 9];
        nan[2] = f64::NAN;
        assert!(e(solve(&full, &ShiftStep::new(&p, 0.3, d).after(&nan, &nan), &set, &never)).contains("previous"));
        assert!(e(solve(&full, &ShiftStep::new(&p, f64::NAN, d), &set, &never)).contains("friction"));
        assert!(e(solve(&full, &ShiftStep::new(&p, 0.3, TangentialDrive::Shift(f64::NAN, 0.0)), &set, &never))
            .contains("drive"));
        assert!(e(solve(&full, &ShiftStep::new(&p, 0.3, d), &TangentialSettings::new(0.0, 5), &never))
            .contains("tolerance"));
    }

    /// The oblique-force problems' contact: a sphere pair (E = 210 GPa, ν = 0.3, R* = 50, P = 1 kN) on 21 × 21
    /// elements over ±1.2a, its discrete pressure: (operators, pressure, Hertz, load).
    fn sphere_21() -> (Influence, Vec<f64>, Hertz3D, f64) {
        let (e, nu, load, r_star) = (210e3, 0.3, 1.0e3, 50.0);
        let body = HalfSpace::new(e, nu).unwrap();
        let hz = Hertz3D::from_load(0.5 / r_star, 0.5 / r_star, e / (2.0 * (1.0 - nu * nu)), load).unwrap();
        let m = 21;
        let d = 2.4 * hz.a_x / m as f64;
        let o = -((m / 2) as f64) * d;
        let grid = ContactGrid::new(m, m, d, d, o, o).unwrap();
        let inf = Influence::new(grid, body.pair(&body), Kernels::Full).unwrap();
        let h = grid.sample(|x, y| (x * x + y * y) / (2.0 * r_star));
        let p =
            normal::solve(&inf, &h, Drive::Load(load), &NormalSettings::default(), &Cancel::never()).unwrap().pressure;
        (inf, p, hz, load)
    }

    /// Both methods, force prescribed, against an independent solver of the same discrete problem: clarabel's
    /// second-order-cone program on the dense matrices ([`super::super::dense`]), with ν = 0.3 (so `C_xy ≠ 0` and the
    /// shears turn out of the force's direction) and an oblique force 0.6 μP at 30°. Same shears to 1e-6 of μp₀
    /// (clarabel's own resolution at the stick–slip boundary is about 2e-7), same force, same rigid shift to 1e-5;
    /// each run by the method asked for (no hand-over).
    #[test]
    fn both_methods_agree_with_clarabel_on_the_disc_under_a_force() {
        for method in [TangentialMethod::ConjugateGradient, TangentialMethod::Fista] {
            agree_with_clarabel_under_a_force(method);
        }
    }

    fn agree_with_clarabel_under_a_force(method: TangentialMethod) {
        use super::super::dense::{ConeSettings, DenseShift, ShiftDrive};
        let (inf, p, _, load) = sphere_21();
        let mu = 0.3;
        let f = (0.6 * mu * load * 30f64.to_radians().cos(), 0.6 * mu * load * 30f64.to_radians().sin());
        let ours = solve(
            &inf,
            &ShiftStep::new(&p, mu, TangentialDrive::Force(f.0, f.1)),
            &TangentialSettings::default().with_method(method),
            &Cancel::never(),
        )
        .unwrap();
        assert_eq!((ours.stop, ours.method), (TangentialStop::Converged, method));
        let theirs = DenseShift::new(&inf, &p, mu, None)
            .unwrap()
            .disc(ShiftDrive::Force([f.0, f.1]), &ConeSettings::default())
            .unwrap();
        let mu_p0 = mu * p.iter().fold(0.0_f64, |m, &v| m.max(v));
        let dq = (0..p.len()).fold(0.0_f64, |m, i| m.max((ours.qx[i] - theirs.qx[i]).hypot(ours.qy[i] - theirs.qy[i])));
        assert!(dq <= 1e-6 * mu_p0, "shears differ by {:.2e} of μp₀", dq / mu_p0);
        let qy_off = ours.qy.iter().zip(&ours.qx).any(|(qy, qx)| (qy / qx - 30f64.to_radians().tan()).abs() > 1e-3);
        assert!(qy_off, "with ν ≠ 0 the shears are not all along the force");
        let w = theirs.shift;
        assert!(
            (ours.shift.0 - w[0]).hypot(ours.shift.1 - w[1]) <= 1e-5 * w[0].hypot(w[1]),
            "{:?} vs {w:?}",
            ours.shift
        );
    }

    /// The conjugate-gradient method (the default for a prescribed shift, `tangential/cg.rs`) against two
    /// independent solvers of the same discrete problem (21 × 21 sphere contact, ν = 0.3, so `C_xy ≠ 0` and the
    /// shears turn off the shift's direction): clarabel's second-order cones on the dense disc problem with the
    /// shift prescribed, from rest and from the previous step's shears (memory: a reversal to −½ the shift); and
    /// FISTA with a rotation added as slip offset (spin-like: the slip's direction turns across the contact). The
    /// shears agree to 1e-6 of μp₀ with clarabel (its interior-point tolerance, as FISTA's test; measured 2.9e-7 on the
    /// reversal) and to 1e-9 with FISTA (both at tolerance 1e-12; measured 1.2e-11); each CG run converges with the disc law's natural residual below 1e-9.
    #[test]
    fn conjugate_gradient_agrees_with_clarabel_and_fista() {
        use super::super::dense::{ConeSettings, DenseShift, ShiftDrive};
        let (inf, p, hz, load) = sphere_21();
        let grid = *inf.grid();
        let mu = 0.3;
        let mu_p0 = mu * p.iter().fold(0.0_f64, |m, &v| m.max(v));
        let diff = |a: &TangentialSolution, qx: &[f64], qy: &[f64]| {
            (0..p.len()).fold(0.0_f64, |m, i| m.max((a.qx[i] - qx[i]).hypot(a.qy[i] - qy[i]))) / mu_p0
        };
        let set = TangentialSettings::new(1e-12, 100_000);
        let cg = |step: &ShiftStep<'_>, set: &TangentialSettings| {
            let s = solve(&inf, step, set, &Cancel::never()).unwrap();
            assert_eq!((s.stop, s.method), (TangentialStop::Converged, set.method), "{s:?}");
            assert!(s.residual <= 1e-9, "residual {:e}", s.residual);
            s
        };
        // The shift of 0.6 μP at 30° (clarabel's, force prescribed), then prescribed.
        let f = (0.6 * mu * load * 30f64.to_radians().cos(), 0.6 * mu * load * 30f64.to_radians().sin());
        let rest = DenseShift::new(&inf, &p, mu, None).unwrap();
        let w = rest.disc(ShiftDrive::Force([f.0, f.1]), &ConeSettings::default()).unwrap().shift;
        let theirs = rest.disc(ShiftDrive::Shift(w), &ConeSettings::default()).unwrap();
        let ours = cg(&ShiftStep::new(&p, mu, TangentialDrive::Shift(w[0], w[1])), &set);
        assert!(ours.stick > 0 && ours.slip > 0, "a partial slip: {} stick, {} slip", ours.stick, ours.slip);
        assert!(diff(&ours, &theirs.qx, &theirs.qy) <= 1e-6, "from rest: {:.2e}", diff(&ours, &theirs.qx, &theirs.qy));
        // Memory: back by half the shift from the loaded state.
        let back = DenseShift::new(&inf, &p, mu, Some((&ours.qx, &ours.qy))).unwrap();
        let theirs = back.disc(ShiftDrive::Shift([-0.5 * w[0], -0.5 * w[1]]), &ConeSettings::default()).unwrap();
        let step = ShiftStep::new(&p, mu, TangentialDrive::Shift(-0.5 * w[0], -0.5 * w[1])).after(&ours.qx, &ours.qy);
        let unloaded = cg(&step, &set);
        let dq = diff(&unloaded, &theirs.qx, &theirs.qy);
        assert!(dq <= 1e-6, "reversal: {dq:.2e}");
        // A rotation as slip offset, against FISTA.
        let phi = 0.5 * w[0].hypot(w[1]) / hz.a_x;
        let ox: Vec<f64> = grid.centres().iter().map(|c| -phi * c.1).collect();
        let oy: Vec<f64> = grid.centres().iter().map(|c| phi * c.0).collect();
        let step = ShiftStep::new(&p, mu, TangentialDrive::Shift(w[0], w[1])).with_offset(&ox, &oy);
        let (ours, fista) = (cg(&step, &set), cg(&step, &set.with_method(TangentialMethod::Fista)));
        assert_eq!((ours.stick, ours.slip), (fista.stick, fista.slip));
        assert!(diff(&ours, &fista.qx, &fista.qy) <= 1e-9, "spin: {:.2e}", diff(&ours, &fista.qx, &fista.qy));
    }

    /// Memory from a state with every shear at its bound (all along `+x`, the limit of full sliding), unloaded to
    /// 0.4 μP by a prescribed force: the conjugate-gradient method starts such a step with every element in stick
    /// (a force needs stick elements to be carried) and solves it itself; its shears equal clarabel's (the dense
    /// cone program from the same previous shears; independent) to 1e-6 of μp₀ (measured 7e-11), and FISTA's to 1e-9
    /// (measured 1.5e-11), in 19 iterations against FISTA's 194.
    #[test]
    fn a_force_step_from_shears_all_at_their_bounds() {
        use super::super::dense::{ConeSettings, DenseShift, ShiftDrive};
        let c = case(20);
        let (mu, load) = (c.mu, c.hz.load);
        let (gx, gy): (Vec<f64>, Vec<f64>) = (c.p.iter().map(|p| mu * p).collect(), vec![0.0; c.p.len()]);
        let f = 0.4 * mu * load;
        let step = ShiftStep::new(&c.p, mu, TangentialDrive::Force(f, 0.0)).after(&gx, &gy);
        let set = TangentialSettings::new(1e-12, 100_000);
        let ours = solve(&c.inf, &step, &set, &Cancel::never()).unwrap();
        assert_eq!((ours.stop, ours.method), (TangentialStop::Converged, TangentialMethod::ConjugateGradient));
        let fista = solve(&c.inf, &step, &set.with_method(TangentialMethod::Fista), &Cancel::never()).unwrap();
        let theirs = DenseShift::new(&c.inf, &c.p, mu, Some((&gx, &gy)))
            .unwrap()
            .disc(ShiftDrive::Force([f, 0.0]), &ConeSettings::default())
            .unwrap();
        let mu_p0 = mu * c.hz.p0;
        let diff = |qx: &[f64], qy: &[f64]| {
            (0..c.p.len()).fold(0.0_f64, |m, i| m.max((ours.qx[i] - qx[i]).hypot(ours.qy[i] - qy[i]))) / mu_p0
        };
        assert!(diff(&theirs.qx, &theirs.qy) <= 1e-6, "clarabel: {:.2e}", diff(&theirs.qx, &theirs.qy));
        assert!(diff(&fista.qx, &fista.qy) <= 1e-9, "FISTA: {:.2e}", diff(&fista.qx, &fista.qy));
        assert!(ours.stick > 0 && ours.slip > 0 && (ours.force.0 - f).abs() <= 1e-10 * f);
    }
}
