//! # A load path on a pair of half-spaces: normal and tangential steps, coupled when the pair asks for it
//!
//! The typed 3D problem: two elastic half-spaces ([`HalfSpace`]: body 1 `z > 0`, body 2 the counter-body), a
//! potential contact area ([`ContactGrid`]), the initial separation ([`Profile`]), Coulomb friction μ on the disc,
//! and a sequence of quasi-static steps ([`Step`]: a normal drive — load or approach — and a tangential drive — the
//! total force at the end of the step, or the rigid shift increment in it). [`Path::solve`] solves the steps in
//! order, each from the previous one's state (the tangential problem has memory: Cattaneo–Mindlin loading,
//! Mindlin–Deresiewicz unloading, Spence's compression of dissimilar bodies, fretting).
//!
//! ## Effects simulated only when the physics asks
//!
//! - Frictionless (`μ = 0`): only the normal kernel `C_zz` is built and only the normal problem solved; the shears
//!   are zero. A non-zero tangential force is then refused (it cannot be carried), a shift is allowed (it does
//!   nothing).
//! - The normal–tangential coupling (`C_zt`, `C_tz`) is built and iterated only when asked (`coupling`) **and** the
//!   pair's coupling constant is non-zero (dissimilar materials; Dundurs' β ≠ 0). For identical materials it
//!   vanishes identically and each step is one normal and one tangential solve.
//!
//! ## The coupled step
//!
//! With the coupling, the gap depends on the shears and the slip on the pressures:
//! `g = h − d + C_zz p + C_zt q` and `s = w + C_tt (q − q′) + C_tz (p − p′)`. Each step alternates the two
//! problems (Panagiotopoulos' process, as CONTACT does): the normal problem with the gap of the current shears, then
//! the tangential problem with the slip offset of the new pressures, until neither the pressures nor the shears
//! change by more than the outer tolerance (relative to `max p` and `max μp`). For |β| small against μ the
//! alternation contracts quickly; [`StepOutcome::outer_iterations`] says how many were needed, and a step that does
//! not settle is `NotConverged`, never a solution.
//!
//! ## What `Solved` means
//!
//! Every inner solve converged with its residual below [`PathSettings::residual`], the outer alternation settled,
//! and the contact stays inside the potential contact area: a contact whose pressures reach the grid's boundary
//! elements is cut off by it, so the step is [`PathStatus::ContactAtGridEdge`] (enlarge the area), not solved.

use super::normal::{self, Drive, NormalSettings, Stop};
use super::operator::{ContactGrid, Influence, Kernels};
use super::tangential::{self, ElementState, ShiftStep, TangentialDrive, TangentialSettings, TangentialStop};
use super::HalfSpace;
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::toeplitz2d::Scratch;

/// The initial separation of the two surfaces (length), positive where they are apart.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Profile {
    /// `h = A x² + B y²` at the element centres (A, B in 1/length, > 0: the pair's relative curvatures,
    /// `A = 1/(2R_x)`); Hertz's ellipse is the reference.
    Quadratic {
        /// Curvature constant along x (1/length).
        a: f64,
        /// Curvature constant along y (1/length).
        b: f64,
    },
    /// One value per element, grid order (`ix + MX·iy`): a measured or computed gap.
    Gap(Vec<f64>),
}

/// One quasi-static step: what holds at its end.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Step {
    /// The normal drive: load or approach at the end of the step.
    pub normal: Drive,
    /// The tangential drive: the total force on body 1 at the end of the step, or the shift increment in it.
    pub tangential: TangentialDrive,
}

impl Step {
    /// A step to the normal drive `normal` and the tangential drive `tangential`.
    pub fn new(normal: Drive, tangential: TangentialDrive) -> Step {
        Step { normal, tangential }
    }
}

/// Settings of [`Path::solve`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct PathSettings {
    /// The normal solver's settings.
    pub normal: NormalSettings,
    /// The tangential solver's settings.
    pub tangential: TangentialSettings,
    /// Outer (coupling) tolerance: the largest change of a pressure relative to `max p`, and of a shear relative to
    /// `max μp`, between two alternations.
    pub outer_tolerance: f64,
    /// Largest number of alternations per step.
    pub max_outer: usize,
    /// The largest inner residual (relative, as the solvers report it) a solved step may have.
    pub residual: f64,
}

impl Default for PathSettings {
    /// Inner defaults, outer tolerance 1e-9, 100 alternations, residual 1e-7.
    fn default() -> Self {
        PathSettings {
            normal: NormalSettings::default(),
            tangential: TangentialSettings::default(),
            outer_tolerance: 1e-9,
            max_outer: 100,
            residual: 1e-7,
        }
    }
}

/// The outcome of a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PathStatus {
    /// Solved: every condition of "What `Solved` means" in the module docs holds.
    Solved,
    /// The contact reaches the potential contact area's boundary: cut off, enlarge the grid.
    ContactAtGridEdge,
    /// An inner solver or the coupling alternation did not converge, or a residual is above the limit.
    NotConverged,
    /// The tangential force exceeds the friction's capacity: no quasi-static solution.
    GrossSliding,
    /// The prescribed approach gives no contact.
    NoContact,
    /// The caller's token was raised.
    Cancelled,
}

/// The answer of one step.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct StepOutcome {
    /// The step's status.
    pub status: PathStatus,
    /// What the status means for this step (one sentence).
    pub message: String,
    /// Pressure per element (stress), grid order.
    pub pressure: Vec<f64>,
    /// Shear `q_x` per element (stress, on body 1).
    pub qx: Vec<f64>,
    /// Shear `q_y` per element.
    pub qy: Vec<f64>,
    /// Element states (exterior, stick, slip; all stick-free for a frictionless path: `Exterior` or `Slip`).
    pub state: Vec<ElementState>,
    /// The deformed gap per element (length): `h − d + C_zz p` (with the coupling's `C_zt q` for a coupled step),
    /// 0 in contact up to the normal residual, ≥ 0 outside.
    pub gap: Vec<f64>,
    /// The approach (length).
    pub approach: f64,
    /// The normal force `A Σ p`.
    pub load: f64,
    /// The tangential force `A Σ q` on body 1.
    pub force: (f64, f64),
    /// The rigid shift of body 1 relative to body 2 accumulated from the path's start (length; NaN once a step
    /// slid grossly).
    pub shift: (f64, f64),
    /// Elements in contact, in stick, in slip.
    pub counts: (usize, usize, usize),
    /// The normal and tangential solvers' residuals of the last alternation.
    pub residuals: (f64, f64),
    /// Alternations of the coupled step (1 without coupling).
    pub outer_iterations: usize,
    /// Inner iterations summed over the alternations: (normal, tangential).
    pub iterations: (usize, usize),
}

/// A load path on a pair of half-spaces (module docs).
#[derive(Clone, Debug)]
pub struct Path {
    influence: Influence,
    h: Vec<f64>,
    friction: f64,
    coupled: bool,
    steps: Vec<Step>,
}

impl Path {
    /// The path of `steps` on `grid` for body 1 `body` on body 2 `counter`, profile `profile`, friction `friction`
    /// (≥ 0; 0: frictionless), with the normal–tangential coupling when `coupling` is asked and the pair is
    /// dissimilar (module docs).
    ///
    /// # Errors
    /// An [`ArgumentError`] naming the argument: a profile gap of the wrong length or not finite, curvatures not
    /// finite and > 0, a friction coefficient not finite and ≥ 0, no steps, a non-zero tangential force without
    /// friction, a step's drive out of range, or a grid too large for its kernels.
    pub fn new(
        grid: ContactGrid,
        body: HalfSpace,
        counter: HalfSpace,
        profile: Profile,
        friction: f64,
        coupling: bool,
        steps: Vec<Step>,
    ) -> Result<Path, ArgumentError> {
        const F: &str = "halfspace::Path::new";
        let h = match profile {
            Profile::Quadratic { a, b } => {
                if !(a.is_finite() && a > 0.0 && b.is_finite() && b > 0.0) {
                    return Err(ArgumentError::new(
                        F,
                        "profile",
                        format!("curvatures A, B finite and > 0 (got {a}, {b})"),
                    ));
                }
                grid.sample(|x, y| a * x * x + b * y * y)
            }
            Profile::Gap(g) => {
                if g.len() != grid.len() || !g.iter().all(|v| v.is_finite()) {
                    return Err(ArgumentError::new(
                        F,
                        "profile",
                        format!("{} finite gaps, one per element", grid.len()),
                    ));
                }
                g
            }
        };
        if !(friction.is_finite() && friction >= 0.0) {
            return Err(ArgumentError::new(F, "friction", format!("finite and ≥ 0 (got {friction})")));
        }
        if steps.is_empty() {
            return Err(ArgumentError::new(F, "steps", "at least one step".to_string()));
        }
        for (k, s) in steps.iter().enumerate() {
            check_step(k, s, friction)?;
        }
        let pair = body.pair(&counter);
        let kernels = if friction > 0.0 { Kernels::Full } else { Kernels::Normal };
        let influence = Influence::new(grid, pair, kernels)?;
        let coupled = coupling && influence.has_coupling();
        Ok(Path { influence, h, friction, coupled, steps })
    }

    /// The influence operators built (which kernels: [`Influence::has_tangential`], [`Influence::has_coupling`]).
    pub fn influence(&self) -> &Influence {
        &self.influence
    }

    /// Whether the steps alternate the coupled normal and tangential problems.
    pub fn is_coupled(&self) -> bool {
        self.coupled
    }

    /// Solve the steps in order (module docs). The path stops after a step that is `GrossSliding`, `NotConverged`
    /// or `Cancelled` (the later steps would start from no valid state); the outcomes so far are returned.
    ///
    /// # Errors
    /// An [`ArgumentError`] only for an internal size mismatch (the solvers' argument checks; not reachable from a
    /// path that [`Path::new`] accepted).
    pub fn solve(&self, settings: &PathSettings, cancel: &Cancel) -> Result<Vec<StepOutcome>, ArgumentError> {
        let n = self.h.len();
        let mut state = State { p: vec![0.0; n], qx: vec![0.0; n], qy: vec![0.0; n], shift: (0.0, 0.0) };
        let mut out = Vec::with_capacity(self.steps.len());
        for step in &self.steps {
            let o = self.step(step, &state, settings, cancel)?;
            let stop = matches!(o.status, PathStatus::GrossSliding | PathStatus::NotConverged | PathStatus::Cancelled);
            state = State { p: o.pressure.clone(), qx: o.qx.clone(), qy: o.qy.clone(), shift: o.shift };
            out.push(o);
            if stop {
                break;
            }
        }
        Ok(out)
    }

    /// One step from `prev` (module docs, "The coupled step").
    fn step(&self, step: &Step, prev: &State, s: &PathSettings, cancel: &Cancel) -> Result<StepOutcome, ArgumentError> {
        let n = self.h.len();
        let mut scratch = Scratch::default();
        let (mut p, mut qx, mut qy) = (prev.p.clone(), prev.qx.clone(), prev.qy.clone());
        let (mut heff, mut ox, mut oy, mut dp) = (self.h.clone(), vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut its = (0, 0);
        let mut outer = 0;
        loop {
            outer += 1;
            if self.coupled {
                self.influence.coupling_gap((&qx, &qy), &mut heff, &mut scratch)?;
                heff.iter_mut().zip(&self.h).for_each(|(e, h)| *e += h);
            }
            let ns = normal::solve(&self.influence, &heff, step.normal, &s.normal, cancel)?;
            its.0 += ns.iterations;
            let mut t = Tangential {
                qx: vec![0.0; n],
                qy: vec![0.0; n],
                res: 0.0,
                stop: TangentialStop::Converged,
                shift: (0.0, 0.0),
                state: None,
            };
            if self.friction > 0.0 && ns.stop != Stop::NoContact {
                if self.coupled {
                    dp.iter_mut().zip(ns.pressure.iter().zip(&prev.p)).for_each(|(d, (a, b))| *d = a - b);
                    self.influence.coupling_slip(&dp, (&mut ox, &mut oy), &mut scratch)?;
                }
                let mut sh = ShiftStep::new(&ns.pressure, self.friction, step.tangential).after(&prev.qx, &prev.qy);
                if self.coupled {
                    sh = sh.with_offset(&ox, &oy);
                }
                let ts = tangential::solve(&self.influence, &sh, &s.tangential, cancel)?;
                its.1 += ts.iterations;
                t = Tangential {
                    res: ts.residual,
                    stop: ts.stop,
                    shift: ts.shift,
                    state: Some(ts.state),
                    qx: ts.qx,
                    qy: ts.qy,
                };
            }
            let pmax = ns.pressure.iter().fold(0.0_f64, |m, &v| m.max(v));
            let change = max_change(&p, &ns.pressure, pmax)
                .max(max_change(&qx, &t.qx, self.friction * pmax))
                .max(max_change(&qy, &t.qy, self.friction * pmax));
            let settled = !self.coupled || change <= s.outer_tolerance;
            p = ns.pressure.clone();
            (qx, qy) = (t.qx.clone(), t.qy.clone());
            let inner_done = matches!(ns.stop, Stop::Cancelled)
                || matches!(t.stop, TangentialStop::Cancelled | TangentialStop::GrossSliding);
            if settled || inner_done || outer >= s.max_outer || ns.stop == Stop::NoContact {
                return Ok(self.outcome(prev, ns, t, (settled, outer, its), s));
            }
        }
    }

    /// The step's outcome and status from the last alternation.
    fn outcome(
        &self,
        prev: &State,
        ns: normal::NormalSolution,
        t: Tangential,
        (settled, outer, its): (bool, usize, (usize, usize)),
        s: &PathSettings,
    ) -> StepOutcome {
        let grid = self.influence.grid();
        let area = grid.area();
        let state = t.state.clone().unwrap_or_else(|| {
            ns.pressure.iter().map(|&p| if p > 0.0 { ElementState::Slip } else { ElementState::Exterior }).collect()
        });
        let count = |e: ElementState| state.iter().filter(|&&x| x == e).count();
        let edge = (0..grid.len()).find(|&i| {
            let (ix, iy) = (i % grid.mx(), i / grid.mx());
            ns.pressure[i] > 0.0 && (ix == 0 || iy == 0 || ix + 1 == grid.mx() || iy + 1 == grid.my())
        });
        let (status, message) =
            status(&ns, &t, settled, edge.map(|i| (i % grid.mx(), i / grid.mx())), s, self.friction);
        let shift =
            if self.friction == 0.0 { prev.shift } else { (prev.shift.0 + t.shift.0, prev.shift.1 + t.shift.1) };
        StepOutcome {
            status,
            message,
            approach: ns.approach,
            load: ns.load,
            force: (area * t.qx.iter().sum::<f64>(), area * t.qy.iter().sum::<f64>()),
            shift,
            counts: (ns.in_contact, count(ElementState::Stick), count(ElementState::Slip)),
            residuals: (ns.residual, t.res),
            outer_iterations: outer,
            iterations: its,
            pressure: ns.pressure,
            gap: ns.gap,
            qx: t.qx,
            qy: t.qy,
            state,
        }
    }
}

/// The state carried from step to step.
struct State {
    p: Vec<f64>,
    qx: Vec<f64>,
    qy: Vec<f64>,
    shift: (f64, f64),
}

/// The tangential part of an alternation.
struct Tangential {
    qx: Vec<f64>,
    qy: Vec<f64>,
    res: f64,
    stop: TangentialStop,
    shift: (f64, f64),
    state: Option<Vec<ElementState>>,
}

/// The status of a step and its sentence (module docs, "What `Solved` means").
fn status(
    ns: &normal::NormalSolution,
    t: &Tangential,
    settled: bool,
    edge: Option<(usize, usize)>,
    s: &PathSettings,
    friction: f64,
) -> (PathStatus, String) {
    use PathStatus as P;
    if ns.stop == Stop::Cancelled || t.stop == TangentialStop::Cancelled {
        return (P::Cancelled, "cancelled by the caller".into());
    }
    if ns.stop == Stop::NoContact {
        return (P::NoContact, "the approach is too small for any element to touch".into());
    }
    if t.stop == TangentialStop::GrossSliding {
        return (P::GrossSliding, "the tangential force is at or above μ times the normal force: gross sliding".into());
    }
    if ns.stop != Stop::Converged || (friction > 0.0 && t.stop != TangentialStop::Converged) || !settled {
        let msg = format!(
            "not converged: normal {:?}, tangential {:?}, coupling {}",
            ns.stop,
            t.stop,
            if settled { "settled" } else { "not settled" }
        );
        return (P::NotConverged, msg);
    }
    if ns.residual > s.residual || t.res > s.residual {
        let msg =
            format!("residuals {:.1e} (normal), {:.1e} (tangential) above {:.0e}", ns.residual, t.res, s.residual);
        return (P::NotConverged, msg);
    }
    if let Some((ix, iy)) = edge {
        let msg = format!("the contact reaches the potential contact area's edge at element ({ix}, {iy}): enlarge it");
        return (P::ContactAtGridEdge, msg);
    }
    (P::Solved, "solved".into())
}

/// `max |a − b| / top` (0 when nothing changed; infinite for a change against a zero scale).
fn max_change(a: &[f64], b: &[f64], top: f64) -> f64 {
    let d = a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    if top > 0.0 {
        d / top
    } else if d > 0.0 {
        f64::INFINITY
    } else {
        0.0
    }
}

/// A step's drives ([`Path::new`]).
fn check_step(k: usize, s: &Step, friction: f64) -> Result<(), ArgumentError> {
    let bad = |msg: String| Err(ArgumentError::new("halfspace::Path::new", "steps", format!("step {k}: {msg}")));
    match s.normal {
        Drive::Load(l) if !(l.is_finite() && l > 0.0) => return bad(format!("a finite normal load > 0 (got {l})")),
        Drive::Approach(d) if !d.is_finite() => return bad(format!("a finite approach (got {d})")),
        _ => {}
    }
    let (a, b, force) = match s.tangential {
        TangentialDrive::Force(a, b) => (a, b, true),
        TangentialDrive::Shift(a, b) => (a, b, false),
    };
    if !(a.is_finite() && b.is_finite()) {
        return bad(format!("finite tangential components (got {a}, {b})"));
    }
    if force && friction == 0.0 && (a != 0.0 || b != 0.0) {
        return bad(format!("a tangential force ({a}, {b}) cannot be carried without friction (μ = 0)"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere_grid(m: usize, half: f64) -> ContactGrid {
        let d = 2.0 * half / m as f64;
        ContactGrid::new(m, m, d, d, -half + 0.5 * d, -half + 0.5 * d).unwrap()
    }

    fn mat_vec(m: &[f64], v: &[f64]) -> Vec<f64> {
        let n = v.len();
        (0..n).map(|i| (0..n).map(|j| m[i * n + j] * v[j]).sum()).collect()
    }

    /// Frictionless: only the normal kernel is built (no tangential, no coupling even for a dissimilar pair asked to
    /// couple), the shears are zero, and a tangential force is refused by name.
    #[test]
    fn frictionless_paths_build_only_the_normal_problem() {
        let (steel, alu) = (HalfSpace::new(210e3, 0.3).unwrap(), HalfSpace::new(70e3, 0.33).unwrap());
        let grid = sphere_grid(21, 1.0);
        let prof = Profile::Quadratic { a: 0.01, b: 0.01 };
        let step = Step::new(Drive::Load(100.0), TangentialDrive::Shift(0.0, 0.0));
        let path = Path::new(grid, steel, alu, prof.clone(), 0.0, true, vec![step]).unwrap();
        assert!(!path.influence().has_tangential() && !path.influence().has_coupling() && !path.is_coupled());
        let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
        assert_eq!(out[0].status, PathStatus::Solved, "{}", out[0].message);
        assert!(out[0].qx.iter().chain(&out[0].qy).all(|&q| q == 0.0) && out[0].outer_iterations == 1);
        let force = Step::new(Drive::Load(100.0), TangentialDrive::Force(1.0, 0.0));
        let err = Path::new(grid, steel, alu, prof, 0.0, true, vec![force]).unwrap_err().to_string();
        assert!(err.contains("steps") && err.contains("without friction"), "{err}");
    }

    /// A contact larger than the potential contact area is `ContactAtGridEdge`, not `Solved`.
    #[test]
    fn a_contact_cut_off_by_the_grid_says_so() {
        let steel = HalfSpace::new(210e3, 0.3).unwrap();
        // Hertz radius for P = 1e4, R = 50: about 1.25; the grid covers |x|, |y| ≤ 1.
        let grid = sphere_grid(15, 1.0);
        let step = Step::new(Drive::Load(1.0e4), TangentialDrive::Force(0.0, 0.0));
        let path =
            Path::new(grid, steel, steel, Profile::Quadratic { a: 0.01, b: 0.01 }, 0.3, true, vec![step]).unwrap();
        let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
        assert_eq!(out[0].status, PathStatus::ContactAtGridEdge, "{}", out[0].message);
        assert!(out[0].message.contains("enlarge"));
    }

    /// Spence's compression of a dissimilar pair (elastic ν = 0.25 on rigid: β = 1/3) with μ = 0.2 in 8 stages of
    /// growing load at zero tangential force: the coupled steps are checked against the coupled conditions
    /// themselves, evaluated with the DENSE influence matrices (built entry by entry from the kernel: a path
    /// independent of the FFT operators and of the alternation): gap `h − d + C_zz p + C_zx q_x + C_zy q_y` zero
    /// under pressure and ≥ 0 elsewhere, and each stage's slip `w + C_tt (q − q′) + C_tz (p − p′)` zero in stick and
    /// opposite to the shear at the bound in slip — to 1e-6 of the step's displacement scales. The shears are
    /// radial (the problem is axisymmetric: no net force, the rigid shift stays 0). Measured: 10 alternations per
    /// stage to 1e-9; the stick radius from the stick area grows with the contact, c/a 0.53–0.58 over stages 2–8
    /// (Spence's self-similarity; stage 1 is a jump from rest, not his incremental loading) — CONTACT's
    /// `spence35.inp` is the quantitative check.
    #[test]
    fn spence_compression_meets_the_coupled_conditions() {
        let (elastic, rigid) = (HalfSpace::new(1.0e3, 0.25).unwrap(), HalfSpace::new(f64::INFINITY, 0.25).unwrap());
        let grid = sphere_grid(31, 1.0);
        let loads = [100.0, 200.0, 300.0, 400.0, 500.0, 600.0, 700.0, 800.0];
        let steps = loads.iter().map(|&l| Step::new(Drive::Load(l), TangentialDrive::Force(0.0, 0.0))).collect();
        let mu = 0.2;
        let path = Path::new(grid, elastic, rigid, Profile::Quadratic { a: 0.5, b: 0.5 }, mu, true, steps).unwrap();
        assert!(path.is_coupled());
        let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
        let inf = path.influence();
        let d = |f: fn(&super::super::Coefficients) -> f64| inf.dense(f).unwrap();
        let (czz, czx, czy) = (d(|c| c.zz), d(|c| c.zx), d(|c| c.zy));
        let (cxx, cxy, cyy, cxz, cyz) = (d(|c| c.xx), d(|c| c.xy), d(|c| c.yy), d(|c| c.xz), d(|c| c.yz));
        let h = grid.sample(|x, y| 0.5 * (x * x + y * y));
        let n = grid.len();
        let (mut p0, mut qx0, mut qy0) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut shift0 = (0.0, 0.0);
        for (k, o) in out.iter().enumerate() {
            assert_eq!(o.status, PathStatus::Solved, "stage {k}: {}", o.message);
            assert!(o.outer_iterations >= 2, "a coupled step alternates");
            let (up, uqx, uqy) = (mat_vec(&czz, &o.pressure), mat_vec(&czx, &o.qx), mat_vec(&czy, &o.qy));
            let scale = up.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for i in 0..n {
                let g = h[i] - o.approach + up[i] + uqx[i] + uqy[i];
                let bad = if o.pressure[i] > 0.0 { g.abs() } else { (-g).max(0.0) };
                assert!(bad <= 1e-6 * scale, "stage {k} element {i}: gap {g:e}, p {}", o.pressure[i]);
            }
            let dqx: Vec<f64> = o.qx.iter().zip(&qx0).map(|(a, b)| a - b).collect();
            let dqy: Vec<f64> = o.qy.iter().zip(&qy0).map(|(a, b)| a - b).collect();
            let dp: Vec<f64> = o.pressure.iter().zip(&p0).map(|(a, b)| a - b).collect();
            let w = (o.shift.0 - shift0.0, o.shift.1 - shift0.1);
            let add3 = |a: Vec<f64>, b: Vec<f64>, c: Vec<f64>, w: f64| -> Vec<f64> {
                (0..n).map(|i| w + a[i] + b[i] + c[i]).collect()
            };
            let (pressure_x, pressure_y) = (mat_vec(&cxz, &dp), mat_vec(&cyz, &dp));
            let s_scale = pressure_x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let sx = add3(mat_vec(&cxx, &dqx), mat_vec(&cxy, &dqy), pressure_x, w.0);
            let sy = add3(mat_vec(&cxy, &dqx), mat_vec(&cyy, &dqy), pressure_y, w.1);
            let gmax = mu * o.pressure.iter().fold(0.0_f64, |m, &v| m.max(v));
            for i in 0..n {
                let s = sx[i].hypot(sy[i]);
                match o.state[i] {
                    ElementState::Stick => assert!(s <= 1e-6 * s_scale, "stage {k} element {i}: stick slips {s:e}"),
                    ElementState::Slip if s > 1e-6 * s_scale => {
                        let g = mu * o.pressure[i];
                        let err = (o.qx[i] + g * sx[i] / s).hypot(o.qy[i] + g * sy[i] / s);
                        assert!(err <= 1e-5 * gmax, "stage {k} element {i}: shear not opposite the slip, {err:e}");
                    }
                    _ => {}
                }
            }
            assert!(
                o.force.0.abs().max(o.force.1.abs()) <= 1e-9 * o.load
                    && o.shift.0.abs() <= 1e-9 * s_scale.max(1e-300) * 1e3
            );
            let stick_radius = (o.counts.1 as f64 * grid.area() / std::f64::consts::PI).sqrt();
            let contact_radius = (o.counts.0 as f64 * grid.area() / std::f64::consts::PI).sqrt();
            println!(
                "stage {k}: c/a {:.3} ({} stick of {} in contact), {} alternations",
                stick_radius / contact_radius,
                o.counts.1,
                o.counts.0,
                o.outer_iterations
            );
            shift0 = o.shift;
            p0 = o.pressure.clone();
            qx0 = o.qx.clone();
            qy0 = o.qy.clone();
        }
    }
}
