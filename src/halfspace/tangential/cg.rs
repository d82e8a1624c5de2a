//! The shift problem by a preconditioned nonlinear conjugate-gradient method on the stick and slip sets
//! ([`super::TangentialMethod::ConjugateGradient`]), after Vollebregt's TangCG (the tangential solver of CONTACT,
//! E.A.H. Vollebregt; its FFT preconditioner as in J. Comput. Phys. 257, 2014). Written here from the equations
//! below.
//!
//! **Unknowns and equations.** The elements split into a stick set `H` and a slip set `S`. In `H` the two shears are
//! free and the slip vanishes, `s_i = 0`. In `S` the shear is on its bound, `q_i = g_i n_i` with the unit vector
//! `n_i = (cos θ_i, sin θ_i)`, and the slip opposes it: its component along `t_i = (−sin θ_i, cos θ_i)` vanishes,
//! `t_iᵀ s_i = 0` (the sign, `n_iᵀ s_i ≤ 0`, is checked separately). The residual `r` is `−s_i` in `H` and
//! `−t_i t_iᵀ s_i` in `S`.
//!
//! **The linearisation.** A shear change `v`, free in `H` and along `t_i` in `S` (a turn `δθ_i = |v_i|/g_i`), changes
//! the slip by `C_tt v`, and the equation in `S` by `t_iᵀ (C_tt v)_i + c_i |v_i|` with `c_i = −n_iᵀ s_i / g_i ≥ 0`
//! (the turn of `t_i`). Hence the Jacobian `J v = P C_tt v + c ∘ v`, `P` the projection that keeps `H` and
//! the `t` component in `S`: symmetric, and positive definite where `c ≥ 0` — a conjugate-gradient method applies.
//!
//! **The iteration.** With the sets and the directions `t_i`, `c_i` fixed, up to [`INNER`] conjugate-gradient steps
//! on `J v = r`: `q ← q + α v`, the slipping shears put back on their circles. Then the constraints are checked: a
//! stick shear beyond its bound slips (scaled back onto the circle), the slip is computed afresh (one product), and a
//! slipping element whose slip has turned along its shear (`s_iᵀ q_i > 0`) sticks. A change of the sets restarts
//! the conjugation; otherwise it runs on with the new linearisation.
//!
//! **The preconditioner.** `B = P S M S P`, with `M = diag(M_xx, M_yy)` the inverses of the compact circulants of
//! `C_xx` and `C_yy` ([`super::Influence::tangential_preconditioner`]) and `S` the diagonal scaling
//! `√(d/(d + c_i))` in `S` (`d` the diagonal compliance; 1 in `H`) that accounts for the turn term — symmetric
//! positive semi-definite, as the method needs. Each step costs the product `C_tt v` (one block FFT pass) and `M`
//! (a quarter of one), each check one more product `C_tt q`.
//!
//! **A prescribed force.** The sum `Σ q = F/A` (`A` one element's area) is a linear constraint `Eᵀ q = F/A` whose
//! multiplier is the shift `w`. The shears are kept on it: the start and every check restore it by one common change
//! of the stick shears, and every preconditioned residual and search direction is projected B-orthogonally onto
//! `Eᵀ v = 0` (`x ← x − B P E G⁻¹ Eᵀ x`, `G = Eᵀ B P E` a 2 × 2 matrix, `B P E` two preconditioner products per
//! check): the projected preconditioned CG of Gould, Hribar & Nocedal (SIAM J. Sci. Comput. 23, 2001). The shift
//! is found at each check as the least-squares fit of the stick and slip equations, `(Eᵀ P E) δw = −Eᵀ P s`, exact at
//! the solution. Without a stick element left to carry the force (or with a singular `G`) the method gives up and
//! the caller solves the step by FISTA.
//!
//! **Stop.** When a step changes no shear by more than `tolerance · max g`, a check changes neither set, and neither
//! the fresh residual (as a shear, `max |r_i| / C_xx(0, 0)`) nor (force prescribed) restoring the force asks for a
//! larger change: a converged linear step alone is not enough, since putting the slipping shears back on their
//! circles leaves a residual of its own. The answer is certified by the caller from the final shears (the natural
//! residual of the disc law).

use super::super::operator::Influence;
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::toeplitz2d::{BlockScratch, Scratch, Toeplitz2d};

/// Conjugate-gradient steps between two checks of the constraints (CONTACT's TangCG uses four).
pub(super) const INNER: usize = 4;

/// An element's set.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Set {
    /// No bound: outside the contact.
    Exterior,
    /// Below the bound, no slip.
    Stick,
    /// On the bound.
    Slip,
}

/// What is prescribed: the shift `w`, or the sum of the shears `Σ q = F/A` (the force over one element's area),
/// whose multiplier is the shift.
#[derive(Clone, Copy)]
pub(super) enum Drive {
    Shift(f64, f64),
    Force(f64, f64),
}

/// The data of one shift step as the method needs them.
pub(super) struct Problem<'a> {
    pub op: &'a Influence,
    /// The bounds `g = μp`.
    pub bound: &'a [f64],
    /// The previous shears `q′`.
    pub prev: (&'a [f64], &'a [f64]),
    /// The slip offset per element.
    pub offset: (&'a [f64], &'a [f64]),
    /// What is prescribed.
    pub drive: Drive,
}

/// What [`run`] returns: the shears, the shift (prescribed or found), the iterations (conjugate-gradient steps)
/// and whether it converged.
pub(super) struct Outcome {
    pub q: Pair,
    pub shift: (f64, f64),
    pub iterations: usize,
    pub stop: super::TangentialStop,
}

/// Work vectors.
struct Work {
    sx: Vec<f64>,
    sy: Vec<f64>,
    dx: Vec<f64>,
    dy: Vec<f64>,
    block: BlockScratch,
    one: Scratch,
}

impl Problem<'_> {
    /// The slip `shift + o + C_tt (q − q′)` into `(sx, sy)`.
    fn slip(&self, q: &Pair, shift: (f64, f64), w: &mut Work) -> Result<(), ArgumentError> {
        for i in 0..q.0.len() {
            w.dx[i] = q.0[i] - self.prev.0[i];
            w.dy[i] = q.1[i] - self.prev.1[i];
        }
        self.op.apply_tangential((&w.dx, &w.dy), (&mut w.sx, &mut w.sy), &mut w.block)?;
        for i in 0..q.0.len() {
            w.sx[i] += shift.0 + self.offset.0[i];
            w.sy[i] += shift.1 + self.offset.1[i];
        }
        Ok(())
    }
}

/// The linearisation at the current shears: per element its set, `t_i` and `c_i` (module docs).
pub(crate) struct Frame {
    pub(crate) set: Vec<Set>,
    pub(crate) tx: Vec<f64>,
    pub(crate) ty: Vec<f64>,
    pub(crate) c: Vec<f64>,
    /// The preconditioner's scaling per element and component (module docs).
    pub(crate) scale: (Vec<f64>, Vec<f64>),
}

impl Frame {
    /// The frame of the current sets at the shears `q` with slips `(sx, sy)`; `d` the diagonal compliances.
    pub(crate) fn update(&mut self, q: (&[f64], &[f64]), s: (&[f64], &[f64]), g: &[f64], d: (f64, f64)) {
        for i in 0..self.set.len() {
            (self.tx[i], self.ty[i], self.c[i], self.scale.0[i], self.scale.1[i]) = (0.0, 0.0, 0.0, 1.0, 1.0);
            if self.set[i] == Set::Slip {
                let (nx, ny) = (q.0[i] / g[i], q.1[i] / g[i]);
                (self.tx[i], self.ty[i]) = (-ny, nx);
                self.c[i] = (-(nx * s.0[i] + ny * s.1[i]) / g[i]).max(0.0);
                self.scale.0[i] = (d.0 / (d.0 + self.c[i])).sqrt();
                self.scale.1[i] = (d.1 / (d.1 + self.c[i])).sqrt();
            }
        }
    }

    /// `P` in place: exterior to zero, slip to its `t` component.
    pub(crate) fn project(&self, x: &mut [f64], y: &mut [f64]) {
        for i in 0..x.len() {
            match self.set[i] {
                Set::Exterior => (x[i], y[i]) = (0.0, 0.0),
                Set::Stick => {}
                Set::Slip => {
                    let a = self.tx[i] * x[i] + self.ty[i] * y[i];
                    (x[i], y[i]) = (a * self.tx[i], a * self.ty[i]);
                }
            }
        }
    }
}

/// A pair of grid vectors (x and y components).
pub(crate) type Pair = (Vec<f64>, Vec<f64>);

fn dot(a: &Pair, b: &Pair) -> f64 {
    a.0.iter().zip(&b.0).map(|(x, y)| x * y).sum::<f64>() + a.1.iter().zip(&b.1).map(|(x, y)| x * y).sum::<f64>()
}

/// The force constraint `Σ q = F/A` (force drive): the target and the preconditioned constraint directions
/// `B P e_x`, `B P e_y` with the inverse of their Gram matrix `G = Eᵀ B P E` (module docs, "A prescribed force").
struct Constraint {
    target: (f64, f64),
    bpe: [Pair; 2],
    ginv: [[f64; 2]; 2],
}

/// The iteration's state (module docs).
struct Cg<'p, 'a> {
    p: &'p Problem<'a>,
    /// The preconditioner `[M_xx, M_yy]`.
    m: &'a [Toeplitz2d; 2],
    /// The diagonal compliances `(C_xx(0, 0), C_yy(0, 0))`.
    d: (f64, f64),
    q: Pair,
    /// The shift: prescribed, or the current estimate of the force constraint's multiplier.
    shift: (f64, f64),
    constraint: Option<Constraint>,
    frame: Frame,
    /// The residual, the preconditioned residual, the search direction and `J v`.
    r: Pair,
    z: Pair,
    v: Pair,
    jv: Pair,
    w: Work,
    /// Whether the next step restarts the conjugation.
    restart: bool,
}

/// The inverse of a symmetric 2 × 2 matrix, `None` when it is (nearly) singular.
pub(crate) fn inverse2(m: [[f64; 2]; 2]) -> Option<[[f64; 2]; 2]> {
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let scale = (m[0][0].abs() + m[1][1].abs()).powi(2);
    (det > 1e-10 * scale && det.is_finite()).then(|| [[m[1][1] / det, -m[0][1] / det], [-m[1][0] / det, m[0][0] / det]])
}

fn sums(v: &Pair) -> (f64, f64) {
    (v.0.iter().sum(), v.1.iter().sum())
}

impl<'p, 'a> Cg<'p, 'a> {
    /// The start: the previous shears projected onto this step's discs (those on or beyond their bound slip), the
    /// slip, the frame and the residual; `None` when a prescribed force leaves no stick element to carry it.
    fn new(p: &'p Problem<'a>) -> Result<Option<Cg<'p, 'a>>, ArgumentError> {
        let (n, g) = (p.bound.len(), p.bound);
        let m = p.op.tangential_preconditioner()?;
        let d = p.op.kernel_table().get(0, 0).map_or((1.0, 1.0), |c| (c.xx, c.yy));
        let z = || vec![0.0; n];
        let w = Work { sx: z(), sy: z(), dx: z(), dy: z(), block: BlockScratch::default(), one: Scratch::default() };
        let (q, mut set) = start_sets(p.prev, g);
        // A prescribed force needs stick elements to carry it: when every previous shear is at its bound, all start
        // in stick (the first check moves those beyond their bound back to slip).
        if matches!(p.drive, Drive::Force(..)) && !set.contains(&Set::Stick) {
            set.iter_mut().filter(|s| **s == Set::Slip).for_each(|s| *s = Set::Stick);
        }
        let (shift, constraint) = match p.drive {
            Drive::Shift(a, b) => ((a, b), None),
            Drive::Force(a, b) => {
                let none = [[0.0; 2]; 2];
                ((0.0, 0.0), Some(Constraint { target: (a, b), bpe: [(z(), z()), (z(), z())], ginv: none }))
            }
        };
        let frame = Frame { set, tx: z(), ty: z(), c: z(), scale: (z(), z()) };
        let (r, zz, v, jv) = ((z(), z()), (z(), z()), (z(), z()), (z(), z()));
        let mut cg = Cg { p, m, d, q, shift, constraint, frame, r, z: zz, v, jv, w, restart: true };
        if cg.restore_force().is_none() {
            return Ok(None);
        }
        cg.p.slip(&cg.q, cg.shift, &mut cg.w)?;
        release_wrong_slips(&mut cg.frame.set, (&cg.q.0, &cg.q.1), (&cg.w.sx, &cg.w.sy));
        Ok(cg.linearise()?.then_some(cg))
    }

    /// Force drive: the shears moved so that `Σ q` is the target again, by the same change on every stick element;
    /// the largest change (`Some(0)` for the shift drive), `None` without stick elements.
    fn restore_force(&mut self) -> Option<f64> {
        let Some(c) = &self.constraint else { return Some(0.0) };
        let (sx, sy) = sums(&self.q);
        let stick = self.frame.set.iter().filter(|&&s| s == Set::Stick).count();
        if stick == 0 {
            return None;
        }
        let (dx, dy) = ((c.target.0 - sx) / stick as f64, (c.target.1 - sy) / stick as f64);
        for i in (0..self.frame.set.len()).filter(|&i| self.frame.set[i] == Set::Stick) {
            self.q.0[i] += dx;
            self.q.1[i] += dy;
        }
        Some(dx.hypot(dy))
    }

    /// The frame and the residual `−P s` at the current shears and slip; with the force prescribed, first the shift
    /// that minimises `|P s|` (least squares: `(Eᵀ P E) δw = −Eᵀ P s`) and the constraint's directions. False when
    /// the constraint's Gram matrix is singular (no stick element, every slip direction alike).
    fn linearise(&mut self) -> Result<bool, ArgumentError> {
        let (g, d) = (self.p.bound, self.d);
        self.frame.update((&self.q.0, &self.q.1), (&self.w.sx, &self.w.sy), g, d);
        if self.constraint.is_some() {
            let (mut a, mut b) = ([[0.0; 2]; 2], (0.0, 0.0));
            let f = &self.frame;
            for i in 0..f.set.len() {
                let (sx, sy) = (self.w.sx[i], self.w.sy[i]);
                match f.set[i] {
                    Set::Exterior => {}
                    Set::Stick => (a[0][0], a[1][1], b.0, b.1) = (a[0][0] + 1.0, a[1][1] + 1.0, b.0 + sx, b.1 + sy),
                    Set::Slip => {
                        let (tx, ty) = (f.tx[i], f.ty[i]);
                        let ts = tx * sx + ty * sy;
                        (a[0][0], a[0][1], a[1][1]) = (a[0][0] + tx * tx, a[0][1] + tx * ty, a[1][1] + ty * ty);
                        (b.0, b.1) = (b.0 + tx * ts, b.1 + ty * ts);
                    }
                }
            }
            a[1][0] = a[0][1];
            let Some(ai) = inverse2(a) else { return Ok(false) };
            let dw = (-(ai[0][0] * b.0 + ai[0][1] * b.1), -(ai[1][0] * b.0 + ai[1][1] * b.1));
            self.shift = (self.shift.0 + dw.0, self.shift.1 + dw.1);
            self.w.sx.iter_mut().for_each(|v| *v += dw.0);
            self.w.sy.iter_mut().for_each(|v| *v += dw.1);
            self.frame.update((&self.q.0, &self.q.1), (&self.w.sx, &self.w.sy), g, d);
            if !self.constraint_directions()? {
                return Ok(false);
            }
        }
        for i in 0..self.q.0.len() {
            (self.r.0[i], self.r.1[i]) = (-self.w.sx[i], -self.w.sy[i]);
        }
        self.frame.project(&mut self.r.0, &mut self.r.1);
        Ok(true)
    }

    /// `B P e_x`, `B P e_y` and the inverse of `G = Eᵀ B P E` for the current frame; false when `G` is singular.
    fn constraint_directions(&mut self) -> Result<bool, ArgumentError> {
        let Some(mut c) = self.constraint.take() else { return Ok(true) };
        let n = self.q.0.len();
        for (k, e) in [(1.0, 0.0), (0.0, 1.0)].into_iter().enumerate() {
            let inside = |i: usize| if self.frame.set[i] == Set::Exterior { 0.0 } else { 1.0 };
            let mut unit: Pair = ((0..n).map(|i| e.0 * inside(i)).collect(), (0..n).map(|i| e.1 * inside(i)).collect());
            self.frame.project(&mut unit.0, &mut unit.1);
            apply_b(self.m, &self.frame, &mut self.w, &unit, &mut c.bpe[k])?;
        }
        let (gx, gy) = (sums(&c.bpe[0]), sums(&c.bpe[1]));
        let ok = inverse2([[gx.0, gy.0], [gx.1, gy.1]]).map(|gi| c.ginv = gi).is_some();
        self.constraint = Some(c);
        Ok(ok)
    }

    /// Force drive: `x ← x − B P E G⁻¹ Eᵀ x`, the part of `x` that changes `Σ q` taken out (B-orthogonally).
    fn keep_force(&self, x: &mut Pair) {
        let Some(c) = &self.constraint else { return };
        let e = sums(x);
        let mu = (c.ginv[0][0] * e.0 + c.ginv[0][1] * e.1, c.ginv[1][0] * e.0 + c.ginv[1][1] * e.1);
        for i in 0..x.0.len() {
            x.0[i] -= c.bpe[0].0[i] * mu.0 + c.bpe[1].0[i] * mu.1;
            x.1[i] -= c.bpe[0].1[i] * mu.0 + c.bpe[1].1[i] * mu.1;
        }
    }

    /// One conjugate-gradient step on `J v = r` (module docs); the largest change of a shear.
    fn step(&mut self) -> Result<f64, ArgumentError> {
        let n = self.q.0.len();
        self.precondition()?;
        let mut z = std::mem::take(&mut self.z);
        self.keep_force(&mut z);
        self.z = z;
        let beta = match (self.restart, dot(&self.v, &self.jv)) {
            (false, vq) if vq > 0.0 => -dot(&self.z, &self.jv) / vq,
            _ => 0.0,
        };
        self.restart = false;
        for i in 0..n {
            self.v.0[i] = self.z.0[i] + beta * self.v.0[i];
            self.v.1[i] = self.z.1[i] + beta * self.v.1[i];
        }
        self.frame.project(&mut self.v.0, &mut self.v.1);
        let mut v = std::mem::take(&mut self.v);
        self.keep_force(&mut v);
        self.v = v;
        self.jacobian()?;
        let (rv, vq) = (dot(&self.r, &self.v), dot(&self.v, &self.jv));
        // `J` is positive definite on the projected directions: `vq = 0` only for `v = 0`, i.e. `r = 0`.
        if !(vq > 0.0 && rv.is_finite()) {
            return Ok(0.0);
        }
        let alpha = rv / vq;
        let (g, q, r) = (self.p.bound, &mut self.q, &mut self.r);
        let mut change = 0.0_f64;
        for i in 0..n {
            let (ax, ay) = (alpha * self.v.0[i], alpha * self.v.1[i]);
            change = change.max(ax.hypot(ay));
            q.0[i] += ax;
            q.1[i] += ay;
            if self.frame.set[i] == Set::Slip {
                let k = g[i] / q.0[i].hypot(q.1[i]);
                q.0[i] *= k;
                q.1[i] *= k;
            }
            r.0[i] -= alpha * self.jv.0[i];
            r.1[i] -= alpha * self.jv.1[i];
        }
        Ok(change)
    }

    /// The checks of the constraints (module docs), the force restored, a fresh slip and linearisation: whether a
    /// set changed and the largest change of a shear in restoring the force (`None`: no stick element left, or a
    /// singular constraint).
    fn check(&mut self) -> Result<Option<(bool, f64)>, ArgumentError> {
        let (g, q, set) = (self.p.bound, &mut self.q, &mut self.frame.set);
        let mut changed = false;
        for i in 0..g.len() {
            let a = q.0[i].hypot(q.1[i]);
            if set[i] == Set::Stick && a > g[i] {
                (q.0[i], q.1[i], set[i]) = (q.0[i] * g[i] / a, q.1[i] * g[i] / a, Set::Slip);
                changed = true;
            }
        }
        let Some(moved) = self.restore_force() else { return Ok(None) };
        self.p.slip(&self.q, self.shift, &mut self.w)?;
        changed |= release_wrong_slips(&mut self.frame.set, (&self.q.0, &self.q.1), (&self.w.sx, &self.w.sy));
        if !self.linearise()? {
            return Ok(None);
        }
        self.restart |= changed;
        Ok(Some((changed, moved)))
    }

    /// The size of the step the fresh residual asks for, `max_i |r_i| / min(C_xx(0, 0), C_yy(0, 0))` (stress): the
    /// last linear step may have met the tolerance while the turn of the slipping shears back onto their circles
    /// left a residual the next steps still have to remove.
    fn fresh_step(&self) -> f64 {
        let r = &self.r;
        (0..r.0.len()).fold(0.0_f64, |m, i| m.max(r.0[i].hypot(r.1[i]))) / self.d.0.min(self.d.1)
    }

    /// The preconditioned residual `z = B r` (module docs).
    fn precondition(&mut self) -> Result<(), ArgumentError> {
        apply_b(self.m, &self.frame, &mut self.w, &self.r, &mut self.z)
    }

    /// `J v = P C_tt v + c ∘ v` into `jv` (module docs).
    fn jacobian(&mut self) -> Result<(), ArgumentError> {
        let (f, v, jv) = (&self.frame, &self.v, &mut self.jv);
        self.p.op.apply_tangential((&v.0, &v.1), (&mut jv.0, &mut jv.1), &mut self.w.block)?;
        f.project(&mut jv.0, &mut jv.1);
        for i in 0..v.0.len() {
            jv.0[i] += f.c[i] * v.0[i];
            jv.1[i] += f.c[i] * v.1[i];
        }
        Ok(())
    }
}

/// The method of the module docs from the previous shears projected onto this step's discs; `None` when a
/// prescribed force leaves the method without a stick element to carry it (or with a singular constraint): the
/// caller then solves the step another way.
pub(super) fn run(
    p: &Problem<'_>,
    tolerance: f64,
    max_iterations: usize,
    cancel: &Cancel,
) -> Result<Option<Outcome>, ArgumentError> {
    let gmax = p.bound.iter().fold(0.0_f64, |a, &b| a.max(b));
    let Some(mut cg) = Cg::new(p)? else { return Ok(None) };
    let mut iterations = 0;
    let stop = loop {
        let mut change = f64::INFINITY;
        for _ in 0..INNER {
            if cancel.is_cancelled() {
                break;
            }
            if iterations >= max_iterations {
                break;
            }
            iterations += 1;
            change = cg.step()?;
            if change <= tolerance * gmax {
                break;
            }
        }
        let Some((changed, moved)) = cg.check()? else { return Ok(None) };
        if cancel.is_cancelled() {
            break super::TangentialStop::Cancelled;
        }
        if !changed && change.max(moved).max(cg.fresh_step()) <= tolerance * gmax {
            break super::TangentialStop::Converged;
        }
        if iterations >= max_iterations {
            break super::TangentialStop::IterationLimit;
        }
    };
    Ok(Some(Outcome { q: cg.q, shift: cg.shift, iterations, stop }))
}

/// `out = B u = P S M S P u` (module docs; `u` already projected, `P u = u`).
fn apply_b(m: &[Toeplitz2d; 2], f: &Frame, w: &mut Work, u: &Pair, out: &mut Pair) -> Result<(), ArgumentError> {
    for i in 0..u.0.len() {
        w.dx[i] = u.0[i] * f.scale.0[i];
        w.dy[i] = u.1[i] * f.scale.1[i];
    }
    m[0].apply_into(&w.dx, &mut out.0, &mut w.one)?;
    m[1].apply_into(&w.dy, &mut out.1, &mut w.one)?;
    for i in 0..u.0.len() {
        out.0[i] *= f.scale.0[i];
        out.1[i] *= f.scale.1[i];
    }
    f.project(&mut out.0, &mut out.1);
    Ok(())
}

/// The start of the stick and slip iterations from the shears `prev`: each projected onto its disc `|q| ≤ g`, those
/// on or beyond their bound in slip, the others in stick, elements without a bound exterior (and zero).
pub(crate) fn start_sets(prev: (&[f64], &[f64]), g: &[f64]) -> (Pair, Vec<Set>) {
    let n = g.len();
    let (mut q, mut set) = ((vec![0.0; n], vec![0.0; n]), vec![Set::Exterior; n]);
    for i in (0..n).filter(|&i| g[i] > 0.0) {
        let (x, y) = (prev.0[i], prev.1[i]);
        let r = x.hypot(y);
        if r >= g[i] && r > 0.0 {
            (q.0[i], q.1[i], set[i]) = (x * g[i] / r, y * g[i] / r, Set::Slip);
        } else {
            (q.0[i], q.1[i], set[i]) = (x, y, Set::Stick);
        }
    }
    (q, set)
}

/// Slipping elements whose slip runs along their shear (`s_iᵀ q_i > 0`) return to stick; whether any did.
pub(crate) fn release_wrong_slips(set: &mut [Set], q: (&[f64], &[f64]), s: (&[f64], &[f64])) -> bool {
    let mut changed = false;
    for i in 0..set.len() {
        if set[i] == Set::Slip && s.0[i] * q.0[i] + s.1[i] * q.1[i] > 0.0 {
            set[i] = Set::Stick;
            changed = true;
        }
    }
    changed
}
