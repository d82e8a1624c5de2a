//! The two-body side of a 2D sweep row (issue 34): the columns a twin disc or a pin in a bore
//! ([`crate::source::two_body`]) needs beside the one-wheel ones, filled by the case runner for every 2D run
//! (its `figures`).
//!
//! - `peak_pressure`: the largest nodal pressure (every 2D row; for a bore the pressure on the load's line, where the
//!   ellipse fit `peak_pressure_fit` of a conformal contact is no Hertzian ellipse).
//! - `contact_radius`: the R* the Hertz and Carter references of the row use ([`Scene::contact_radius`]: R for one
//!   wheel, R₁R₂/(R₁ + R₂) for a twin disc, R·R_b/(R_b − R) for a bore with clearance; empty at zero clearance).
//! - `counter_body` (`rigid`, `half_plane`, `disc`, `bore`) and `counter_radius` (R₂ or R_b).
//! - `contact_half_angle` (two bodies): the loaded arc's right edge seen from the wheel's centre, in radians from the
//!   load's line ([`loaded_arc_edge`]).
//! - `pin_bore_half_angle`, `pin_bore_p0` and their errors `pin_bore_half_angle_err`, `pin_bore_p0_err` (|BEM −
//!   theory|/theory against `contact_half_angle` and `peak_pressure`): Persson's frictionless pin in an infinite
//!   plate of the same material ([`crate::theory::pin_bore`]) at the run's load, for a bore whose pin and plate are
//!   of one material and a frictionless scene; at zero clearance the load-independent angle. The plate of the scene
//!   is finite (its outer circle clamped), so the error also carries the plate's size: an outer radius of 30R costs
//!   about 1e-3 (tests/two_bodies.rs).

use crate::post::NodeResult;
use crate::results::SolverRun;
use crate::scene::{CounterBody, Scene};
use crate::theory::PinBore;

/// Collocation nodes of the pin-bore reference (converged to about 1e-8: its tests).
const PIN_BORE_NODES: usize = 64;

/// The two-body figures of a row (module docs); all empty where they do not apply.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct TwoBodyFigures {
    /// The largest nodal pressure (stress unit).
    pub peak_pressure: Option<f64>,
    /// The R* of the row's Hertz and Carter references (length unit).
    pub contact_radius: Option<f64>,
    /// The counter-body's kind: `rigid`, `half_plane`, `disc` or `bore`.
    pub counter_body: Option<String>,
    /// The counter-body's radius: R₂ of a disc, R_b of a bore (length unit).
    pub counter_radius: Option<f64>,
    /// The loaded arc's right edge from the load's line, seen from the wheel's centre (radians).
    pub contact_half_angle: Option<f64>,
    /// The pin-bore reference's half-angle at the run's load (radians).
    pub pin_bore_half_angle: Option<f64>,
    /// The pin-bore reference's peak pressure at the run's load (stress unit).
    pub pin_bore_p0: Option<f64>,
    /// |contact_half_angle − pin_bore_half_angle| / pin_bore_half_angle.
    pub pin_bore_half_angle_err: Option<f64>,
    /// |peak_pressure − pin_bore_p0| / pin_bore_p0.
    pub pin_bore_p0_err: Option<f64>,
}

/// The right edge of the loaded arc of a two-body contact, in radians from the load's line (the wheel's −y axis) as
/// seen from the wheel's centre: p² extrapolated linearly to zero through the last two loaded nodes (p ∝ √(b − θ)
/// at a smooth edge). `None` without two loaded nodes with falling pressure at the right end.
pub fn loaded_arc_edge(nodes: &[NodeResult]) -> Option<f64> {
    let theta = |n: &NodeResult| n.x.atan2(-n.y);
    let i = (1..nodes.len()).rev().find(|&i| nodes[i].pressure > 0.0)?;
    let (t1, t2) = (theta(&nodes[i - 1]), theta(&nodes[i]));
    let (q1, q2) = (nodes[i - 1].pressure.powi(2), nodes[i].pressure.powi(2));
    (q1 > q2).then(|| t2 + q2 * (t2 - t1) / (q1 - q2))
}

/// The counter-body's kind as written in the CSV.
fn kind_name(c: &CounterBody) -> Option<&'static str> {
    match c {
        CounterBody::Rigid => Some("rigid"),
        CounterBody::HalfPlane { .. } => Some("half_plane"),
        CounterBody::Disc { .. } => Some("disc"),
        CounterBody::Bore { .. } => Some("bore"),
        #[allow(unreachable_patterns)]
        _ => None,
    }
}

/// The pin-bore reference at load `p` for a scene it applies to (module docs): (half-angle, peak pressure).
pub fn pin_bore_reference(scene: &Scene, p: f64) -> Option<(f64, f64)> {
    let CounterBody::Bore { material, radius, .. } = *scene.counter_body() else { return None };
    let r = scene.radius();
    if material != scene.wheel().material || scene.friction() != 0.0 || !(p > 0.0 && p.is_finite()) {
        return None;
    }
    let clearance = radius - r;
    let theory = if clearance > 0.0 {
        PinBore::at_load(p / (scene.contact_modulus() * clearance), PIN_BORE_NODES)?
    } else {
        PinBore::zero_clearance(PIN_BORE_NODES)?
    };
    Some((theory.half_angle, theory.peak_times_radius_over_load() * p / r))
}

/// A 2D row's two-body figures from its scene and run.
pub(super) fn figures(scene: &Scene, r: &SolverRun) -> TwoBodyFigures {
    let mut out = TwoBodyFigures::default();
    fill(&mut out, scene, r);
    out
}

fn fill(f: &mut TwoBodyFigures, scene: &Scene, r: &SolverRun) {
    let nodes = r.answer_nodes();
    f.peak_pressure = nodes.iter().map(|n| n.pressure).reduce(f64::max);
    f.contact_radius = Some(scene.contact_radius()).filter(|v| v.is_finite() && *v > 0.0);
    f.counter_body = kind_name(scene.counter_body()).map(str::to_string);
    f.counter_radius = match *scene.counter_body() {
        CounterBody::Disc { radius, .. } | CounterBody::Bore { radius, .. } => Some(radius),
        _ => None,
    };
    if f.counter_radius.is_none() {
        return;
    }
    f.contact_half_angle = loaded_arc_edge(nodes);
    let load = r.resultants.map(|x| x.normal);
    let Some((b, p0)) = load.and_then(|p| pin_bore_reference(scene, p)) else { return };
    f.pin_bore_half_angle = Some(b);
    f.pin_bore_p0 = Some(p0);
    f.pin_bore_half_angle_err = f.contact_half_angle.map(|x| (x - b).abs() / b);
    f.pin_bore_p0_err = f.peak_pressure.map(|x| (x - p0).abs() / p0);
}
