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
//! - **Carter** (steady rolling, β = 0; Johnson, *Contact Mechanics*, §8.2; REFERENCES.md): with the creepage
//!   prescribed, c/a = 1 − |ξ|R/(μa) (full slip for |ξ| ≥ μa/R); with the tangential load prescribed,
//!   c/a = √(1 − |Q|/(μP)) and |ξ| = (μa/R)(1 − c/a); Q/(μP) = −sgn(ξ)(1 − (c/a)²) (ξ > 0 brakes: the friction on the
//!   wheel is negative, [`crate::formulation::slip`]); the stick zone touches the leading edge (a − 2c < x < a
//!   rolling towards +x), centred at d = a − c, where q = −sgn(ξ) μ p0 [√(1 − x²/a²) − (c/a)√(1 − (x − d)²/c²)];
//!   q = −sgn(ξ) μ p in the slip zone. Errors: Q/(μP) absolute, the stick zone's half-width and centre in elements,
//!   the RMS of |q − q_C|/(μ p0) over the loaded nodes, and the computed creepage relative to Carter's.
//!
//! The closed forms are [`crate::theory`]'s ([`Hertz2D`], [`theory::cattaneo_traction`], [`theory::carter_traction`],
//! …), each tested there against an independent computation; this module only poses them for a scene and a run.
//! The sweep CSVs, the reports and `rollbem check` all use these functions.

use crate::post::NodeState;
use crate::results::SolverRun;
use crate::scene::{BodyModel, Dof, Rolling, Scene};
use crate::theory::{self, Hertz2D};
use crate::tolerances::{CATTANEO_EDGE_ELEMENTS, CATTANEO_MAX_A_OVER_R_AT_NU_HALF};
use serde::Serialize;

/// Error figures of one run against the references that apply (null where one does not apply).
#[derive(Debug, Clone, Copy, Default, Serialize, PartialEq)]
#[non_exhaustive]
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
    /// Cattaneo–Mindlin: L2 error of the shear over the contact, ‖q − q_CM‖₂ / ‖μ p_Hertz‖₂ (tributary-length
    /// weights, as the Hertz L2 error): the norm that converges with the mesh (the worst error beside the
    /// square-root corners at ±c does not).
    pub cm_shear_l2_err: Option<f64>,
    /// Measured Q/(μP) of a steady-rolling run (Carter scenes).
    pub carter_q_over_mup: Option<f64>,
    /// Carter's Q/(μP).
    pub carter_q_over_mup_exact: Option<f64>,
    /// Measured stick-zone half-width over a.
    pub carter_c_over_a: Option<f64>,
    /// Carter's c/a.
    pub carter_c_over_a_exact: Option<f64>,
    /// (c − c_Carter) in contact elements.
    pub carter_c_err_elements: Option<f64>,
    /// (stick-zone centre − d) in contact elements.
    pub carter_centre_err_elements: Option<f64>,
    /// RMS of |q − q_Carter| / (μ p0) over the loaded nodes.
    pub carter_shear_rms: Option<f64>,
    /// |ξ − ξ_Carter| / |ξ_Carter| when the tangential load is prescribed (the creepage computed).
    pub carter_creepage_err: Option<f64>,
}

/// Hertz at load `p` with the scene's effective radius R* ([`Scene::contact_radius`]: the wheel's on a flat) and
/// pair modulus E*.
pub fn hertz_at(scene: &Scene, p: f64) -> Hertz2D {
    Hertz2D::from_load(p, scene.contact_radius(), scene.contact_modulus())
}

/// Where a half-space theory of the decoupled problem (Cattaneo–Mindlin, Carter) stands for a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Domain {
    /// Its assumptions hold: the half-plane model of the wheel, with the normal and tangential problems decoupled
    /// (Dundurs' β of the pair zero, or `coupling = false`). Checked against the theory within a tolerance.
    Holds,
    /// The finite (BEM) wheel, decoupled: the theory is the limit a/R → 0 of this problem, not the problem. A finite
    /// body keeps a normal–tangential coupling of order a/R through its curvature and its support, which moves the
    /// stick zone by a fixed length that no mesh refinement removes. Compared with the theory as a model
    /// comparison, with the model error computed on the half-plane counterpart ([`half_space_counterpart`]).
    FiniteBody,
    /// β ≠ 0 with the coupling on, a strip of half-spaces (`[mesh] strip_width`, not the theory's plane
    /// strain), a viscoelastic body or a falling friction law: the theory's problem is not this one; no comparison.
    Outside,
}

/// The domain of the decoupled half-space theories for a scene ([`Domain`]).
pub fn decoupled_domain(scene: &Scene) -> Domain {
    let decoupled = !scene.law().coupling || scene.dundurs_beta().abs() < 1e-12;
    if scene.strip_width().is_some() || scene.is_viscoelastic() || scene.slip_velocity_friction().is_some() {
        return Domain::Outside;
    }
    match (decoupled, scene.model()) {
        (false, _) => Domain::Outside,
        (true, BodyModel::HalfPlane) => Domain::Holds,
        (true, BodyModel::Bem) => Domain::FiniteBody,
    }
}

/// Whether Carter is compared with a run: steady rolling with μ > 0, P > 0, and the decoupled problem
/// ([`decoupled_domain`] not `Outside`).
pub fn carter_applies(scene: &Scene, p: f64) -> bool {
    let steady = matches!(scene.rolling(), Some(Rolling::Steady { .. }));
    steady && scene.friction() > 0.0 && p > 0.0 && decoupled_domain(scene) != Domain::Outside
}

/// The model the half-space theories assume, for a finite-wheel scene they are compared with
/// ([`Domain::FiniteBody`]): the same material, radius (a circular profile), counter-body, contact law, drive,
/// rolling and candidate zone, with the wheel modelled as an elastic half-plane (constant elements; a quadratic
/// mesh's nodes become as many constant elements on the same zone), solved by `active_set`. With a second finite
/// body (a counter-disc) the counterpart is the pair of half-planes the theories assume: the wheel's radius the
/// effective R* ([`Scene::contact_radius`]), the counter-disc an elastic half-plane of its material, the zone the
/// same width in x. `None` when the scene is not compared with a half-space theory on the finite wheel.
pub fn half_space_counterpart(scene: &Scene) -> Option<crate::Result<Scene>> {
    let compared = cattaneo_applies(scene) || matches!(scene.rolling(), Some(Rolling::Steady { .. }));
    if decoupled_domain(scene) != Domain::FiniteBody || !compared || scene.friction() == 0.0 {
        return None;
    }
    let pair = crate::source::two_body::counter_of(scene.counter_body()).map(|(c, _)| {
        let m = *c.material();
        (scene.contact_radius(), m, scene.zone().half_width(scene.radius()))
    });
    Some(scene.edit(|d| {
        d.name = format!("{}-half-space", d.name);
        if let Some((r_star, m, half_width)) = pair {
            d.wheel.radius = r_star;
            d.counter_body = crate::scene::document::CounterBodyTable::HalfPlane {
                youngs_modulus: m.youngs_modulus,
                poisson_ratio: m.poisson_ratio,
                datum_depth: None,
                viscoelastic: None,
            };
            d.mesh.contact_arc_deg = None;
            d.mesh.contact_half_width = Some(half_width);
        }
        d.wheel.model = BodyModel::HalfPlane;
        d.wheel.support = None;
        d.wheel.profile = None;
        d.wheel.datum_depth = None;
        if d.mesh.element == crate::scene::ElementKind::Quadratic {
            d.mesh.contact_elements *= 3;
        }
        d.mesh.element = crate::scene::ElementKind::Constant;
        d.mesh.other_elements = None;
        d.drive.rotation = None;
        d.drive.moment = None;
        d.solvers = crate::scene::document::SolversTable::using(&["active_set"]);
        d.checks = None;
        d.stresses = None;
    }))
}

/// Carter's solution for a steady-rolling run ([`carter_solution`]), from [`crate::theory`]'s closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CarterReference {
    /// Hertz at the run's load P.
    pub(crate) hertz: Hertz2D,
    /// Stick-zone half-width over a.
    pub(crate) c_over_a: f64,
    /// Q/(μP): negative for ξ > 0 (braking: the friction on the wheel is negative).
    pub(crate) q_over_mup: f64,
    /// The creepage ξ: the prescribed one, or Carter's for the prescribed Q.
    pub(crate) creepage: f64,
    /// Centre d of the stick zone (at the leading edge: signed with the rolling direction).
    pub(crate) centre: f64,
    /// Rolling direction, ±1.
    direction: f64,
}

impl CarterReference {
    /// Carter's shear traction on the wheel at x, for friction coefficient `mu`: [`theory::carter_traction`],
    /// mirrored when rolling towards −x.
    pub(crate) fn traction(&self, mu: f64, x: f64) -> f64 {
        let q_force = self.q_over_mup * mu * self.hertz.load;
        theory::carter_traction(&self.hertz, mu, q_force, self.direction * x)
    }
}

/// Carter's solution for a steady-rolling run, at the run's P. `None` when it does not apply or the run has no
/// resultant.
pub(crate) fn carter_solution(scene: &Scene, run: &SolverRun) -> Option<CarterReference> {
    let p = run.resultants?.normal;
    if !carter_applies(scene, p) {
        return None;
    }
    let direction = f64::from(scene.rolling()?.direction());
    let (mu, r) = (scene.friction(), scene.contact_radius());
    let hertz = hertz_at(scene, p);
    let (c_over_a, creepage) = match scene.drive()?.tangential {
        Dof::Displacement(xi) => (theory::carter_c_over_a_of_creepage(&hertz, mu, r, xi), xi),
        Dof::Load(q) => (theory::carter_c_over_a(q / (mu * p)), theory::carter_creepage(&hertz, mu, r, q)),
    };
    let q_over_mup = theory::carter_force(&hertz, mu, r, creepage) / (mu * hertz.load);
    let centre = direction * theory::carter_stick_zone(&hertz, c_over_a).1;
    Some(CarterReference { hertz, c_over_a, q_over_mup, creepage, centre, direction })
}

/// Whether Hertz is compared with a scene: frictionless, and in plane strain (not on a strip of half-spaces,
/// `[mesh] strip_width`).
pub fn hertz_applies(scene: &Scene) -> bool {
    let conformal = matches!(scene.counter_body(), crate::scene::CounterBody::Bore { .. });
    scene.friction() == 0.0 && scene.strip_width().is_none() && !conformal && !scene.is_viscoelastic()
}

/// Hertz at the run's load P, when [`hertz_applies`] and the run solved with P > 0.
pub fn hertz_for(scene: &Scene, run: &SolverRun) -> Option<Hertz2D> {
    if !hertz_applies(scene) {
        return None;
    }
    let p = run.resultants?.normal;
    (p > 0.0).then(|| hertz_at(scene, p))
}

/// Whether the normal and tangential problems decouple as the half-plane theories (Cattaneo–Mindlin, Carter)
/// assume: coupling switched off, or Dundurs' β of the pair zero (ν = 0.5 on a rigid flat, two identical
/// half-planes) — on the half-plane model exactly, on the finite wheel only for a/R ≤
/// [`CATTANEO_MAX_A_OVER_R_AT_NU_HALF`] (a finite wheel keeps a coupling of order a/R through its curvature and
/// bending even where β = 0). `p` is the normal load.
pub fn beta_zero(scene: &Scene, p: f64) -> bool {
    let r = scene.radius();
    let a_over_r = hertz_at(scene, p).a / r;
    let beta_vanishes = scene.dundurs_beta().abs() < 1e-12;
    let finite_ok = scene.model() == BodyModel::HalfPlane || a_over_r <= CATTANEO_MAX_A_OVER_R_AT_NU_HALF;
    !scene.law().coupling || (beta_vanishes && finite_ok)
}

/// Whether Cattaneo–Mindlin is compared with a scene's runs: a static problem (no steady rolling), P and Q
/// prescribed with the rotation held (or no rotation: the half-plane), 0 < |Q| < μP, and the decoupled problem
/// ([`decoupled_domain`] not `Outside`: a check where it holds, a model comparison on the finite wheel).
pub fn cattaneo_applies(scene: &Scene) -> bool {
    let Some(d) = scene.drive() else { return false };
    if matches!(scene.rolling(), Some(Rolling::Steady { .. })) {
        return false;
    }
    let mu = scene.friction();
    match (d.normal, d.tangential, d.rotational) {
        (Dof::Load(p), Dof::Load(q), Dof::Displacement(_)) => {
            decoupled_domain(scene) != Domain::Outside && mu > 0.0 && q != 0.0 && q.abs() < mu * p
        }
        _ => false,
    }
}

/// Contact element length (user's unit).
pub fn element_length(scene: &Scene) -> f64 {
    scene.zone().element_length(scene.radius())
}

/// Tributary length of node i from the node spacing (user's unit).
fn tributary(nodes: &[crate::post::NodeResult], i: usize) -> f64 {
    match (i.checked_sub(1).map(|j| nodes[j].x), nodes.get(i + 1).map(|x| x.x)) {
        (Some(a), Some(b)) => 0.5 * (b - a),
        (Some(a), None) => nodes[i].x - a,
        (None, Some(b)) => b - nodes[i].x,
        (None, None) => 1.0,
    }
}

/// Compute the metrics of a run.
pub fn metrics(scene: &Scene, run: &SolverRun) -> Metrics {
    let mut m = Metrics::default();
    if run.contact.is_none() {
        return m;
    }
    hertz_metrics(scene, run, &mut m);
    carter_metrics(scene, run, &mut m);
    cattaneo_metrics(scene, run, &mut m);
    m
}

/// The Hertz figures of [`Metrics`], where Hertz applies.
fn hertz_metrics(scene: &Scene, run: &SolverRun, m: &mut Metrics) {
    let (Some(contact), Some(h)) = (&run.contact, hertz_for(scene, run)) else { return };
    m.hertz_a_err = contact.fit_half_width.map(|a| (a - h.a).abs() / h.a);
    m.hertz_p0_err = contact.fit_peak_pressure.map(|p| (p - h.p0).abs() / h.p0);
    let (mut num, mut den) = (0.0, 0.0);
    let nodes = &run.nodes;
    for (i, n) in nodes.iter().enumerate() {
        let w = tributary(nodes, i);
        let ph = h.pressure(n.x);
        num += w * (n.pressure - ph).powi(2);
        den += w * ph * ph;
    }
    m.hertz_l2_err = (den > 0.0).then(|| (num / den).sqrt());
}

/// The Carter figures of [`Metrics`], where Carter applies.
fn carter_metrics(scene: &Scene, run: &SolverRun, m: &mut Metrics) {
    let (Some(c), Some(res)) = (carter_solution(scene, run), run.resultants) else { return };
    let (h, mu, elem) = (c.hertz, scene.friction(), element_length(scene));
    m.carter_q_over_mup = Some(res.tangential / (mu * res.normal));
    m.carter_q_over_mup_exact = Some(c.q_over_mup);
    m.carter_c_over_a_exact = Some(c.c_over_a);
    let c_exact = c.c_over_a * h.a;
    match crate::post::stick_edges(&run.nodes) {
        Some((left, right)) => {
            let (half, centre) = (0.5 * (right - left), 0.5 * (right + left));
            m.carter_c_over_a = Some(half / h.a);
            m.carter_c_err_elements = Some((half - c_exact) / elem);
            m.carter_centre_err_elements = Some((centre - c.centre) / elem);
        }
        None => {
            m.carter_c_over_a = Some(0.0);
            m.carter_c_err_elements = Some(-c_exact / elem);
        }
    }
    let (mut sum2, mut count) = (0.0, 0usize);
    for n in run.nodes.iter().filter(|n| n.state != NodeState::Separated) {
        sum2 += ((n.shear - c.traction(mu, n.x)) / (mu * h.p0)).powi(2);
        count += 1;
    }
    m.carter_shear_rms = (count > 0).then(|| (sum2 / count as f64).sqrt());
    let computed = run.rolling.and_then(|r| (!r.creepage_prescribed).then_some(r.creepage).flatten());
    let xi = c.creepage;
    m.carter_creepage_err = computed.filter(|_| xi != 0.0).map(|x| (x - xi).abs() / xi.abs());
}

/// The Cattaneo–Mindlin figures of [`Metrics`], where Cattaneo–Mindlin applies.
fn cattaneo_metrics(scene: &Scene, run: &SolverRun, m: &mut Metrics) {
    if !cattaneo_applies(scene) {
        return;
    }
    let Some((Dof::Load(p), Dof::Load(q))) = scene.drive().map(|d| (d.normal, d.tangential)) else { return };
    let mu = scene.friction();
    let h = hertz_at(scene, p);
    let ce = h.a * theory::cattaneo_c_over_a(q / (mu * p));
    let elem = element_length(scene);
    m.cm_c_over_a_exact = Some(ce / h.a);
    let nodes = &run.nodes;
    if let Some((left, right)) = crate::post::stick_edges(nodes) {
        let (c, centre) = (0.5 * (right - left), 0.5 * (right + left));
        m.cm_c_over_a = Some(c / h.a);
        m.cm_c_err_elements = Some((c - ce) / elem);
        m.cm_centre_elements = Some(centre / elem);
    }
    let q_cm = |x: f64| theory::cattaneo_traction(&h, mu, q, x);
    let (mut num, mut den) = (0.0, 0.0);
    for (i, n) in nodes.iter().enumerate() {
        let w = tributary(nodes, i);
        num += w * (n.shear - q_cm(n.x)).powi(2);
        den += w * (mu * h.pressure(n.x)).powi(2);
    }
    m.cm_shear_l2_err = (den > 0.0).then(|| (num / den).sqrt());
    let edge = CATTANEO_EDGE_ELEMENTS * elem;
    let away = |x: f64| x.abs() <= h.a - edge && (x.abs() - ce).abs() >= edge;
    let worst = nodes.iter().filter(|n| away(n.x)).map(|n| (n.shear - q_cm(n.x)).abs() / (mu * h.p0));
    m.cm_shear_err = Some(worst.fold(0.0, f64::max));
}
