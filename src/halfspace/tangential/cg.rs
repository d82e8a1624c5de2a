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
//! **The preconditioner.** `B = P S M S P`, with `M = diag(M_xx, M_yy)` the inverses of the circulant embeddings
//! of `C_xx` and `C_yy` ([`super::Influence::tangential_preconditioner`]) and `S` the diagonal scaling
//! `√(d/(d + c_i))` in `S` (`d` the diagonal compliance; 1 in `H`) that accounts for the turn term — symmetric
//! positive semi-definite, as the method needs. Each step costs two FFT passes: the product `C_tt v` and `M`.
//!
//! **Stop.** When a step changes no shear by more than `tolerance · max g` and a check changes neither set. The
//! answer is certified by the caller from the final shears (the natural residual of the disc law).

use super::super::operator::Influence;
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::toeplitz2d::{BlockScratch, Scratch, Toeplitz2d};

/// Conjugate-gradient steps between two checks of the constraints (CONTACT's TangCG uses four).
pub(super) const INNER: usize = 4;

/// An element's set.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Set {
    Exterior,
    Stick,
    Slip,
}

/// The data of one shift step as the method needs them (shift drive).
pub(super) struct Problem<'a> {
    pub op: &'a Influence,
    /// The bounds `g = μp`.
    pub bound: &'a [f64],
    /// The previous shears `q′`.
    pub prev: (&'a [f64], &'a [f64]),
    /// The slip offset per element.
    pub offset: (&'a [f64], &'a [f64]),
    /// The rigid shift increment.
    pub shift: (f64, f64),
}

/// What [`run`] returns: the shears, the iterations (conjugate-gradient steps) and whether it converged.
pub(super) struct Outcome {
    pub q: Pair,
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
    /// The slip `w + o + C_tt (q − q′)` into `(sx, sy)`.
    fn slip(&self, q: &Pair, w: &mut Work) -> Result<(), ArgumentError> {
        for i in 0..q.0.len() {
            w.dx[i] = q.0[i] - self.prev.0[i];
            w.dy[i] = q.1[i] - self.prev.1[i];
        }
        self.op.apply_tangential((&w.dx, &w.dy), (&mut w.sx, &mut w.sy), &mut w.block)?;
        for i in 0..q.0.len() {
            w.sx[i] += self.shift.0 + self.offset.0[i];
            w.sy[i] += self.shift.1 + self.offset.1[i];
        }
        Ok(())
    }
}

/// The linearisation at the current shears: per element its set, `t_i` and `c_i` (module docs).
struct Frame {
    set: Vec<Set>,
    tx: Vec<f64>,
    ty: Vec<f64>,
    c: Vec<f64>,
    /// The preconditioner's scaling per element and component (module docs).
    scale: (Vec<f64>, Vec<f64>),
}

impl Frame {
    /// The frame of the current sets at the shears `q` with slips `(sx, sy)`; `d` the diagonal compliances.
    fn update(&mut self, q: &Pair, s: (&[f64], &[f64]), g: &[f64], d: (f64, f64)) {
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
    fn project(&self, x: &mut [f64], y: &mut [f64]) {
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
type Pair = (Vec<f64>, Vec<f64>);

fn dot(a: &Pair, b: &Pair) -> f64 {
    a.0.iter().zip(&b.0).map(|(x, y)| x * y).sum::<f64>() + a.1.iter().zip(&b.1).map(|(x, y)| x * y).sum::<f64>()
}

/// The iteration's state (module docs).
struct Cg<'p, 'a> {
    p: &'p Problem<'a>,
    /// The preconditioner `[M_xx, M_yy]`.
    m: &'a [Toeplitz2d; 2],
    /// The diagonal compliances `(C_xx(0, 0), C_yy(0, 0))`.
    d: (f64, f64),
    q: Pair,
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

impl<'p, 'a> Cg<'p, 'a> {
    /// The start: the previous shears projected onto this step's discs (those on or beyond their bound slip), the
    /// slip, the frame and the residual.
    fn new(p: &'p Problem<'a>) -> Result<Cg<'p, 'a>, ArgumentError> {
        let (n, g) = (p.bound.len(), p.bound);
        let m = p.op.tangential_preconditioner()?;
        let d = p.op.kernel_table().get(0, 0).map_or((1.0, 1.0), |c| (c.xx, c.yy));
        let z = || vec![0.0; n];
        let w = Work { sx: z(), sy: z(), dx: z(), dy: z(), block: BlockScratch::default(), one: Scratch::default() };
        let mut q = (z(), z());
        let mut set = vec![Set::Exterior; n];
        for i in (0..n).filter(|&i| g[i] > 0.0) {
            let (x, y) = (p.prev.0[i], p.prev.1[i]);
            let r = x.hypot(y);
            if r >= g[i] && r > 0.0 {
                (q.0[i], q.1[i], set[i]) = (x * g[i] / r, y * g[i] / r, Set::Slip);
            } else {
                (q.0[i], q.1[i], set[i]) = (x, y, Set::Stick);
            }
        }
        let frame = Frame { set, tx: z(), ty: z(), c: z(), scale: (z(), z()) };
        let mut cg =
            Cg { p, m, d, q, frame, r: (z(), z()), z: (z(), z()), v: (z(), z()), jv: (z(), z()), w, restart: true };
        p.slip(&cg.q, &mut cg.w)?;
        release_wrong_slips(&mut cg.frame.set, &cg.q, (&cg.w.sx, &cg.w.sy));
        cg.linearise();
        Ok(cg)
    }

    /// The frame and the residual `−P s` at the current shears and slip.
    fn linearise(&mut self) {
        let f = &mut self.frame;
        f.update(&self.q, (&self.w.sx, &self.w.sy), self.p.bound, self.d);
        for i in 0..self.q.0.len() {
            (self.r.0[i], self.r.1[i]) = (-self.w.sx[i], -self.w.sy[i]);
        }
        f.project(&mut self.r.0, &mut self.r.1);
    }

    /// One conjugate-gradient step on `J v = r` (module docs); the largest change of a shear.
    fn step(&mut self) -> Result<f64, ArgumentError> {
        let n = self.q.0.len();
        self.precondition()?;
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

    /// The checks of the constraints (module docs), a fresh slip and linearisation; whether a set changed.
    fn check(&mut self) -> Result<bool, ArgumentError> {
        let (g, q, set) = (self.p.bound, &mut self.q, &mut self.frame.set);
        let mut changed = false;
        for i in 0..g.len() {
            let a = q.0[i].hypot(q.1[i]);
            if set[i] == Set::Stick && a > g[i] {
                (q.0[i], q.1[i], set[i]) = (q.0[i] * g[i] / a, q.1[i] * g[i] / a, Set::Slip);
                changed = true;
            }
        }
        self.p.slip(&self.q, &mut self.w)?;
        changed |= release_wrong_slips(&mut self.frame.set, &self.q, (&self.w.sx, &self.w.sy));
        self.linearise();
        self.restart |= changed;
        Ok(changed)
    }

    /// The preconditioned residual `z = P S M S r` (module docs).
    fn precondition(&mut self) -> Result<(), ArgumentError> {
        let (f, w, r, z) = (&self.frame, &mut self.w, &self.r, &mut self.z);
        for i in 0..r.0.len() {
            w.dx[i] = r.0[i] * f.scale.0[i];
            w.dy[i] = r.1[i] * f.scale.1[i];
        }
        self.m[0].apply_into(&w.dx, &mut z.0, &mut w.one)?;
        self.m[1].apply_into(&w.dy, &mut z.1, &mut w.one)?;
        for i in 0..r.0.len() {
            z.0[i] *= f.scale.0[i];
            z.1[i] *= f.scale.1[i];
        }
        f.project(&mut z.0, &mut z.1);
        Ok(())
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

/// The method of the module docs from the previous shears projected onto this step's discs.
pub(super) fn run(
    p: &Problem<'_>,
    tolerance: f64,
    max_iterations: usize,
    cancel: &Cancel,
) -> Result<Outcome, ArgumentError> {
    let gmax = p.bound.iter().fold(0.0_f64, |a, &b| a.max(b));
    let mut cg = Cg::new(p)?;
    let mut iterations = 0;
    let stop = loop {
        let mut change = f64::INFINITY;
        for _ in 0..INNER {
            if cancel.is_cancelled() {
                return Ok(Outcome { q: cg.q, iterations, stop: super::TangentialStop::Cancelled });
            }
            if iterations >= max_iterations {
                return Ok(Outcome { q: cg.q, iterations, stop: super::TangentialStop::IterationLimit });
            }
            iterations += 1;
            change = cg.step()?;
            if change <= tolerance * gmax {
                break;
            }
        }
        if !cg.check()? && change <= tolerance * gmax {
            break super::TangentialStop::Converged;
        }
    };
    Ok(Outcome { q: cg.q, iterations, stop })
}

/// Slipping elements whose slip runs along their shear (`s_iᵀ q_i > 0`) return to stick; whether any did.
fn release_wrong_slips(set: &mut [Set], q: &Pair, s: (&[f64], &[f64])) -> bool {
    let mut changed = false;
    for i in 0..set.len() {
        if set[i] == Set::Slip && s.0[i] * q.0[i] + s.1[i] * q.1[i] > 0.0 {
            set[i] = Set::Stick;
            changed = true;
        }
    }
    changed
}
