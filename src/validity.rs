//! Whether a solver's answer is the wheel's: the checks that turn a residual-clean solution of the *discrete,
//! linearised* problem into a status other than `solved` when the model itself is used outside its range, and the
//! exact decision of a failed load-driven solve ([`crate::admissible`]).
//!
//! - **Linearised kinematics** ([`Status::KinematicsOutOfRange`]): the rigid rotation φ of the support enters the
//!   gaps as φx and the moment equilibrium with the undeformed lever arms, valid only while the arc φR is small
//!   against the contact half-width a ([`ROTATION_ARC_MAX`]). A rigid *shift* is exact (a translation of the wheel
//!   along a flat changes no gap and no lever arm about the wheel's centre), so it is not limited.
//! - **The candidate zone** ([`Status::ContactAtZoneEdge`]): a contact whose outermost candidate node is loaded is
//!   cut off by the mesh; the message says how wide the zone must be ([`ZONE_WIDTH_FACTOR`]).
//! - **A failed load-driven solve** (Lemke's ray, a refused or unconverged answer): the LP of static admissibility
//!   decides whether any contact forces carry the loads; if none do, the run is `infeasible` with the meaning of
//!   the certificate.

use crate::admissible::{admissibility, explain, required_centre, Admissibility};
use crate::formulation::{ContactProblem, Dof, ProblemKind};
use crate::post::{Evaluation, NodeState};
use crate::scene::ZoneExtent;
use crate::scene::{BodyModel, Scene};
use crate::status::{Status, VerdictReason};
use crate::tolerances::{ROTATION_ARC_MAX, ZONE_WIDTH_FACTOR};

/// The status and message a residual-clean solution gets when the model is used outside its range (`None`: it
/// stands as `solved`). The kinematics are judged first: a zone cannot be widened out of a rolling wheel.
pub fn judge(scene: &Scene, problem: &ContactProblem, ev: &Evaluation) -> Option<(Status, VerdictReason, String)> {
    kinematics(scene, problem, ev)
        .map(|(s, m)| (s, VerdictReason::Kinematics, m))
        .or_else(|| zone_edge(scene, problem, ev).map(|(s, m)| (s, VerdictReason::ZoneEdge, m)))
}

/// The contact half-width the run is judged against: the larger of the loaded nodes' extent (plus half an element)
/// and Hertz's a at the run's load, never below half an element (user's units).
fn contact_scale(scene: &Scene, ev: &Evaluation) -> f64 {
    let h = scene.zone().element_length(scene.radius());
    let measured = ev.contact.half_width.map_or(0.0, |w| w + 0.5 * h);
    let p = ev.resultants.normal;
    let hertz = if p > 0.0 { crate::references::hertz_at(scene, p).a } else { 0.0 };
    measured.max(hertz).max(0.5 * h)
}

/// [`Status::KinematicsOutOfRange`] when |φ|R exceeds [`ROTATION_ARC_MAX`] contact half-widths.
fn kinematics(scene: &Scene, problem: &ContactProblem, ev: &Evaluation) -> Option<(Status, String)> {
    let phi = ev.rigid_body.rotation;
    let r = scene.radius();
    let a = contact_scale(scene, ev);
    let arc = phi.abs() * r;
    if arc.is_nan() || arc <= ROTATION_ARC_MAX * a {
        return None;
    }
    let mut msg = format!(
        "the wheel turned by φ = {phi:.3e} rad, which moves its contact points by φR = {arc:.3e}, {:.2} contact \
         half-widths (a ≈ {a:.3e}); the linearised kinematics hold only for φR ≤ {ROTATION_ARC_MAX}a (they tilt the \
         gaps by φx where a round wheel turning about its centre changes none, and keep the undeformed lever arms of \
         the moment), so this answer is not the wheel's",
        arc / a
    );
    if let Dof::Load(m) = problem.drive.rotational {
        // The problem's drive is in the user's units.
        let q = match problem.drive.tangential {
            Dof::Load(q) => q,
            Dof::Displacement(_) => 0.0,
        };
        msg.push_str(&match required_centre(problem) {
            Some(xc) => format!(
                "; with the moment prescribed (M = {m:.4e}) and Q = {q:.4e}, the moment about the axle needs the \
                 pressure centre at (M − RQ)/P = {xc:.4e} from the middle, which a round wheel does not hold (it \
                 carries a moment about its axle only through the tangential force, and otherwise rolls): hold the \
                 rotation (`rotation = 0`) or prescribe the moment the tangential force balances (M = RQ = {:.4e} \
                 centres the contact)",
                r * q
            ),
            None => "; the moment is carried by tilting the contact, which a round wheel free to turn does not do \
                     (it rolls): hold the rotation (`rotation = 0`) or prescribe a moment the contact can carry"
                .to_string(),
        });
    }
    Some((Status::KinematicsOutOfRange, msg))
}

/// [`Status::ContactAtZoneEdge`] when the outermost candidate node on either side is loaded.
fn zone_edge(scene: &Scene, problem: &ContactProblem, ev: &Evaluation) -> Option<(Status, String)> {
    let nodes = &ev.nodes;
    let (first, last) = (nodes.first()?, nodes.last()?);
    let edge = [first, last]
        .into_iter()
        .filter(|nd| nd.state != NodeState::Separated)
        .max_by(|a, b| a.pressure.total_cmp(&b.pressure))?;
    let l0 = problem.flex.scales.length;
    let weights = &problem.flex.weights;
    let (mut fx, mut f) = (0.0, 0.0);
    for (nd, w) in nodes.iter().zip(weights) {
        fx += nd.x * nd.pressure * w * l0;
        f += nd.pressure * w * l0;
    }
    let r = scene.radius();
    // The pressure centre; a symmetric contact's round-off (1e-17 R) is shown as the 0 it is.
    let centre = if f > 0.0 { fx / f } else { 0.0 };
    let centre = if centre.abs() < 1e-12 * r { 0.0 } else { centre };
    let c = &ev.contact;
    let mid = 0.5 * (c.x_min.unwrap_or(0.0) + c.x_max.unwrap_or(0.0));
    let middle =
        nodes.iter().min_by(|a, b| (a.x - mid).abs().total_cmp(&(b.x - mid).abs())).map_or(0.0, |n| n.pressure);
    let p = ev.resultants.normal;
    let a_h = if p > 0.0 { crate::references::hertz_at(scene, p).a } else { 0.0 };
    let need = ZONE_WIDTH_FACTOR * (centre.abs() + a_h);
    let at_least = if matches!(problem.drive.normal, Dof::Displacement(_)) {
        " at least (the approach is prescribed, and the cut-off zone carries less than the full contact would)"
    } else {
        ""
    };
    let mut msg = format!(
        "the contact reaches the edge of the candidate zone: the outermost node, at x = {:.4e}, carries p = {:.4e} \
         ({:.2} times the {:.4e} at mid-contact), so the contact is cut off by the mesh, not by the wheel",
        edge.x,
        edge.pressure,
        edge.pressure / middle.max(f64::MIN_POSITIVE),
        middle
    );
    let m = scene.zone();
    let w0 = m.half_width(r);
    let bem = scene.model() == BodyModel::Bem;
    let elements = |ratio: f64| (m.elements as f64 * ratio).ceil() as usize;
    if need >= r {
        msg.push_str(&format!(
            "; no candidate zone on this wheel can hold it: the contact needs a half-width of about {need:.3e}{at_least} \
             (pressure centre {centre:.3e}, Hertz's a = {a_h:.3e} at P = {p:.4e}, a/R = {:.2}), beyond the radius \
             R = {r}: the load is beyond small-strain contact of this wheel",
            a_h / r
        ));
    } else if let ZoneExtent::Span { x_min, x_max } = m.extent {
        msg.push_str(&format!(
            "; widen contact_x to at least [{:.4e}, {:.4e}]{at_least} (now [{x_min:.4e}, {x_max:.4e}]; pressure centre \
             {centre:.3e}, Hertz's a = {a_h:.3e} at P = {p:.4e}), with contact_elements ≥ {} to keep the element size",
            x_min.min(-need),
            x_max.max(need),
            elements((x_max.max(need) - x_min.min(-need)) / (x_max - x_min))
        ));
    } else if matches!(m.extent, ZoneExtent::HalfWidth { .. }) || !bem {
        msg.push_str(&format!(
            "; widen it to contact_half_width ≥ {need:.4e}{at_least} (now {w0:.4e}; pressure centre {centre:.3e}, \
             Hertz's a = {a_h:.3e} at P = {p:.4e}), with contact_elements ≥ {} to keep the element size",
            elements(need / w0)
        ));
    } else {
        let arc = 2.0 * (need / r).asin().to_degrees();
        msg.push_str(&format!(
            "; widen it to contact_arc_deg ≥ {arc:.4}{at_least} (now {:.4}; a half-width of {need:.4e} for the \
             pressure centre {centre:.3e} and Hertz's a = {a_h:.3e} at P = {p:.4e}), with contact_elements ≥ {} to keep \
             the element size",
            m.arc_rad(r).to_degrees(),
            elements(arc.to_radians() / m.arc_rad(r))
        ));
    }
    Some((Status::ContactAtZoneEdge, msg))
}

/// The exact decision of a load-driven run that did not solve (Lemke's ray, a refused or unconverged answer): the
/// LP of static admissibility. `Some` with the new status and message when the LP proves the loads cannot be
/// carried (`infeasible`, whatever the solver said) or, for Lemke's ray, when it shows that statically admissible
/// forces exist (the ray is then the solver's failure, and the message says so).
pub fn decide(problem: &ContactProblem, solver: crate::solvers::SolverId, status: Status) -> Option<(Status, String)> {
    let failed = matches!(status, Status::RayTermination | Status::NotConverged | Status::NumericalError);
    let loaded = problem.dofs.iter().any(|d| d.is_load());
    if !failed || !loaded || matches!(problem.kind, ProblemKind::GrossSliding { .. }) {
        return None;
    }
    match admissibility(problem) {
        Admissibility::Infeasible(cert) => Some((
            Status::Infeasible,
            format!("infeasible: {} ({solver} ended with {status})", explain(problem, &cert)),
        )),
        Admissibility::Feasible if status == Status::RayTermination => Some((
            Status::RayTermination,
            "statically admissible contact forces exist on the candidate zone (the equilibrium LP with p ≥ 0, |q| ≤ μp \
             is feasible), so the loads are within friction and the zone; Lemke's ray on this LCP, which is not \
             copositive-plus, leaves the elastic problem undecided"
                .to_string(),
        )),
        Admissibility::Feasible => None,
        Admissibility::Undecided(why) => Some((status, format!("static admissibility undecided: {why}"))),
    }
}
