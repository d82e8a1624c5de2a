//! Post-processing: per-node results, resultants, contact extent and the solver-independent residuals.
//!
//! Every quantity here is recomputed from the flexibility and the solver's nodal forces and rigid motion, never
//! taken from the solver's own bookkeeping: the gap is `g = g₀ + F_NN p + R_N ρ`, the residuals measure the
//! *physical* conditions (no penetration, no tension, complementarity of gap and pressure, equilibrium with the
//! drive loads). Values are returned in the user's units.
//!
//! Node states: `separated` when the pressure is zero, else `slip` when |q| = μp (always the case without
//! friction, where q = μp = 0: the node slides freely), else `stick`.

use crate::condense::{Flexibility, Model};
use crate::formulation::{MODE_APPROACH, MODE_ROTATION, MODE_SHIFT};
use crate::hertz;
use crate::scene::{Dof, Scene};
use serde::Serialize;

/// Relative pressure below which a node counts as separated (of the peak pressure).
pub const SEPARATED_PRESSURE: f64 = 1e-9;

/// State of a contact node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum NodeState {
    /// In contact, |q| < μp.
    Stick,
    /// In contact, |q| = μp (every contact node when μ = 0).
    Slip,
    /// Not in contact: p = 0.
    Separated,
}

/// Results at one contact node (user's units).
#[derive(Debug, Clone, Serialize)]
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
    /// Slip of the wheel relative to the flat (u_x; null when not computed).
    pub slip: Option<f64>,
    /// Stick / slip / separated.
    pub state: NodeState,
    /// Slip velocity s_t* (seed eq. 12), null unless the scene has `[rolling]`.
    pub slip_velocity: Option<f64>,
}

/// Resultants of the contact tractions on the wheel.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Resultants {
    /// P = Σ f_y (force per unit thickness).
    pub normal: f64,
    /// Q = Σ f_x.
    pub tangential: f64,
    /// M = Σ (x f_y − y f_x) about the wheel centre.
    pub moment: f64,
}

/// The support's rigid motion.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct RigidBody {
    /// Approach d_N (length).
    pub normal: f64,
    /// Tangential shift d_T (length).
    pub tangential: f64,
    /// Rotation φ (radians, counter-clockwise).
    pub rotation: f64,
}

/// Contact extent and key figures.
#[derive(Debug, Clone, Serialize)]
pub struct ContactSummary {
    /// Smallest x of a loaded node (null if none).
    pub x_min: Option<f64>,
    /// Largest x of a loaded node.
    pub x_max: Option<f64>,
    /// (x_max − x_min)/2 from loaded nodes (brackets a within ±h/2).
    pub half_width: Option<f64>,
    /// Largest nodal pressure.
    pub peak_pressure: f64,
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
    /// Number of slipping nodes.
    pub nodes_slip: usize,
}

/// Solver-independent residuals, relative (see [`evaluate`]); null where a condition does not apply.
#[derive(Debug, Clone, Copy, Serialize)]
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
    /// Largest of the residuals that apply.
    pub fn max(&self) -> f64 {
        [
            self.complementarity,
            self.penetration,
            self.tension,
            self.friction.unwrap_or(0.0),
            self.equilibrium.unwrap_or(0.0),
        ]
        .into_iter()
        .fold(0.0, f64::max)
    }
}

/// Everything post-processing derives from one solution.
#[derive(Debug, Clone)]
pub struct Evaluation {
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

/// Evaluate a frictionless solution: `f` are the dimensionless nodal normal forces, `rigid` the dimensionless rigid
/// motion (shift, approach, rotation). The reference gap ℓ of the residuals is the largest rigid gap
/// `|g₀ + R_N ρ|` over the candidate zone: the gap the contact has to close or keep open.
pub fn evaluate_frictionless(
    scene: &Scene,
    model: &Model,
    flex: &Flexibility,
    f: &[f64],
    rigid: [f64; 3],
) -> Evaluation {
    let n = flex.n();
    let (l0, e) = (model.length, model.modulus);
    let p: Vec<f64> = (0..n).map(|i| f[i] / flex.weights[i]).collect();
    let rig_gap: Vec<f64> =
        (0..n).map(|i| flex.g0[i] + (0..3).map(|m| flex.rigid_n[(i, m)] * rigid[m]).sum::<f64>()).collect();
    let uy: Vec<f64> = (0..n)
        .map(|i| {
            (0..n).map(|j| flex.nn[(i, j)] * p[j]).sum::<f64>()
                + (0..3).map(|m| flex.rigid_n[(i, m)] * rigid[m]).sum::<f64>()
        })
        .collect();
    let gap: Vec<f64> = (0..n).map(|i| flex.g0[i] + uy[i]).collect();
    let pmax = p.iter().fold(0.0_f64, |a, &v| a.max(v));
    let ell = rig_gap.iter().fold(0.0_f64, |a, &v| a.max(v.abs())).max(f64::MIN_POSITIVE);
    let pref = pmax.max(f64::MIN_POSITIVE);
    let complementarity = (0..n).map(|i| (p[i] * gap[i]).abs()).fold(0.0, f64::max) / (pref * ell);
    let penetration = (-gap.iter().cloned().fold(f64::INFINITY, f64::min)).max(0.0) / ell;
    let tension = (-p.iter().cloned().fold(f64::INFINITY, f64::min)).max(0.0) / pref;
    let fsum: f64 = f.iter().sum();
    let msum: f64 = (0..n).map(|i| flex.x[i] * f[i]).sum();
    let mut eq: Option<f64> = None;
    if let Dof::Load(pl) = scene.drive.normal() {
        let r = (fsum * e * l0 - pl).abs() / pl.abs();
        eq = Some(eq.unwrap_or(0.0).max(r));
    }
    if let Dof::Load(ml) = scene.drive.rotational() {
        let m = msum * e * l0 * l0;
        // Relative to |M|, or to P·R when the prescribed moment is zero.
        let scale = ml.abs().max((fsum * e * l0).abs() * scene.wheel.radius).max(f64::MIN_POSITIVE);
        let r = (m - ml).abs() / scale;
        eq = Some(eq.unwrap_or(0.0).max(r));
    }
    let residuals = Residuals { complementarity, penetration, tension, friction: None, equilibrium: eq };

    let cut = SEPARATED_PRESSURE * pmax;
    let nodes: Vec<NodeResult> = (0..n)
        .map(|i| NodeResult {
            x: flex.x[i] * l0,
            y: flex.y[i] * l0,
            pressure: p[i] * e,
            shear: 0.0,
            u_x: None,
            u_y: uy[i] * l0,
            gap: gap[i] * l0,
            slip: None,
            state: if p[i] > cut && pmax > 0.0 { NodeState::Slip } else { NodeState::Separated },
            slip_velocity: None,
        })
        .collect();
    let loaded: Vec<&NodeResult> = nodes.iter().filter(|nd| nd.state != NodeState::Separated).collect();
    let x_min = loaded.first().map(|nd| nd.x);
    let x_max = loaded.last().map(|nd| nd.x);
    let xs: Vec<f64> = nodes.iter().map(|nd| nd.x).collect();
    let ps: Vec<f64> =
        nodes.iter().map(|nd| if nd.state == NodeState::Separated { 0.0 } else { nd.pressure }).collect();
    let fit = hertz::fit_ellipse(&xs, &ps);
    let contact = ContactSummary {
        x_min,
        x_max,
        half_width: x_min.zip(x_max).map(|(a, b)| 0.5 * (b - a)),
        peak_pressure: pmax * e,
        fit_half_width: fit.map(|f| f.0),
        fit_peak_pressure: fit.map(|f| f.1),
        stick_x_min: None,
        stick_x_max: None,
        nodes_contact: loaded.len(),
        nodes_stick: 0,
        nodes_slip: loaded.len(),
    };
    Evaluation {
        nodes,
        resultants: Resultants { normal: fsum * e * l0, tangential: 0.0, moment: msum * e * l0 * l0 },
        rigid_body: RigidBody {
            normal: rigid[MODE_APPROACH] * l0,
            tangential: rigid[MODE_SHIFT] * l0,
            rotation: rigid[MODE_ROTATION],
        },
        contact,
        residuals,
    }
}
