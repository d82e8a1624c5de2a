//! Two finite bodies: the wheel's BEM model against a second BEM body — a disc (the twin-disc rig) or a plate with a
//! circular bore (the pin in a bore, a conformal contact) — each meshed and condensed once like the wheel
//! ([`super::bem_wheel`]), their flexibilities summed in the pair's relative kinematics.
//!
//! **Geometry** (the wheel's frame, `DESIGN.md`): the wheel (radius R₁) is centred at the origin, its potential
//! contact zone around its bottom point. A counter-disc of radius R₂ is centred at (0, −(R₁ + R₂)), touching the
//! wheel at (0, −R₁); a bore of radius R_b ≥ R₁ is centred at (0, R_b − R₁), touching it at the same point from
//! outside (clearance R_b − R₁, zero allowed). The plate's outer boundary is a concentric circle of radius R_o,
//! clamped; a counter-disc is clamped on a hub or on an arc opposite the contact. The counter-body's support is the
//! fixed frame: the rigid modes are the wheel support's, relative to it.
//!
//! **Pairs.** Each wheel contact vertex at polar angle θ casts the ray from the wheel's centre through it; the
//! counter-body's contact vertices are where these rays meet its circle, so that its contact elements face the
//! wheel's one for one and node i of one body (in increasing x) faces node i of the other. The pair's frame is the
//! interface's: N_i = normalize(n₂ − n₁), the bisector of the two bodies' outward normals at the paired nodes (the
//! pressure on the wheel acts along N_i), T_i = (N_y, −N_x): the flat's frame N = y, T = x for two equal discs, the
//! wheel's inward normal in a bore, so the frame turns with a contact arc of any width
//! ([`crate::flexibility::Flexibility::normals`]). The **initial gap** is exact: the distance from the wheel's node
//! along −N_i to the counter-body's boundary as meshed (its circle for quadratic elements, its chord for constant
//! ones: a chord's sagitta is part of the gap, as on the wheel), never x²/2R. Steady rolling takes the slip of the
//! pair's turning frame ([`steady_slip`]).
//!
//! **Flexibility.** Each body is condensed with both traction columns, giving the global 2 × 2 block of
//! displacement per unit nodal force at every pair of contact nodes, K₁ and K₂. A nodal force F on the wheel is −F on
//! the counter-body, so the relative displacement is u₁ − u₂ = (K₁ + K₂) F, projected on the frames:
//! `K_ab(i, j) = a_iᵀ (K₁ + K₂)_ij b_j`, a, b ∈ {N, T}. Friction and normal–tangential coupling then come from both
//! bodies' flexibilities, with no half-space assumption. Each body is made dimensionless by its own size (the wheel
//! by 2R₁, the counter-disc by 2R₂, the plate by 2R_o, so every distance in a body stays ≤ 1, clear of the degenerate
//! scales of the logarithmic kernel) and its own modulus; a 2D flexibility per unit nodal force is then E·u/F in
//! either unit, so K₂ enters the wheel's units multiplied by E₁/E₂.
//!
//! **Interior stresses** ([`build_with`] asked for them): the wheel's boundary response is kept as for one wheel
//! ([`super::Built::boundary`]) and the counter-body's beside it with the pair's frames ([`PairResponse`]), so that
//! each body's field follows from its own boundary solution under the contact tractions (on the counter-body the
//! opposite ones).

use super::{Blocks, Built, SourceInfo, SourceTiming};
use crate::bem::kelvin::Kelvin;
use crate::error::{ArgumentError, Result};
use crate::flexibility::{Flexibility, ModeKind, RigidMode, Scales};
use crate::material::Material;
use crate::mesh::{Mesh, MeshSpec, Shape};
use crate::scene::{Support, Wheel};
use faer::Mat;

/// The second finite body (lengths in the user's unit, moduli in the user's stress unit).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Counter {
    /// A disc of radius `radius` below the wheel, supported on a hub or a clamped arc (`Support::TopArc`: the arc
    /// centred opposite the contact, i.e. at the disc's bottom).
    Disc {
        /// Radius R₂.
        radius: f64,
        /// Its material.
        material: Material,
        /// Its support.
        support: Support,
    },
    /// A plate with a circular bore of radius `radius` ≥ the wheel's (the wheel is the pin), its outer boundary a
    /// concentric circle of radius `outer_radius`, clamped, in `outer_elements` uniform elements.
    Bore {
        /// Bore radius R_b (clearance R_b − R₁ ≥ 0).
        radius: f64,
        /// Outer radius R_o > R_b.
        outer_radius: f64,
        /// Elements on the outer circle (≥ 8).
        outer_elements: usize,
        /// Its material.
        material: Material,
    },
}

/// The scene's second finite body with the number of elements on its boundary beyond the contact zone, when the
/// counter-body is one (`kind = "disc"` or `"bore"`).
pub fn counter_of(body: &crate::scene::CounterBody) -> Option<(Counter, usize)> {
    use crate::scene::CounterBody;
    match *body {
        CounterBody::Disc { material, radius, support, other_elements } => {
            Some((Counter::Disc { radius, material, support }, other_elements))
        }
        CounterBody::Bore { material, radius, outer_radius, other_elements, outer_elements } => {
            Some((Counter::Bore { radius, outer_radius, outer_elements, material }, other_elements))
        }
        _ => None,
    }
}

impl Counter {
    /// Its material.
    pub fn material(&self) -> &Material {
        match self {
            Counter::Disc { material, .. } | Counter::Bore { material, .. } => material,
        }
    }
}

/// A pair of finite bodies: the wheel with its support and mesh, and the counter-body with the number of elements on
/// its boundary beyond the contact zone (its contact zone faces the wheel's, element for element).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct TwoBodies {
    /// The wheel (or pin).
    pub wheel: Wheel,
    /// The wheel's support.
    pub support: Support,
    /// The wheel's mesh (the counter-body's zone follows its contact zone).
    pub spec: MeshSpec,
    /// The counter-body.
    pub counter: Counter,
    /// Elements on the counter-body's circle beyond its contact zone (≥ 4).
    pub counter_other_elements: usize,
}

impl TwoBodies {
    /// A pair of bodies (checked when built, [`build`]).
    pub fn new(
        wheel: Wheel,
        support: Support,
        spec: MeshSpec,
        counter: Counter,
        counter_other_elements: usize,
    ) -> Self {
        TwoBodies { wheel, support, spec, counter, counter_other_elements }
    }

    /// The wheel's reference length L0 = 2R₁.
    fn length(&self) -> f64 {
        2.0 * self.wheel.radius
    }

    /// The counter-body's circle (centre, radius) in the wheel's dimensionless units, and whether the wheel lies
    /// inside it (a bore).
    fn circle(&self) -> ([f64; 2], f64, bool) {
        let l0 = self.length();
        let r1 = 0.5;
        match self.counter {
            Counter::Disc { radius, .. } => {
                let r2 = radius / l0;
                ([0.0, -(r1 + r2)], r2, false)
            }
            Counter::Bore { radius, .. } => {
                let r2 = radius / l0;
                ([0.0, r2 - r1], r2, true)
            }
        }
    }

    /// The counter-body's own reference length: its diameter (disc) or its outer diameter (plate).
    fn counter_length(&self) -> f64 {
        match self.counter {
            Counter::Disc { radius, .. } => 2.0 * radius,
            Counter::Bore { outer_radius, .. } => 2.0 * outer_radius,
        }
    }

    fn check(&self) -> std::result::Result<(), ArgumentError> {
        const F: &str = "two_body::build";
        let r1 = self.wheel.radius;
        let ok = |v: f64| v > 0.0 && v.is_finite();
        match self.counter {
            Counter::Disc { radius, .. } if !ok(radius) => {
                Err(ArgumentError::new(F, "counter.radius", format!("must be finite and > 0, got {radius}")))
            }
            Counter::Bore { radius, .. } if !(radius >= r1 && radius.is_finite()) => Err(ArgumentError::new(
                F,
                "counter.radius",
                format!("a bore's radius must be at least the pin's ({r1}), got {radius}"),
            )),
            _ if !ok(self.counter.material().youngs_modulus) => Err(ArgumentError::new(
                F,
                "counter.material",
                "the counter-body must be elastic (E finite and > 0)".to_string(),
            )),
            _ => Ok(()),
        }
    }
}

/// Where the ray from `p` along the unit `d` first meets the circle (`c`, `r`) from `p` (p inside or outside it),
/// as the distance t ≥ 0 along the ray; `None` if it misses. Stable for p near the circle (no cancellation of
/// t's two terms).
fn ray_circle(p: [f64; 2], d: [f64; 2], c: [f64; 2], r: f64) -> Option<f64> {
    let w = [p[0] - c[0], p[1] - c[1]];
    let b = d[0] * w[0] + d[1] * w[1];
    let wn = w[0].hypot(w[1]);
    let cc = (wn - r) * (wn + r);
    let disc = b * b - cc;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    if cc > 0.0 {
        // Outside: the nearer root, c / (−b + √(b² − c)), when the circle lies ahead.
        (b < 0.0).then(|| cc / (-b + s))
    } else {
        // Inside (or on it): the positive root −c / (b + √(b² − c)).
        Some(if b + s > 0.0 { -cc / (b + s) } else { 0.0 })
    }
}

/// Where the ray from `p` along `d` meets the line through `a` and `b` (distance along the ray).
fn ray_chord(p: [f64; 2], d: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let e = [b[0] - a[0], b[1] - a[1]];
    let cross = |u: [f64; 2], v: [f64; 2]| u[0] * v[1] - u[1] * v[0];
    cross([a[0] - p[0], a[1] - p[1]], e) / cross(d, e)
}

/// Both bodies' dimensionless models (see the module docs).
struct Models {
    wheel: super::bem_wheel::Model,
    counter: super::bem_wheel::Model,
    /// The counter-body's centre in the wheel's units, and its length scale relative to the wheel's (L2/L0).
    centre: [f64; 2],
    scale: f64,
}

/// Mesh both bodies: the wheel as [`Mesh::wheel`], the counter-body's zone on the rays through the wheel's contact
/// vertices.
fn models(b: &TwoBodies) -> std::result::Result<Models, ArgumentError> {
    b.check()?;
    let wheel = super::bem_wheel::Model::new(&b.wheel, b.support, &b.spec)?;
    let l0 = b.length();
    let (c2, r2, _) = b.circle();
    let thetas = crate::mesh::contact_vertex_angles(0.5, &b.spec.zone.scaled(l0));
    let mut zone = Vec::with_capacity(thetas.len());
    for &t in &thetas {
        let d = [t.cos(), t.sin()];
        let Some(s) = ray_circle([0.0, 0.0], d, c2, r2) else {
            return Err(ArgumentError::new(
                "two_body::build",
                "spec.zone",
                "the wheel's contact zone reaches beyond the counter-body's circle".to_string(),
            ));
        };
        zone.push((s * d[1] - c2[1]).atan2(s * d[0] - c2[0]));
    }
    if zone.first() > zone.last() {
        zone.reverse();
    }
    let l2 = b.counter_length();
    let scale = l2 / l0;
    let kind = b.spec.element;
    let n_other = b.counter_other_elements;
    let mesh = match b.counter {
        Counter::Disc { support, .. } => {
            let support = match support {
                Support::Hub { radius } => Support::Hub { radius: radius / l2 },
                s => s,
            };
            Mesh::counter_disc(kind, [0.0, 0.0], r2 / scale, &zone, n_other, support)?
        }
        Counter::Bore { outer_radius, outer_elements, .. } => {
            Mesh::bore_plate(kind, [0.0, 0.0], r2 / scale, &zone, n_other, outer_radius / l2, outer_elements)?
        }
    };
    let m = b.counter.material();
    let counter = super::bem_wheel::Model {
        mesh,
        kelvin: Kelvin::new(1.0, m.poisson_ratio),
        length: l2,
        modulus: m.youngs_modulus,
    };
    Ok(Models { wheel, counter, centre: c2, scale })
}

/// A body's global blocks: `k[(2r + a, 2c + b)]` = displacement component a (0 = x, 1 = y) of contact node r per
/// unit nodal force component b at contact node c, in the body's own dimensionless units, times `factor`.
fn global_blocks(model: &super::bem_wheel::Model, sol: &Mat<f64>, factor: f64) -> Mat<f64> {
    let mesh = &model.mesh;
    let nc = mesh.contact_nodes.len();
    // Right-hand side columns: t_y of contact node c at c, t_x at nc + c (Blocks::All).
    Mat::from_fn(2 * nc, 2 * nc, |i, j| {
        let (r, a) = (i / 2, i % 2);
        let (c, b) = (j / 2, j % 2);
        let col = if b == 1 { c } else { nc + c };
        factor * sol[(2 * mesh.contact_nodes[r] + a, col)] / mesh.nodes[mesh.contact_nodes[c]].weight
    })
}

/// The exact initial gap of each pair: from the wheel's node along its outward normal to the counter-body's
/// boundary as meshed (wheel units).
fn initial_gaps(m: &Models, circle: ([f64; 2], f64), normals: &[[f64; 2]]) -> Vec<f64> {
    let (w, c) = (&m.wheel.mesh, &m.counter.mesh);
    let to_wheel = |p: [f64; 2]| [m.centre[0] + m.scale * p[0], m.centre[1] + m.scale * p[1]];
    w.contact_nodes
        .iter()
        .zip(&c.contact_nodes)
        .zip(normals)
        .map(|((&i, &j), nv)| {
            let (p, d) = (w.nodes[i].pos, [-nv[0], -nv[1]]);
            match c.elements[c.nodes[j].element].shape {
                Shape::Straight { a, b } => ray_chord(p, d, to_wheel(a), to_wheel(b)),
                Shape::Arc(_) => ray_circle(p, d, circle.0, circle.1).unwrap_or(f64::NAN),
            }
        })
        .collect()
}

/// The pair's normal N_i: the bisector of the two bodies' normals at the paired nodes, normalize(n₂ − n₁) — the
/// normal of the interface the two surfaces meet on (for two equal discs exactly the flat's N = y; for a bore the
/// wheel's inward normal to O(ΔR/R)). The frame of the pair's slip must be the interface's, not one body's: with the
/// wheel's own normal the frame would turn by 1/R₁ per unit length along a flat interface, and the steady-rolling
/// slip ∂u_T/∂x would pick up the rigid approach times 1/R₁ (a spurious creepage of order δ/R₁).
fn pair_normals(w: &Mesh, c: &Mesh) -> Vec<[f64; 2]> {
    w.contact_nodes
        .iter()
        .zip(&c.contact_nodes)
        .map(|(&i, &j)| {
            let (n1, n2) = (w.nodes[i].normal, c.nodes[j].normal);
            let v = [n2[0] - n1[0], n2[1] - n1[1]];
            let len = v[0].hypot(v[1]);
            [v[0] / len, v[1] / len]
        })
        .collect()
}

/// The counter-body's whole boundary response to unit contact tractions and the pair's frames, kept when the scene
/// asks for interior stresses ([`build_with`]). The counter-body's model is its own: lengths over its length L₂,
/// stresses over its modulus, its centre at the origin; its contact node i faces the wheel's contact node i.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct PairResponse {
    /// The counter-body's response (its model, dimensionless by its own length and modulus).
    pub counter: super::bem_wheel::BoundaryResponse,
    /// The pair's normal N_i at each contact node (the pressure on the wheel acts along N_i, the shear along
    /// T_i = (N_y, −N_x)).
    pub normals: Vec<[f64; 2]>,
    /// The counter-body's centre in the wheel's dimensionless units (lengths over L₀ = 2R₁, the wheel's centre at
    /// the origin).
    pub centre: [f64; 2],
    /// L₂/L₀: a length in the counter-body's units times this is one in the wheel's.
    pub scale: f64,
    /// The counter-body's circle (radius) and its hub's radius (0 for a clamped arc), in its own units.
    pub radius: f64,
    /// The hub's radius in its own units (0 without a hub).
    pub hub: f64,
}

/// The steady-rolling slip operator of a pair of finite bodies rolling in direction `direction` (±1): the upwind
/// difference of [`crate::formulation::SlipOperator::steady`] on the contact nodes' x, plus the frame's turning.
/// The slip is the tangential component of the derivative of the relative displacement vector,
/// T·∂Δu/∂x = ∂u_T/∂x − κ u_N with κ = dψ/dx the rate at which the pair's frame turns (ψ the angle of T); in contact
/// the relative normal displacement (rigid motion included) is u_N = −g₀, so the offset is c_i = −dir κ_i g₀,i
/// (zero for two equal discs, whose interface is flat; where a node is separated its slip carries no traction).
pub fn steady_slip(flex: &Flexibility, direction: i32) -> crate::formulation::SlipOperator {
    let mut op = crate::formulation::SlipOperator::steady(&flex.x, direction);
    let Some(normals) = &flex.normals else { return op };
    let n = flex.n();
    let angle = |i: usize| -normals[i][0].atan2(normals[i][1]);
    let kappa = |i: usize| {
        let (lo, hi) = (i.saturating_sub(1), (i + 1).min(n - 1));
        if hi == lo {
            0.0
        } else {
            (angle(hi) - angle(lo)) / (flex.x[hi] - flex.x[lo])
        }
    };
    op.offset = Some((0..n).map(|i| -f64::from(direction) * kappa(i) * flex.g0[i]).collect());
    op
}

/// Build the flexibility of a pair of finite bodies with the blocks asked for (see the module docs). A pair it
/// cannot mesh is refused, naming the argument; a singular BEM system is [`crate::error::Error::Numerical`].
pub fn build(bodies: &TwoBodies, blocks: Blocks) -> Result<Built> {
    build_with(bodies, blocks, false)
}

/// [`build`], keeping both bodies' boundary responses when `responses` is true (a scene with `[stresses]`): the
/// wheel's in [`Built::boundary`], the counter-body's with the pair's frames in [`Built::pair`].
pub fn build_with(bodies: &TwoBodies, blocks: Blocks, responses: bool) -> Result<Built> {
    let m = models(bodies)?;
    let (_, h1, t1, sol1) = super::bem_wheel::condense_with_response(&m.wheel, Blocks::All)?;
    let (_, h2, t2, sol2) = super::bem_wheel::condense_with_response(&m.counter, Blocks::All)?;
    let (wm, cm) = (&m.wheel.mesh, &m.counter.mesh);
    let n = wm.contact_nodes.len();
    // K₁ + K₂ in the wheel's units (K₂ times E₁/E₂), global components.
    let k1 = global_blocks(&m.wheel, &sol1, 1.0);
    let k2 = global_blocks(&m.counter, &sol2, m.wheel.modulus / m.counter.modulus);
    let k = k1 + k2;
    let normals = pair_normals(wm, cm);
    let tangent = |v: [f64; 2]| [v[1], -v[0]];
    let project = |a: &dyn Fn(usize) -> [f64; 2], b: &dyn Fn(usize) -> [f64; 2]| {
        Mat::from_fn(n, n, |i, j| {
            let (ai, bj) = (a(i), b(j));
            let mut v = 0.0;
            for p in 0..2 {
                for q in 0..2 {
                    v += ai[p] * k[(2 * i + p, 2 * j + q)] * bj[q];
                }
            }
            v
        })
    };
    let nn = |i: usize| normals[i];
    let tt = |i: usize| tangent(normals[i]);
    let all = blocks != Blocks::Normal;
    let coupled = blocks == Blocks::All;
    // Rigid modes of the wheel's support relative to the fixed counter-body, projected on the frames.
    let rot0 = sol1.ncols() - 1;
    let rotation: Vec<[f64; 2]> =
        wm.contact_nodes.iter().map(|&i| [sol1[(2 * i, rot0)], sol1[(2 * i + 1, rot0)]]).collect();
    let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
    let mode = |kind: ModeKind, u: &dyn Fn(usize) -> [f64; 2]| RigidMode {
        kind,
        normal: (0..n).map(|i| dot(nn(i), u(i))).collect(),
        tangential: all.then(|| (0..n).map(|i| dot(tt(i), u(i))).collect()),
    };
    let modes = vec![
        mode(ModeKind::Shift, &|_| [1.0, 0.0]),
        mode(ModeKind::Approach, &|_| [0.0, -1.0]),
        mode(ModeKind::Rotation, &|i| rotation[i]),
    ];
    let (c2, r2, _) = bodies.circle();
    let g0 = initial_gaps(&m, (c2, r2), &normals);
    let flex = Flexibility {
        k_nn: project(&nn, &nn),
        k_nt: coupled.then(|| project(&nn, &tt)),
        k_tn: coupled.then(|| project(&tt, &nn)),
        k_tt: all.then(|| project(&tt, &tt)),
        modes,
        x: wm.contact_nodes.iter().map(|&i| wm.nodes[i].pos[0]).collect(),
        y: wm.contact_nodes.iter().map(|&i| wm.nodes[i].pos[1]).collect(),
        g0,
        weights: wm.contact_nodes.iter().map(|&i| wm.nodes[i].weight).collect(),
        normals: Some(normals),
        scales: Scales { length: m.wheel.length, modulus: m.wheel.modulus },
        id: Default::default(),
        derived: Default::default(),
    };
    debug_assert_eq!(cm.contact_nodes.len(), n);
    let info = SourceInfo {
        elements: wm.elements.len() + cm.elements.len(),
        nodes: wm.n_nodes() + cm.n_nodes(),
        element: bodies.spec.element,
        system_size: Some(h1.system_size.max(h2.system_size)),
        pivot_ratio: Some(h1.pivot_ratio.max(h2.pivot_ratio)),
        condition: Some(h1.system_condition.max(h2.system_condition)),
        contact_element_length: bodies.spec.zone.element_length(bodies.wheel.radius),
        viscoelastic: false,
    };
    let (boundary, pair) = if responses {
        let (boundary, pair) = keep_responses(bodies, m, sol1, sol2, flex.normals.clone().unwrap_or_default());
        (Some(boundary), Some(pair))
    } else {
        (None, None)
    };
    Ok(Built {
        info,
        flex,
        timing: SourceTiming { assembly: t1.assembly + t2.assembly, condensation: t1.condensation + t2.condensation },
        boundary,
        pair,
    })
}

/// Both bodies' boundary responses (both built with the tangential columns), the counter-body's with the pair's
/// frames.
fn keep_responses(
    bodies: &TwoBodies,
    m: Models,
    sol1: Mat<f64>,
    sol2: Mat<f64>,
    normals: Vec<[f64; 2]>,
) -> (super::bem_wheel::BoundaryResponse, PairResponse) {
    use super::bem_wheel::BoundaryResponse;
    let l2 = bodies.counter_length();
    let hub = match bodies.counter {
        Counter::Disc { support: Support::Hub { radius }, .. } => radius / l2,
        _ => 0.0,
    };
    let radius = match bodies.counter {
        Counter::Disc { radius, .. } | Counter::Bore { radius, .. } => radius / l2,
    };
    let wheel = BoundaryResponse { model: m.wheel, matrix: sol1, tangential: true };
    let counter = BoundaryResponse { model: m.counter, matrix: sol2, tangential: true };
    (wheel, PairResponse { counter, normals, centre: m.centre, scale: m.scale, radius, hub })
}
