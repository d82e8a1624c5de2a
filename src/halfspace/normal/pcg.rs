//! The bound-constrained, FFT-preconditioned conjugate-gradient iteration of the normal problem
//! ([`super::NormalMethod::PreconditionedCg`], the default; the method is described in [`super`]'s module docs).

use super::{Drive, Stop};
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::halfspace::operator::Influence;
use crate::toeplitz2d::{Scratch, Toeplitz2d};

/// The state of the iteration: pressures `p`, displacements `u = C p` (kept up to date), the contact set, and the
/// conjugate-gradient vectors.
pub(super) struct Pcg<'a> {
    op: &'a Influence,
    pre: &'a Toeplitz2d,
    h: &'a [f64],
    drive: Drive,
    /// `Σ p` to hold (load-driven).
    total: f64,
    pub(super) p: Vec<f64>,
    pub(super) u: Vec<f64>,
    active: Vec<bool>,
    r: Vec<f64>,
    z: Vec<f64>,
    v: Vec<f64>,
    q: Vec<f64>,
    /// `M 1_S` on the contact set (load-driven: the direction that carries the load constraint).
    w: Vec<f64>,
    w_sum: f64,
    pub(super) scratch: Scratch,
    pub(super) iterations: usize,
    /// Products with `C_zz` and with the preconditioner, for the docs' cost figures.
    pub(super) products: usize,
}

impl<'a> Pcg<'a> {
    /// The iteration from the starting pressures `p0` (the contact set is where `p0 > 0`).
    pub(super) fn new(op: &'a Influence, pre: &'a Toeplitz2d, h: &'a [f64], drive: Drive, p0: Vec<f64>) -> Pcg<'a> {
        let n = h.len();
        let total = p0.iter().sum();
        let active = p0.iter().map(|&v| v > 0.0).collect();
        let z = || vec![0.0; n];
        Pcg {
            op,
            pre,
            h,
            drive,
            total,
            p: p0,
            u: z(),
            active,
            r: z(),
            z: z(),
            v: z(),
            q: z(),
            w: z(),
            w_sum: 0.0,
            scratch: Scratch::default(),
            iterations: 0,
            products: 0,
        }
    }

    /// `u = C p` afresh.
    fn refresh(&mut self) -> Result<(), ArgumentError> {
        self.products += 1;
        self.op.apply_normal(&self.p, &mut self.u, &mut self.scratch)
    }

    /// The approach: prescribed, or (load-driven) the mean of `h + u` over the contact set, the multiplier of
    /// `Σ p = total` at the solution.
    pub(super) fn approach(&self) -> f64 {
        match self.drive {
            Drive::Approach(d) => d,
            Drive::Load(_) => {
                let (s, c) = (0..self.h.len())
                    .filter(|&i| self.active[i])
                    .fold((0.0, 0usize), |(s, c), i| (s + self.h[i] + self.u[i], c + 1));
                if c > 0 {
                    s / c as f64
                } else {
                    0.0
                }
            }
        }
    }

    /// The loop: a preconditioned CG step on the contact set, the projection `p ≥ 0` (elements with a negative
    /// pressure leave the set), the entry of the elements outside it with a negative gap; conjugation restarts
    /// whenever the set changes. Stops when the set is unchanged and the relative pressure change is under the
    /// tolerance.
    pub(super) fn run(
        &mut self,
        tolerance: f64,
        max_iterations: usize,
        cancel: &Cancel,
    ) -> Result<Stop, ArgumentError> {
        self.refresh()?;
        let (mut changed, mut rz_old) = (true, 0.0_f64);
        while self.iterations < max_iterations {
            if cancel.is_cancelled() {
                return Ok(Stop::Cancelled);
            }
            self.iterations += 1;
            if changed && matches!(self.drive, Drive::Load(_)) {
                self.constraint_direction()?;
            }
            let rz = self.precondition()?;
            let beta = if changed || rz_old <= 0.0 { 0.0 } else { rz / rz_old };
            for i in 0..self.h.len() {
                self.v[i] = if self.active[i] { self.z[i] + beta * self.v[i] } else { 0.0 };
            }
            self.products += 1;
            self.op.apply_normal(&self.v, &mut self.q, &mut self.scratch)?;
            let vq: f64 = (0..self.h.len()).filter(|&i| self.active[i]).map(|i| self.v[i] * self.q[i]).sum();
            if vq.is_nan() || vq <= 0.0 {
                // A zero direction: the residual vanished on the set (rz = 0) or round-off; nothing moves.
                changed = self.update_set(false)?;
                if !changed {
                    return Ok(Stop::Converged);
                }
                continue;
            }
            let alpha = rz / vq;
            let mut change = 0.0;
            for i in 0..self.h.len() {
                if self.active[i] {
                    self.p[i] += alpha * self.v[i];
                    change += (alpha * self.v[i]).abs();
                }
                self.u[i] += alpha * self.q[i];
            }
            rz_old = rz;
            let clipped = self.clip();
            changed = self.update_set(clipped)?;
            let scale: f64 = self.p.iter().sum::<f64>().max(f64::MIN_POSITIVE);
            if !changed && change / scale <= tolerance {
                return Ok(Stop::Converged);
            }
        }
        Ok(Stop::IterationLimit)
    }

    /// `w = M 1_S` restricted to the contact set, and its sum (load-driven).
    fn constraint_direction(&mut self) -> Result<(), ArgumentError> {
        for i in 0..self.h.len() {
            self.r[i] = if self.active[i] { 1.0 } else { 0.0 };
        }
        self.products += 1;
        self.pre.apply_into(&self.r, &mut self.w, &mut self.scratch)?;
        let mut sum = 0.0;
        for i in 0..self.h.len() {
            if self.active[i] {
                sum += self.w[i];
            } else {
                self.w[i] = 0.0;
            }
        }
        self.w_sum = sum;
        Ok(())
    }

    /// The residual `r = d − h − u` on the contact set (the gap's negative), the preconditioned `z = M r` on the
    /// set — projected, load-driven, onto `Σ z = 0` along `w` so that the step keeps the load — and `rᵀ z`.
    fn precondition(&mut self) -> Result<f64, ArgumentError> {
        let d = self.approach();
        for i in 0..self.h.len() {
            self.r[i] = if self.active[i] { d - self.h[i] - self.u[i] } else { 0.0 };
        }
        self.products += 1;
        self.pre.apply_into(&self.r, &mut self.z, &mut self.scratch)?;
        let mut zsum = 0.0;
        for i in 0..self.h.len() {
            if self.active[i] {
                zsum += self.z[i];
            } else {
                self.z[i] = 0.0;
            }
        }
        if matches!(self.drive, Drive::Load(_)) && self.w_sum > 0.0 {
            let c = zsum / self.w_sum;
            for i in 0..self.h.len() {
                self.z[i] -= c * self.w[i];
            }
        }
        Ok((0..self.h.len()).map(|i| self.r[i] * self.z[i]).sum())
    }

    /// The projection: negative pressures set to zero (those elements leave the set). Returns whether any was.
    fn clip(&mut self) -> bool {
        let mut clipped = false;
        for i in 0..self.h.len() {
            if self.active[i] && self.p[i] < 0.0 {
                self.p[i] = 0.0;
                self.active[i] = false;
                clipped = true;
            }
        }
        clipped
    }

    /// After a clipped step: `u` afresh (the clipped pressures changed it) and, load-driven, the load restored by
    /// scaling (`u` scales with `p`). Then the elements outside the set with a negative gap enter it. Returns
    /// whether the set changed.
    fn update_set(&mut self, clipped: bool) -> Result<bool, ArgumentError> {
        if clipped {
            self.refresh()?;
            if let Drive::Load(_) = self.drive {
                let sum: f64 = self.p.iter().sum();
                if sum > 0.0 {
                    let s = self.total / sum;
                    self.p.iter_mut().for_each(|v| *v *= s);
                    self.u.iter_mut().for_each(|v| *v *= s);
                } else {
                    // Every pressure clipped: start again uniform on the elements of least separation.
                    self.restart_uniform()?;
                }
            }
        }
        let d = self.approach();
        let mut entered = false;
        for i in 0..self.h.len() {
            if !self.active[i] && self.h[i] - d + self.u[i] < 0.0 {
                self.active[i] = true;
                entered = true;
            }
        }
        Ok(clipped || entered)
    }

    /// The load spread uniformly over the whole grid (the load-driven start), when a step clipped every pressure.
    fn restart_uniform(&mut self) -> Result<(), ArgumentError> {
        let n = self.h.len();
        self.p.iter_mut().for_each(|v| *v = self.total / n as f64);
        self.active.iter_mut().for_each(|a| *a = true);
        self.refresh()
    }
}
