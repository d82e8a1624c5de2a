//! Analytic references applied to a solved run, as error figures (REFERENCES.md):
//!
//! - **Hertz** (frictionless scenes): relative errors of the fitted half-width a and peak pressure p0, and the
//!   relative L2 error of the nodal pressures, `√(Σ w (p − p_H)²) / √(Σ w p_H²)` with the tributary lengths w,
//!   all at the run's load P (equal load, never equal approach).
//! - **Cattaneo–Mindlin** (β = 0: ν = 0.5 or `coupling = false`; P and Q prescribed, rotation held, |Q| < μP):
//!   stick-zone half-width c against `a √(1 − Q/(μP))`, the stick zone's edges taken midway between the outermost
//!   sticking node and its slipping neighbour, in elements; and the worst shear error `|q − q_CM| / (μ p0)` over
//!   the nodes more than 1.5 elements from ±a and ±c (where q_CM has infinite slopes and a nodal comparison
//!   measures where the discrete edge falls, not the traction).
//!
//! The sweep CSVs, the reports and `rollbem check` all use these functions.

use crate::hertz::Hertz;
use crate::post::NodeState;
use crate::results::SolverRun;
use crate::scene::{BodyModel, Dof, Scene};
use crate::tolerances::{CATTANEO_EDGE_ELEMENTS, CATTANEO_MAX_A_OVER_R_AT_NU_HALF};
use serde::Serialize;

/// Error figures of one run against the references that apply (null where one does not apply).
#[derive(Debug, Clone, Copy, Default, Serialize, PartialEq)]
pub struct Metrics {
    /// |a_fit − a_H| / a_H.
    pub hertz_a_err: Option<f64>,
    /// |p0_fit − p0_H| / p0_H.
    pub hertz_p0_err: Option<f64>,
    /// Relative L2 error of the nodal pressures against Hertz.
    pub hertz_l2_err: Option<f64>,
    /// Measured stick-zone half-width over a (Cattaneo–Mindlin scenes).
    pub cm_c_over_a: Option<f64>,
    /// √(1 − Q/(μP)).
    pub cm_c_over_a_exact: Option<f64>,
    /// (c − c_exact) in contact elements.
    pub cm_c_err_elements: Option<f64>,
    /// Stick-zone centre in contact elements (0 for Cattaneo–Mindlin).
    pub cm_centre_elements: Option<f64>,
    /// Worst |q − q_CM| / (μ p0) away from ±a and ±c.
    pub cm_shear_err: Option<f64>,
}

/// Hertz at the run's load P, when the scene is frictionless and the run solved with P > 0.
pub fn hertz_for(scene: &Scene, run: &SolverRun) -> Option<Hertz> {
    if scene.contact.friction > 0.0 {
        return None;
    }
    let p = run.resultants?.normal;
    (p > 0.0).then(|| Hertz::with_modulus(scene.wheel.radius, scene.contact_modulus(), p))
}

/// Whether the normal and tangential problems decouple as the half-plane theories (Cattaneo–Mindlin, Carter)
/// assume: coupling switched off, or Dundurs' β of the pair zero (ν = 0.5 on a rigid flat, two identical
/// half-planes) — on the half-plane model exactly, on the finite wheel only for a/R ≤
/// [`CATTANEO_MAX_A_OVER_R_AT_NU_HALF`] (a finite wheel keeps a coupling of order a/R through its curvature and
/// bending even where β = 0). `p` is the normal load.
pub fn beta_zero(scene: &Scene, p: f64) -> bool {
    let w = &scene.wheel;
    let a_over_r = Hertz::with_modulus(w.radius, scene.contact_modulus(), p).half_width / w.radius;
    let beta_vanishes = scene.dundurs_beta().abs() < 1e-12;
    let finite_ok = w.model == BodyModel::HalfPlane || a_over_r <= CATTANEO_MAX_A_OVER_R_AT_NU_HALF;
    !scene.contact.coupling || (beta_vanishes && finite_ok)
}

/// Whether Cattaneo–Mindlin applies: β = 0 ([`beta_zero`]), P and Q prescribed with the rotation held (or no
/// rotation: the half-plane), 0 < |Q| < μP.
pub fn cattaneo_applies(scene: &Scene) -> bool {
    let mu = scene.contact.friction;
    match (scene.drive.normal(), scene.drive.tangential(), scene.drive.rotational()) {
        (Dof::Load(p), Dof::Load(q), Dof::Displacement(_)) => {
            beta_zero(scene, p) && mu > 0.0 && q != 0.0 && q.abs() < mu * p
        }
        _ => false,
    }
}

/// Contact element length (user's unit).
pub fn element_length(scene: &Scene) -> f64 {
    scene.mesh.element_length(scene.wheel.radius)
}

/// Compute the metrics of a run.
pub fn metrics(scene: &Scene, run: &SolverRun) -> Metrics {
    let mut m = Metrics::default();
    let Some(contact) = &run.contact else { return m };
    if let Some(h) = hertz_for(scene, run) {
        m.hertz_a_err = contact.fit_half_width.map(|a| (a - h.half_width).abs() / h.half_width);
        m.hertz_p0_err = contact.fit_peak_pressure.map(|p| (p - h.peak_pressure).abs() / h.peak_pressure);
        let (mut num, mut den) = (0.0, 0.0);
        let nodes = &run.nodes;
        for (i, n) in nodes.iter().enumerate() {
            // Tributary length from the node spacing (user's unit).
            let w = match (i.checked_sub(1).map(|j| nodes[j].x), nodes.get(i + 1).map(|x| x.x)) {
                (Some(a), Some(b)) => 0.5 * (b - a),
                (Some(a), None) => n.x - a,
                (None, Some(b)) => b - n.x,
                (None, None) => 1.0,
            };
            let ph = h.pressure(n.x);
            num += w * (n.pressure - ph).powi(2);
            den += w * ph * ph;
        }
        m.hertz_l2_err = (den > 0.0).then(|| (num / den).sqrt());
    }
    if cattaneo_applies(scene) {
        if let (Dof::Load(p), Dof::Load(q)) = (scene.drive.normal(), scene.drive.tangential()) {
            let mu = scene.contact.friction;
            let h = Hertz::with_modulus(scene.wheel.radius, scene.contact_modulus(), p);
            let ce = h.half_width * (1.0 - q.abs() / (mu * p)).sqrt();
            let elem = element_length(scene);
            m.cm_c_over_a_exact = Some(ce / h.half_width);
            let nodes = &run.nodes;
            let first = nodes.iter().position(|n| n.state == NodeState::Stick);
            let last = nodes.iter().rposition(|n| n.state == NodeState::Stick);
            if let (Some(f), Some(l)) = (first, last) {
                let left = if f > 0 { 0.5 * (nodes[f].x + nodes[f - 1].x) } else { nodes[f].x };
                let right = if l + 1 < nodes.len() { 0.5 * (nodes[l].x + nodes[l + 1].x) } else { nodes[l].x };
                let (c, centre) = (0.5 * (right - left), 0.5 * (right + left));
                m.cm_c_over_a = Some(c / h.half_width);
                m.cm_c_err_elements = Some((c - ce) / elem);
                m.cm_centre_elements = Some(centre / elem);
            }
            let sg = q.signum();
            let edge = CATTANEO_EDGE_ELEMENTS * elem;
            let away = |x: f64| x.abs() <= h.half_width - edge && (x.abs() - ce).abs() >= edge;
            let mut worst = 0.0_f64;
            for n in nodes.iter().filter(|n| away(n.x)) {
                let pa = h.pressure(n.x);
                let qa = sg
                    * if n.x.abs() < ce {
                        mu * pa - mu * h.peak_pressure * (ce / h.half_width) * (1.0 - (n.x / ce).powi(2)).sqrt()
                    } else {
                        mu * pa
                    };
                worst = worst.max((n.shear - qa).abs() / (mu * h.peak_pressure));
            }
            m.cm_shear_err = Some(worst);
        }
    }
    m
}
