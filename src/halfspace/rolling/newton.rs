//! The steady-rolling equations by a semismooth Newton method with preconditioned GMRES
//! ([`super::solve`]; the equations are in the parent's docs).
//!
//! **Unknowns and equations.** As for the shift problem (`tangential/cg.rs`): the elements split into a stick set
//! `H` (`s_i = 0`, both shears free) and a slip set `S` (the shear on its bound along `n_i`, free to turn along
//! `t_i`; the equation `t_iᵀ s_i = 0`), with the slip now `s = w + K q`, `K = C_tt D` the rolling operator
//! (parent docs). With the force prescribed, the uniform creepage `(ξ, η)` is two more unknowns and `Σ q = F/A`
//! two more equations.
//!
//! **One Newton step.** At the current shears and sets the linearisation is `J v = P K v + c ∘ v` (`P` keeps `H` and
//! the `t` component in `S`; `c_i = −n_iᵀ s_i/g_i ≥ 0` the turn of `t_i`), as in the shift problem but not
//! symmetric: `K`'s difference `D` along the rolling direction makes it a transport operator. The step solves
//! `J v = −P s` (plus `Eᵀ v = F/A − Σ q` and the creepage change with the force prescribed) by GMRES (Saad &
//! Schultz 1986) with right preconditioning, to a relative residual ([`FORCING`]) or [`super::RollingSettings`]'s
//! Krylov dimension; then `q ← q + v`, the slipping shears put back on their circles, stick shears beyond their
//! bound moved to slip, and the slip computed afresh (one product): slipping elements whose slip runs along their
//! shear return to stick.
//!
//! **The preconditioner** is `B = P (D + E)⁻¹ P M P`: `M` the inverse circulants of `C_xx`, `C_yy` (as for the
//! shift problem) and `(D + E)⁻¹` the exact inverse of the difference plus a diagonal, a running sum along each row
//! from the leading edge, `u_i = (Δx z_i + u_up(i)) / (1 + Δx e_i)` (O(N)). Where everything sticks (`E = 0`),
//! `K B = C D P D⁻¹ P M ≈ C M ≈ I` away from the contact's edges: the transport is undone exactly, and GMRES is
//! left with what the circulant misses. In the slip set the turn term `c_i` adds to the diagonal `K_d` of `K`;
//! `e_i = c_i / (Δx K_d)` makes the local inverse `1/(K_d + c_i)`, and cuts the running sum where the turn term
//! dominates — near the contact's edge, where `g_i → 0` and `c_i = |s_i|/g_i` grows without bound. Without `E`
//! GMRES stalls once the slip area forms (CONTACT's `tang_problm_1c`: 460 products with `E = 0`, 40 GMRES steps per
//! Newton step reducing the residual by 0.1 to 0.5; 106 with it, at the same forcing).
//!
//! **Stop.** When a fresh slip changes neither set and asks for no shear change larger than `tolerance · max g`
//! (as a diagonal step `max |r_i| / K_d`, `K_d` the diagonal of `K`) and, with the force prescribed, the force is
//! met to the same tolerance. The caller certifies the answer from the final shears (the natural residual).

use super::super::operator::Influence;
use super::super::tangential::cg::{release_wrong_slips, start_sets, Frame, Set};
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::toeplitz2d::{BlockScratch, Scratch};

/// The relative residuals at which GMRES ends one Newton step: while the last step changed a set, and once it
/// changed none (an inexact Newton method: a step need not be exact while the sets are still moving; near the
/// answer the Newton steps converge as fast as GMRES is asked to). Measured on CONTACT's `tang_problm_1c` and `2c`:
/// 0.3 / 0.01 take 83 and 139 products, 0.05 throughout 106 and 187, 0.1 / 0.01 106 and 171.
pub(super) const FORCING: (f64, f64) = (0.3, 0.01);

/// What is prescribed besides the spin: the uniform creepage `(ξ, η)`, or the sum of the shears `Σ q = F/A`.
#[derive(Clone, Copy)]
pub(super) enum Drive {
    Creepage(f64, f64),
    Force(f64, f64),
}

/// The data of one steady-rolling problem as the method needs them.
pub(super) struct Problem<'a> {
    pub op: &'a Influence,
    /// The bounds `g = μp`.
    pub bound: &'a [f64],
    /// The part of the rigid slip that is not uniform: the spin's `(−φ y, φ x)` plus any offset (dimensionless).
    pub rigid: (Vec<f64>, Vec<f64>),
    pub drive: Drive,
    /// True when the contact rolls along +x (material enters at the largest x).
    pub plus_x: bool,
    /// The start shears.
    pub start: (&'a [f64], &'a [f64]),
}

/// What [`run`] returns.
pub(super) struct Outcome {
    pub q: (Vec<f64>, Vec<f64>),
    pub creepage: (f64, f64),
    /// Operator products (`K` applications, the preconditioner's FFT passes not counted).
    pub products: usize,
    /// Newton steps.
    pub steps: usize,
    pub stop: super::RollingStop,
}

/// Work vectors of one product.
struct Work {
    dx: Vec<f64>,
    dy: Vec<f64>,
    block: BlockScratch,
    one: Scratch,
}

impl Problem<'_> {
    fn n(&self) -> usize {
        self.bound.len()
    }

    /// `out = D v`: `(v_i − v_upstream(i)) / dx` per component, the upstream element the next one against the
    /// rolling direction (zero beyond the grid).
    fn difference(&self, v: &[f64], out: &mut [f64]) {
        let grid = self.op.grid();
        let (mx, h) = (grid.mx(), grid.dx());
        for (row_v, row_o) in v.chunks(mx).zip(out.chunks_mut(mx)) {
            for ix in 0..mx {
                let up = if self.plus_x { row_v.get(ix + 1) } else { ix.checked_sub(1).map(|k| &row_v[k]) };
                row_o[ix] = (row_v[ix] - up.copied().unwrap_or(0.0)) / h;
            }
        }
    }

    /// `z ← (D + diag(e))⁻¹ z` in place: the running sum along each row from the leading edge, damped where
    /// `e > 0` (`u_i = (Δx z_i + u_up(i)) / (1 + Δx e_i)`).
    fn cumulate_damped(&self, z: &mut [f64], e: &[f64]) {
        let grid = self.op.grid();
        let (mx, h) = (grid.mx(), grid.dx());
        for (row, erow) in z.chunks_mut(mx).zip(e.chunks(mx)) {
            let mut acc = 0.0;
            let mut step = |ix: usize| {
                acc = (h * row[ix] + acc) / (1.0 + h * erow[ix]);
                row[ix] = acc;
            };
            if self.plus_x {
                (0..mx).rev().for_each(&mut step);
            } else {
                (0..mx).for_each(&mut step);
            }
        }
    }

    /// `out = K v = C_tt D v` (one tangential product).
    fn apply_k(&self, v: (&[f64], &[f64]), out: (&mut [f64], &mut [f64]), w: &mut Work) -> Result<(), ArgumentError> {
        self.difference(v.0, &mut w.dx);
        self.difference(v.1, &mut w.dy);
        self.op.apply_tangential((&w.dx, &w.dy), out, &mut w.block)
    }

    /// The diagonal of `K = C_tt D` per component, `(C(0) − C(e_up)) / Δx` (`e_up` the offset of the upstream
    /// element; 1/stress).
    pub(super) fn diagonals(&self) -> (f64, f64) {
        let table = self.op.kernel_table();
        let c0 = table.get(0, 0).map(|c| (c.xx, c.yy)).unwrap_or((1.0, 1.0));
        // v_i enters (D v)_i with 1/Δx and (D v)_j, up(j) = i, with −1/Δx: offset i − j = ±1.
        let off = if self.plus_x { 1 } else { -1 };
        let c1 = table.get(off, 0).map(|c| (c.xx, c.yy)).unwrap_or((0.0, 0.0));
        let h = self.op.grid().dx();
        (((c0.0 - c1.0) / h).max(f64::MIN_POSITIVE), ((c0.1 - c1.1) / h).max(f64::MIN_POSITIVE))
    }

    /// The smaller diagonal of `K` (for the natural residual).
    pub(super) fn diagonal(&self) -> f64 {
        let d = self.diagonals();
        d.0.min(d.1)
    }

    /// The slip `w + rigid + K q` into `s` (allocating its work space).
    pub(super) fn slip_of(
        &self,
        q: (&[f64], &[f64]),
        creep: (f64, f64),
        s: (&mut [f64], &mut [f64]),
    ) -> Result<(), ArgumentError> {
        let n = self.n();
        let mut w =
            Work { dx: vec![0.0; n], dy: vec![0.0; n], block: BlockScratch::default(), one: Scratch::default() };
        self.slip(q, creep, s, &mut w)
    }

    /// The slip `w + rigid + K q` into `s`.
    fn slip(
        &self,
        q: (&[f64], &[f64]),
        creep: (f64, f64),
        s: (&mut [f64], &mut [f64]),
        w: &mut Work,
    ) -> Result<(), ArgumentError> {
        self.apply_k(q, (&mut *s.0, &mut *s.1), w)?;
        for i in 0..self.n() {
            s.0[i] += creep.0 + self.rigid.0[i];
            s.1[i] += creep.1 + self.rigid.1[i];
        }
        Ok(())
    }
}

/// The iteration's state.
struct Newton<'p, 'a> {
    p: &'p Problem<'a>,
    m: &'a [crate::toeplitz2d::Toeplitz2d; 2],
    /// The diagonal of `K` per component.
    d: (f64, f64),
    q: (Vec<f64>, Vec<f64>),
    creep: (f64, f64),
    s: (Vec<f64>, Vec<f64>),
    frame: Frame,
    /// The preconditioner's damping per component (module docs).
    damping: (Vec<f64>, Vec<f64>),
    /// GMRES's basis vectors, kept between Newton steps.
    basis: Vec<Vec<f64>>,
    w: Work,
    /// Force drive: the target `F/A`, and the scalings of the creepage unknowns and the force equations.
    force: Option<((f64, f64), f64, f64)>,
    products: usize,
}

impl<'p, 'a> Newton<'p, 'a> {
    fn new(p: &'p Problem<'a>) -> Result<Newton<'p, 'a>, ArgumentError> {
        let (n, g) = (p.n(), p.bound);
        let m = p.op.tangential_preconditioner()?;
        let d = p.diagonals();
        let z = || vec![0.0; n];
        let (q, set) = start_sets(p.start, g);
        let (creep, force) = match p.drive {
            Drive::Creepage(a, b) => ((a, b), None),
            Drive::Force(a, b) => {
                let nc = g.iter().filter(|&&v| v > 0.0).count().max(1) as f64;
                ((0.0, 0.0), Some(((a, b), 1.0 / nc.sqrt(), d.0.min(d.1) / nc.sqrt())))
            }
        };
        let frame = Frame { set, tx: z(), ty: z(), c: z(), scale: (z(), z()) };
        let w = Work { dx: z(), dy: z(), block: BlockScratch::default(), one: Scratch::default() };
        Ok(Newton {
            p,
            m,
            d,
            q,
            creep,
            s: (z(), z()),
            frame,
            damping: (z(), z()),
            basis: Vec::new(),
            w,
            force,
            products: 0,
        })
    }

    /// A fresh slip, the sets checked, the frame; whether a slipping element returned to stick.
    fn refresh(&mut self) -> Result<bool, ArgumentError> {
        self.p.slip((&self.q.0, &self.q.1), self.creep, (&mut self.s.0, &mut self.s.1), &mut self.w)?;
        self.products += 1;
        let changed = release_wrong_slips(&mut self.frame.set, (&self.q.0, &self.q.1), (&self.s.0, &self.s.1));
        self.update_frame();
        Ok(changed)
    }

    /// The residual `−P s` (and, force drive, the scaled force defect) into the flat vector `r`; the largest shear
    /// change it asks for (a diagonal step) and the force defect per contact element.
    fn residual(&self, r: &mut [f64]) -> (f64, f64) {
        let n = self.p.n();
        let (rx, rest) = r.split_at_mut(n);
        let (ry, extra) = rest.split_at_mut(n);
        for i in 0..n {
            (rx[i], ry[i]) = (-self.s.0[i], -self.s.1[i]);
        }
        self.frame.project(rx, ry);
        let step = (0..n).fold(0.0_f64, |m, i| m.max((rx[i] / self.d.0).hypot(ry[i] / self.d.1)));
        let mut defect = 0.0;
        if let Some(((fx, fy), _, tau)) = self.force {
            let (sx, sy): (f64, f64) = (self.q.0.iter().sum(), self.q.1.iter().sum());
            (extra[0], extra[1]) = (tau * (fx - sx), tau * (fy - sy));
            let nc = self.p.bound.iter().filter(|&&v| v > 0.0).count().max(1) as f64;
            defect = (fx - sx).hypot(fy - sy) / nc;
        }
        (step, defect)
    }

    /// The preconditioner `out = B y = P (D + E)⁻¹ P M P y` on the shear part (module docs).
    fn precondition(&mut self, y: &[f64], out: &mut [f64]) -> Result<(), ArgumentError> {
        let n = self.p.n();
        let (ox, oy) = out.split_at_mut(n);
        let oy = &mut oy[..n];
        self.w.dx.copy_from_slice(&y[..n]);
        self.w.dy.copy_from_slice(&y[n..2 * n]);
        self.frame.project(&mut self.w.dx, &mut self.w.dy);
        self.m[0].apply_into(&self.w.dx, ox, &mut self.w.one)?;
        self.m[1].apply_into(&self.w.dy, oy, &mut self.w.one)?;
        self.frame.project(ox, oy);
        self.p.cumulate_damped(ox, &self.damping.0);
        self.p.cumulate_damped(oy, &self.damping.1);
        self.frame.project(ox, oy);
        Ok(())
    }

    /// The frame for a fresh slip, and the preconditioner's damping `e_i = c_i / (Δx K_d)` per component.
    fn update_frame(&mut self) {
        self.frame.update((&self.q.0, &self.q.1), (&self.s.0, &self.s.1), self.p.bound, self.d);
        let h = self.p.op.grid().dx();
        for (i, c) in self.frame.c.iter().enumerate() {
            self.damping.0[i] = c / (h * self.d.0);
            self.damping.1[i] = c / (h * self.d.1);
        }
    }

    /// The preconditioned operator on a flat vector `(y, ω)`: `(J B y + P E σ ω, τ Eᵀ B y)` into `out`, with `z`
    /// work space for `B y`.
    fn operator(&mut self, y: &[f64], z: &mut [f64], out: &mut [f64]) -> Result<(), ArgumentError> {
        let n = self.p.n();
        self.precondition(y, z)?;
        let (zx, zy) = z[..2 * n].split_at(n);
        let (ox, rest) = out.split_at_mut(n);
        let (oy, extra) = rest.split_at_mut(n);
        self.p.apply_k((zx, zy), (&mut *ox, &mut oy[..]), &mut self.w)?;
        self.products += 1;
        let f = &self.frame;
        f.project(ox, oy);
        for i in 0..n {
            ox[i] += f.c[i] * zx[i];
            oy[i] += f.c[i] * zy[i];
        }
        if let Some((_, sigma, tau)) = self.force {
            let (wx, wy) = (sigma * y[2 * n], sigma * y[2 * n + 1]);
            for i in (0..n).filter(|&i| f.set[i] != Set::Exterior) {
                let (mut ex, mut ey) = ([wx], [wy]);
                if f.set[i] == Set::Slip {
                    let a = f.tx[i] * wx + f.ty[i] * wy;
                    (ex[0], ey[0]) = (a * f.tx[i], a * f.ty[i]);
                }
                ox[i] += ex[0];
                oy[i] += ey[0];
            }
            extra[0] = tau * zx.iter().sum::<f64>();
            extra[1] = tau * zy.iter().sum::<f64>();
        }
        Ok(())
    }

    /// One Newton step: GMRES on the preconditioned operator from `r`, then the update of the shears (and the
    /// creepage); the largest shear change and whether a stick element moved to slip. `budget` caps the products.
    fn step(
        &mut self,
        r: &[f64],
        krylov: usize,
        budget: usize,
        forcing: f64,
        cancel: &Cancel,
    ) -> Result<(f64, bool), ArgumentError> {
        let n = self.p.n();
        let y = gmres(self, r, krylov.min(budget.max(1)), forcing, cancel)?;
        let mut dq = vec![0.0; r.len()];
        self.precondition(&y, &mut dq)?;
        if let Some((_, sigma, _)) = self.force {
            self.creep.0 += sigma * y[2 * n];
            self.creep.1 += sigma * y[2 * n + 1];
        }
        let (g, set) = (self.p.bound, &mut self.frame.set);
        let (mut change, mut to_slip) = (0.0_f64, false);
        for i in 0..n {
            change = change.max(dq[i].hypot(dq[n + i]));
            self.q.0[i] += dq[i];
            self.q.1[i] += dq[n + i];
            let a = self.q.0[i].hypot(self.q.1[i]);
            if set[i] == Set::Slip || (set[i] == Set::Stick && a > g[i]) {
                to_slip |= set[i] == Set::Stick;
                set[i] = Set::Slip;
                let k = if a > 0.0 { g[i] / a } else { 0.0 };
                self.q.0[i] *= k;
                self.q.1[i] *= k;
            }
        }
        Ok((change, to_slip))
    }
}

/// Right-preconditioned GMRES with at most `m` steps on the operator of [`Newton::operator`] from the zero start
/// and the right-hand side `r`: the coefficients `y` (apply `B` for the shear change). Modified Gram–Schmidt,
/// Givens rotations; ends at the relative residual `forcing`. The basis is kept in `nw.basis` between calls.
fn gmres(
    nw: &mut Newton<'_, '_>,
    r: &[f64],
    m: usize,
    forcing: f64,
    cancel: &Cancel,
) -> Result<Vec<f64>, ArgumentError> {
    let len = r.len();
    let beta = norm(r);
    if beta == 0.0 || !beta.is_finite() {
        return Ok(vec![0.0; len]);
    }
    let mut basis = std::mem::take(&mut nw.basis);
    while basis.len() < m + 1 {
        basis.push(vec![0.0; len]);
    }
    basis[0].iter_mut().zip(r).for_each(|(a, b)| *a = b / beta);
    let mut h = vec![vec![0.0; m]; m + 1];
    let (mut cs, mut sn, mut g) = (vec![0.0; m], vec![0.0; m], vec![0.0; m + 1]);
    g[0] = beta;
    let mut z = vec![0.0; len];
    let mut k = 0;
    while k < m && !cancel.is_cancelled() {
        let (done, rest) = basis.split_at_mut(k + 1);
        let w = &mut rest[0];
        nw.operator(&done[k], &mut z, w)?;
        for (j, vj) in done.iter().enumerate() {
            h[j][k] = dot(w, vj);
            w.iter_mut().zip(vj).for_each(|(a, b)| *a -= h[j][k] * b);
        }
        h[k + 1][k] = norm(w);
        for j in 0..k {
            let t = cs[j] * h[j][k] + sn[j] * h[j + 1][k];
            h[j + 1][k] = -sn[j] * h[j][k] + cs[j] * h[j + 1][k];
            h[j][k] = t;
        }
        let next = h[k + 1][k];
        let rho = h[k][k].hypot(next);
        (cs[k], sn[k]) = if rho > 0.0 { (h[k][k] / rho, next / rho) } else { (1.0, 0.0) };
        h[k][k] = rho;
        g[k + 1] = -sn[k] * g[k];
        g[k] *= cs[k];
        k += 1;
        if g[k].abs() <= forcing * beta || next == 0.0 {
            break;
        }
        w.iter_mut().for_each(|a| *a /= next);
    }
    // Back substitution for the coefficients of the basis, then the flat solution Σ c_j v_j.
    let mut c = vec![0.0; k];
    for i in (0..k).rev() {
        let s: f64 = (i + 1..k).map(|j| h[i][j] * c[j]).sum();
        c[i] = if h[i][i] != 0.0 { (g[i] - s) / h[i][i] } else { 0.0 };
    }
    let mut y = vec![0.0; len];
    for (cj, vj) in c.iter().zip(&basis) {
        y.iter_mut().zip(vj).for_each(|(a, b)| *a += cj * b);
    }
    nw.basis = basis;
    Ok(y)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// The method of the module docs; `max_products` caps the operator products, `krylov` the GMRES dimension of one
/// Newton step.
pub(super) fn run(
    p: &Problem<'_>,
    tolerance: f64,
    max_products: usize,
    krylov: usize,
    cancel: &Cancel,
) -> Result<Outcome, ArgumentError> {
    let gmax = p.bound.iter().fold(0.0_f64, |a, &b| a.max(b));
    let mut nw = Newton::new(p)?;
    let len = 2 * p.n() + if nw.force.is_some() { 2 } else { 0 };
    let mut r = vec![0.0; len];
    let (mut steps, mut to_slip) = (0, true);
    let stop = loop {
        let released = nw.refresh()?;
        let (fresh, defect) = nw.residual(&mut r);
        if cancel.is_cancelled() {
            break super::RollingStop::Cancelled;
        }
        if !released && !to_slip && fresh <= tolerance * gmax && defect <= tolerance * gmax {
            break super::RollingStop::Converged;
        }
        if nw.products >= max_products {
            break super::RollingStop::IterationLimit;
        }
        steps += 1;
        let forcing = if released || to_slip { FORCING.0 } else { FORCING.1 };
        (_, to_slip) = nw.step(&r, krylov, max_products - nw.products, forcing, cancel)?;
    };
    Ok(Outcome { q: nw.q, creepage: nw.creep, products: nw.products, steps, stop })
}
