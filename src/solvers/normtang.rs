//! NORM-TANG: Kalker's split of the frictional contact problem (Kalker 1990 ch. 2; González & Abascal 2000, the
//! seed's ref. \[3\]) into a normal problem with the shear fixed (NORM) and a tangential problem with the pressure
//! fixed (TANG, a Tresca box |h| ≤ μf), alternated until the change of the tractions falls under a tolerance.
//!
//! - **NORM** (h fixed): `g = g₀ + R_N ρ + K_NN f + K_NT h ≥ 0 ⊥ f ≥ 0`; with the normal load prescribed the
//!   approach d_N is an unknown tied by Σf = P.
//! - **TANG** (f fixed): slip `s = R_T ρ + K_TN f + K_TT h`, `−μf ≤ h ≤ μf`, with s = 0 where |h| < μf, s ≤ 0 at
//!   h = μf, s ≥ 0 at h = −μf (friction opposes slip); with the tangential load prescribed the shift d_T is an
//!   unknown tied by Σh = Q, and |Q| ≥ μP is gross sliding (`infeasible`).
//!
//! Two inner solvers: **projected Gauss–Seidel** sweeps `x_i ← clamp(x_i − ω r_i / K_ii, lo_i, hi_i)` (ω the
//! relaxation; convergent for symmetric positive definite K, which a collocation flexibility is only nearly), and
//! **clarabel** on the sub-problems as QPs with the symmetric part of K followed by an active-set polish with the
//! nonsymmetric K ([`super::clarabel_qp`], `super::clarabel_box`). With PGS a prescribed load is met by a
//! safeguarded root-find on the rigid displacement (the resultant is monotone in it: Illinois regula falsi);
//! clarabel carries the load as an equality constraint whose multiplier is the rigid displacement.
//!
//! The split converges when the coupling is weak (β small, or `coupling = false`, where one NORM and one TANG
//! solve are exact); with strong coupling (ν → 0, high μ) it may not, and says so (`not_converged` with the
//! achieved change). A moment load is not supported by the split (use Lemke's loading formulation).

use super::clarabel_box::solve_box;
use super::clarabel_qp::{solve_frictionless, QpSettings};
use super::{settings_of, Entry, Facts, Figures, Solver, SolverId, Start, Termination, Validate, Work};
use crate::cancel::Cancel;
use crate::formulation::{ContactProblem, Dof, DofKind, Solution};
use faer::Mat;
use serde::{Deserialize, Serialize};

/// Slot of the shift in the split's rigid-motion arrays.
const MODE_SHIFT: usize = 0;
/// Slot of the approach.
const MODE_APPROACH: usize = 1;
/// Slot of the rotation.
const MODE_ROTATION: usize = 2;

/// The slot of a DOF (the creepage of steady rolling is the tangential DOF, in the shift's slot).
fn slot(kind: DofKind) -> usize {
    match kind {
        DofKind::Shift | DofKind::Creepage => MODE_SHIFT,
        DofKind::Approach => MODE_APPROACH,
        DofKind::Rotation => MODE_ROTATION,
    }
}

/// The contact problem split into its normal and tangential blocks, NORM-TANG's own view of it: nodal-force
/// matrices (row-major, and K_NN column-major too for the QP inner solver), rigid responses, and the drive in
/// dimensionless units. The tangential blocks are those of the slip (`D K_TT`, `D K_TN` and the DOFs' slip
/// responses, plus the slip operator's offset), so TANG solves Coulomb's law on the problem's own slip. The cross
/// blocks are zero when `coupling = false`; the tangential blocks are empty for a frictionless problem.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Split {
    /// Contact nodes.
    pub n: usize,
    /// Friction coefficient.
    pub mu: f64,
    /// Whether K_NT, K_TN are kept.
    pub coupling: bool,
    /// K_NN, row-major.
    pub knn_rows: Vec<f64>,
    /// K_NN, column-major.
    pub knn_cols: Vec<f64>,
    /// K_NT, row-major (empty without friction).
    pub knt_rows: Vec<f64>,
    /// D K_TN, row-major.
    pub ktn_rows: Vec<f64>,
    /// D K_TT, row-major.
    pub ktt_rows: Vec<f64>,
    /// The slip operator's offset c (zeros when it has none).
    pub slip_offset: Vec<f64>,
    /// Initial gaps.
    pub g0: Vec<f64>,
    /// Normal rigid responses per node (shift, approach, rotation slots).
    pub rn: Vec<[f64; 3]>,
    /// Slip responses per node (zeros without the tangential blocks).
    pub rt: Vec<[f64; 3]>,
    /// Prescribed rigid motion (load-driven entries 0).
    pub rigid_given: [f64; 3],
    /// Normal drive, dimensionless.
    pub normal: Dof,
    /// Tangential drive, dimensionless.
    pub tangential: Dof,
    /// A starting guess (f, h, rigid motion by slot): the problem's warm start, if any. A guess whose f or h is not
    /// n long is ignored (the cold start).
    pub start: Option<(Vec<f64>, Vec<f64>, [f64; 3])>,
    /// The caller's cancellation token, checked at every outer iteration and inner sweep.
    pub cancel: Cancel,
}

impl Split {
    /// The split view of a problem (frictionless or frictional; the caller has checked that NORM-TANG applies),
    /// starting from `warm` (a nearby solution in the problem's unknowns) when it has the problem's shape.
    pub fn from_problem(p: &ContactProblem, warm: Option<&Solution>) -> Split {
        let flex = p.flex;
        let n = flex.n();
        let mu = p.law.friction;
        let frictional = mu > 0.0;
        let coupling = p.law.coupling && frictional;
        let rows = |m: &Mat<f64>| {
            let mut v = Vec::with_capacity(n * n);
            for i in 0..n {
                for j in 0..n {
                    v.push(m[(i, j)]);
                }
            }
            v
        };
        let knn_rows = rows(&flex.k_nn);
        let mut knn_cols = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                knn_cols[i + j * n] = knn_rows[i * n + j];
            }
        }
        let tangential_rows = |m: &Option<Mat<f64>>| match (frictional, m) {
            (true, Some(m)) => rows(&p.slip.apply_mat(m)),
            _ => Vec::new(),
        };
        let knt_rows = if frictional { flex.k_nt.as_ref().map(&rows).unwrap_or_default() } else { Vec::new() };
        let (ktn_rows, ktt_rows) = (tangential_rows(&flex.k_tn), tangential_rows(&flex.k_tt));
        let mut rigid_given = [0.0; 3];
        let mut rn = vec![[0.0; 3]; n];
        let mut rt = vec![[0.0; 3]; n];
        let mut normal = Dof::Displacement(0.0);
        let mut tangential = Dof::Displacement(0.0);
        for d in &p.dofs {
            let k = slot(d.kind);
            if let Dof::Displacement(v) = d.drive {
                rigid_given[k] = v;
            }
            for i in 0..n {
                rn[i][k] = d.gap[i];
                if let Some(s) = &d.slip {
                    rt[i][k] = s[i];
                }
            }
            match d.kind {
                DofKind::Approach => normal = d.drive,
                // Without friction a zero tangential load is a free tangential DOF: nothing to solve.
                DofKind::Shift | DofKind::Creepage if frictional => tangential = d.drive,
                DofKind::Shift | DofKind::Creepage | DofKind::Rotation => {}
            }
        }
        Split {
            n,
            mu,
            coupling,
            knn_rows,
            knn_cols,
            knt_rows,
            ktn_rows,
            ktt_rows,
            slip_offset: p.slip.offset.clone().unwrap_or_else(|| vec![0.0; n]),
            g0: flex.g0.clone(),
            rn,
            rt,
            rigid_given,
            normal,
            tangential,
            start: warm.filter(|w| w.f.len() == n && w.rigid.len() == p.dofs.len()).map(|w| {
                let mut rigid = rigid_given;
                for (d, v) in p.dofs.iter().zip(&w.rigid) {
                    if d.is_load() {
                        rigid[slot(d.kind)] = *v;
                    }
                }
                (w.f.clone(), w.h.clone().filter(|h| h.len() == n).unwrap_or_else(|| vec![0.0; n]), rigid)
            }),
            cancel: Cancel::never(),
        }
    }
}

/// Settings of NORM-TANG with projected Gauss–Seidel inner sweeps (`[solvers.pgs]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PgsSettings {
    /// Relative tolerance on the change of (f, h) between outer iterations (inner sweeps and load root-finds are
    /// driven to a tenth of it). Default 1e-10.
    pub tolerance: f64,
    /// Maximum Gauss–Seidel sweeps per inner solve. Default 100 000.
    pub max_sweeps: usize,
    /// Maximum NORM-TANG outer iterations. Default 200.
    pub max_outer: usize,
    /// Over-relaxation ω in (0, 2). Default 1.
    pub relaxation: f64,
}

impl Default for PgsSettings {
    fn default() -> Self {
        PgsSettings { tolerance: 1e-10, max_sweeps: 100_000, max_outer: 200, relaxation: 1.0 }
    }
}

impl Validate for PgsSettings {
    fn tolerance(&self) -> Option<f64> {
        Some(self.tolerance)
    }

    fn validate(&self) -> Result<(), (&'static str, String)> {
        super::check_tolerance("tolerance", self.tolerance)?;
        super::check_count("max_sweeps", self.max_sweeps)?;
        super::check_count("max_outer", self.max_outer)?;
        if !(self.relaxation > 0.0 && self.relaxation < 2.0) {
            return Err(("relaxation", format!("must lie in (0, 2) (got {})", self.relaxation)));
        }
        Ok(())
    }
}

/// Settings of NORM-TANG with clarabel QPs as inner solver (`[solvers.normtang_qp]`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NormTangQpSettings {
    /// Relative tolerance on the change of (f, h) between outer iterations. Default 1e-10.
    pub tolerance: f64,
    /// Maximum outer iterations. Default 200.
    pub max_outer: usize,
    /// The QP solver's settings.
    pub qp: QpSettings,
}

impl Default for NormTangQpSettings {
    fn default() -> Self {
        NormTangQpSettings { tolerance: 1e-10, max_outer: 200, qp: QpSettings::default() }
    }
}

impl Validate for NormTangQpSettings {
    fn tolerance(&self) -> Option<f64> {
        Some(self.tolerance)
    }

    fn validate(&self) -> Result<(), (&'static str, String)> {
        super::check_tolerance("tolerance", self.tolerance)?;
        super::check_count("max_outer", self.max_outer)?;
        super::check_tolerance("qp.tolerance", self.qp.tolerance)?;
        super::check_count("qp.max_iter", self.qp.max_iter as usize)
    }
}

/// The inner solver.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub enum Inner {
    /// Projected Gauss–Seidel.
    Pgs(PgsSettings),
    /// clarabel QPs.
    Qp(NormTangQpSettings),
}

/// Result of NORM-TANG.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Outcome {
    /// Normal nodal forces (dimensionless).
    pub f: Vec<f64>,
    /// Tangential nodal forces (None for a frictionless scene).
    pub h: Option<Vec<f64>>,
    /// Rigid motion (shift, approach, rotation).
    pub rigid: [f64; 3],
    /// Outcome.
    pub status: Termination,
    /// Detail.
    pub message: String,
    /// Total Gauss–Seidel sweeps (PGS inner).
    pub sweeps: usize,
    /// Outer NORM-TANG iterations.
    pub outer: usize,
    /// Total interior-point iterations (QP inner).
    pub qp_iterations: u32,
}

/// Why an inner solve failed.
struct Failure(Termination, String);

/// Projected Gauss–Seidel on `r = q + K x`, `lo ≤ x ≤ hi` (box LCP). `k` row-major. Returns sweeps used and
/// whether the largest update fell under `tol · max|x|`.
#[allow(clippy::too_many_arguments)]
pub fn pgs_box(
    k: &[f64],
    n: usize,
    q: &[f64],
    lo: &[f64],
    hi: &[f64],
    x: &mut [f64],
    omega: f64,
    tol: f64,
    max_sweeps: usize,
    cancel: &Cancel,
) -> (usize, bool) {
    for i in 0..n {
        x[i] = x[i].clamp(lo[i], hi[i]);
    }
    for sweep in 1..=max_sweeps {
        let mut change = 0.0_f64;
        let mut scale = 0.0_f64;
        for i in 0..n {
            let row = &k[i * n..(i + 1) * n];
            let r = q[i] + row.iter().zip(x.iter()).map(|(a, b)| a * b).sum::<f64>();
            let new = (x[i] - omega * r / row[i]).clamp(lo[i], hi[i]);
            change = change.max((new - x[i]).abs());
            x[i] = new;
            scale = scale.max(new.abs());
        }
        if change <= tol * scale || scale == 0.0 && change == 0.0 {
            return (sweep, true);
        }
        if cancel.is_cancelled() {
            return (sweep, false);
        }
    }
    (max_sweeps, false)
}

/// Gauss–Seidel needs a positive diagonal; a collocation flexibility on a very coarse or distorted mesh can lack
/// one (it is only nearly symmetric positive definite).
fn check_diagonal(k: &[f64], n: usize, which: &str) -> Result<(), Failure> {
    match (0..n).find(|&i| k[i * n + i].is_nan() || k[i * n + i] <= 0.0) {
        Some(i) => Err(Failure(
            Termination::NumericalError,
            format!(
                "the {which} flexibility has a non-positive diagonal entry at contact node {i} ({:e}): it is not \
                 positive definite, so projected Gauss–Seidel cannot run (refine the mesh, or use lemke)",
                k[i * n + i]
            ),
        )),
        None => Ok(()),
    }
}

/// Find d with S(d) = target for a monotone S (increasing when `increasing`), starting at `d0` with a first
/// step `step`: bracket by doubling, then Illinois regula falsi. `eval` returns S(d) or a failure.
fn root<F: FnMut(f64) -> Result<f64, Failure>>(
    mut eval: F,
    target: f64,
    d0: f64,
    step: f64,
    increasing: bool,
    tol: f64,
) -> Result<f64, Failure> {
    let sgn = if increasing { 1.0 } else { -1.0 };
    let g = |s: f64| sgn * (s - target);
    let mut eval = move |d: f64| -> Result<f64, Failure> {
        let v = eval(d)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Failure(
                Termination::NumericalError,
                format!("the resultant is not finite at rigid displacement {d:e}"),
            ))
        }
    };
    let (mut a, mut ga) = (d0, g(eval(d0)?));
    if ga.abs() <= tol {
        return Ok(a);
    }
    let dir = if ga < 0.0 { 1.0 } else { -1.0 };
    let mut h = step.abs().max(f64::MIN_POSITIVE);
    let (mut b, mut gb);
    let mut tries = 0;
    loop {
        b = a + dir * h;
        gb = g(eval(b)?);
        if gb.abs() <= tol {
            return Ok(b);
        }
        if gb.signum() != ga.signum() {
            break;
        }
        a = b;
        ga = gb;
        h *= 2.0;
        tries += 1;
        if tries > 200 {
            return Err(Failure(Termination::NotConverged, "could not bracket the prescribed load".into()));
        }
    }
    let mut side = 0;
    for _ in 0..200 {
        let c = (a * gb - b * ga) / (gb - ga);
        let gc = g(eval(c)?);
        if gc.abs() <= tol || (b - a).abs() <= 1e-15 * (a.abs() + b.abs()) {
            return Ok(c);
        }
        if gc.signum() == gb.signum() {
            b = c;
            gb = gc;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            ga = gc;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    Err(Failure(Termination::NotConverged, "the load root-find did not converge".into()))
}

/// Solve the split problem.
pub fn solve(p: &Split, inner: &Inner) -> Outcome {
    let n = p.n;
    let (mut f, mut h, mut rigid) = match &p.start {
        Some((f, h, r)) if f.len() == n && h.len() == n => (f.clone(), h.clone(), *r),
        _ => (vec![0.0; n], vec![0.0; n], p.rigid_given),
    };
    let mut sweeps = 0usize;
    let mut qp_iterations = 0u32;
    let (tolerance, max_outer) = match inner {
        Inner::Pgs(s) => (s.tolerance, s.max_outer),
        Inner::Qp(s) => (s.tolerance, s.max_outer),
    };
    let frictional = p.mu > 0.0;
    let mut outer = 0;
    let mut change = f64::INFINITY;
    let result = loop {
        outer += 1;
        if p.cancel.is_cancelled() {
            break Err(Failure(Termination::NotConverged, format!("cancelled at outer iteration {outer}")));
        }
        let (f_prev, h_prev) = (f.clone(), h.clone());
        if let Err(Failure(st, msg)) = norm(p, inner, &h, &mut f, &mut rigid, &mut sweeps, &mut qp_iterations) {
            break Err(Failure(st, format!("NORM, outer iteration {outer}: {msg}")));
        }
        if frictional {
            if let Err(Failure(st, msg)) = tang(p, inner, &f, &mut h, &mut rigid, &mut sweeps, &mut qp_iterations) {
                break Err(Failure(st, format!("TANG, outer iteration {outer}: {msg}")));
            }
        }
        let scale = f.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
        change =
            f.iter().zip(&f_prev).chain(h.iter().zip(&h_prev)).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs())) / scale;
        if !frictional || change <= tolerance || f.iter().all(|&v| v == 0.0) {
            break Ok(());
        }
        if outer >= max_outer {
            break Err(Failure(
                Termination::NotConverged,
                format!(
                    "NORM-TANG did not converge in {max_outer} outer iterations: last change {change:.3e} > {tolerance:.0e} \
                     (strong normal–tangential coupling?)"
                ),
            ));
        }
    };
    let (status, message) = match result {
        Ok(()) => (
            Termination::Solved,
            format!(
                "converged in {outer} outer iteration(s), last change {:.3e}",
                if change.is_finite() { change } else { 0.0 }
            ),
        ),
        Err(Failure(st, msg)) => (st, msg),
    };
    Outcome { f, h: frictional.then_some(h), rigid, status, message, sweeps, outer, qp_iterations }
}

/// The normal step of NORM-TANG: the normal forces `f` (and, under a normal load, the approach) for the shear
/// forces `h`.
fn norm(
    p: &Split,
    inner: &Inner,
    h: &[f64],
    f: &mut Vec<f64>,
    rigid: &mut [f64; 3],
    sweeps: &mut usize,
    qp_iterations: &mut u32,
) -> Result<(), Failure> {
    let n = p.n;
    // q without the approach term.
    let q0: Vec<f64> = (0..n)
        .map(|i| {
            p.g0[i]
                + p.rn[i][MODE_SHIFT] * rigid[MODE_SHIFT]
                + p.rn[i][MODE_ROTATION] * rigid[MODE_ROTATION]
                + if p.coupling { (0..n).map(|j| p.knt_rows[i * n + j] * h[j]).sum::<f64>() } else { 0.0 }
        })
        .collect();
    let c: Vec<f64> = (0..n).map(|i| p.rn[i][MODE_APPROACH]).collect();
    let lo = vec![0.0; n];
    let hi = vec![f64::INFINITY; n];
    match inner {
        Inner::Pgs(s) => {
            check_diagonal(&p.knn_rows, n, "normal")?;
            let mut solve_at = |d: f64, f: &mut Vec<f64>| -> Result<f64, Failure> {
                let q: Vec<f64> = (0..n).map(|i| q0[i] + c[i] * d).collect();
                let (sw, ok) =
                    pgs_box(&p.knn_rows, n, &q, &lo, &hi, f, s.relaxation, 0.1 * s.tolerance, s.max_sweeps, &p.cancel);
                *sweeps += sw;
                if !ok {
                    return Err(pgs_not_converged(s.max_sweeps, *sweeps));
                }
                Ok(f.iter().sum())
            };
            match p.normal {
                Dof::Displacement(_) => {
                    solve_at(rigid[MODE_APPROACH], f)?;
                }
                Dof::Load(pl) => {
                    let kmax = (0..n).map(|i| p.knn_rows[i * n + i]).fold(0.0_f64, f64::max);
                    // First touch: the smallest approach that closes a gap.
                    let first = (0..n).map(|i| q0[i] / -c[i]).fold(f64::INFINITY, f64::min);
                    let d0 = if f.iter().any(|&v| v > 0.0) { rigid[MODE_APPROACH] } else { first };
                    let d = root(|d| solve_at(d, f), pl, d0, pl * kmax, true, 0.1 * s.tolerance * pl)?;
                    solve_at(d, f)?;
                    rigid[MODE_APPROACH] = d;
                }
            }
        }
        Inner::Qp(s) => {
            let q: Vec<f64> = match p.normal {
                Dof::Displacement(_) => (0..n).map(|i| q0[i] + c[i] * rigid[MODE_APPROACH]).collect(),
                Dof::Load(_) => q0.clone(),
            };
            let ones = vec![1.0; n];
            let load = match p.normal {
                Dof::Load(pl) => Some((ones.as_slice(), pl)),
                Dof::Displacement(_) => None,
            };
            let out = solve_frictionless(&p.knn_cols, n, &q, load, &s.qp);
            *qp_iterations += out.iterations;
            if !out.status.is_solved() {
                return Err(Failure(Termination::from(&out.status), format!("clarabel: {}", out.status)));
            }
            *f = out.f;
            if let Some(d) = out.approach {
                rigid[MODE_APPROACH] = d;
            }
        }
    }
    Ok(())
}

/// The failure of an inner PGS solve that used up `max_sweeps`; `sweeps` counts all sweeps so far.
fn pgs_not_converged(max_sweeps: usize, sweeps: usize) -> Failure {
    Failure(
        Termination::NotConverged,
        format!(
            "projected Gauss–Seidel did not converge in {max_sweeps} sweeps of one inner solve (max_sweeps; {sweeps} \
             sweeps in all, counting the inner solves before it)"
        ),
    )
}

/// The tangential sub-problem on the nodes in contact (those with a positive friction bound μ·f): the box LCP
/// `r = q0 + c·d + K h`, `lo ≤ h ≤ hi`, with `d` the rigid shift.
struct TangSub {
    /// Indices of the nodes in contact, into the full node list.
    act: Vec<usize>,
    /// K_tt restricted to the nodes in contact, row-major, `act.len()²`.
    ktt_rows: Vec<f64>,
    /// Lower bounds −μ f.
    lo: Vec<f64>,
    /// Upper bounds μ f.
    hi: Vec<f64>,
    /// Slip without the shift term.
    q0: Vec<f64>,
    /// Shift column of the slip.
    c: Vec<f64>,
}

impl TangSub {
    /// The sub-problem for normal forces `f` and the other rigid modes fixed at `rigid`.
    fn new(p: &Split, f: &[f64], rigid: &[f64; 3]) -> TangSub {
        let (n, mu) = (p.n, p.mu);
        let q0: Vec<f64> = (0..n)
            .map(|i| {
                p.rt[i][MODE_APPROACH] * rigid[MODE_APPROACH]
                    + p.rt[i][MODE_ROTATION] * rigid[MODE_ROTATION]
                    + if p.coupling { (0..n).map(|j| p.ktn_rows[i * n + j] * f[j]).sum::<f64>() } else { 0.0 }
                    + p.slip_offset[i]
            })
            .collect();
        let c: Vec<f64> = (0..n).map(|i| p.rt[i][MODE_SHIFT]).collect();
        let lo: Vec<f64> = f.iter().map(|&v| -mu * v.max(0.0)).collect();
        let hi: Vec<f64> = f.iter().map(|&v| mu * v.max(0.0)).collect();
        // Nodes out of contact carry no shear: drop them from the sub-problem.
        let act: Vec<usize> = (0..n).filter(|&i| hi[i] > 0.0).collect();
        let mut ktt_rows = Vec::with_capacity(act.len() * act.len());
        for &i in &act {
            for &j in &act {
                ktt_rows.push(p.ktt_rows[i * n + j]);
            }
        }
        let pick = |v: &[f64]| act.iter().map(|&i| v[i]).collect::<Vec<f64>>();
        let (lo, hi, q0, c) = (pick(&lo), pick(&hi), pick(&q0), pick(&c));
        TangSub { act, ktt_rows, lo, hi, q0, c }
    }
}

/// The tangential step of NORM-TANG: the shear forces `h` (and, under a tangential load, the shift) for the
/// normal forces `f`. Fails with `Infeasible` at gross sliding (|Q| ≥ μP).
fn tang(
    p: &Split,
    inner: &Inner,
    f: &[f64],
    h: &mut [f64],
    rigid: &mut [f64; 3],
    sweeps: &mut usize,
    qp_iterations: &mut u32,
) -> Result<(), Failure> {
    let mu = p.mu;
    let psum: f64 = f.iter().sum();
    if let Dof::Load(ql) = p.tangential {
        if ql.abs() >= mu * psum {
            return Err(Failure(
                Termination::Infeasible,
                format!(
                    "gross sliding: the tangential load |Q| exceeds the friction limit μP (|Q|/(μP) = {:.6})",
                    ql.abs() / (mu * psum)
                ),
            ));
        }
    }
    let sub = TangSub::new(p, f, rigid);
    // Nodes out of contact (μ f = 0) carry no shear.
    for (i, hi) in h.iter_mut().enumerate() {
        if mu * f[i].max(0.0) == 0.0 {
            *hi = 0.0;
        }
    }
    let mut x: Vec<f64> = sub.act.iter().map(|&i| h[i]).collect();
    match inner {
        Inner::Pgs(s) => tang_pgs(p, s, &sub, psum, &mut x, rigid, sweeps)?,
        Inner::Qp(s) => tang_qp(p, s, &sub, &mut x, rigid, qp_iterations)?,
    }
    for (a, &i) in sub.act.iter().enumerate() {
        h[i] = x[a];
    }
    Ok(())
}

/// The tangential sub-problem by projected Gauss–Seidel; under a tangential load the shift is found by a root
/// search on the resultant (normal load `psum`).
fn tang_pgs(
    p: &Split,
    s: &PgsSettings,
    sub: &TangSub,
    psum: f64,
    x: &mut Vec<f64>,
    rigid: &mut [f64; 3],
    sweeps: &mut usize,
) -> Result<(), Failure> {
    let na = sub.act.len();
    check_diagonal(&sub.ktt_rows, na, "tangential")?;
    let mut solve_at = |d: f64, x: &mut Vec<f64>| -> Result<f64, Failure> {
        let q: Vec<f64> = (0..na).map(|i| sub.q0[i] + sub.c[i] * d).collect();
        let (sw, ok) = pgs_box(
            &sub.ktt_rows,
            na,
            &q,
            &sub.lo,
            &sub.hi,
            x,
            s.relaxation,
            0.1 * s.tolerance,
            s.max_sweeps,
            &p.cancel,
        );
        *sweeps += sw;
        if !ok {
            return Err(pgs_not_converged(s.max_sweeps, *sweeps));
        }
        Ok(x.iter().sum())
    };
    match p.tangential {
        Dof::Displacement(_) => {
            solve_at(rigid[MODE_SHIFT], x)?;
        }
        Dof::Load(ql) => {
            let mu = p.mu;
            let kmax = (0..na).map(|i| sub.ktt_rows[i * na + i]).fold(0.0_f64, f64::max);
            let step = (mu * psum * kmax).max(f64::MIN_POSITIVE);
            let tol = 0.1 * s.tolerance * mu * psum;
            let d = root(|d| solve_at(d, x), ql, rigid[MODE_SHIFT], step, false, tol)?;
            solve_at(d, x)?;
            rigid[MODE_SHIFT] = d;
        }
    }
    Ok(())
}

/// The tangential sub-problem as a box QP by clarabel; under a tangential load the shift is the multiplier of
/// the resultant constraint.
fn tang_qp(
    p: &Split,
    s: &NormTangQpSettings,
    sub: &TangSub,
    x: &mut Vec<f64>,
    rigid: &mut [f64; 3],
    qp_iterations: &mut u32,
) -> Result<(), Failure> {
    let na = sub.act.len();
    let q: Vec<f64> = match p.tangential {
        Dof::Displacement(_) => (0..na).map(|i| sub.q0[i] + sub.c[i] * rigid[MODE_SHIFT]).collect(),
        Dof::Load(_) => sub.q0.clone(),
    };
    let mut cols = vec![0.0; na * na];
    for i in 0..na {
        for j in 0..na {
            cols[i + j * na] = sub.ktt_rows[i * na + j];
        }
    }
    let ones = vec![1.0; na];
    let eq = match p.tangential {
        Dof::Load(ql) => Some((ones.as_slice(), ql)),
        Dof::Displacement(_) => None,
    };
    let out = solve_box(&cols, na, &q, &sub.lo, &sub.hi, eq, &s.qp);
    *qp_iterations += out.iterations;
    if !out.status.is_solved() {
        return Err(Failure(Termination::from(&out.status), format!("clarabel (TANG): {}", out.status)));
    }
    *x = out.x;
    if let Some(nu) = out.nu {
        // Gradient K h + q + ν·1 with the shift column ≈ 1: ν is the shift.
        rigid[MODE_SHIFT] = nu;
    }
    Ok(())
}

/// NORM-TANG with projected Gauss–Seidel inner sweeps, as a contact solver.
pub struct Pgs {
    /// Its settings.
    pub settings: PgsSettings,
}

/// NORM-TANG with clarabel QPs as inner solver, as a contact solver.
pub struct NormTangQp {
    /// Its settings.
    pub settings: NormTangQpSettings,
}

/// NORM-TANG with PGS: its identity.
pub const PGS_ID: SolverId = SolverId::new("pgs");

/// NORM-TANG with clarabel QPs: its identity.
pub const NORMTANG_QP_ID: SolverId = SolverId::new("normtang_qp");

/// Why NORM-TANG does not apply to a prescribed moment.
const NO_MOMENT: &str = "the NORM-TANG split does not carry a prescribed moment (use lemke)";

/// Registry entry of NORM-TANG with PGS.
pub const PGS_ENTRY: Entry = Entry::new::<PgsSettings>(
    "pgs",
    "NORM-TANG split (Kalker; González & Abascal) with projected Gauss–Seidel sweeps; no moment load",
    true,
    &["sweeps", "outer"],
    |_, s| Box::new(Pgs { settings: settings_of::<PgsSettings>(s).copied().unwrap_or_default() }),
    // Up to m sweeps of m² each on the dense rows.
    |m| (5e-9 * m * m * m, 24.0 * m * m),
);

/// Registry entry of NORM-TANG with clarabel QPs.
pub const NORMTANG_QP_ENTRY: Entry = Entry::new::<NormTangQpSettings>(
    "normtang_qp",
    "NORM-TANG with clarabel QPs as the inner solver; no moment load",
    true,
    &["iterations", "outer"],
    |_, s| Box::new(NormTangQp { settings: settings_of::<NormTangQpSettings>(s).cloned().unwrap_or_default() }),
    super::clarabel::cost,
);

/// Whether NORM-TANG applies: not with a prescribed moment, not at the sliding limit.
/// What the NORM-TANG split (both inner solvers) cannot take.
fn admits(f: &Facts) -> Result<(), String> {
    if f.moment_load {
        Err(NO_MOMENT.into())
    } else if f.sliding_limit {
        Err("at the sliding limit |Q| = μP the problem is solved as full slip by lemke".into())
    } else {
        Ok(())
    }
}

/// Run NORM-TANG from a start and put its answer in the one solution shape.
fn run(p: &ContactProblem, inner: &Inner, start: Start) -> super::Outcome {
    let mut split = Split::from_problem(p, start.solution_for(p));
    split.cancel = start.cancel;
    let out = solve(&split, inner);
    let work = match inner {
        Inner::Pgs(_) => Work::of(&[("sweeps", out.sweeps as u64), ("outer", out.outer as u64)]),
        Inner::Qp(_) => Work::of(&[("iterations", out.qp_iterations as u64), ("outer", out.outer as u64)]),
    };
    let rigid = p.dofs.iter().map(|d| out.rigid[slot(d.kind)]).collect();
    super::Outcome {
        solution: Some(Solution { f: out.f, h: out.h, rigid, tangential_known: true }),
        status: out.status,
        message: out.message,
        work,
        figures: Figures::default(),
        state: None,
    }
}

impl Solver for Pgs {
    fn id(&self) -> SolverId {
        PGS_ID
    }
    fn admits(&self, f: &Facts) -> Result<(), String> {
        admits(f)
    }
    fn tolerance(&self) -> Option<f64> {
        Some(self.settings.tolerance)
    }
    fn solve_from(&self, p: &ContactProblem, start: Start) -> super::Outcome {
        run(p, &Inner::Pgs(self.settings), start)
    }
}

impl Solver for NormTangQp {
    fn id(&self) -> SolverId {
        NORMTANG_QP_ID
    }
    fn admits(&self, f: &Facts) -> Result<(), String> {
        if f.steady_rolling && f.friction {
            return Err("the steady-rolling tangential operator D K_TT is far from symmetric, and the QP inner \
                        solver symmetrises it; use pgs or lemke"
                .into());
        }
        admits(f)
    }
    fn tolerance(&self) -> Option<f64> {
        Some(self.settings.tolerance)
    }
    fn solve_from(&self, p: &ContactProblem, start: Start) -> super::Outcome {
        run(p, &Inner::Qp(self.settings.clone()), start)
    }
}
