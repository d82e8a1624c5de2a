//! Wheel meshes: the boundary of a disk (support `top_arc`) or an annulus (support `hub`), with a finer,
//! uniform mesh on the potential contact arc around the bottom point and a smooth geometric size grading into the
//! rest of the outer boundary.
//!
//! Geometry conventions (`DESIGN.md`): x horizontal, y up, the wheel centre at the origin, the flat the line
//! y = −R touching the undeformed wheel at (0, −R). Angles are polar angles (radians, counter-clockwise from +x);
//! the bottom point is at −π/2. The outer circle is traversed counter-clockwise and the hub circle clockwise, so
//! the body lies on the left and the outward normal is `n = (t_y, −t_x)` for the unit tangent `t`.
//!
//! Constant elements are straight chords between vertices on the circle, with one node (collocation point) at the
//! chord's midpoint. Quadratic elements follow the exact circular arc, with three nodes at ξ = −2/3, 0, 2/3
//! ([`crate::bem::quadratic`]).

use crate::error::ArgumentError;
use crate::scene::{ContactZone, ElementKind, Support, ZoneExtent, MAX_NODES, MIN_CONTACT_ELEMENT_ANGLE};
use std::f64::consts::PI;

/// Collocation points in the element's intrinsic coordinate ξ ∈ [−1, 1] (discontinuous quadratic element: the
/// nodes are interior, so no node is shared between elements).
pub const XI_NODES: [f64; 3] = [-2.0 / 3.0, 0.0, 2.0 / 3.0];

/// A circular-arc boundary element: position(ξ) = centre + radius·(cos θ, sin θ), θ(ξ) = θm + ξ·(theta1 − theta0)/2,
/// θm = (theta0 + theta1)/2, ξ ∈ [−1, 1]. It is traversed from `theta0` to `theta1`: theta1 > theta0 is
/// counter-clockwise (outer boundary of a disk), theta1 < theta0 clockwise (e.g. the hole of an annulus). Angles in
/// radians, lengths in the caller's (dimensionless) length unit.
///
/// The outward normal of the body is n = (t_y, −t_x), t = dx/ds the unit tangent in the traversal direction, i.e.
/// n = +(cos θ, sin θ) for a CCW element and −(cos θ, sin θ) for a CW one (body to the left of the traversal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcElement {
    /// Centre of the circle carrying the arc.
    pub centre: [f64; 2],
    /// Radius of the circle (> 0).
    pub radius: f64,
    /// Angle at ξ = −1 (radians).
    pub theta0: f64,
    /// Angle at ξ = +1 (radians).
    pub theta1: f64,
}

impl ArcElement {
    /// Mid angle θm = (theta0 + theta1)/2.
    #[inline]
    pub fn theta_mid(&self) -> f64 {
        0.5 * (self.theta0 + self.theta1)
    }

    /// Signed half angle h = (theta1 − theta0)/2, so θ(ξ) = θm + h ξ.
    #[inline]
    pub fn half_angle(&self) -> f64 {
        0.5 * (self.theta1 - self.theta0)
    }

    /// Angle θ(ξ) at intrinsic coordinate `xi`.
    #[inline]
    pub fn theta(&self, xi: f64) -> f64 {
        self.theta_mid() + xi * self.half_angle()
    }

    /// Point on the arc at intrinsic coordinate `xi` ∈ [−1, 1].
    #[inline]
    pub fn position(&self, xi: f64) -> [f64; 2] {
        let (s, c) = self.theta(xi).sin_cos();
        [self.centre[0] + self.radius * c, self.centre[1] + self.radius * s]
    }

    /// Outward unit normal of the body at `xi`: +(cos θ, sin θ) if CCW, −(cos θ, sin θ) if CW.
    #[inline]
    pub fn normal(&self, xi: f64) -> [f64; 2] {
        let (s, c) = self.theta(xi).sin_cos();
        let sg = self.orientation();
        [sg * c, sg * s]
    }

    /// +1 for a counter-clockwise element (theta1 > theta0), −1 for a clockwise one.
    #[inline]
    pub fn orientation(&self) -> f64 {
        if self.theta1 >= self.theta0 {
            1.0
        } else {
            -1.0
        }
    }

    /// Jacobian ds/dξ = radius·|theta1 − theta0|/2 (constant along the element); the arc length is 2·jacobian.
    #[inline]
    pub fn jacobian(&self) -> f64 {
        self.radius * self.half_angle().abs()
    }

    /// Arc length of the element, radius·|theta1 − theta0|.
    #[inline]
    pub fn length(&self) -> f64 {
        2.0 * self.jacobian()
    }

    /// Positions of the three collocation nodes (at [`XI_NODES`]).
    pub fn nodes(&self) -> [[f64; 2]; 3] {
        XI_NODES.map(|xi| self.position(xi))
    }

    /// ∫ N_j ds over the element for the three nodes: (0.75, 0.5, 0.75) × jacobian; they sum to the arc length.
    pub fn node_weights(&self) -> [f64; 3] {
        let j = self.jacobian();
        [0.75 * j, 0.5 * j, 0.75 * j]
    }
}

/// Boundary condition class of an element (and of its nodes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bc {
    /// Traction-free outer boundary: displacements unknown.
    Free,
    /// Potential contact zone: displacements and tractions both unknown (tied by the contact law).
    Contact,
    /// Clamped to the rigid support: displacement = the support's rigid motion, tractions unknown.
    Support,
}

/// Geometry of one element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Straight element from `a` to `b` (constant elements).
    Straight {
        /// Start vertex.
        a: [f64; 2],
        /// End vertex.
        b: [f64; 2],
    },
    /// Exact circular arc (quadratic elements).
    Arc(ArcElement),
}

/// One boundary element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Element {
    /// Geometry.
    pub shape: Shape,
    /// Boundary condition class.
    pub bc: Bc,
    /// Index of the element's first node in [`Mesh::nodes`]; its nodes are consecutive.
    pub first_node: usize,
    /// Number of nodes (1 for constant, 3 for quadratic).
    pub n_nodes: usize,
}

/// One node (collocation point): where displacements and tractions are sampled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// Position (length unit of the mesh).
    pub pos: [f64; 2],
    /// Outward unit normal of the body.
    pub normal: [f64; 2],
    /// ∫ N_j ds: the length that carries this node's traction (tributary length; resultant = Σ weight·t).
    pub weight: f64,
    /// Owning element.
    pub element: usize,
    /// Boundary condition class.
    pub bc: Bc,
    /// Initial gap to the flat y = −R of the wheel of outer radius R (length unit of the mesh; ≥ 0 on the outer
    /// circle). On the outer circle it is computed from the polar angle, not as `pos[1] + R`, so that it keeps its
    /// relative precision at the contact point (see [`Mesh::initial_gap`]).
    pub gap: f64,
}

/// A meshed wheel boundary.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Element family.
    pub kind: ElementKind,
    /// Outer radius (length unit of the mesh).
    pub radius: f64,
    /// Elements, outer circle first (counter-clockwise from the left end of the contact arc), then the hub.
    pub elements: Vec<Element>,
    /// Nodes, element by element.
    pub nodes: Vec<Node>,
    /// Indices of the contact nodes, in increasing x.
    pub contact_nodes: Vec<usize>,
}

/// Sizes `h0·r^k`, k = 1..=n, with the ratio r chosen so they sum to `span` (r < 1 when n·h0 > span).
fn graded_sizes(h0: f64, span: f64, n: usize) -> Vec<f64> {
    let total = |r: f64| (1..=n).map(|k| h0 * r.powi(k as i32)).sum::<f64>();
    let (mut lo, mut hi) = (1e-3_f64, 10.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if total(mid) > span {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let r = 0.5 * (lo + hi);
    let mut sizes: Vec<f64> = (1..=n).map(|k| h0 * r.powi(k as i32)).collect();
    // Absorb the bisection's last rounding so the sizes close the span exactly.
    let s: f64 = sizes.iter().sum();
    for h in &mut sizes {
        *h *= span / s;
    }
    sizes
}

/// What a wheel's boundary mesh is made of: the element family, the potential contact zone with its elements and
/// the number of elements on the rest of the outer boundary (graded from the contact size; the hub circle, if any,
/// gets elements in proportion to its circumference).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshSpec {
    /// Element family.
    pub element: ElementKind,
    /// The potential contact zone.
    pub zone: ContactZone,
    /// Elements on the rest of the outer boundary (≥ 4).
    pub other_elements: usize,
}

impl MeshSpec {
    /// The BEM wheel's mesh of a scene, with its support (`None` for the half-plane model).
    pub fn of_scene(scene: &crate::scene::Scene) -> Option<(Support, MeshSpec)> {
        let (support, element, other_elements) = scene.bem_wheel()?;
        Some((support, MeshSpec { element, zone: *scene.zone(), other_elements }))
    }

    /// A mesh with a contact arc of `arc_deg` degrees.
    pub fn arc(element: ElementKind, arc_deg: f64, contact_elements: usize, other_elements: usize) -> MeshSpec {
        MeshSpec { element, zone: ContactZone::arc(arc_deg, contact_elements), other_elements }
    }
}

/// Polar angles of the potential contact zone's vertices on a circle of radius `radius`, counter-clockwise from its
/// left end: uniform in angle when `spec` gives `contact_arc_deg`; uniform in x, θ_k = −π/2 + asin(x_k/R), when it
/// gives `contact_half_width` (in the unit of `radius`). The half-plane model puts its strips between the x of the
/// same vertices, so both models share their collocation points.
pub fn contact_vertex_angles(radius: f64, zone: &ContactZone) -> Vec<f64> {
    let nc = zone.elements;
    match zone.extent {
        ZoneExtent::HalfWidth { half_width: w } => {
            (0..=nc).map(|k| -PI / 2.0 + ((-w + 2.0 * w * k as f64 / nc as f64) / radius).asin()).collect()
        }
        ZoneExtent::Span { x_min, x_max } => {
            (0..=nc).map(|k| -PI / 2.0 + ((x_min + (x_max - x_min) * k as f64 / nc as f64) / radius).asin()).collect()
        }
        ZoneExtent::Arc { .. } => {
            let alpha = zone.arc_rad(radius);
            let h0 = alpha / nc as f64;
            let start = -PI / 2.0 - alpha / 2.0;
            std::iter::once(start).chain((1..=nc).map(|k| start + h0 * k as f64)).collect()
        }
    }
}

/// Continue a circle's increasing vertex angles from the end of its contact zone (`angles` holds the zone's
/// vertices, `classes` its elements) around to the zone's start: `no` elements graded from the zone's end size `h0`
/// (the zone subtends `alpha`), all free, or with a clamped arc of `clamp` radians centred opposite the zone, its
/// uniform elements' count chosen to continue the grading. The last angle is left for the caller to close exactly.
fn close_circle(angles: &mut Vec<f64>, classes: &mut Vec<Bc>, h0: f64, alpha: f64, no: usize, clamp: Option<f64>) {
    let mut a = *angles.last().expect("a zone has vertices");
    let mut push = |h: f64, bc: Bc, angles: &mut Vec<f64>| {
        a += h;
        angles.push(a);
        classes.push(bc);
    };
    let Some(beta) = clamp else {
        let nr = no.div_ceil(2);
        let nl = no - nr;
        let span = PI - alpha / 2.0;
        let right = graded_sizes(h0, span, nr);
        let left = graded_sizes(h0, span, nl);
        for h in right.iter().chain(left.iter().rev()) {
            push(*h, Bc::Free, angles);
        }
        return;
    };
    let span = PI - alpha / 2.0 - beta / 2.0;
    // Choose how many uniform elements the clamped arc gets so that their size continues the grading.
    let mut best: Option<(f64, usize)> = None;
    for ntop in 1..=no.saturating_sub(2).max(1) {
        let nr = (no - ntop).div_ceil(2);
        let nl = no - ntop - nr;
        if nl == 0 {
            continue;
        }
        let Some(&last) = graded_sizes(h0, span, nr).last() else { continue };
        let mismatch = ((beta / ntop as f64) / last).ln().abs();
        if best.is_none_or(|(m, _)| mismatch < m) {
            best = Some((mismatch, ntop));
        }
    }
    let ntop = best.map(|b| b.1).unwrap_or(1);
    let nr = (no - ntop).div_ceil(2);
    let nl = no - ntop - nr;
    let right = graded_sizes(h0, span, nr);
    let left = graded_sizes(h0, span, nl);
    for h in &right {
        push(*h, Bc::Free, angles);
    }
    for _ in 0..ntop {
        push(beta / ntop as f64, Bc::Support, angles);
    }
    for h in left.iter().rev() {
        push(*h, Bc::Free, angles);
    }
}

/// The domain of a counter-body's zone (see [`Mesh::counter_disc`]).
fn check_counter_zone(
    f: &'static str,
    kind: ElementKind,
    radius: f64,
    zone: &[f64],
    other: usize,
) -> Result<(), ArgumentError> {
    if !(radius > 0.0 && radius.is_finite()) {
        return Err(ArgumentError::new(f, "radius", format!("must be finite and > 0, got {radius}")));
    }
    let increasing = zone.windows(2).all(|w| w[1] - w[0] >= MIN_CONTACT_ELEMENT_ANGLE);
    if zone.len() < 2 || !increasing || !zone.iter().all(|t| t.is_finite()) || zone[zone.len() - 1] - zone[0] >= PI {
        return Err(ArgumentError::new(
            f,
            "zone",
            "must be at least two finite increasing vertex angles, each element subtending at least \
             MIN_CONTACT_ELEMENT_ANGLE, spanning less than 180 degrees"
                .to_string(),
        ));
    }
    if other < 4 {
        return Err(ArgumentError::new(f, "other_elements", format!("must be at least 4, got {other}")));
    }
    let per = match kind {
        ElementKind::Constant => 1,
        ElementKind::Quadratic => 3,
    };
    if (zone.len() - 1).saturating_add(other).saturating_mul(per) > MAX_NODES {
        return Err(ArgumentError::new(f, "zone", format!("more than the {MAX_NODES} nodes a BEM body may have")));
    }
    Ok(())
}

/// The domain of [`Mesh::wheel`]: a wheel it can mesh, with the bounds a scene's validation applies to the same
/// quantities (`crate::scene`, with errors naming the scene's keys).
fn check_wheel(radius: f64, support: Support, spec: &MeshSpec) -> Result<(), ArgumentError> {
    let bad = |argument, message: String| Err(ArgumentError::new("Mesh::wheel", argument, message));
    if !(radius > 0.0 && radius.is_finite()) {
        return bad("radius", format!("must be finite and > 0, got {radius}"));
    }
    let nc = spec.zone.elements;
    if nc == 0 {
        return bad("spec.zone.elements", "must be at least 1 (the contact zone's elements)".into());
    }
    if spec.other_elements < 4 {
        return bad("spec.other_elements", format!("must be at least 4, got {}", spec.other_elements));
    }
    let per = match spec.element {
        ElementKind::Constant => 1,
        ElementKind::Quadratic => 3,
    };
    if nc.saturating_add(spec.other_elements).saturating_mul(per) > MAX_NODES {
        return bad(
            "spec",
            format!("{} + {} elements: more than the {MAX_NODES} nodes a BEM wheel may have", nc, spec.other_elements),
        );
    }
    match spec.zone.extent {
        ZoneExtent::Arc { degrees } if !(degrees > 0.0 && degrees < 180.0) => {
            return bad("spec.zone", format!("a contact arc must lie in (0, 180) degrees, got {degrees}"));
        }
        ZoneExtent::HalfWidth { half_width } if !(half_width > 0.0 && half_width < radius) => {
            return bad(
                "spec.zone",
                format!("a contact half-width must lie in (0, radius = {radius}), got {half_width}"),
            );
        }
        ZoneExtent::Span { .. } => {
            return bad(
                "spec.zone",
                "a zone placed off-centre is for the half-plane model; the wheel's is centred".into(),
            );
        }
        _ => {}
    }
    let per_element = spec.zone.arc_rad(radius) / nc as f64;
    if per_element.is_nan() || per_element < MIN_CONTACT_ELEMENT_ANGLE {
        return bad(
            "spec.zone",
            format!("its {nc} elements subtend {per_element:.1e} rad each, below {MIN_CONTACT_ELEMENT_ANGLE:e}"),
        );
    }
    let alpha = spec.zone.arc_rad(radius);
    match support {
        Support::Hub { radius: rh } if !(rh > 0.0 && rh < radius) => {
            bad("support", format!("a hub's radius must lie in (0, radius = {radius}), got {rh}"))
        }
        Support::TopArc { angle_deg } if !(angle_deg > 0.0 && angle_deg < 180.0) => {
            bad("support", format!("a top arc must lie in (0, 180) degrees, got {angle_deg}"))
        }
        Support::TopArc { angle_deg } if alpha.to_degrees() + angle_deg >= 300.0 => {
            bad("support", "the clamped top arc and the contact arc overlap or leave no free boundary".into())
        }
        _ => Ok(()),
    }
}

impl Mesh {
    /// Mesh a wheel of outer radius `radius` with the given support (its lengths, and `spec`'s contact half-width,
    /// in the same unit as `radius`). A wheel it cannot mesh is refused, naming the argument: a radius not finite
    /// and > 0, no contact element, fewer than 4 other elements, more than [`MAX_NODES`] nodes, a contact arc outside
    /// (0°, 180°) or a half-width outside (0, radius), an off-centre zone, contact elements of less than
    /// [`MIN_CONTACT_ELEMENT_ANGLE`] each, a hub outside the wheel, a top arc outside (0°, 180°) or overlapping the
    /// contact zone (the bounds a scene's validation applies).
    pub fn wheel(radius: f64, support: Support, spec: &MeshSpec) -> Result<Mesh, ArgumentError> {
        check_wheel(radius, support, spec)?;
        let alpha = spec.zone.arc_rad(radius);
        let nc = spec.zone.elements;
        let start = -PI / 2.0 - alpha / 2.0;
        // Outer-circle vertex angles, counter-clockwise, and the class of each element.
        let mut angles = contact_vertex_angles(radius, &spec.zone);
        let mut classes = vec![Bc::Contact; nc];
        // The grading into the rest of the boundary starts from the size of the contact zone's end element.
        let h0 = match spec.zone.extent {
            ZoneExtent::Arc { .. } => alpha / nc as f64,
            ZoneExtent::HalfWidth { .. } | ZoneExtent::Span { .. } => angles[nc] - angles[nc - 1],
        };
        let clamp = match support {
            Support::Hub { .. } => None,
            Support::TopArc { angle_deg } => Some(angle_deg.to_radians()),
        };
        let no = spec.other_elements;
        close_circle(&mut angles, &mut classes, h0, alpha, no, clamp);
        // Close the circle exactly.
        if let Some(last) = angles.last_mut() {
            *last = start + 2.0 * PI;
        }

        let mut mesh =
            Mesh { kind: spec.element, radius, elements: Vec::new(), nodes: Vec::new(), contact_nodes: Vec::new() };
        for (k, bc) in classes.iter().enumerate() {
            mesh.push_element(radius, angles[k], angles[k + 1], *bc);
        }
        if let Support::Hub { radius: rh } = support {
            let mean_other = (2.0 * PI - alpha) * radius / no as f64;
            let nh = ((2.0 * PI * rh / mean_other).round() as usize).max(12);
            let dh = 2.0 * PI / nh as f64;
            for k in 0..nh {
                // Clockwise: the body (the annulus) lies on the left of the hole's boundary.
                let t0 = PI / 2.0 - dh * k as f64;
                mesh.push_element(rh, t0, t0 - dh, Bc::Support);
            }
        }
        mesh.contact_nodes = (0..mesh.nodes.len()).filter(|&i| mesh.nodes[i].bc == Bc::Contact).collect();
        mesh.contact_nodes.sort_by(|&a, &b| mesh.nodes[a].pos[0].total_cmp(&mesh.nodes[b].pos[0]));
        Ok(mesh)
    }

    /// The boundary of a counter-disc ([`crate::source::two_body`]): a circle of radius `radius` about `centre`
    /// (counter-clockwise), whose potential contact zone has the vertex angles `zone` (polar angles about `centre`,
    /// increasing, symmetric about their middle angle, the zone's elements `Bc::Contact`), the rest of the circle in
    /// `other_elements` elements graded from the zone's end size, and the support: a hub (a clamped concentric circle
    /// of that radius, clockwise) or a clamped arc of `angle_deg` centred opposite the zone. Node gaps are 0 (a
    /// counter-body's gap is the pair's, [`crate::source::two_body`]). Refused, naming the argument: a zone of fewer
    /// than two vertices or spanning 180° or more, fewer than 4 other elements, more than [`MAX_NODES`] nodes, a hub
    /// outside the disc, a clamped arc outside (0°, 180°) or leaving no free boundary.
    pub fn counter_disc(
        kind: ElementKind,
        centre: [f64; 2],
        radius: f64,
        zone: &[f64],
        other_elements: usize,
        support: Support,
    ) -> Result<Mesh, ArgumentError> {
        check_counter_zone("Mesh::counter_disc", kind, radius, zone, other_elements)?;
        let (alpha, nc) = (zone[zone.len() - 1] - zone[0], zone.len() - 1);
        let clamp = match support {
            Support::Hub { radius: rh } if !(rh > 0.0 && rh < radius) => {
                return Err(ArgumentError::new(
                    "Mesh::counter_disc",
                    "support",
                    format!("a hub's radius must lie in (0, radius = {radius}), got {rh}"),
                ))
            }
            Support::Hub { .. } => None,
            Support::TopArc { angle_deg } => {
                if !(angle_deg > 0.0 && angle_deg < 180.0) || alpha.to_degrees() + angle_deg >= 300.0 {
                    return Err(ArgumentError::new(
                        "Mesh::counter_disc",
                        "support",
                        format!("a clamped arc must lie in (0, 180) degrees and leave free boundary, got {angle_deg}"),
                    ));
                }
                Some(angle_deg.to_radians())
            }
        };
        let mut angles = zone.to_vec();
        let mut classes = vec![Bc::Contact; nc];
        close_circle(&mut angles, &mut classes, zone[nc] - zone[nc - 1], alpha, other_elements, clamp);
        if let Some(last) = angles.last_mut() {
            *last = zone[0] + 2.0 * PI;
        }
        let mut mesh = Mesh { kind, radius, elements: Vec::new(), nodes: Vec::new(), contact_nodes: Vec::new() };
        for (k, bc) in classes.iter().enumerate() {
            mesh.push_circle_element(centre, radius, angles[k], angles[k + 1], *bc);
        }
        if let Support::Hub { radius: rh } = support {
            let mean_other = (2.0 * PI - alpha) * radius / other_elements as f64;
            let nh = ((2.0 * PI * rh / mean_other).round() as usize).max(12);
            let dh = 2.0 * PI / nh as f64;
            for k in 0..nh {
                let t0 = PI / 2.0 - dh * k as f64;
                mesh.push_circle_element(centre, rh, t0, t0 - dh, Bc::Support);
            }
        }
        mesh.sort_contact_nodes();
        Ok(mesh)
    }

    /// The boundary of a plate with a circular bore ([`crate::source::two_body`]): the bore, a circle of radius
    /// `radius` about `centre` traversed clockwise (the plate lies outside it), with the potential contact zone of
    /// vertex angles `zone` (as [`Mesh::counter_disc`]) and the rest of the bore free in `other_elements` graded
    /// elements; and the plate's outer boundary, a concentric circle of radius `outer_radius` clamped to the rigid
    /// frame, in `outer_elements` uniform elements (counter-clockwise). Refused as [`Mesh::counter_disc`], and for an
    /// outer radius not beyond the bore or fewer than 8 outer elements.
    pub fn bore_plate(
        kind: ElementKind,
        centre: [f64; 2],
        radius: f64,
        zone: &[f64],
        other_elements: usize,
        outer_radius: f64,
        outer_elements: usize,
    ) -> Result<Mesh, ArgumentError> {
        const F: &str = "Mesh::bore_plate";
        check_counter_zone(F, kind, radius, zone, other_elements.saturating_add(outer_elements))?;
        if !(outer_radius > radius && outer_radius.is_finite()) {
            let m = format!("must be finite and beyond the bore's radius {radius}, got {outer_radius}");
            return Err(ArgumentError::new(F, "outer_radius", m));
        }
        if outer_elements < 8 {
            return Err(ArgumentError::new(F, "outer_elements", format!("must be at least 8, got {outer_elements}")));
        }
        let (alpha, nc) = (zone[zone.len() - 1] - zone[0], zone.len() - 1);
        let mut angles = zone.to_vec();
        let mut classes = vec![Bc::Contact; nc];
        close_circle(&mut angles, &mut classes, zone[nc] - zone[nc - 1], alpha, other_elements, None);
        if let Some(last) = angles.last_mut() {
            *last = zone[0] + 2.0 * PI;
        }
        let mut mesh =
            Mesh { kind, radius: outer_radius, elements: Vec::new(), nodes: Vec::new(), contact_nodes: Vec::new() };
        let d = 2.0 * PI / outer_elements as f64;
        for k in 0..outer_elements {
            let t0 = -PI / 2.0 + d * k as f64;
            mesh.push_circle_element(centre, outer_radius, t0, t0 + d, Bc::Support);
        }
        // Clockwise: the elements of the increasing angle list in reverse, each from its larger angle.
        for k in (0..classes.len()).rev() {
            mesh.push_circle_element(centre, radius, angles[k + 1], angles[k], classes[k]);
        }
        mesh.sort_contact_nodes();
        Ok(mesh)
    }

    /// List the contact nodes in increasing x.
    fn sort_contact_nodes(&mut self) {
        self.contact_nodes = (0..self.nodes.len()).filter(|&i| self.nodes[i].bc == Bc::Contact).collect();
        let nodes = &self.nodes;
        self.contact_nodes.sort_by(|&a, &b| nodes[a].pos[0].total_cmp(&nodes[b].pos[0]));
    }

    /// One element on the circle of radius `rho` about `centre`, from angle `t0` to `t1` (counter-clockwise when
    /// t1 > t0), its nodes' gaps 0 (a counter-body's mesh).
    fn push_circle_element(&mut self, centre: [f64; 2], rho: f64, t0: f64, t1: f64, bc: Bc) {
        let e = self.elements.len();
        let first = self.nodes.len();
        match self.kind {
            ElementKind::Constant => {
                let a = [centre[0] + rho * t0.cos(), centre[1] + rho * t0.sin()];
                let b = [centre[0] + rho * t1.cos(), centre[1] + rho * t1.sin()];
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let len = dx.hypot(dy);
                let t = [dx / len, dy / len];
                let pos = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                self.nodes.push(Node { pos, normal: [t[1], -t[0]], weight: len, element: e, bc, gap: 0.0 });
                self.elements.push(Element { shape: Shape::Straight { a, b }, bc, first_node: first, n_nodes: 1 });
            }
            ElementKind::Quadratic => {
                let arc = ArcElement { centre, radius: rho, theta0: t0, theta1: t1 };
                let w = arc.node_weights();
                for (j, &xi) in XI_NODES.iter().enumerate() {
                    let node =
                        Node { pos: arc.position(xi), normal: arc.normal(xi), weight: w[j], element: e, bc, gap: 0.0 };
                    self.nodes.push(node);
                }
                self.elements.push(Element { shape: Shape::Arc(arc), bc, first_node: first, n_nodes: 3 });
            }
        }
    }

    fn push_element(&mut self, rho: f64, t0: f64, t1: f64, bc: Bc) {
        let e = self.elements.len();
        let first = self.nodes.len();
        // 1 + sin θ = 2 sin²((θ + π/2)/2): exact to relative rounding near θ = −π/2, where y + R cancels.
        let outer = rho == self.radius;
        let lift = |t: f64| rho * 2.0 * (0.5 * (t + PI / 2.0)).sin().powi(2);
        match self.kind {
            ElementKind::Constant => {
                let a = [rho * t0.cos(), rho * t0.sin()];
                let b = [rho * t1.cos(), rho * t1.sin()];
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let len = dx.hypot(dy);
                let t = [dx / len, dy / len];
                let pos = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                self.nodes.push(Node {
                    pos,
                    normal: [t[1], -t[0]],
                    weight: len,
                    element: e,
                    bc,
                    gap: if outer { 0.5 * (lift(t0) + lift(t1)) } else { pos[1] + self.radius },
                });
                self.elements.push(Element { shape: Shape::Straight { a, b }, bc, first_node: first, n_nodes: 1 });
            }
            ElementKind::Quadratic => {
                let arc = ArcElement { centre: [0.0, 0.0], radius: rho, theta0: t0, theta1: t1 };
                let w = arc.node_weights();
                for (j, &xi) in XI_NODES.iter().enumerate() {
                    let pos = arc.position(xi);
                    self.nodes.push(Node {
                        pos,
                        normal: arc.normal(xi),
                        weight: w[j],
                        element: e,
                        bc,
                        gap: if outer { lift(arc.theta(xi)) } else { pos[1] + self.radius },
                    });
                }
                self.elements.push(Element { shape: Shape::Arc(arc), bc, first_node: first, n_nodes: 3 });
            }
        }
    }

    /// Whether the mesh holds together as the boundary element code reads it (its fields are public, so a mesh built
    /// or edited by hand may not): each element has the node count of its shape (1 straight, 3 arc) at consecutive
    /// indices from `first_node` within [`Mesh::nodes`], each node names the element that holds it, and
    /// [`Mesh::contact_nodes`] lists each node of class [`Bc::Contact`] once and no other. `Err` names the first
    /// element or node that breaks it; every public function that reads a mesh checks this first.
    pub fn check(&self) -> Result<(), ArgumentError> {
        let bad = |message: String| Err(ArgumentError::new("Mesh::check", "mesh", message));
        for (e, el) in self.elements.iter().enumerate() {
            let per = match el.shape {
                Shape::Straight { .. } => 1,
                Shape::Arc(_) => 3,
            };
            if el.n_nodes != per {
                return bad(format!("element {e} has {} nodes, its shape {per}", el.n_nodes));
            }
            let end = el.first_node.checked_add(per).filter(|&end| end <= self.nodes.len());
            let Some(end) = end else {
                return bad(format!(
                    "element {e}'s nodes {}.. lie beyond the {} nodes",
                    el.first_node,
                    self.nodes.len()
                ));
            };
            if let Some(i) = (el.first_node..end).find(|&i| self.nodes[i].element != e) {
                return bad(format!("node {i} lies in element {e} but names element {}", self.nodes[i].element));
            }
        }
        for (i, node) in self.nodes.iter().enumerate() {
            let held = self
                .elements
                .get(node.element)
                .is_some_and(|el| (el.first_node..el.first_node + el.n_nodes).contains(&i));
            if !held {
                return bad(format!("node {i} names element {}, which does not hold it", node.element));
            }
        }
        let mut listed = vec![false; self.nodes.len()];
        for &i in &self.contact_nodes {
            match listed.get_mut(i) {
                Some(seen) if !*seen && self.nodes[i].bc == Bc::Contact => *seen = true,
                _ => return bad(format!("contact_nodes lists node {i} twice, or one that is not a contact node")),
            }
        }
        if let Some(i) = (0..self.nodes.len()).find(|&i| self.nodes[i].bc == Bc::Contact && !listed[i]) {
            return bad(format!("contact node {i} is missing from contact_nodes"));
        }
        Ok(())
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Exact initial gap of node `i` to the flat y = −R: `g0 = y_i + R` (≥ 0 for nodes on the arc; a constant
    /// element's chord midpoint lies inside the circle by the sagitta, which is part of its initial gap).
    ///
    /// On the outer circle it is evaluated as R·2 sin²(φ/2), φ = θ + π/2 the angle from the contact point (the
    /// mean of its two vertices' for a constant element's chord midpoint), not as `y_i + R`: the difference of two
    /// numbers of size R loses the gap's relative precision as ε/φ², which made the contact pressure of a contact
    /// half-angle of 1e-7 rad wrong by 30 % of p0 (`tests/mesh_precision.rs`). `None` for a node the mesh does
    /// not have.
    pub fn initial_gap(&self, i: usize) -> Option<f64> {
        self.nodes.get(i).map(|n| n.gap)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(element: ElementKind) -> MeshSpec {
        MeshSpec::arc(element, 30.0, 24, 32)
    }

    #[test]
    fn seed_mesh_counts_and_closure() {
        // The seed's Fig. 5/6 mesh: 56 elements, 24 of them on 1/12 of the contour.
        let m = Mesh::wheel(1.0, Support::TopArc { angle_deg: 30.0 }, &spec(ElementKind::Constant)).unwrap();
        assert_eq!(m.elements.len(), 56);
        assert_eq!(m.contact_nodes.len(), 24);
        // Closed polygon inscribed in the circle: consecutive elements share vertices, every vertex lies on the
        // circle, and the subtended angles add up to 2π.
        let mut total = 0.0;
        for (k, e) in m.elements.iter().enumerate() {
            let Shape::Straight { a, b } = e.shape else { panic!("constant elements are straight") };
            let Shape::Straight { a: next, .. } = m.elements[(k + 1) % m.elements.len()].shape else { unreachable!() };
            assert!((b[0] - next[0]).abs() < 1e-15 && (b[1] - next[1]).abs() < 1e-15, "gap after element {k}");
            assert!((a[0].hypot(a[1]) - 1.0).abs() < 1e-15);
            total += (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1]);
        }
        assert!((total - 2.0 * PI).abs() < 1e-12, "angles add to {total}");
        let n_support = m.elements.iter().filter(|e| e.bc == Bc::Support).count();
        assert!(n_support >= 1);
        // Grading is smooth: neighbouring free elements differ by less than 40 % in size.
        for w in m.nodes.windows(2) {
            let r = w[1].weight / w[0].weight;
            assert!(r < 1.4 && r > 1.0 / 1.4, "size jump {r}");
        }
    }

    /// The angle a closed boundary's elements subtend about `c`, summed in traversal order (2π counter-clockwise).
    fn turning(m: &Mesh, c: [f64; 2], radius: f64) -> f64 {
        m.elements
            .iter()
            .filter_map(|e| match e.shape {
                Shape::Straight { a, b } if ((a[0] - c[0]).hypot(a[1] - c[1]) - radius).abs() < 1e-12 => {
                    let (u, v) = ([a[0] - c[0], a[1] - c[1]], [b[0] - c[0], b[1] - c[1]]);
                    Some((u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1]))
                }
                _ => None,
            })
            .sum()
    }

    #[test]
    fn counter_disc_and_bore_plate_close_and_face_their_zone() {
        // Expected (geometry): a counter-disc's circle closes counter-clockwise (2π), its contact nodes lie on the
        // zone in increasing x with outward normals; a bore closes clockwise (−2π), its normals point into the hole
        // (out of the plate), and its clamped outer circle closes counter-clockwise.
        let c = [0.0, -1.0];
        let zone: Vec<f64> = (0..=10).map(|k| PI / 2.0 - 0.05 + 0.01 * k as f64).collect();
        let d = Mesh::counter_disc(ElementKind::Constant, c, 0.5, &zone, 40, Support::Hub { radius: 0.1 }).unwrap();
        assert!((turning(&d, c, 0.5) - 2.0 * PI).abs() < 1e-12);
        assert!((turning(&d, c, 0.1) + 2.0 * PI).abs() < 1e-12, "the hub clockwise");
        assert_eq!(d.contact_nodes.len(), 10);
        let xs: Vec<f64> = d.contact_nodes.iter().map(|&i| d.nodes[i].pos[0]).collect();
        assert!(xs.windows(2).all(|w| w[0] < w[1]));
        for &i in &d.contact_nodes {
            let n = d.nodes[i];
            let r = [n.pos[0] - c[0], n.pos[1] - c[1]];
            assert!((n.normal[0] * r[0] + n.normal[1] * r[1]) / r[0].hypot(r[1]) > 0.999, "outward");
        }
        let zone: Vec<f64> = (0..=10).map(|k| -PI / 2.0 - 0.5 + 0.1 * k as f64).collect();
        let b = Mesh::bore_plate(ElementKind::Quadratic, c, 0.02, &zone, 30, 0.5, 32).unwrap();
        assert_eq!(b.contact_nodes.len(), 30);
        for n in &b.nodes {
            let r = [n.pos[0] - c[0], n.pos[1] - c[1]];
            let radial = (n.normal[0] * r[0] + n.normal[1] * r[1]) / r[0].hypot(r[1]);
            if r[0].hypot(r[1]) < 0.1 {
                assert!((radial + 1.0).abs() < 1e-12, "the bore's normal points into the hole");
            } else {
                assert!((radial - 1.0).abs() < 1e-12 && n.bc == Bc::Support);
            }
        }
        let bc = Mesh::bore_plate(ElementKind::Constant, c, 0.02, &zone, 30, 0.5, 32).unwrap();
        assert!((turning(&bc, c, 0.02) + 2.0 * PI).abs() < 1e-12, "the bore clockwise");
        assert!((turning(&bc, c, 0.5) - 2.0 * PI).abs() < 1e-12);
        // Refusals name the argument.
        let bad = Mesh::bore_plate(ElementKind::Constant, c, 0.02, &zone, 30, 0.01, 32).unwrap_err();
        assert_eq!(bad.argument, "outer_radius");
        let bad = Mesh::counter_disc(ElementKind::Constant, c, 0.5, &zone[..1], 40, Support::Hub { radius: 0.1 });
        assert_eq!(bad.unwrap_err().argument, "zone");
        let bad = Mesh::counter_disc(ElementKind::Constant, c, 0.5, &zone, 40, Support::Hub { radius: 0.6 });
        assert_eq!(bad.unwrap_err().argument, "support");
    }

    #[test]
    fn hub_mesh_normals_point_out_of_the_annulus() {
        let m = Mesh::wheel(2.0, Support::Hub { radius: 0.5 }, &spec(ElementKind::Quadratic)).unwrap();
        for n in &m.nodes {
            let r = n.pos[0].hypot(n.pos[1]);
            let radial = (n.normal[0] * n.pos[0] + n.normal[1] * n.pos[1]) / r;
            if r > 1.0 {
                assert!((radial - 1.0).abs() < 1e-12);
            } else {
                assert!((radial + 1.0).abs() < 1e-12);
                assert_eq!(n.bc, Bc::Support);
            }
        }
        // Contact nodes are in increasing x and symmetric about x = 0.
        let xs: Vec<f64> = m.contact_nodes.iter().map(|&i| m.nodes[i].pos[0]).collect();
        assert!(xs.windows(2).all(|w| w[0] < w[1]));
        assert!((xs[0] + xs[xs.len() - 1]).abs() < 1e-12);
    }
}
