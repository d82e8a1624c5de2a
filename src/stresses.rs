//! Subsurface stresses (`[stresses]` in a scene): the wheel's stress field on a regular grid below the contact,
//! computed from a run's solved contact tractions, with its maxima.
//!
//! # Grid and axes
//! x runs along the surface as in the node results; the depth z is measured from the flat (the line y = −R that the
//! undeformed wheel touches at x = 0), positive into the wheel: the grid point (x, z) is the point (x, z − R) of the
//! wheel's axes, and the point at depth z of the half-plane model. Nodes are `x_i = x₀ + i (x₁ − x₀)/(nx − 1)`,
//! `z_j = z₀ + j (z₁ − z₀)/(nz − 1)`; every field is stored row-major, index `j·nx + i`, row 0 the shallowest.
//!
//! # Quantities ([`StressQuantity`])
//! In the (x, z) axes, plane strain, **tension positive**, in the scene's stress unit: `sxx` = σ_xx, `szz` = σ_zz,
//! `txz` = τ_xz (z points into the wheel, so on the loaded surface σ_zz = −p and τ_xz = −q for the tractions p, q
//! acting on the wheel), `syy` = ν(σ_xx + σ_zz), `principal_shear` = τ₁ = √(((σ_xx − σ_zz)/2)² + τ_xz²),
//! `von_mises` = √(½[(σ_xx − σ_yy)² + (σ_yy − σ_zz)² + (σ_zz − σ_xx)²] + 3τ_xz²) and `orthogonal_shear` = τ_xz.
//! The **maximum** of a quantity is its grid value of largest magnitude, sign kept (so the maximum of σ_zz is its
//! most compressive value), with its position; only points that have a value count.
//!
//! # The two models of the wheel
//! * **Half-plane** (`[wheel] model = "half_plane"`): the closed-form field of uniform-traction strips
//!   ([`crate::halfplane::strip_stress`], Johnson §2.6–2.7) superposed over the contact grid's strips, each carrying
//!   its node's (p, q). It is exact for the piecewise-uniform tractions at every depth z ≥ 0. On the surface (z = 0)
//!   the value is the limit z → 0⁺ (σ_zz = −p, τ_xz = −q under a strip); exactly at a strip edge on the surface
//!   σ_xx of a shear strip is infinite (a log singularity of the piecewise-uniform shear): that point (up to
//!   round-off, 1e-9 of a strip width) is refused as [`PointError::Singular`]. Near such an edge the surface value
//!   of σ_xx is that of the piecewise-uniform shear, (2Δq/π) ln(h/d) away from the continuous traction's at a
//!   distance d from an edge where the shear jumps by Δq: a surface row meant to stand for the continuous contact
//!   is best placed at the strips' centres.
//! * **Finite wheel** (`model = "bem"`): the Somigliana identity for stresses ([`crate::bem::stress`]) on the whole
//!   boundary solution. After the contact solve, the boundary problem is solved again with the contact tractions as
//!   known data and the support clamped in place, by superposition of the boundary's responses to unit contact
//!   tractions that the condensation computed anyway ([`crate::source::bem_wheel::BoundaryResponse`]): nothing is
//!   assembled or factorised again. The support's rigid motion is left out, since a rigid motion is stress-free.
//!   The quadrature is accurate to ~1e-9 of the stress scale up to the boundary, but the boundary data are
//!   discontinuous between elements (constant or discontinuous quadratic), which spoils the field within a few
//!   element lengths of the boundary ([`crate::bem::stress`], "Interpolation"). A grid with a point closer to an
//!   element than [`STRESS_NEAR_BOUNDARY_CONSTANT`] (2.5, constant elements) or [`STRESS_NEAR_BOUNDARY_QUADRATIC`]
//!   (0.5, quadratic) of its lengths, or a point outside the wheel (below its undeformed surface, or in the hub's
//!   hole), is therefore refused before anything is solved, as an input error naming `stresses.depth` (or
//!   `stresses.x`) and the first such point (exit code 2, nothing written): never a wrong value.
//!
//! With an elastic counter-body (`[counter_body] kind = "half_plane"`) the counter-body's own field is computed
//! beside the wheel's ([`StressEvaluator::evaluate_counter_body`]): the half-plane below the contact under the
//! opposite tractions, on the same grid, depth measured into it. A counter-disc (`kind = "disc"`, two finite bodies,
//! [`crate::source::two_body`]) gets its own BEM field the same way: its boundary solution under the opposite
//! tractions along the pair's frames, the grid's depth measured into it from the contact point, τ_xz in its (x,
//! depth) axes, its points refused near its boundary as the wheel's are (tests/two_bodies.rs: both discs' fields
//! against McEwen's at a/R = 0.01 and 0.005). A bore's plate has no field (refused with `[stresses]`).
//!
//! # The surface
//! Besides the grid, every field is evaluated on the surface (depth 0) at the contact elements' centres — the
//! half-plane's closed form there, the BEM wheel's boundary stress from its tractions and the tangential strain of
//! its boundary displacement — and the maxima include those points. Sliding contacts peak there (τ₁ = μp₀ at every
//! surface point of a contact in full slip for μ ≥ 1/√7, Smith & Liu 1953), and a grid's surface row on the
//! elements' edges is refused (the half-plane's singular σ_xx), so without them the maximum would be reported below
//! the surface.
//!
//! # Where and when
//! Only a scene with `[stresses]` computes anything ("simulate only the effects a scene calls for"). Every solved
//! run gets its field ([`crate::pipeline::run_scene`]); a load path computes it at the end of each step (its last
//! substep; the intermediate substeps of a step are increments towards that end and are not reported), so the
//! path's final runs carry the field at the path's end (`crate::pipeline::path`).
//!
//! # Output
//! `runs[].stresses` of the result document ([`StressResult`]): the grid, the quantities, `maxima.<quantity> =
//! {value, x, depth}`, the number of refused points per reason, the evaluation time and the field: inline
//! (`field.values.<quantity>`, with `null` where a point is refused and `field.error` naming the reason per point)
//! for grids of up to [`MAX_INLINE_POINTS`] points, and for larger grids in a CSV file beside the JSON document
//! (`csv` names it; `rollbem run --json` writes it, [`StressResult::spill`]).

use crate::bem::stress::{InteriorStress, StressError};
use crate::error::{ArgumentError, Error};
use crate::halfplane::strip_stress;
use crate::mesh::{Mesh, Shape};
use crate::post::NodeResult;
pub use crate::scene::StressQuantity;
use crate::scene::{BodyModel, ElementKind, Scene, Support};
use crate::source::bem_wheel::BoundaryResponse;
use crate::source::two_body::PairResponse;
use crate::source::{half_plane::Grid, Built};
use crate::tolerances::{STRESS_NEAR_BOUNDARY_CONSTANT, STRESS_NEAR_BOUNDARY_QUADRATIC};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

/// Largest grid (nx·nz points) whose field is written inline in the result document; larger fields go to a CSV file
/// beside it.
pub const MAX_INLINE_POINTS: usize = 20_000;

/// Why a grid point has no value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum PointError {
    /// Outside the wheel: below its undeformed surface, or in the hub's hole (BEM wheel; such a grid is refused
    /// as an input error by [`StressEvaluator::new`], so a result never holds it).
    OutsideBody,
    /// Closer to an element than [`STRESS_NEAR_BOUNDARY_CONSTANT`] or [`STRESS_NEAR_BOUNDARY_QUADRATIC`] of its
    /// lengths (BEM wheel): the discontinuous boundary data would make the value wrong there (refused as an input
    /// error by [`StressEvaluator::new`], like [`PointError::OutsideBody`]).
    NearBoundary,
    /// A singular point of the discrete field: on the surface exactly at the edge of a half-plane strip carrying
    /// shear (σ_xx infinite), or any other non-finite value.
    Singular,
}

impl PointError {
    /// Name as written in results.
    pub fn name(self) -> &'static str {
        match self {
            PointError::OutsideBody => "outside_body",
            PointError::NearBoundary => "near_boundary",
            PointError::Singular => "singular",
        }
    }
}

/// The regular grid of a `[stresses]` table (user's length unit; module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[non_exhaustive]
pub struct StressGrid {
    /// `[min, max]` of x.
    pub x: [f64; 2],
    /// `[min, max]` of the depth.
    pub depth: [f64; 2],
    /// `[nx, nz]`.
    pub points: [usize; 2],
}

impl StressGrid {
    /// x of node column `i`.
    pub fn x_at(&self, i: usize) -> f64 {
        lerp(self.x, i, self.points[0])
    }

    /// Depth of node row `j`.
    pub fn depth_at(&self, j: usize) -> f64 {
        lerp(self.depth, j, self.points[1])
    }

    /// Number of points nx·nz.
    pub fn len(&self) -> usize {
        self.points[0] * self.points[1]
    }

    /// Whether the grid has no points (never, for a validated scene).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// `(x, depth)` of point `k` (row-major).
    pub fn point(&self, k: usize) -> (f64, f64) {
        // A grid has at least one column (a validated scene's); `max(1)` keeps an edited one from dividing by 0.
        let nx = self.points[0].max(1);
        (self.x_at(k % nx), self.depth_at(k / nx))
    }
}

/// Node `i` of `n` evenly spaced from `r[0]` to `r[1]` (the ends exact).
fn lerp(r: [f64; 2], i: usize, n: usize) -> f64 {
    if i + 1 == n {
        r[1]
    } else {
        r[0] + (r[1] - r[0]) * i as f64 / (n - 1) as f64
    }
}

/// The value of a quantity for the stress `s = [σ_xx, σ_zz, τ_xz]` and Poisson's ratio `nu` (module docs).
pub fn quantity(q: StressQuantity, s: [f64; 3], nu: f64) -> f64 {
    let [sxx, szz, txz] = s;
    let syy = nu * (sxx + szz);
    match q {
        StressQuantity::Sxx => sxx,
        StressQuantity::Szz => szz,
        StressQuantity::Txz | StressQuantity::OrthogonalShear => txz,
        StressQuantity::Syy => syy,
        StressQuantity::PrincipalShear => (0.5 * (sxx - szz)).hypot(txz),
        StressQuantity::VonMises => {
            let (a, b, c) = (sxx - syy, syy - szz, szz - sxx);
            (0.5 * (a * a + b * b + c * c) + 3.0 * txz * txz).sqrt()
        }
    }
}

/// The largest-magnitude value of a quantity on the grid and where it is (user's units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Maximum {
    /// The value (sign kept).
    pub value: f64,
    /// x of the point.
    pub x: f64,
    /// Depth of the point.
    pub depth: f64,
}

/// The stress tensor at every grid point, or why a point has none (user's units).
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct StressField {
    /// The grid.
    pub grid: StressGrid,
    /// Poisson's ratio of the wheel (for σ_yy and von Mises).
    pub nu: f64,
    /// `[σ_xx, σ_zz, τ_xz]` per point, row-major.
    pub stress: Vec<Result<[f64; 3], PointError>>,
    /// The surface (depth 0) at the contact elements' centres: (x, `[σ_xx, σ_zz, τ_xz]`) — where the stresses of a
    /// sliding contact peak (the maximum principal shear is μ p₀ at every surface point of a contact in full slip,
    /// Smith & Liu 1953) and where a grid's surface row may fall on element edges.
    pub surface: Vec<(f64, Result<[f64; 3], PointError>)>,
}

impl StressField {
    /// The value of `q` at point `k`, if the grid has that point and the point has a value.
    pub fn value(&self, q: StressQuantity, k: usize) -> Option<f64> {
        self.stress.get(k)?.ok().map(|s| quantity(q, s, self.nu))
    }

    /// The maximum of `q` (largest magnitude, first in row-major order on ties), if any point has a value.
    pub fn maximum(&self, q: StressQuantity) -> Option<Maximum> {
        let mut best: Option<Maximum> = None;
        let mut consider = |value: f64, x: f64, depth: f64| {
            if best.is_none_or(|b| value.abs() > b.value.abs()) {
                best = Some(Maximum { value, x, depth });
            }
        };
        for k in 0..self.stress.len() {
            if let Some(v) = self.value(q, k) {
                let (x, depth) = self.grid.point(k);
                consider(v, x, depth);
            }
        }
        // The surface after the grid: a surface value wins only when it is strictly larger.
        for (x, st) in &self.surface {
            if let Ok(st) = st {
                consider(quantity(q, *st, self.nu), *x, 0.0);
            }
        }
        best
    }

    /// The field as CSV: columns `x, depth`, one per quantity, and `error` (empty unless the point is refused,
    /// then its reason and empty values); one row per point, row-major.
    pub fn csv(&self, quantities: &[StressQuantity]) -> String {
        use std::fmt::Write as _;
        let mut out = String::from("x,depth");
        for q in quantities {
            out.push(',');
            out.push_str(q.name());
        }
        out.push_str(",error\n");
        for (k, s) in self.stress.iter().enumerate() {
            let (x, z) = self.grid.point(k);
            write!(out, "{x:e},{z:e}").expect("writing to a String");
            for &q in quantities {
                match s {
                    Ok(s) => write!(out, ",{:e}", quantity(q, *s, self.nu)).expect("writing to a String"),
                    Err(_) => out.push(','),
                }
            }
            writeln!(out, ",{}", s.err().map_or("", |e| e.name())).expect("writing to a String");
        }
        out
    }
}

/// The subsurface stresses of one run (`runs[].stresses` in the result document; module docs). It serialises and
/// deserialises as the document's keys; the stress tensor at every point ([`StressResult::field`]) is kept in memory
/// after an evaluation and is not part of the document (its quantities' values are, in `field`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct StressResult {
    /// What body the field is in (`wheel`).
    #[serde(default = "wheel")]
    pub body: String,
    /// Which model of the wheel produced the field.
    pub model: BodyModel,
    /// The grid.
    pub grid: StressGrid,
    /// The quantities reported.
    pub quantities: Vec<StressQuantity>,
    /// The maximum of every reported quantity (largest |value|, sign kept, and where), in the quantities' order.
    #[serde(with = "ordered_maxima")]
    pub maxima: Vec<(StressQuantity, Option<Maximum>)>,
    /// Number of refused points per reason.
    pub refused: BTreeMap<String, usize>,
    /// Wall-clock time of the evaluation, seconds.
    pub time_s: f64,
    /// The quantities' values at the grid points (null once [`StressResult::spill`] moved them to a CSV file).
    #[serde(rename = "field")]
    pub values: Option<FieldValues>,
    /// The quantities at the surface, at the contact elements' centres (included in the maxima).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surface: Option<SurfaceValues>,
    /// The CSV file beside the result document that holds the field, once [`StressResult::spill`] moved it there.
    pub csv: Option<String>,
    /// The stress tensor at every point, in memory after an evaluation (empty when read back from a document).
    #[serde(skip)]
    pub field: StressField,
}

fn wheel() -> String {
    "wheel".into()
}

/// The inline field of the document: node coordinates, one array per quantity (null where refused, row-major) and
/// the reason per refused point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct FieldValues {
    /// x of the grid's columns.
    pub x: Vec<f64>,
    /// Depth of the grid's rows.
    pub depth: Vec<f64>,
    /// Per quantity name, its value at every point (row-major; null where refused).
    pub values: BTreeMap<String, Vec<Option<f64>>>,
    /// Per point, why it has no value (null where it has one).
    pub error: Vec<Option<PointError>>,
}

/// The surface values of the document: x of the contact elements' centres (depth 0) and, per quantity name, its
/// value there (null where refused).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SurfaceValues {
    /// x of the points.
    pub x: Vec<f64>,
    /// Per quantity name, its value at every point.
    pub values: BTreeMap<String, Vec<Option<f64>>>,
}

impl StressResult {
    /// The document form of an evaluated field.
    pub fn of(model: BodyModel, quantities: Vec<StressQuantity>, field: StressField, time_s: f64) -> StressResult {
        let g = field.grid;
        let maxima = quantities.iter().map(|&q| (q, field.maximum(q))).collect();
        let mut refused = BTreeMap::new();
        for e in field.stress.iter().filter_map(|s| s.err()) {
            *refused.entry(e.name().to_string()).or_insert(0) += 1;
        }
        let surface = (!field.surface.is_empty()).then(|| SurfaceValues {
            x: field.surface.iter().map(|(x, _)| *x).collect(),
            values: quantities
                .iter()
                .map(|&q| {
                    let v = field.surface.iter().map(|(_, s)| s.ok().map(|s| quantity(q, s, field.nu))).collect();
                    (q.name().to_string(), v)
                })
                .collect(),
        });
        let values = FieldValues {
            x: (0..g.points[0]).map(|i| g.x_at(i)).collect(),
            depth: (0..g.points[1]).map(|j| g.depth_at(j)).collect(),
            values: quantities
                .iter()
                .map(|&q| (q.name().to_string(), (0..field.stress.len()).map(|k| field.value(q, k)).collect()))
                .collect(),
            error: field.stress.iter().map(|s| s.err()).collect(),
        };
        StressResult {
            body: wheel(),
            model,
            grid: g,
            quantities,
            maxima,
            refused,
            time_s,
            values: Some(values),
            surface,
            csv: None,
            field,
        }
    }

    /// The maximum of every reported quantity, in the order of [`StressResult::quantities`].
    pub fn maxima(&self) -> Vec<(StressQuantity, Option<Maximum>)> {
        self.maxima.clone()
    }

    /// The maximum of one reported quantity (grid and surface), if it has one.
    pub fn maximum_of(&self, q: StressQuantity) -> Option<Maximum> {
        self.maxima.iter().find(|(m, _)| *m == q).and_then(|(_, v)| *v)
    }

    /// Number of refused points per reason.
    pub fn refused(&self) -> BTreeMap<String, usize> {
        self.refused.clone()
    }

    /// For a grid of more than [`MAX_INLINE_POINTS`] points: name the CSV file `file` (a name beside the result
    /// document) in place of the inline field and return its text; `None` (and nothing changed) for a small grid.
    pub fn spill(&mut self, file: &str) -> Option<String> {
        if self.grid.len() <= MAX_INLINE_POINTS {
            return None;
        }
        self.csv = Some(file.to_string());
        self.values = None;
        Some(self.field.csv(&self.quantities))
    }
}

/// `maxima` as a JSON object keyed by quantity name, in the quantities' order (both ways).
mod ordered_maxima {
    use super::{Maximum, StressQuantity};
    use serde::ser::SerializeMap;
    use serde::{Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &[(StressQuantity, Option<Maximum>)], s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(v.len()))?;
        for (q, x) in v {
            m.serialize_entry(q, x)?;
        }
        m.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<(StressQuantity, Option<Maximum>)>, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = Vec<(StressQuantity, Option<Maximum>)>;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a map of stress maxima by quantity")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut m: A) -> Result<Self::Value, A::Error> {
                let mut out = Vec::new();
                while let Some(e) = m.next_entry()? {
                    out.push(e);
                }
                Ok(out)
            }
        }
        d.deserialize_map(V)
    }
}

/// What the evaluation needs of the wheel model.
#[derive(Debug)]
enum Body<'a> {
    /// The half-plane's strips `[a_j, b_j]` (user's length unit), one per contact node.
    HalfPlane { a: Vec<f64>, b: Vec<f64> },
    /// The BEM wheel: its boundary response, the dimensionless grid points and, per point, why it is refused; with
    /// a second finite body, the pair's normals (the contact tractions act along them, not along y and x).
    Wheel {
        response: &'a BoundaryResponse,
        points: Vec<[f64; 2]>,
        refused: Vec<Option<PointError>>,
        normals: Option<&'a [[f64; 2]]>,
    },
}

/// An elastic counter-body's field.
#[derive(Debug)]
enum CounterField<'a> {
    /// A half-plane: its strips (the contact grid's, user's length unit) and its ν.
    HalfPlane { a: Vec<f64>, b: Vec<f64>, nu: f64 },
    /// A finite disc (`[counter_body] kind = "disc"`): its boundary response with the pair's frames, the grid points
    /// in its own dimensionless axes (depth measured into it from the contact point) and, per point, why refused.
    Disc { pair: &'a PairResponse, points: Vec<[f64; 2]>, refused: Vec<Option<PointError>> },
}

/// The contact tractions on a body as the global components its boundary response takes, (t_y, t_x), divided by
/// `e`: on the wheel (`sign` = 1) the pressure acts along the pair's normal N and the shear along T = (N_y, −N_x)
/// (N = y, T = x without a second finite body), on the counter-body (`sign` = −1) the opposite.
fn global_tractions(nodes: &[NodeResult], normals: Option<&[[f64; 2]]>, sign: f64, e: f64) -> (Vec<f64>, Vec<f64>) {
    let n = |i: usize| normals.map_or([0.0, 1.0], |v| v[i]);
    let ty = nodes.iter().enumerate().map(|(i, v)| sign * (v.pressure * n(i)[1] - v.shear * n(i)[0]) / e).collect();
    let tx = nodes.iter().enumerate().map(|(i, v)| sign * (v.pressure * n(i)[0] + v.shear * n(i)[1]) / e).collect();
    (ty, tx)
}

/// The stress evaluation of a scene, set up once and applied to every solved run ([`StressEvaluator::evaluate`]).
#[derive(Debug)]
pub struct StressEvaluator<'a> {
    grid: StressGrid,
    quantities: Vec<StressQuantity>,
    model: BodyModel,
    nu: f64,
    modulus: f64,
    body: Body<'a>,
    /// An elastic counter-body's field (`None` for a rigid flat, or a bore: no field).
    counter: Option<CounterField<'a>>,
}

impl<'a> StressEvaluator<'a> {
    /// The evaluator of a validated scene on its built source, or `None` when the scene has no `[stresses]`.
    /// Called before anything is solved, so that a grid the BEM wheel cannot evaluate is refused at once.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `stresses.depth` (or `stresses.x`, `path` the scene file) when a grid point of the
    /// BEM wheel lies outside the wheel or within [`STRESS_NEAR_BOUNDARY_CONSTANT`] (constant elements) or
    /// [`STRESS_NEAR_BOUNDARY_QUADRATIC`] (quadratic) element lengths of its boundary, where the discontinuous
    /// boundary data would make the value wrong (module docs). The message names the first such point, its distance
    /// to the boundary and what would fix it.
    ///
    /// [`Error::Unsupported`] when the scene's wheel is a BEM wheel but `built` kept no boundary response (a source
    /// keeps one whenever the scene it was built for has `[stresses]`, [`crate::source::build`]).
    pub fn new(scene: &Scene, built: &'a Built) -> crate::error::Result<Option<StressEvaluator<'a>>> {
        let Some(spec) = scene.stresses() else { return Ok(None) };
        let path = scene.origin();
        let grid = StressGrid { x: spec.x, depth: spec.depth, points: spec.points };
        let l0 = built.flex.scales.length;
        let body = match scene.model() {
            BodyModel::HalfPlane => {
                let g = Grid::of(scene);
                Body::HalfPlane { a: g.a.iter().map(|v| v * l0).collect(), b: g.b.iter().map(|v| v * l0).collect() }
            }
            BodyModel::Bem => {
                let Some(response) = built.boundary.as_ref() else {
                    return Err(crate::error::Error::Unsupported {
                        path: path.to_path_buf(),
                        message: "stresses: the model was built without the boundary response the BEM wheel's \
                                  stresses need (build it from a scene with [stresses])"
                            .into(),
                    });
                };
                let r = scene.radius();
                let hub = match scene.body() {
                    crate::scene::Body::Bem { support: Support::Hub { radius }, .. } => *radius,
                    _ => 0.0,
                };
                let points: Vec<[f64; 2]> = (0..grid.len())
                    .map(|k| {
                        let (x, z) = grid.point(k);
                        [x / l0, (z - r) / l0]
                    })
                    .collect();
                let mesh = &response.model.mesh;
                let refused: Vec<Option<PointError>> =
                    points.par_iter().map(|&p| refusal(mesh, p, r / l0, hub / l0)).collect();
                if let Some(k) = refused.iter().position(Option::is_some) {
                    return Err(refused_grid(&grid, &refused, k, mesh, points[k], (l0, r), path, "BEM wheel"));
                }
                let normals = built.pair.as_ref().map(|p| p.normals.as_slice());
                Body::Wheel { response, points, refused, normals }
            }
        };
        let counter = match scene.counter_body() {
            crate::scene::CounterBody::HalfPlane { material, .. } => {
                let g = Grid::of(scene);
                let scale = |v: &[f64]| v.iter().map(|x| x * l0).collect::<Vec<f64>>();
                Some(CounterField::HalfPlane { a: scale(&g.a), b: scale(&g.b), nu: material.poisson_ratio })
            }
            crate::scene::CounterBody::Disc { radius, .. } => Some(disc_field(scene, built, &grid, *radius, path)?),
            _ => None,
        };
        Ok(Some(StressEvaluator {
            grid,
            quantities: spec.quantities(),
            model: scene.model(),
            nu: scene.wheel().material.poisson_ratio,
            modulus: scene.wheel().material.youngs_modulus,
            body,
            counter,
        }))
    }

    /// The number of contact nodes of the source: the length of the `nodes` that [`StressEvaluator::evaluate`] takes.
    pub fn contact_nodes(&self) -> usize {
        match &self.body {
            Body::HalfPlane { a, .. } => a.len(),
            Body::Wheel { response, .. } => response.model.mesh.contact_nodes.len(),
        }
    }

    /// `nodes` of one entry per contact node of the source, else the error naming them.
    fn check_nodes(&self, function: &'static str, nodes: &[NodeResult]) -> Result<(), ArgumentError> {
        if nodes.len() == self.contact_nodes() {
            return Ok(());
        }
        Err(ArgumentError::new(
            function,
            "nodes",
            format!(
                "has {} entries, the source {} contact nodes: a run of another model?",
                nodes.len(),
                self.contact_nodes()
            ),
        ))
    }

    /// The field of a solved run from its contact nodes' tractions (`pressure`, `shear`, user's units, in contact-node
    /// order), evaluated in parallel over the grid points. `nodes` without one entry per contact node of the source
    /// ([`StressEvaluator::contact_nodes`]) are refused.
    pub fn evaluate(&self, nodes: &[NodeResult]) -> Result<StressResult, ArgumentError> {
        self.check_nodes("StressEvaluator::evaluate", nodes)?;
        let t0 = Instant::now();
        let (stress, surface) = match &self.body {
            Body::HalfPlane { a, b } => (half_plane_field(&self.grid, a, b, nodes), half_plane_surface(a, b, nodes)),
            Body::Wheel { response, points, refused, normals } => {
                let (ty, tx) = global_tractions(nodes, *normals, 1.0, self.modulus);
                bem_field(response, &ty, &tx, points, refused, 1.0)?
            }
        };
        let field = StressField { grid: self.grid, nu: self.nu, stress, surface };
        Ok(StressResult::of(self.model, self.quantities.clone(), field, t0.elapsed().as_secs_f64()))
    }

    /// The elastic counter-body's field from the same run (`None` for a rigid flat): the half-plane below the
    /// contact loaded by the opposite tractions, on the same grid with depth measured into the counter-body and x
    /// as on the wheel. Mirrored into the wheel's configuration the counter-body carries the pressure p and the
    /// shear −q, so its field is the half-plane formula with (p, −q) and its own ν; τ_xz is in its (x, depth) axes.
    /// Refused as [`StressEvaluator::evaluate`].
    ///
    /// A finite disc's field (`[counter_body] kind = "disc"`) is its own BEM solution under the opposite contact
    /// tractions (along the pair's frames), on the same grid with depth measured into the disc from the contact
    /// point and x as on the wheel, τ_xz in its (x, depth) axes.
    pub fn evaluate_counter_body(&self, nodes: &[NodeResult]) -> Result<Option<StressResult>, ArgumentError> {
        let (a, b, nu) = match self.counter.as_ref() {
            None => return Ok(None),
            Some(CounterField::Disc { pair, points, refused }) => {
                self.check_nodes("StressEvaluator::evaluate_counter_body", nodes)?;
                let t0 = Instant::now();
                let model = &pair.counter.model;
                let (ty, tx) = global_tractions(nodes, Some(&pair.normals), -1.0, model.modulus);
                let (stress, surface) = bem_field(&pair.counter, &ty, &tx, points, refused, -1.0)?;
                let field = StressField { grid: self.grid, nu: model.kelvin.nu, stress, surface };
                let mut r =
                    StressResult::of(BodyModel::Bem, self.quantities.clone(), field, t0.elapsed().as_secs_f64());
                r.body = "counter_body".into();
                return Ok(Some(r));
            }
            Some(CounterField::HalfPlane { a, b, nu }) => (a, b, nu),
        };
        self.check_nodes("StressEvaluator::evaluate_counter_body", nodes)?;
        if a.len() != nodes.len() {
            return Err(ArgumentError::new(
                "StressEvaluator::evaluate_counter_body",
                "nodes",
                format!("has {} entries, the counter-body {} strips", nodes.len(), a.len()),
            ));
        }
        let t0 = Instant::now();
        let mirrored: Vec<NodeResult> = nodes.iter().map(|n| NodeResult { shear: -n.shear, ..n.clone() }).collect();
        let field = StressField {
            grid: self.grid,
            nu: *nu,
            stress: half_plane_field(&self.grid, a, b, &mirrored),
            surface: half_plane_surface(a, b, &mirrored),
        };
        let mut r = StressResult::of(BodyModel::HalfPlane, self.quantities.clone(), field, t0.elapsed().as_secs_f64());
        r.body = "counter_body".into();
        Ok(Some(r))
    }
}

/// A BEM body's field and surface values (user's units) from its contact tractions (t_y, t_x, dimensionless by its
/// modulus, in its contact-node order) at its dimensionless `points` (those refused left as their reason): `tz` = 1
/// when the grid's depth runs along +y (the wheel, depth upward from its bottom point), −1 along −y (a counter-disc
/// below the contact), so that τ_xz = tz σ_xy.
#[allow(clippy::type_complexity)]
fn bem_field(
    response: &BoundaryResponse,
    ty: &[f64],
    tx: &[f64],
    points: &[[f64; 2]],
    refused: &[Option<PointError>],
    tz: f64,
) -> Result<(Vec<Result<[f64; 3], PointError>>, Vec<(f64, Result<[f64; 3], PointError>)>), ArgumentError> {
    let e = response.model.modulus;
    let (u, t) = response.boundary(ty, tx)?;
    let model = &response.model;
    let ev = InteriorStress::new(&model.mesh, &model.kelvin, &u, &t)?;
    let todo: Vec<usize> = (0..points.len()).filter(|&k| refused[k].is_none()).collect();
    let sub: Vec<[f64; 2]> = todo.iter().map(|&k| points[k]).collect();
    let mut out: Vec<Result<[f64; 3], PointError>> =
        refused.iter().map(|r| Err(r.unwrap_or(PointError::Singular))).collect();
    for (k, s) in todo.into_iter().zip(ev.evaluate_par(&sub)) {
        out[k] = match s {
            Ok(s) => finite([s[0] * e, s[1] * e, tz * s[2] * e]),
            Err(StressError::OutsideBody) => Err(PointError::OutsideBody),
            Err(StressError::OnBoundary { .. }) => Err(PointError::NearBoundary),
            Err(StressError::NotFinite) => Err(PointError::Singular),
        };
    }
    let surface =
        wheel_surface(response, &u, &t, e).into_iter().map(|(x, s)| (x, s.map(|s| [s[0], s[1], tz * s[2]]))).collect();
    Ok((out, surface))
}

/// The counter-disc's field set-up: the grid's points in its own axes (depth into it from the contact point at
/// (0, −R₁)), refused as the wheel's are.
fn disc_field<'a>(
    scene: &Scene,
    built: &'a Built,
    grid: &StressGrid,
    radius: f64,
    path: &Path,
) -> crate::error::Result<CounterField<'a>> {
    let Some(pair) = built.pair.as_ref() else {
        return Err(Error::Unsupported {
            path: path.to_path_buf(),
            message: "stresses: the model was built without the counter-disc's boundary response (build it from a \
                      scene with [stresses])"
                .into(),
        });
    };
    let (l0, r1) = (built.flex.scales.length, scene.radius());
    let points: Vec<[f64; 2]> = (0..grid.len())
        .map(|k| {
            let (x, z) = grid.point(k);
            let (xw, yw) = (x / l0, (-r1 - z) / l0);
            [(xw - pair.centre[0]) / pair.scale, (yw - pair.centre[1]) / pair.scale]
        })
        .collect();
    let mesh = &pair.counter.model.mesh;
    let refused: Vec<Option<PointError>> =
        points.par_iter().map(|&p| refusal(mesh, p, pair.radius, pair.hub)).collect();
    if let Some(k) = refused.iter().position(Option::is_some) {
        let l2 = pair.counter.model.length;
        return Err(refused_grid(grid, &refused, k, mesh, points[k], (l2, radius), path, "counter-disc"));
    }
    Ok(CounterField::Disc { pair, points, refused })
}

/// The half-plane's surface values at its strips' centres (user's units).
fn half_plane_surface(a: &[f64], b: &[f64], nodes: &[NodeResult]) -> Vec<(f64, Result<[f64; 3], PointError>)> {
    (0..a.len())
        .map(|i| {
            let x = 0.5 * (a[i] + b[i]);
            let mut s = [0.0; 3];
            for j in (0..a.len()).filter(|&j| nodes[j].pressure != 0.0 || nodes[j].shear != 0.0) {
                let st = strip_stress(a[j], b[j], nodes[j].pressure, nodes[j].shear, x, 0.0);
                s[0] += st.sxx;
                s[1] += st.szz;
                s[2] += st.txz;
            }
            (x, finite(s))
        })
        .collect()
}

/// The BEM wheel's surface values at its contact elements' centres, from the boundary solution (`u`, `t`
/// dimensionless, `e` the stress scale): the traction gives σ_zz and τ_xz, the tangential strain of the boundary
/// displacement σ_xx ([`crate::bem::stress::boundary_stress`]).
fn wheel_surface(
    response: &BoundaryResponse,
    u: &[[f64; 2]],
    t: &[[f64; 2]],
    e: f64,
) -> Vec<(f64, Result<[f64; 3], PointError>)> {
    let model = &response.model;
    let mesh = &model.mesh;
    let l0 = model.length;
    mesh.elements
        .iter()
        .enumerate()
        .filter(|(_, el)| el.bc == crate::mesh::Bc::Contact)
        .map(|(i, el)| {
            let x = match el.shape {
                Shape::Straight { a, b } => 0.5 * (a[0] + b[0]) * l0,
                Shape::Arc(arc) => arc.position(0.0)[0] * l0,
            };
            // `u`, `t` are the response's own boundary solution on its mesh (checked when it was computed).
            let s = crate::bem::stress::boundary_stress(mesh, &model.kelvin, u, t, i, 0.0)
                .ok()
                .flatten()
                .ok_or(PointError::Singular)
                .and_then(|s| finite([s[0] * e, s[1] * e, s[2] * e]));
            (x, s)
        })
        .collect()
}

/// A stress with every component finite, else [`PointError::Singular`].
fn finite(s: [f64; 3]) -> Result<[f64; 3], PointError> {
    if s.iter().all(|v| v.is_finite()) {
        Ok(s)
    } else {
        Err(PointError::Singular)
    }
}

/// A surface grid node closer than this many strip widths to the edge of a half-plane strip carrying shear counts as
/// on the edge ([`PointError::Singular`]): round-off of the edges' and nodes' coordinates is ~1e-16 relative, and
/// the log singularity's value at such a distance would be meaningless.
const STRIP_EDGE_SNAP: f64 = 1e-9;

/// The half-plane's field: every loaded strip's closed form, superposed (user's units).
fn half_plane_field(
    grid: &StressGrid,
    a: &[f64],
    b: &[f64],
    nodes: &[NodeResult],
) -> Vec<Result<[f64; 3], PointError>> {
    debug_assert_eq!(nodes.len(), a.len(), "checked by the caller (StressEvaluator::check_nodes)");
    let loaded: Vec<(f64, f64, f64, f64)> = (0..a.len())
        .filter(|&j| nodes[j].pressure != 0.0 || nodes[j].shear != 0.0)
        .map(|j| (a[j], b[j], nodes[j].pressure, nodes[j].shear))
        .collect();
    (0..grid.len())
        .into_par_iter()
        .map(|k| {
            let (x, z) = grid.point(k);
            // On the surface at the edge of a strip carrying shear σ_xx is infinite (log singularity). The strips'
            // edges and the grid's nodes are computed apart, so "at the edge" is up to round-off: a node within
            // STRIP_EDGE_SNAP of a strip width from such an edge would otherwise get a finite but arbitrary value
            // (the log of the round-off).
            let on_edge = |&&(a, b, _, q): &&(f64, f64, f64, f64)| {
                q != 0.0 && ((x - a).abs() <= STRIP_EDGE_SNAP * (b - a) || (x - b).abs() <= STRIP_EDGE_SNAP * (b - a))
            };
            if z == 0.0 && loaded.iter().any(|s| on_edge(&s)) {
                return Err(PointError::Singular);
            }
            let mut s = [0.0; 3];
            for &(a, b, p, q) in &loaded {
                let st = strip_stress(a, b, p, q, x, z);
                s[0] += st.sxx;
                s[1] += st.szz;
                s[2] += st.txz;
            }
            finite(s)
        })
        .collect()
}

/// Why a BEM grid point (dimensionless wheel axes) is refused, if it is: outside the wheel's circles (radius
/// `outer`, hub radius `hub`, 0 for none), or within [`STRESS_NEAR_BOUNDARY_CONSTANT`] (or `_QUADRATIC`) lengths of
/// an element of `mesh`.
fn refusal(mesh: &Mesh, p: [f64; 2], outer: f64, hub: f64) -> Option<PointError> {
    let r = p[0].hypot(p[1]);
    if r >= outer || (hub > 0.0 && r <= hub) {
        return Some(PointError::OutsideBody);
    }
    let reach = match mesh.kind {
        ElementKind::Constant => STRESS_NEAR_BOUNDARY_CONSTANT,
        ElementKind::Quadratic => STRESS_NEAR_BOUNDARY_QUADRATIC,
    };
    let near = mesh.elements.iter().any(|e| {
        let (d, len) = distance_to_element(&e.shape, p);
        d < reach * len
    });
    near.then_some(PointError::NearBoundary)
}

/// The input error for a BEM grid whose point `k` (dimensionless wheel axes `p`, length scale `l0`, wheel radius
/// `r`) is refused: it names `stresses.depth` when the point is in the grid's shallowest row or the wheel's inner
/// half (the hub), `stresses.x` otherwise (the grid reaches sideways to where the rim curves up into it).
#[allow(clippy::too_many_arguments)]
fn refused_grid(
    grid: &StressGrid,
    refused: &[Option<PointError>],
    k: usize,
    mesh: &Mesh,
    p: [f64; 2],
    (l0, r): (f64, f64),
    path: &Path,
    body: &str,
) -> Error {
    let (x, z) = grid.point(k);
    let count = refused.iter().filter(|e| e.is_some()).count();
    let (d, len) = mesh
        .elements
        .iter()
        .map(|e| distance_to_element(&e.shape, p))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((f64::INFINITY, f64::NAN));
    let reach = match mesh.kind {
        ElementKind::Constant => STRESS_NEAR_BOUNDARY_CONSTANT,
        ElementKind::Quadratic => STRESS_NEAR_BOUNDARY_QUADRATIC,
    };
    let field = if k < grid.points[0] || p[0].hypot(p[1]) * l0 < 0.5 * r { "stresses.depth" } else { "stresses.x" };
    let why = match refused[k] {
        Some(PointError::OutsideBody) => format!("lies outside the {body} (beyond its rim or in the hub's hole)"),
        _ => format!(
            "lies {:.4e} from the boundary, within {reach} lengths of an element ({:.4e} long): there the BEM \
             field is not accurate (the boundary data jump between elements)",
            d * l0,
            len * l0
        ),
    };
    Error::Invalid {
        path: path.to_path_buf(),
        field: field.to_string(),
        message: format!(
            "{count} of the {} grid points cannot be evaluated for the {body}; the first, x = {x:.6e}, depth = \
             {z:.6e}, {why}. Move the grid away from the boundary (start it deeper, or narrow it), or refine the mesh \
             there (the half-plane model has values up to the surface)",
            grid.len()
        ),
    }
}

/// Distance from `p` to an element and the element's length.
fn distance_to_element(shape: &Shape, p: [f64; 2]) -> (f64, f64) {
    match *shape {
        Shape::Straight { a, b } => {
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len2 = dx * dx + dy * dy;
            let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0);
            let (cx, cy) = (a[0] + t * dx, a[1] + t * dy);
            ((p[0] - cx).hypot(p[1] - cy), len2.sqrt())
        }
        Shape::Arc(arc) => {
            let (dx, dy) = (p[0] - arc.centre[0], p[1] - arc.centre[1]);
            let (lo, hi) = (arc.theta0.min(arc.theta1), arc.theta0.max(arc.theta1));
            // The point's polar angle brought into [lo, lo + 2π).
            let phi = lo + (dy.atan2(dx) - lo).rem_euclid(std::f64::consts::TAU);
            let d = if phi <= hi {
                (dx.hypot(dy) - arc.radius).abs()
            } else {
                let e = |xi: f64| {
                    let q = arc.position(xi);
                    (p[0] - q[0]).hypot(p[1] - q[1])
                };
                e(-1.0).min(e(1.0))
            };
            (d, arc.length())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::ArcElement;

    #[test]
    fn quantities_of_a_known_tensor() {
        // σ = diag(−3, −1) + τ 1: τ₁ = √(1 + 1) , σ_yy = 0.25·(−4) = −1, von Mises by hand.
        let s = [-3.0, -1.0, 1.0];
        let nu = 0.25;
        assert_eq!(quantity(StressQuantity::Syy, s, nu), -1.0);
        assert!((quantity(StressQuantity::PrincipalShear, s, nu) - 2f64.sqrt()).abs() < 1e-15);
        let vm = (0.5 * ((-3.0f64 + 1.0).powi(2) + 0.0 + 4.0) + 3.0).sqrt();
        assert!((quantity(StressQuantity::VonMises, s, nu) - vm).abs() < 1e-15);
        assert_eq!(quantity(StressQuantity::OrthogonalShear, s, nu), 1.0);
    }

    #[test]
    fn distances_to_straight_and_arc_elements() {
        let seg = Shape::Straight { a: [0.0, 0.0], b: [2.0, 0.0] };
        assert_eq!(distance_to_element(&seg, [1.0, 0.5]), (0.5, 2.0));
        assert_eq!(distance_to_element(&seg, [3.0, 0.0]).0, 1.0);
        // A quarter arc of the unit circle, counter-clockwise and clockwise.
        for (t0, t1) in [(0.0, std::f64::consts::FRAC_PI_2), (std::f64::consts::FRAC_PI_2, 0.0)] {
            let arc = Shape::Arc(ArcElement { centre: [0.0, 0.0], radius: 1.0, theta0: t0, theta1: t1 });
            assert!((distance_to_element(&arc, [0.5, 0.5]).0 - (1.0 - 0.5f64.sqrt())).abs() < 1e-15);
            assert!((distance_to_element(&arc, [0.0, -1.0]).0 - 2f64.sqrt()).abs() < 1e-15);
            assert!((distance_to_element(&arc, [0.0, 0.0]).1 - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        }
    }

    #[test]
    fn maximum_is_the_largest_magnitude_with_its_sign() {
        let grid = StressGrid { x: [0.0, 1.0], depth: [0.0, 1.0], points: [2, 2] };
        let f = StressField {
            grid,
            nu: 0.3,
            stress: vec![Ok([1.0, 0.0, 0.0]), Err(PointError::NearBoundary), Ok([-2.0, 0.0, 0.0]), Ok([1.5, 0.0, 0.0])],
            surface: Vec::new(),
        };
        assert_eq!(f.maximum(StressQuantity::Sxx), Some(Maximum { value: -2.0, x: 0.0, depth: 1.0 }));
        let csv = f.csv(&[StressQuantity::Sxx]);
        assert_eq!(csv.lines().nth(2), Some("1e0,0e0,,near_boundary"));
    }
}
