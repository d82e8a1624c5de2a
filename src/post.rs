//! Post-processing: per-node results, resultants, contact extent and the solver-independent residuals.
//!
//! Every quantity here is recomputed from the flexibility and the solver's nodal forces and rigid motion, never
//! taken from the solver's own bookkeeping: the gap is `g = g₀ + K_NN f + K_NT h + Σ r_m ρ_m`, the slip comes from
//! the problem's slip operator ([`crate::formulation::slip`]), and the residuals measure the *physical* conditions
//! (no penetration, no tension, complementarity of gap and pressure, Coulomb's law on the slip, equilibrium with the
//! drive loads). Values are returned in the user's units.
//!
//! Node states: `separated` when the pressure is zero; without friction `contact` (no friction law, so neither
//! stick nor slip); with friction `slip` when |q| = μp, else `stick`.

use crate::error::ArgumentError;
use crate::flexibility::ModeKind;
use crate::formulation::{ContactProblem, Dof, Solution};
use crate::tolerances::{SEPARATED_PRESSURE, STICK_MARGIN};
use serde::{Deserialize, Serialize};

/// State of a contact node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum NodeState {
    /// In contact, |q| < μp.
    Stick,
    /// In contact, |q| = μp (μ > 0).
    Slip,
    /// In contact without friction (μ = 0): the contact law has no stick or slip.
    Contact,
    /// Not in contact: p = 0.
    Separated,
}

impl NodeState {
    /// Its name as written in results (`stick`, `slip`, `contact`, `separated`).
    pub fn name(self) -> &'static str {
        match self {
            NodeState::Stick => "stick",
            NodeState::Slip => "slip",
            NodeState::Contact => "contact",
            NodeState::Separated => "separated",
        }
    }
}

/// Results at one contact node (user's units).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct NodeResult {
    /// x of the node (undeformed).
    pub x: f64,
    /// y of the node (undeformed).
    pub y: f64,
    /// Pressure p = t_y ≥ 0 on the wheel.
    pub pressure: f64,
    /// Shear q = t_x on the wheel (0 without friction).
    pub shear: f64,
    /// Displacement u_x including the rigid motion (null when the tangential problem was not built).
    pub u_x: Option<f64>,
    /// Displacement u_y including the rigid motion.
    pub u_y: f64,
    /// Gap g = g₀ + u_y to the flat.
    pub gap: f64,
    /// Slip of the wheel relative to the flat (u_x at a contact node; null when separated or not computed).
    pub slip: Option<f64>,
    /// Stick / slip / contact (frictionless) / separated.
    pub state: NodeState,
    /// Slip velocity s_t* (seed eq. 12), null unless the scene has `[rolling]`.
    pub slip_velocity: Option<f64>,
}

/// Resultants of the contact tractions on the wheel.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Resultants {
    /// P = Σ f_y (force per unit thickness).
    pub normal: f64,
    /// Q = Σ f_x.
    pub tangential: f64,
    /// M = Σ (x f_y − y f_x) about the wheel centre.
    pub moment: f64,
}

/// The support's rigid motion.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[non_exhaustive]
pub struct RigidBody {
    /// Approach d_N (length).
    pub normal: f64,
    /// Tangential shift d_T (length); null when indeterminate (at the sliding limit |Q| = μP).
    pub tangential: Option<f64>,
    /// Rotation φ (radians, counter-clockwise).
    pub rotation: f64,
}

/// Contact extent and key figures.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct ContactSummary {
    /// Smallest x of a loaded node (null if none).
    pub x_min: Option<f64>,
    /// Largest x of a loaded node.
    pub x_max: Option<f64>,
    /// (x_max − x_min)/2 from loaded nodes (brackets a within ±h/2).
    pub half_width: Option<f64>,
    /// Largest nodal pressure.
    pub peak_pressure: f64,
    /// Pressure scale of the relative residuals and comparisons: the peak pressure, floored by E·ℓ/L0 (ℓ the rigid
    /// gap scale), so that a run without contact is compared on a meaningful scale.
    pub pressure_scale: f64,
    /// a from the elliptic fit p² = p0²(1 − x²/a²) (meaningful for Hertz-like pressure; null if the fit fails).
    pub fit_half_width: Option<f64>,
    /// p0 from the same fit.
    pub fit_peak_pressure: Option<f64>,
    /// Smallest x of a sticking node.
    pub stick_x_min: Option<f64>,
    /// Largest x of a sticking node.
    pub stick_x_max: Option<f64>,
    /// Number of loaded nodes.
    pub nodes_contact: usize,
    /// Number of sticking nodes.
    pub nodes_stick: usize,
    /// Number of slipping nodes (0 without friction, where contact nodes neither stick nor slip).
    pub nodes_slip: usize,
}

/// The rolling figures of a run: the creepage and the counts of Coulomb-law inconsistencies of the slip velocities.
fn rolling_result(
    problem: &ContactProblem,
    sol: &Solution,
    r: RollingPost,
    nodes: &[NodeResult],
    slip_scale: f64,
) -> RollingResult {
    use crate::formulation::DofKind;
    let mu = problem.law.friction;
    let (mode, creepage, prescribed) = match r {
        RollingPost::Seed { creepage, .. } => (crate::scene::RollingMode::Seed, Some(creepage), true),
        RollingPost::Transient { creepage, .. } => (crate::scene::RollingMode::Transient, Some(creepage), true),
        RollingPost::Steady => {
            let d = problem.dofs.iter().find(|d| d.kind == DofKind::Creepage);
            let prescribed = d.is_some_and(|d| !d.is_load());
            let known = sol.tangential_known || prescribed;
            (crate::scene::RollingMode::Steady, known.then(|| problem.rigid_value(sol, DofKind::Creepage)), prescribed)
        }
    };
    let scale = match r {
        RollingPost::Steady => slip_scale,
        RollingPost::Seed { creepage, .. } | RollingPost::Transient { creepage, .. } => {
            let smax = nodes.iter().filter_map(|n| n.slip_velocity).fold(0.0_f64, |m, v| m.max(v.abs()));
            slip_scale.max(creepage.abs()).max(smax)
        }
    };
    let margin = crate::tolerances::STATE_MARGIN * scale;
    let pscale = nodes.iter().fold(0.0_f64, |m, n| m.max(n.pressure));
    let mut moving = 0;
    let mut not_opposed = 0;
    for n in nodes {
        let Some(s) = n.slip_velocity else { continue };
        match n.state {
            NodeState::Stick if s.abs() > margin => moving += 1,
            NodeState::Slip if mu > 0.0 && s * n.shear > margin * crate::tolerances::STATE_MARGIN * pscale => {
                not_opposed += 1
            }
            _ => {}
        }
    }
    RollingResult {
        mode,
        creepage,
        creepage_prescribed: prescribed,
        stick_nodes_moving: moving,
        slip_nodes_not_opposed: not_opposed,
        slip_velocity_scale: scale,
    }
}

/// Solver-independent residuals, relative (see [`evaluate`]); null where a condition does not apply.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Residuals {
    /// max |p_i g_i| / (p_max ℓ).
    pub complementarity: f64,
    /// max(0, −min g) / ℓ.
    pub penetration: f64,
    /// max(0, −min p) / p_max.
    pub tension: f64,
    /// max(0, |q| − μp) / (μ p_max); null without friction.
    pub friction: Option<f64>,
    /// Worst |resultant − load| / |load| over the load-driven DOFs; null when displacement-driven.
    pub equilibrium: Option<f64>,
}

impl Residuals {
    /// Every residual, those that do not apply as 0: complementarity, penetration, tension, friction, equilibrium.
    pub fn parts(&self) -> [f64; 5] {
        [
            self.complementarity,
            self.penetration,
            self.tension,
            self.friction.unwrap_or(0.0),
            self.equilibrium.unwrap_or(0.0),
        ]
    }

    /// Largest of the residuals that apply; NaN if any is NaN (`f64::max` drops a NaN, so a NaN residual would
    /// otherwise pass every bound as 0: fuzz target `scene`, `fuzz/regressions/lemke-nan-residual-max-load.toml`).
    pub fn max(&self) -> f64 {
        let parts = self.parts();
        if parts.iter().any(|v| v.is_nan()) {
            return f64::NAN;
        }
        parts.into_iter().fold(0.0, f64::max)
    }
}

/// Everything post-processing derives from one solution.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Evaluation {
    /// Rolling figures (when the scene rolls).
    pub rolling: Option<RollingResult>,
    /// The total tangential displacement u_T of the contact nodes, rigid motion included (dimensionless; when the
    /// tangential problem is built): a load path carries it to the next step.
    pub u_t: Option<Vec<f64>>,
    /// The problem's slip s at the contact nodes (dimensionless; the slip increment of a load step).
    pub slip: Option<Vec<f64>>,
    /// Per contact node.
    pub nodes: Vec<NodeResult>,
    /// Resultants.
    pub resultants: Resultants,
    /// Rigid motion.
    pub rigid_body: RigidBody,
    /// Contact figures.
    pub contact: ContactSummary,
    /// Residuals.
    pub residuals: Residuals,
}

impl Evaluation {
    /// The first value of the evaluated solution that is not finite (a nodal pressure, shear, gap, displacement,
    /// slip or slip velocity, a resultant or a rigid-body value), named with its node, or `None` when all are
    /// finite. A solution with one is refused whatever its residuals say: they are computed from these values,
    /// and comparisons with NaN drop it (a clarabel run with NaN pressures on a wheel of modulus 2.2e-308 had all
    /// residuals 0; found by the `scene` fuzz target).
    pub fn first_non_finite(&self) -> Option<String> {
        let bad = |v: f64| !v.is_finite();
        for (k, n) in self.nodes.iter().enumerate() {
            let values = [
                ("pressure", Some(n.pressure)),
                ("shear", Some(n.shear)),
                ("gap", Some(n.gap)),
                ("u_x", n.u_x),
                ("u_y", Some(n.u_y)),
                ("slip", n.slip),
                ("slip velocity", n.slip_velocity),
            ];
            if let Some((name, Some(v))) = values.into_iter().find(|(_, v)| v.is_some_and(bad)) {
                return Some(format!("the {name} at contact node {k} (x = {:.4e}) is {v}", n.x));
            }
        }
        let (r, b) = (&self.resultants, &self.rigid_body);
        let values = [
            ("normal resultant", Some(r.normal)),
            ("tangential resultant", Some(r.tangential)),
            ("moment", Some(r.moment)),
            ("normal rigid-body displacement", Some(b.normal)),
            ("tangential rigid-body displacement", b.tangential),
            ("rigid-body rotation", Some(b.rotation)),
        ];
        values.into_iter().find_map(|(name, v)| v.filter(|v| bad(*v)).map(|v| format!("the {name} is {v}")))
    }
}

/// The rolling a scene asks for, as post-processing sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum RollingPost {
    /// The seed's formulation: a static solution, then the slip velocity of eq. 12 with this creepage and rolling
    /// direction (the same upwind operator as steady rolling, [`crate::formulation::slip::upwind`]).
    Seed {
        /// Creepage ξ.
        creepage: f64,
        /// Rolling direction ±1.
        direction: i32,
    },
    /// Steady rolling: the slip velocity is the problem's own slip.
    Steady,
    /// A step of transient rolling: the slip velocity is the slip increment over the rolled distance (dimensionless,
    /// lengths / L0); with `roll = 0` (a step that does not roll) there is none.
    Transient {
        /// Creepage ξ.
        creepage: f64,
        /// Rolled distance of the step, dimensionless.
        roll: f64,
    },
}

/// What rolling adds to a run: the creepage, and how far the slip velocities are from Coulomb's law.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[non_exhaustive]
pub struct RollingResult {
    /// `steady` or `seed`.
    pub mode: crate::scene::RollingMode,
    /// The creepage ξ: prescribed, or computed from the prescribed tangential load (null when indeterminate, at the
    /// sliding limit).
    pub creepage: Option<f64>,
    /// Whether the creepage was prescribed (else the tangential load was, and ξ computed).
    pub creepage_prescribed: bool,
    /// Sticking nodes whose slip velocity is not zero (|s| above [`crate::tolerances::STATE_MARGIN`] of the slip
    /// velocity scale): an inconsistency of Coulomb's law, expected in the seed's formulation.
    pub stick_nodes_moving: usize,
    /// Slipping nodes whose shear does not oppose their slip velocity (q·s > 0 beyond the same margin).
    pub slip_nodes_not_opposed: usize,
    /// The slip velocity scale these counts are relative to: max(|ξ|, max |s|, μ w/R) with w the candidate zone's
    /// half-width (the creepage at which a contact of that size saturates).
    pub slip_velocity_scale: f64,
}

/// Evaluate a solution of `problem` (with the seed's eq. 12 slip velocity when `rolling` is given).
///
/// Residuals (relative, solver-independent): ℓ is the largest rigid gap `|g₀ + Σ r_m ρ_m|` over the candidate zone
/// (the gap the contact has to close or keep open), and `p_max` below is floored by E·ℓ/L0; `complementarity` is
/// max |p g| / (p_max ℓ); `friction` the worst of the Coulomb cone violation max(0, |q| − μp)/(μ p_max), the slip of
/// sticking material |s|(μp − |q|)/(ℓ μ p_max) and slip along the friction force max(0, s q)/(ℓ μ p_max) (the slip
/// terms only where the tangential rigid motion is known); `equilibrium` the worst relative error of a prescribed
/// resultant (Q relative to max(|Q|, μP), M to max(|M|, P R)).
///
/// A solution of another shape than the problem's ([`Solution::fits`]: a solver's, or a plug-in's, answer is not
/// trusted to have it) is refused, naming it.
pub fn evaluate(
    problem: &ContactProblem,
    sol: &Solution,
    rolling: Option<RollingPost>,
) -> Result<Evaluation, ArgumentError> {
    if !sol.fits(problem) {
        return Err(ArgumentError::new(
            "evaluate",
            "sol",
            format!(
                "has {} normal forces, {} tangential and {} rigid values; the problem has {} contact nodes and {} \
                 rigid DOFs",
                sol.f.len(),
                sol.h.as_ref().map_or(0, Vec::len),
                sol.rigid.len(),
                problem.n(),
                problem.dofs.len()
            ),
        ));
    }
    let flex = problem.flex;
    let n = flex.n();
    let (l0, e) = (flex.scales.length, flex.scales.modulus);
    let mu = problem.law.friction;
    let h = sol.h.as_deref();
    let shift_known = sol.tangential_known;
    let k = Kinematics::of(problem, sol);
    let residuals = residuals(problem, sol, &k);
    let pmax = k.p.iter().fold(0.0_f64, |a, &v| a.max(v));
    let cut = SEPARATED_PRESSURE * pmax;
    let in_contact: Vec<bool> = (0..n).map(|i| pmax > 0.0 && k.p[i] > cut).collect();
    let state = |i: usize| {
        if !in_contact[i] {
            NodeState::Separated
        } else if mu == 0.0 {
            NodeState::Contact
        } else if h.is_some() && k.q[i].abs() < mu * k.p[i] * (1.0 - STICK_MARGIN) {
            NodeState::Stick
        } else {
            NodeState::Slip
        }
    };
    // Slip velocities: the problem's own slip in steady rolling, eq. 12 applied to the static solution for the seed.
    let sv: Option<Vec<f64>> = match (rolling, &k.ux) {
        (Some(RollingPost::Steady), _) => k.slip.clone(),
        (Some(RollingPost::Transient { roll, .. }), _) if roll > 0.0 => {
            k.slip.as_ref().map(|s| s.iter().map(|v| v / roll).collect())
        }
        (Some(RollingPost::Seed { creepage, direction }), Some(ux)) => {
            let d = crate::formulation::slip::upwind(&flex.x, direction);
            Some(d.apply(ux).into_iter().map(|v| creepage + v).collect())
        }
        _ => None,
    };
    let steady = matches!(rolling, Some(RollingPost::Steady));
    let nodes: Vec<NodeResult> = (0..n)
        .map(|i| NodeResult {
            x: flex.x[i] * l0,
            y: flex.y[i] * l0,
            pressure: k.p[i] * e,
            shear: k.q[i] * e,
            u_x: k.ux.as_ref().filter(|_| shift_known).map(|u| u[i] * l0),
            u_y: k.uy[i] * l0,
            gap: k.gap[i] * l0,
            slip: k.slip.as_ref().filter(|_| shift_known && h.is_some() && in_contact[i] && !steady).map(|s| s[i] * l0),
            state: state(i),
            slip_velocity: sv.as_ref().filter(|_| in_contact[i]).map(|v| v[i]),
        })
        .collect();
    let contact = summary(&nodes, pmax * e, pmax.max(k.ell) * e);
    let rolling = rolling.map(|r| rolling_result(problem, sol, r, &nodes, k.slip_scale));
    let rigid = |kind: ModeKind| problem.rigid_value(sol, kind);
    Ok(Evaluation {
        u_t: k.ux.clone(),
        slip: k.slip.clone(),
        rolling,
        nodes,
        resultants: resultants(problem, sol),
        rigid_body: RigidBody {
            normal: rigid(ModeKind::Approach) * l0,
            tangential: shift_known.then_some(rigid(ModeKind::Shift) * l0),
            rotation: rigid(ModeKind::Rotation),
        },
        contact,
        residuals,
    })
}

/// Tractions, displacements, gaps and slips of a solution at the contact nodes (dimensionless).
struct Kinematics {
    /// Pressures p = f / w.
    p: Vec<f64>,
    /// Shears q = h / w (zeros without the tangential problem).
    q: Vec<f64>,
    /// u_y, rigid motion included.
    uy: Vec<f64>,
    /// u_x, rigid motion included (when the tangential blocks exist).
    ux: Option<Vec<f64>>,
    /// The slip s = D u_x + c of the problem's slip operator, plus the creepage in steady rolling.
    slip: Option<Vec<f64>>,
    /// Gaps g = g₀ + u_y.
    gap: Vec<f64>,
    /// The gap scale ℓ: the largest rigid gap |g₀ + Σ r_m ρ_m| (floored at the smallest positive number).
    ell: f64,
    /// The scale of the slip: ℓ for the static slip (a displacement); for the steady slip velocity
    /// max(|ξ|, max |s|, μ w/R), w the candidate zone's half-width (the creepage that saturates such a contact).
    slip_scale: f64,
}

impl Kinematics {
    fn of(problem: &ContactProblem, sol: &Solution) -> Kinematics {
        let flex = problem.flex;
        let n = flex.n();
        let coupling = problem.law.coupling;
        let (f, h) = (&sol.f, sol.h.as_deref());
        let p: Vec<f64> = (0..n).map(|i| f[i] / flex.weights[i]).collect();
        let q: Vec<f64> = match h {
            Some(h) => (0..n).map(|i| h[i] / flex.weights[i]).collect(),
            None => vec![0.0; n],
        };
        // K v by columns (K is column-major: contiguous passes; a row-by-row sum strides through memory).
        let matvec = |m: &faer::Mat<f64>, v: &[f64]| -> Vec<f64> {
            let y = m * faer::ColRef::from_slice(v);
            y.iter().copied().collect()
        };
        let add = |a: &mut Vec<f64>, b: Vec<f64>| a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
        let rig = |i: usize, tangential: bool| -> f64 {
            flex.modes
                .iter()
                .map(|m| {
                    let r = if tangential { m.tangential.as_ref().map_or(0.0, |t| t[i]) } else { m.normal[i] };
                    r * problem.rigid_value(sol, m.kind)
                })
                .sum()
        };
        let mut uy = matvec(&flex.k_nn, f);
        if let (Some(nt), Some(h), true) = (&flex.k_nt, h, coupling) {
            add(&mut uy, matvec(nt, h));
        }
        uy.iter_mut().enumerate().for_each(|(i, v)| *v += rig(i, false));
        let ux: Option<Vec<f64>> = flex.k_tt.as_ref().map(|tt| {
            let mut u = match h {
                Some(h) => matvec(tt, h),
                None => vec![0.0; n],
            };
            if let (Some(tn), true) = (&flex.k_tn, coupling) {
                add(&mut u, matvec(tn, f));
            }
            u.iter_mut().enumerate().for_each(|(i, v)| *v += rig(i, true));
            u
        });
        let creepage = problem.rigid_value(sol, crate::formulation::DofKind::Creepage);
        let slip: Option<Vec<f64>> = ux.as_ref().map(|u| {
            let mut s = problem.slip.slip(u);
            if problem.slip.is_steady() {
                s.iter_mut().for_each(|v| *v += creepage);
            }
            s
        });
        let gap: Vec<f64> = (0..n).map(|i| flex.g0[i] + uy[i]).collect();
        let ell =
            (0..n).map(|i| flex.g0[i] + rig(i, false)).fold(0.0_f64, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE);
        let slip_scale = if problem.slip.is_steady() {
            // The creepage at which a contact of the candidate zone's half-width w saturates: μ w / R.
            let w = 0.5 * (flex.x.last().copied().unwrap_or(0.0) - flex.x.first().copied().unwrap_or(0.0));
            // Over the loaded nodes: a separated node's slip velocity means nothing (the leading-edge row of D).
            let smax = slip
                .as_ref()
                .map_or(0.0, |s| s.iter().zip(f).filter(|(_, f)| **f > 0.0).fold(0.0_f64, |m, (v, _)| m.max(v.abs())));
            creepage.abs().max(smax).max(problem.law.friction * w / 0.5) // R = 1/2 in units of L0
        } else {
            ell
        }
        .max(f64::MIN_POSITIVE);
        Kinematics { p, q, uy, ux, slip, gap, ell, slip_scale }
    }
}

/// The resultants of a solution's tractions (user's units).
fn resultants(problem: &ContactProblem, sol: &Solution) -> Resultants {
    let flex = problem.flex;
    let (f, h) = (&sol.f, sol.h.as_deref());
    let sc = flex.scales;
    let (fsum, hsum, msum) = if flex.normals.is_some() {
        // Per-node frames (two finite bodies): the global force on the wheel, F = f N + h T at each node.
        let (mut fx, mut fy, mut m) = (0.0, 0.0, 0.0);
        for i in 0..flex.n() {
            let (nv, tv) = flex.frame(i);
            let hi = h.map(|h| h[i]).unwrap_or(0.0);
            let (gx, gy) = (f[i] * nv[0] + hi * tv[0], f[i] * nv[1] + hi * tv[1]);
            fx += gx;
            fy += gy;
            m += flex.x[i] * gy - flex.y[i] * gx;
        }
        (fy, fx, m)
    } else {
        let fsum: f64 = f.iter().sum();
        let hsum: f64 = h.map(|h| h.iter().sum()).unwrap_or(0.0);
        let msum: f64 = (0..flex.n()).map(|i| flex.x[i] * f[i] - flex.y[i] * h.map(|h| h[i]).unwrap_or(0.0)).sum();
        (fsum, hsum, msum)
    };
    let (e, l0) = (sc.modulus, sc.length);
    Resultants { normal: fsum * e * l0, tangential: hsum * e * l0, moment: msum * e * l0 * l0 }
}

/// The solver-independent residuals of a solution (see [`evaluate`]).
fn residuals(problem: &ContactProblem, sol: &Solution, k: &Kinematics) -> Residuals {
    let n = problem.n();
    let mu = problem.law.friction;
    let (p, q, ell, sl) = (&k.p, &k.q, k.ell, k.slip_scale);
    let pmax = p.iter().fold(0.0_f64, |a, &v| a.max(v));
    // Pressure scale of the residuals: the peak pressure, floored by the stress a strain ℓ/L0 would cause (E = 1
    // in these units), so a solution without contact is not divided by zero.
    let pref = pmax.max(ell);
    let complementarity = (0..n).map(|i| (p[i] * k.gap[i]).abs()).fold(0.0, f64::max) / (pref * ell);
    let penetration = (-k.gap.iter().cloned().fold(f64::INFINITY, f64::min)).max(0.0) / ell;
    let tension = (-p.iter().cloned().fold(f64::INFINITY, f64::min)).max(0.0) / pref;
    let friction = sol.h.as_ref().map(|_| {
        let fref = (mu * pref).max(f64::MIN_POSITIVE);
        let mut worst = 0.0_f64;
        for i in 0..n {
            worst = worst.max((q[i].abs() - mu * p[i]).max(0.0) / fref);
            if let (Some(s), true) = (&k.slip, sol.tangential_known) {
                let s = s[i];
                worst = worst.max(s.abs() * (mu * p[i] - q[i].abs()).max(0.0) / (sl * fref));
                worst = worst.max((s * q[i]).max(0.0) / (sl * fref));
            }
        }
        worst
    });
    let r = resultants(problem, sol);
    let (pr, qr, mr) = (r.normal, r.tangential, r.moment);
    let mut eq: Option<f64> = None;
    let mut worse = |r: f64| eq = Some(eq.unwrap_or(0.0).max(r));
    let drive = &problem.drive;
    if let Dof::Load(pl) = drive.normal {
        worse((pr - pl).abs() / pl.abs());
    }
    if let (Dof::Load(ql), Some(_)) = (drive.tangential, &sol.h) {
        worse((qr - ql).abs() / ql.abs().max(mu * pr.abs()).max(f64::MIN_POSITIVE));
    }
    if let Dof::Load(ml) = drive.rotational {
        worse((mr - ml).abs() / ml.abs().max(pr.abs() * problem.flex.scales.radius()).max(f64::MIN_POSITIVE));
    }
    Residuals { complementarity, penetration, tension, friction, equilibrium: eq }
}

/// Contact extent, peak and fitted Hertz figures, stick zone, from the nodal results (user's units).
fn summary(nodes: &[NodeResult], peak_pressure: f64, pressure_scale: f64) -> ContactSummary {
    let loaded: Vec<&NodeResult> = nodes.iter().filter(|nd| nd.state != NodeState::Separated).collect();
    let sticking: Vec<&NodeResult> = nodes.iter().filter(|nd| nd.state == NodeState::Stick).collect();
    let x_min = loaded.first().map(|nd| nd.x);
    let x_max = loaded.last().map(|nd| nd.x);
    let xs: Vec<f64> = nodes.iter().map(|nd| nd.x).collect();
    let ps: Vec<f64> =
        nodes.iter().map(|nd| if nd.state == NodeState::Separated { 0.0 } else { nd.pressure }).collect();
    let fit = crate::theory::Hertz2D::fit(&xs, &ps).map(|h| (h.a, h.p0));
    ContactSummary {
        x_min,
        x_max,
        half_width: x_min.zip(x_max).map(|(a, b)| 0.5 * (b - a)),
        peak_pressure,
        pressure_scale,
        fit_half_width: fit.map(|f| f.0),
        fit_peak_pressure: fit.map(|f| f.1),
        stick_x_min: sticking.first().map(|nd| nd.x),
        stick_x_max: sticking.last().map(|nd| nd.x),
        nodes_contact: loaded.len(),
        nodes_stick: sticking.len(),
        nodes_slip: nodes.iter().filter(|nd| nd.state == NodeState::Slip).count(),
    }
}

/// The stick zone's edges (left, right), each midway between the outermost sticking node and its slipping or
/// separated neighbour (user's units); `None` when nothing sticks.
pub fn stick_edges(nodes: &[NodeResult]) -> Option<(f64, f64)> {
    let first = nodes.iter().position(|n| n.state == NodeState::Stick)?;
    let last = nodes.iter().rposition(|n| n.state == NodeState::Stick)?;
    let left = if first > 0 { 0.5 * (nodes[first].x + nodes[first - 1].x) } else { nodes[first].x };
    let right = if last + 1 < nodes.len() { 0.5 * (nodes[last].x + nodes[last + 1].x) } else { nodes[last].x };
    Some((left, right))
}
