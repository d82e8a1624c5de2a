//! Static admissibility of a load-driven contact problem, decided exactly by a small linear program.
//!
//! Whatever the elasticity, a static solution has nodal forces on the candidate zone with
//!
//! ```text
//!   f_i ≥ 0,   |h_i| ≤ μ f_i,   row_nᵀ f + row_tᵀ h = L_d   for every load-driven DOF d
//! ```
//!
//! (the equilibrium rows of [`crate::formulation::RigidDof`]: 1ᵀf = P, 1ᵀh = Q, xᵀf − yᵀh = M). So when this
//! LP has no solution, no static state exists, and Farkas' lemma gives the proof: multipliers δ_d, one per
//! equilibrium row — a *virtual rigid motion* of the support (approach, shift, rotation) — such that every node's
//! virtual motion (a_i, b_i) = Σ_d δ_d (row_n,d(i), row_t,d(i)) lies in the dual friction cone a_i ≥ μ|b_i| (every
//! admissible contact force does non-negative work on it) while the prescribed loads do negative work, Σ_d L_d δ_d
//! < 0. clarabel finds the certificate; [`admissibility`] re-checks it in its own arithmetic
//! ([`crate::tolerances::FARKAS_MARGIN`]) before calling the problem infeasible.
//!
//! The LP is a necessary condition only: when it is feasible, statically admissible tractions exist, but whether
//! the elastic problem has a solution is a question for the LCP.

use crate::formulation::{ContactProblem, Dof, DofKind, RigidDof};
use crate::tolerances::FARKAS_MARGIN;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus,
    SupportedConeT::{NonnegativeConeT, ZeroConeT},
};

/// A verified Farkas certificate: the virtual rigid motion that every admissible contact force resists and the
/// prescribed loads drive.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Certificate {
    /// The virtual motion per load-driven DOF (dimensionless, normalised to max |δ| = 1), in the problem's DOF
    /// order.
    pub motion: Vec<(DofKind, f64)>,
    /// The loads' virtual work Σ L_d δ_d in user's units (negative).
    pub work: f64,
    /// The smallest dual-cone margin min_i (a_i − μ|b_i|) / max_i(|a_i|, |b_i|) (≥ −FARKAS_MARGIN).
    pub cone_margin: f64,
}

/// The verdict of the LP.
#[derive(Debug, Clone, PartialEq)]
pub enum Admissibility {
    /// Statically admissible contact forces exist (or nothing is load-driven: a displacement-driven contact always
    /// has a static state).
    Feasible,
    /// No contact forces on the candidate zone carry the loads; the certificate proves it.
    Infeasible(Certificate),
    /// The LP could not decide (clarabel failed, or its certificate did not verify); the text says why.
    Undecided(String),
}

/// The load-driven DOFs of a problem with their equilibrium rows (the user's view: every prescribed resultant,
/// including the tangential one of a normal-only problem, which its nodal forces still have to carry).
fn load_rows<'p>(p: &'p ContactProblem) -> Vec<&'p RigidDof> {
    p.dofs.iter().filter(|d| d.is_load()).collect()
}

/// Decide whether any contact forces on the candidate zone carry the problem's prescribed loads.
pub fn admissibility(p: &ContactProblem) -> Admissibility {
    let rows = load_rows(p);
    let n = p.n();
    let mu = p.law.friction;
    let load = |d: &RigidDof| match d.drive {
        Dof::Load(v) => v,
        Dof::Displacement(_) => 0.0,
    };
    // Row scales (largest coefficient) and the force scale s: x̂ = x / s, b̂_d = b_d / (r_d s).
    let rscale: Vec<f64> = rows
        .iter()
        .map(|d| (0..n).fold(0.0_f64, |m, i| m.max(d.row_n[i].abs()).max(d.row_t[i].abs())).max(f64::MIN_POSITIVE))
        .collect();
    let s = rows.iter().zip(&rscale).fold(0.0_f64, |m, (d, r)| m.max(load(d).abs() / r));
    if rows.is_empty() || s == 0.0 {
        return Admissibility::Feasible;
    }
    if n == 0 {
        return verify(p, &rows, &rows.iter().map(|d| -load(d).signum()).collect::<Vec<_>>())
            .map_or_else(|| Admissibility::Undecided("no candidate nodes".into()), Admissibility::Infeasible);
    }
    let frictional = mu > 0.0;
    let nvar = if frictional { 2 * n } else { n };
    let meq = rows.len();
    let mineq = if frictional { 2 * n } else { n };
    // Columns: f_i (equilibrium rows, then −μ in both cone rows of node i), h_i (equilibrium rows, then ±1).
    let (mut colptr, mut rowval, mut nzval) = (vec![0], Vec::new(), Vec::new());
    for j in 0..nvar {
        let (node, tangential) = (j % n, j >= n);
        for (k, d) in rows.iter().enumerate() {
            let v = if tangential { d.row_t[node] } else { d.row_n[node] };
            if v != 0.0 {
                rowval.push(k);
                nzval.push(v / rscale[k]);
            }
        }
        if frictional {
            rowval.extend([meq + 2 * node, meq + 2 * node + 1]);
            nzval.extend(if tangential { [1.0, -1.0] } else { [-mu, -mu] });
        } else {
            rowval.push(meq + node);
            nzval.push(-1.0);
        }
        colptr.push(rowval.len());
    }
    let a = CscMatrix::new(meq + mineq, nvar, colptr, rowval, nzval);
    let mut b = vec![0.0; meq + mineq];
    for (k, d) in rows.iter().enumerate() {
        b[k] = load(d) / (rscale[k] * s);
    }
    let zero = CscMatrix::new(nvar, nvar, vec![0; nvar + 1], Vec::new(), Vec::new());
    let c = vec![0.0; nvar];
    let cones = [ZeroConeT(meq), NonnegativeConeT(mineq)];
    let settings = match DefaultSettingsBuilder::default().verbose(false).build() {
        Ok(st) => st,
        Err(e) => return Admissibility::Undecided(format!("clarabel settings: {e}")),
    };
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut solver = DefaultSolver::new(&zero, &c, &a, &b, &cones, settings).map_err(|e| format!("{e}"))?;
        solver.solve();
        Ok::<_, String>((solver.solution.status, solver.solution.z.clone()))
    }));
    let (status, z) = match run {
        Ok(Ok(r)) => r,
        Ok(Err(m)) => return Admissibility::Undecided(format!("clarabel setup: {m}")),
        Err(_) => return Admissibility::Undecided("clarabel panicked".into()),
    };
    match status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => Admissibility::Feasible,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            let y: Vec<f64> = (0..meq).map(|k| z[k] / rscale[k]).collect();
            // The certificate's sign convention is checked, not assumed: verify both orientations.
            let neg: Vec<f64> = y.iter().map(|v| -v).collect();
            match verify(p, &rows, &y).or_else(|| verify(p, &rows, &neg)) {
                Some(cert) => Admissibility::Infeasible(cert),
                None => Admissibility::Undecided(format!(
                    "clarabel reports the LP {status:?} but its certificate does not verify in the dual friction cone"
                )),
            }
        }
        other => Admissibility::Undecided(format!("clarabel ended with {other:?}")),
    }
}

/// Check a candidate Farkas certificate δ (one multiplier per load row) in our own arithmetic; `Some` when it
/// proves infeasibility.
fn verify(p: &ContactProblem, rows: &[&RigidDof], delta: &[f64]) -> Option<Certificate> {
    let n = p.n();
    let mu = p.law.friction;
    let dmax = delta.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if dmax == 0.0 || !dmax.is_finite() {
        return None;
    }
    let delta: Vec<f64> = delta.iter().map(|v| v / dmax).collect();
    let mut scale = 0.0_f64;
    let mut margin = f64::INFINITY;
    let virtual_motion: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let a: f64 = rows.iter().zip(&delta).map(|(d, y)| y * d.row_n[i]).sum();
            let b: f64 = rows.iter().zip(&delta).map(|(d, y)| y * d.row_t[i]).sum();
            (a, b)
        })
        .collect();
    for &(a, b) in &virtual_motion {
        scale = scale.max(a.abs()).max(b.abs());
    }
    for &(a, b) in &virtual_motion {
        // Without friction only the normal component matters (h = 0).
        let m = if mu > 0.0 { a - mu * b.abs() } else { a };
        margin = margin.min(m / scale.max(f64::MIN_POSITIVE));
    }
    if n == 0 {
        margin = 0.0;
    }
    let sc = p.flex.scales;
    let user_load = |d: &RigidDof| match d.user {
        Dof::Load(v) => v,
        Dof::Displacement(_) => 0.0,
    };
    let load = |d: &RigidDof| match d.drive {
        Dof::Load(v) => v,
        Dof::Displacement(_) => 0.0,
    };
    let work: f64 = rows.iter().zip(&delta).map(|(d, y)| load(d) * y).sum();
    let work_scale: f64 = rows.iter().zip(&delta).map(|(d, y)| (load(d) * y).abs()).sum();
    if margin < -FARKAS_MARGIN || work >= -FARKAS_MARGIN * work_scale {
        return None;
    }
    // The virtual work in user's units: a rotation's δ is dimensionless (radians), a length's scales with L0.
    let user_work: f64 = rows
        .iter()
        .zip(&delta)
        .map(|(d, y)| user_load(d) * y * if d.kind == DofKind::Rotation { 1.0 } else { sc.length })
        .sum();
    Some(Certificate {
        motion: rows.iter().zip(&delta).map(|(d, y)| (d.kind, *y)).collect(),
        work: user_work,
        cone_margin: margin,
    })
}

/// A sentence saying what a certificate means for the problem, with the prescribed loads and, when P, Q and M are
/// all prescribed, where the moment about the axle would need the pressure centre (user's units).
pub fn explain(p: &ContactProblem, cert: &Certificate) -> String {
    let name = |k: DofKind| match k {
        DofKind::Approach => "approach",
        DofKind::Shift => "shift",
        DofKind::Rotation => "rotation",
        DofKind::Creepage => "creepage",
    };
    let motion: Vec<String> = cert.motion.iter().map(|(k, v)| format!("δ{} = {v:+.3}", name(*k))).collect();
    let mut text = format!(
        "no contact forces on the candidate zone (p ≥ 0, |q| ≤ μp) carry the prescribed loads: the virtual rigid \
         motion {} of the support is resisted by every admissible contact force while the loads drive it (their \
         virtual work {:.3e} < 0; Farkas' certificate of the equilibrium LP, verified)",
        motion.join(", "),
        cert.work
    );
    if let Some(centre) = required_centre(p) {
        let sc = p.flex.scales;
        let (lo, hi) = zone(p);
        text.push_str(&format!(
            "; the moment about the axle needs the pressure centre at x ≈ (M − RQ)/P = {:.4e}, and the candidate zone \
             spans [{:.4e}, {:.4e}]",
            centre,
            lo * sc.length,
            hi * sc.length
        ));
    }
    text
}

/// The candidate zone's node range in x (dimensionless).
fn zone(p: &ContactProblem) -> (f64, f64) {
    let x = &p.flex.x;
    (x.iter().cloned().fold(f64::INFINITY, f64::min), x.iter().cloned().fold(f64::NEG_INFINITY, f64::max))
}

/// Where the moment equilibrium puts the pressure centre when P, Q and M are all prescribed: x_c = (M − R̄Q)/P with
/// R̄ the mean depth −y of the candidate nodes (user's units); `None` otherwise.
pub fn required_centre(p: &ContactProblem) -> Option<f64> {
    let (Dof::Load(pl), Dof::Load(q), Dof::Load(m)) = (p.drive.normal, p.drive.tangential, p.drive.rotational) else {
        return None;
    };
    let n = p.n();
    if pl <= 0.0 || n == 0 {
        return None;
    }
    let depth = -p.flex.y.iter().sum::<f64>() / n as f64 * p.flex.scales.length;
    Some((m - depth * q) / pl)
}
