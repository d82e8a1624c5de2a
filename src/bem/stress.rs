//! Interior stresses from a solved boundary: the Somigliana identity for stresses (Brebbia & Dominguez,
//! *Boundary Elements: an introductory course*, ch. 5; Becker, *The Boundary Element Method in Engineering*).
//!
//! # The identity and its kernels
//! With the conventions of [`super::kelvin`] — `r = x − ξ` (boundary field point `x` minus interior source point
//! `ξ`), `r,i = r_i / r`, `∂r/∂n = r,k n_k`, `n` the outward unit normal at `x` — the displacement at an interior
//! point is `u_l(ξ) = ∫ U*_lk t_k ds − ∫ T*_lk u_k ds` (the BIE with `c_lk = δ_lk`). Differentiating with respect
//! to `ξ` and applying plane-strain Hooke's law `σ_ij = λ δ_ij u_m,m + G (u_i,j + u_j,i)`, `λ = 2Gν/(1 − 2ν)`,
//! gives
//!
//! ```text
//! σ_ij(ξ) = ∫ D_kij t_k ds − ∫ S_kij u_k ds
//!
//! D_kij = 1/(4π(1−ν) r) · { (1−2ν)(δ_ki r,j + δ_kj r,i − δ_ij r,k) + 2 r,i r,j r,k }
//!
//! S_kij = G/(2π(1−ν) r²) · { 2 ∂r/∂n [ (1−2ν) δ_ij r,k + ν (δ_ik r,j + δ_jk r,i) − 4 r,i r,j r,k ]
//!                            + 2ν (n_i r,j r,k + n_j r,i r,k)
//!                            + (1−2ν)(2 n_k r,i r,j + n_j δ_ik + n_i δ_jk)
//!                            − (1−4ν) n_k δ_ij }
//! ```
//!
//! (Brebbia & Dominguez ch. 5, plane strain). These are exactly `λ δ_ij ∂U*_mk/∂ξ_m +
//! G(∂U*_ik/∂ξ_j + ∂U*_jk/∂ξ_i)` and the same with T*, for the U*, T* of [`Kelvin::u`] and [`Kelvin::t`]: the unit
//! test `kernels_are_hooke_of_kelvin_source_derivatives` checks that by finite differences, so the signs are those
//! of kelvin.rs by construction. Stresses are positive in tension.
//!
//! # Interpolation
//! `u` and `t` are the nodal values of the BEM solution, interpolated as the BEM does: constant on a straight
//! element ([`Shape::Straight`]), Lagrange-quadratic through the three nodes of an arc element ([`Shape::Arc`],
//! [`super::quadratic::shape`]).
//!
//! # Quadrature
//! Every integrand is analytic in the element coordinate ξ ∈ [−1, 1] except at the complex zeros of r²: for a
//! straight element of half length a, ξ* = ((ξ_s − m)·t ± i |(ξ_s − m)·n|)/a (m the midpoint); for an arc, the
//! formula of [`super::quadratic`] (ξ* = (φ − θm ± i ln(ρ_s/R))/h plus the 2π images). D has double poles there,
//! S poles of order three. The Gauss–Legendre error of an n-point rule is ∝ ρ^(−2n), ρ the Bernstein-ellipse
//! parameter of the nearest singularity (ρ + 1/ρ = |z − 1| + |z + 1|).
//! * **Far elements** (ρ ≥ [`RHO_ACCEPT`] on the whole element, i.e. beyond roughly one element length): a single
//!   rule of n = ⌈K/ln ρ⌉ points (K = [`ORDER_K`], n ≥ [`N_MIN`]); positions, normals, weights and interpolated
//!   u, t at those points are precomputed once per element and order ([`InteriorStress::new`]), so a far element
//!   costs n kernel evaluations (n = 3 beyond ~25 element lengths).
//! * **Near elements** (ρ < RHO_ACCEPT): the element is halved recursively until, on every piece, the
//!   singularity's ρ relative to the piece reaches RHO_ACCEPT, and the piece gets ⌈K/ln ρ⌉ points; the pieces
//!   shrink geometrically towards the foot of the singularity, so the cost grows only like ln(L/δ) for a point
//!   at distance δ from an element of length L.
//! * **Rigid-translation subtraction**: since a rigid translation is stress-free, `∫ S_kij ds = 0` over the closed
//!   boundary, and the identity is evaluated with `u − u₀`, `u₀` the displacement of the node nearest to ξ. This
//!   removes the `|u|·L/δ` size of the near-boundary S integrals (δ the distance to the boundary), so round-off
//!   and quadrature errors scale with the displacement *variation* near ξ, not with a rigid motion of the wheel.
//!
//! Accuracy of the quadrature alone (tests/bem_stress.rs, against brute-force composite Gauss rules of the same
//! discrete integrals): ~1e-11 of the stress scale on a grid under the contact, ≤ 7e-10 (quadratic) and ≤ 2e-8
//! (constant elements, next to an element end where the computed stress is itself ~70× the scale) at 1e-1 to
//! 1e-3 element lengths from the boundary.
//!
//! That is the error in integrating the *discrete* boundary data. The data's own interpolation error is a
//! different matter and dominates within about one element length of the boundary: both element families are
//! discontinuous between elements, and a displacement jump J at an element end adds a stress ~ G·J/δ at distance
//! δ from it. With exact Lamé data this gives errors of ~1e-4 (quadratic, off element mid-points) but 1e-2–1e-1
//! (quadratic, 1e-3 lengths from an element end) and O(1) or worse (constant elements, anywhere within ~1
//! element length). Near the boundary, prefer [`boundary_stress`] or points at least one element length inside.
//!
//! # Inside, outside, on the boundary
//! A point is in the body when the winding number of the whole boundary about it is 1 (outer circle CCW, holes CW:
//! a point in the hub's hole has winding 0). It is counted without trigonometry: signed crossings of a ray with the
//! elements' chords, plus ±1 for an arc when the point lies between its chord and the arc. A point closer
//! than [`ON_BOUNDARY_TOL`] element lengths to an element is [`StressError::OnBoundary`]; there the identity's
//! integrals diverge — use [`boundary_stress`] instead.
//!
//! # Units
//! Those of the mesh and of the [`Kelvin`] constants: lengths in the mesh's unit, `u` in the same length unit,
//! `t` and the returned stresses in the unit of Kelvin's shear modulus (rollbem's pipeline: lengths / L0, stresses
//! / E).

use super::kelvin::Kelvin;
use super::quadratic::{shape, ArcElement, XI_NODES};
use super::quadrature::gl;
use crate::error::ArgumentError;
use crate::mesh::{Mesh, Shape};
use rayon::prelude::*;
use std::f64::consts::PI;

/// Why no stress is returned at a point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum StressError {
    /// The point is outside the body, including inside a hole (winding number of the boundary ≠ 1).
    #[error("point outside the body (or in a hole)")]
    OutsideBody,
    /// The point is within [`ON_BOUNDARY_TOL`] element lengths of `element` (the integrals of the Somigliana
    /// identity diverge there); `node` is the element's node it coincides with, if any (same tolerance).
    #[error("point on the boundary (element {element}, node {node:?}): use boundary_stress")]
    OnBoundary {
        /// Index of the element (in [`Mesh::elements`]).
        element: usize,
        /// Index of the coinciding node (in [`Mesh::nodes`]), if the point is at a node.
        node: Option<usize>,
    },
    /// A coordinate of the point is NaN or infinite.
    #[error("point coordinates are not finite")]
    NotFinite,
}

/// A point closer to an element than this fraction of the element's length is [`StressError::OnBoundary`]
/// (closer than that, cancellation in the `1/δ`-sized near integrals would cost more than 7 digits).
pub const ON_BOUNDARY_TOL: f64 = 1e-9;

/// Bernstein-ellipse parameter above which a piece (or a whole far element) is integrated without halving.
pub const RHO_ACCEPT: f64 = 3.0;

/// Gauss order constant: a piece whose nearest singularity has Bernstein parameter ρ gets n = ⌈ORDER_K / ln ρ⌉
/// points (nominal error ρ^(−2n) ≤ e^(−2·ORDER_K)); calibrated by the tests of this module so that the
/// quadrature error is ≲ 1e-9 of the stress scale, also for the triple poles of S close to the boundary.
pub const ORDER_K: f64 = 14.0;

/// Fewest Gauss points per element or piece.
pub const N_MIN: usize = 3;
/// Most Gauss points per piece (reached only for ρ just above [`RHO_ACCEPT`]).
const N_MAX: usize = 24;
/// Maximum halving depth (2⁻⁵⁰ of an element: far below [`ON_BOUNDARY_TOL`]).
const MAX_DEPTH: u32 = 50;

/// Gauss points n for Bernstein parameter ρ: n = ⌈ORDER_K / ln ρ⌉ clamped to [N_MIN, N_MAX].
#[inline]
fn order_for(rho: f64) -> usize {
    if !rho.is_finite() {
        return N_MIN;
    }
    ((ORDER_K / rho.ln()).ceil() as usize).clamp(N_MIN, N_MAX)
}

/// Largest order a far element (ρ ≥ RHO_ACCEPT) can need: the far tables hold orders N_MIN..=this.
fn far_order_max() -> usize {
    order_for(RHO_ACCEPT)
}

/// `order_for` without transcendental functions, for the far field: `thr[i]` = e^(ORDER_K/(N_MIN + i)) is the
/// smallest ρ that order N_MIN + i accepts, so the order is N_MIN + (number of thresholds above ρ), and `z2_min`
/// = ((thr₀ + 1/thr₀)/2)² is the |z|² beyond which ρ(z) ≥ thr₀ without computing ρ (ρ + 1/ρ = |z − 1| + |z + 1|
/// ≥ 2|z|).
#[derive(Debug, Clone)]
struct OrderTable {
    thr: Vec<f64>,
    z2_min: f64,
}

impl OrderTable {
    fn new() -> OrderTable {
        let thr: Vec<f64> = (N_MIN..=far_order_max()).map(|n| (ORDER_K / n as f64).exp()).collect();
        let t0 = thr[0];
        OrderTable { z2_min: (0.5 * (t0 + 1.0 / t0)).powi(2), thr }
    }

    /// Order for Bernstein parameter ρ ≥ RHO_ACCEPT (agrees with `order_for` up to rounding at the thresholds).
    #[inline]
    fn order(&self, rho: f64) -> usize {
        N_MIN + self.thr.iter().take_while(|&&t| rho < t).count()
    }
}

/// Bernstein-ellipse parameter ρ ≥ 1 of the point z = (zr, zi) relative to [−1, 1].
#[inline]
fn bernstein_rho(zr: f64, zi: f64) -> f64 {
    let zi2 = zi * zi;
    let sum = ((zr - 1.0) * (zr - 1.0) + zi2).sqrt() + ((zr + 1.0) * (zr + 1.0) + zi2).sqrt();
    0.5 * (sum + (sum * sum - 4.0).max(0.0).sqrt())
}

/// A third-order tensor in 2D, `a[k][i][j]`.
pub type Kernel3 = [[[f64; 2]; 2]; 2];

/// The Somigliana kernels at boundary point `x` (outward unit normal `n`) for the interior point `xi`:
/// returns `(d, s)` with `d[k][i][j] = D_kij` and `s[k][i][j] = S_kij` (module docs; `k` the component of the
/// boundary traction or displacement, `ij` the stress component at `xi`). `D` has units 1/length, `S` stress /
/// length² (× Kelvin's modulus). Used by the tests and as the readable reference of the fused evaluation.
pub fn somigliana_kernels(k: &Kelvin, x: [f64; 2], n: [f64; 2], xi: [f64; 2]) -> (Kernel3, Kernel3) {
    let rv = [x[0] - xi[0], x[1] - xi[1]];
    let r = rv[0].hypot(rv[1]);
    let d = [rv[0] / r, rv[1] / r];
    let drdn = d[0] * n[0] + d[1] * n[1];
    let nu = k.nu;
    let cd = k.ct / r;
    let cs = 2.0 * k.shear_modulus * k.ct / (r * r);
    let del = |a: usize, b: usize| if a == b { 1.0 } else { 0.0 };
    let mut dk = [[[0.0; 2]; 2]; 2];
    let mut sk = [[[0.0; 2]; 2]; 2];
    for kk in 0..2 {
        for i in 0..2 {
            for j in 0..2 {
                dk[kk][i][j] = cd
                    * (k.b12 * (del(kk, i) * d[j] + del(kk, j) * d[i] - del(i, j) * d[kk]) + 2.0 * d[i] * d[j] * d[kk]);
                sk[kk][i][j] = cs
                    * (2.0
                        * drdn
                        * (k.b12 * del(i, j) * d[kk] + nu * (del(i, kk) * d[j] + del(j, kk) * d[i])
                            - 4.0 * d[i] * d[j] * d[kk])
                        + 2.0 * nu * (n[i] * d[j] * d[kk] + n[j] * d[i] * d[kk])
                        + k.b12 * (2.0 * n[kk] * d[i] * d[j] + n[j] * del(i, kk) + n[i] * del(j, kk))
                        - (1.0 - 4.0 * nu) * n[kk] * del(i, j));
            }
        }
    }
    (dk, sk)
}

/// Material constants of the fused kernel evaluation.
#[derive(Debug, Clone, Copy)]
struct Consts {
    /// 1/(4π(1−ν)).
    cd: f64,
    /// G/(2π(1−ν)).
    cs: f64,
    nu: f64,
    b12: f64,
    b14: f64,
}

/// Add `w · (D_kij t_k − S_kij u_k)` for `r = x − ξ` to `acc = [σxx, σyy, σxy]`, without square roots: the
/// kernels of the module docs with `r,i / r = r_i / r²`.
#[inline(always)]
fn accumulate(c: &Consts, r: [f64; 2], n: [f64; 2], u: [f64; 2], t: [f64; 2], w: f64, acc: &mut [f64; 3]) {
    let r2 = r[0] * r[0] + r[1] * r[1];
    let inv = 1.0 / r2;
    let inv2 = inv * inv;
    let tr = t[0] * r[0] + t[1] * r[1];
    let a = r[0] * n[0] + r[1] * n[1];
    let b = u[0] * r[0] + u[1] * r[1];
    let un = u[0] * n[0] + u[1] * n[1];
    let wd = w * c.cd;
    let ws = w * c.cs;
    // D·t = cd [ b12 (t_i r_j + t_j r_i − δ_ij t·r)/r² + 2 r_i r_j (t·r)/r⁴ ]
    let d_lin = wd * c.b12 * inv;
    let d_rr = wd * 2.0 * tr * inv2;
    // S·u = cs [ 2a(b12 δ_ij b + ν(u_i r_j + u_j r_i))/r⁴ − 8ab r_i r_j/r⁶ + 2ν b (n_i r_j + n_j r_i)/r⁴
    //            + b12 (2 (u·n) r_i r_j / r⁴ + (n_j u_i + n_i u_j)/r²) − (1−4ν)(u·n) δ_ij / r² ]
    let s_rr = ws * (-8.0 * a * b * inv2 * inv + 2.0 * c.b12 * un * inv2);
    let s_ur = ws * 2.0 * c.nu * a * inv2;
    let s_nr = ws * 2.0 * c.nu * b * inv2;
    let s_nu = ws * c.b12 * inv;
    let s_d = ws * (2.0 * a * c.b12 * b * inv2 - c.b14 * un * inv);
    let sxx = d_lin * (2.0 * t[0] * r[0] - tr) + d_rr * r[0] * r[0]
        - (s_rr * r[0] * r[0] + 2.0 * (s_ur * u[0] * r[0] + s_nr * n[0] * r[0] + s_nu * n[0] * u[0]) + s_d);
    let syy = d_lin * (2.0 * t[1] * r[1] - tr) + d_rr * r[1] * r[1]
        - (s_rr * r[1] * r[1] + 2.0 * (s_ur * u[1] * r[1] + s_nr * n[1] * r[1] + s_nu * n[1] * u[1]) + s_d);
    let sxy = d_lin * (t[0] * r[1] + t[1] * r[0]) + d_rr * r[0] * r[1]
        - (s_rr * r[0] * r[1]
            + s_ur * (u[0] * r[1] + u[1] * r[0])
            + s_nr * (n[0] * r[1] + n[1] * r[0])
            + s_nu * (n[1] * u[0] + n[0] * u[1]));
    acc[0] += sxx;
    acc[1] += syy;
    acc[2] += sxy;
}

/// Element geometry in the form the evaluation needs.
#[derive(Debug, Clone, Copy)]
enum Geom {
    /// x(ξ) = mid + ξ·half·tan, constant normal.
    Straight { mid: [f64; 2], tan: [f64; 2], n: [f64; 2], half: f64 },
    /// The arc, the index of its circle in [`InteriorStress::circles`], θm and h (θ = θm + hξ).
    Arc { arc: ArcElement, circle: usize, thm: f64, h: f64 },
}

/// One element with its interpolation data.
#[derive(Debug, Clone, Copy)]
struct El {
    geom: Geom,
    len: f64,
    first_node: usize,
    n_nodes: usize,
    u: [[f64; 2]; 3],
    t: [[f64; 2]; 3],
}

impl El {
    /// Position, outward normal, ds/dξ, interpolated u and t at ξ.
    #[inline]
    fn at(&self, xi: f64) -> ([f64; 2], [f64; 2], f64, [f64; 2], [f64; 2]) {
        match self.geom {
            Geom::Straight { mid, tan, n, half } => {
                ([mid[0] + xi * half * tan[0], mid[1] + xi * half * tan[1]], n, half, self.u[0], self.t[0])
            }
            Geom::Arc { arc, thm, h, .. } => {
                let (s, c) = (thm + h * xi).sin_cos();
                let sg = arc.orientation();
                let x = [arc.centre[0] + arc.radius * c, arc.centre[1] + arc.radius * s];
                let nn = shape(xi);
                let mut u = [0.0; 2];
                let mut t = [0.0; 2];
                for j in 0..3 {
                    for m in 0..2 {
                        u[m] += nn[j] * self.u[j][m];
                        t[m] += nn[j] * self.t[j][m];
                    }
                }
                (x, [sg * c, sg * s], arc.jacobian(), u, t)
            }
        }
    }
}

/// A precomputed quadrature point of a far-field rule.
#[derive(Debug, Clone, Copy)]
struct FarPoint {
    x: [f64; 2],
    n: [f64; 2],
    /// Gauss weight × ds/dξ.
    w: f64,
    u: [f64; 2],
    t: [f64; 2],
}

/// A piece of the boundary for the winding number: the chord a → b and, for an arc piece, its circle (the point
/// is between chord and arc when inside the circle and on the arc's side of the chord).
#[derive(Debug, Clone, Copy)]
struct WindPiece {
    a: [f64; 2],
    b: [f64; 2],
    /// (centre, radius², orientation ±1) for an arc piece.
    arc: Option<([f64; 2], f64, f64)>,
}

/// Make every piece end exactly where the next piece of its loop starts: each end point `b` is replaced by the
/// nearest start point `a` of any piece when it is within 1e-9 of the piece's chord length (consecutive elements
/// computed from slightly different angles then share their vertex bit for bit).
fn snap(mut wind: Vec<WindPiece>) -> Vec<WindPiece> {
    let starts: Vec<[f64; 2]> = wind.iter().map(|w| w.a).collect();
    for w in &mut wind {
        let len = (w.b[0] - w.a[0]).hypot(w.b[1] - w.a[1]);
        let mut best = (f64::INFINITY, w.b);
        for &a in &starts {
            let d = (a[0] - w.b[0]).hypot(a[1] - w.b[1]);
            if d < best.0 {
                best = (d, a);
            }
        }
        if best.0 <= 1e-9 * len {
            w.b = best.1;
        }
    }
    wind
}

/// Per-point data of one circle: offset from the centre, ρ_s, polar angle φ and ln(ρ_s/R).
#[derive(Debug, Clone, Copy, Default)]
struct CircleAt {
    rho_s: f64,
    phi: f64,
    ell: f64,
}

/// Evaluator of interior stresses for one boundary solution: precomputes the far-field quadrature data once, then
/// evaluates any number of points ([`InteriorStress::at`], [`InteriorStress::evaluate`]). Units and signs as in
/// the module docs.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct InteriorStress {
    c: Consts,
    els: Vec<El>,
    /// Nodal positions (for the on-node check and u₀).
    node_pos: Vec<[f64; 2]>,
    /// Nodal displacements.
    node_u: Vec<[f64; 2]>,
    /// Circles (centre, radius) carrying the arc elements.
    circles: Vec<([f64; 2], f64)>,
    far: Vec<FarPoint>,
    /// `far[far_off[e] + tri(n)..][..n]` is element e's n-point rule (orders N_MIN..=far_order_max()).
    far_off: Vec<usize>,
    wind: Vec<WindPiece>,
    orders: OrderTable,
}

/// Offset of the n-point rule within an element's block of far rules (orders N_MIN, N_MIN+1, …).
#[inline]
fn tri(n: usize) -> usize {
    (N_MIN..n).sum()
}

impl InteriorStress {
    /// Prepare the evaluation for `mesh`, material `k` and the boundary solution `u`, `t` (one value per node of
    /// the mesh, in node order; units in the module docs). Refused, naming the argument, when `u` or `t` does not
    /// have one entry per node or the mesh does not hold together ([`Mesh::check`]: e.g. an element whose node
    /// count does not match its shape).
    pub fn new(mesh: &Mesh, k: &Kelvin, u: &[[f64; 2]], t: &[[f64; 2]]) -> Result<InteriorStress, ArgumentError> {
        check_solution("InteriorStress::new", mesh, u, t)?;
        let nu = k.nu;
        let c = Consts { cd: k.ct, cs: 2.0 * k.shear_modulus * k.ct, nu, b12: k.b12, b14: 1.0 - 4.0 * nu };
        let mut circles: Vec<([f64; 2], f64)> = Vec::new();
        let mut els = Vec::with_capacity(mesh.elements.len());
        let mut wind = Vec::new();
        for e in &mesh.elements {
            let mut eu = [[0.0; 2]; 3];
            let mut et = [[0.0; 2]; 3];
            for j in 0..e.n_nodes.min(3) {
                eu[j] = u[e.first_node + j];
                et[j] = t[e.first_node + j];
            }
            let (geom, len) = match e.shape {
                Shape::Straight { a, b } => {
                    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                    let len = dx.hypot(dy);
                    let tan = [dx / len, dy / len];
                    wind.push(WindPiece { a, b, arc: None });
                    let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                    (Geom::Straight { mid, tan, n: [tan[1], -tan[0]], half: 0.5 * len }, len)
                }
                Shape::Arc(arc) => {
                    let key = (arc.centre, arc.radius);
                    let circle = match circles.iter().position(|c| *c == key) {
                        Some(i) => i,
                        None => {
                            circles.push(key);
                            circles.len() - 1
                        }
                    };
                    // Winding pieces of at most a quarter circle each.
                    let span = arc.theta1 - arc.theta0;
                    let m = ((span.abs() / (0.5 * PI)).ceil() as usize).max(1);
                    for p in 0..m {
                        let th0 = arc.theta0 + span * p as f64 / m as f64;
                        let th1 = if p + 1 == m { arc.theta1 } else { arc.theta0 + span * (p + 1) as f64 / m as f64 };
                        let pos =
                            |th: f64| [arc.centre[0] + arc.radius * th.cos(), arc.centre[1] + arc.radius * th.sin()];
                        wind.push(WindPiece {
                            a: pos(th0),
                            b: pos(th1),
                            arc: Some((arc.centre, arc.radius * arc.radius, arc.orientation())),
                        });
                    }
                    let thm = 0.5 * (arc.theta0 + arc.theta1);
                    (Geom::Arc { arc, circle, thm, h: 0.5 * span }, arc.length())
                }
            };
            els.push(El { geom, len, first_node: e.first_node, n_nodes: e.n_nodes, u: eu, t: et });
        }
        let nf = far_order_max();
        let mut far = Vec::with_capacity(els.len() * tri(nf + 1));
        let mut far_off = Vec::with_capacity(els.len());
        for el in &els {
            far_off.push(far.len());
            for n in N_MIN..=nf {
                for (xq, wq) in gl(n).iter() {
                    let (x, nn, jac, uq, tq) = el.at(xq);
                    far.push(FarPoint { x, n: nn, w: wq * jac, u: uq, t: tq });
                }
            }
        }
        Ok(InteriorStress {
            c,
            els,
            node_pos: mesh.nodes.iter().map(|n| n.pos).collect(),
            node_u: u.to_vec(),
            circles,
            far,
            far_off,
            wind: snap(wind),
            orders: OrderTable::new(),
        })
    }

    /// Singularities (re, im) of element `el`'s integrands in its ξ coordinate for the point `p` (entries with
    /// infinite re are absent).
    #[inline]
    fn singularities(&self, el: &El, p: [f64; 2], circ: &[CircleAt]) -> [[f64; 2]; 3] {
        match el.geom {
            Geom::Straight { mid, tan, n, half } => {
                let d = [p[0] - mid[0], p[1] - mid[1]];
                let re = (d[0] * tan[0] + d[1] * tan[1]) / half;
                let im = ((d[0] * n[0] + d[1] * n[1]) / half).abs();
                [[re, im], [f64::INFINITY, 0.0], [f64::INFINITY, 0.0]]
            }
            Geom::Arc { circle, thm, h, .. } => {
                let ca = circ[circle];
                if ca.rho_s <= 1e-300 {
                    return [[f64::INFINITY, 0.0]; 3];
                }
                let im = (ca.ell / h).abs();
                let mut dphi = ca.phi - thm;
                while dphi > PI {
                    dphi -= 2.0 * PI;
                }
                while dphi <= -PI {
                    dphi += 2.0 * PI;
                }
                [[dphi / h, im], [(dphi - 2.0 * PI) / h, im], [(dphi + 2.0 * PI) / h, im]]
            }
        }
    }

    /// Distance from `p` to element `el`.
    fn distance(&self, el: &El, p: [f64; 2], circ: &[CircleAt]) -> f64 {
        match el.geom {
            Geom::Straight { mid, tan, half, .. } => {
                let d = [p[0] - mid[0], p[1] - mid[1]];
                let s = (d[0] * tan[0] + d[1] * tan[1]).clamp(-half, half);
                (d[0] - s * tan[0]).hypot(d[1] - s * tan[1])
            }
            Geom::Arc { arc, circle, thm, h } => {
                let ca = circ[circle];
                let mut dphi = ca.phi - thm;
                while dphi > PI {
                    dphi -= 2.0 * PI;
                }
                while dphi <= -PI {
                    dphi += 2.0 * PI;
                }
                if dphi.abs() <= h.abs() {
                    (ca.rho_s - arc.radius).abs()
                } else {
                    let (a, b) = (arc.position(-1.0), arc.position(1.0));
                    (p[0] - a[0]).hypot(p[1] - a[1]).min((p[0] - b[0]).hypot(p[1] - b[1]))
                }
            }
        }
    }

    /// Winding number of the boundary about `p` (1 inside the body), by signed crossings of the ray from `p`
    /// towards +x with the chords (Sunday's rule: an upward chord crossed with `p` on its left counts +1, a
    /// downward one with `p` on its right −1; `p` on a chord's line counts as right of it), plus, for an arc
    /// piece, its orientation when `p` lies between chord and arc (the arc then winds once more about `p` than
    /// its chord). The pieces' endpoints are snapped ([`snap`]), so each loop is closed bit for bit and every
    /// crossing is counted once. No trigonometry.
    fn winding(&self, p: [f64; 2]) -> i32 {
        let mut w = 0;
        for wp in &self.wind {
            let (a, b) = (wp.a, wp.b);
            let cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            let left = cr > 0.0;
            if a[1] <= p[1] {
                if b[1] > p[1] && left {
                    w += 1;
                }
            } else if b[1] <= p[1] && !left {
                w -= 1;
            }
            if let Some((c, r2, sg)) = wp.arc {
                let d2 = (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2);
                // The centre is on the left of a CCW chord (right of a CW one); the segment is on the other side.
                let arc_side = if sg > 0.0 { !left } else { left };
                if d2 < r2 && arc_side {
                    w += if sg > 0.0 { 1 } else { -1 };
                }
            }
        }
        w
    }

    /// Stress `[σxx, σyy, σxy]` at the interior point `p` (tension positive; units in the module docs), or why
    /// there is none.
    pub fn at(&self, p: [f64; 2]) -> Result<[f64; 3], StressError> {
        let mut rho = Vec::new();
        self.at_with(p, &mut rho)
    }

    /// [`InteriorStress::at`] with a reusable scratch vector.
    fn at_with(&self, p: [f64; 2], rho: &mut Vec<f64>) -> Result<[f64; 3], StressError> {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(StressError::NotFinite);
        }
        let circ: Vec<CircleAt> = self
            .circles
            .iter()
            .map(|&(c, r)| {
                let (dx, dy) = (p[0] - c[0], p[1] - c[1]);
                let rho_s = dx.hypot(dy);
                CircleAt { rho_s, phi: dy.atan2(dx), ell: (rho_s / r).ln() }
            })
            .collect();
        // Pass 1: Bernstein parameter of every element; on-boundary check for the near ones.
        rho.clear();
        let mut nearest = (f64::INFINITY, 0usize);
        for (e, el) in self.els.iter().enumerate() {
            let s = self.singularities(el, p, &circ);
            let z2 = s[0][0] * s[0][0] + s[0][1] * s[0][1];
            let mut r = if z2 >= self.orders.z2_min {
                // Far enough for the lowest order: the exact ρ does not matter (recorded as +∞ → N_MIN).
                f64::INFINITY
            } else {
                bernstein_rho(s[0][0], s[0][1])
            };
            // The 2π images of an arc's singularity: ρ(z) ≥ |z| ≥ |re|, so only one nearer than ρ can matter.
            for z in &s[1..] {
                if z[0].is_finite() && z[0].abs() < r {
                    r = r.min(bernstein_rho(z[0], z[1]));
                }
            }
            rho.push(r);
            if r < nearest.0 {
                nearest = (r, e);
            }
            if r < RHO_ACCEPT && self.distance(el, p, &circ) <= ON_BOUNDARY_TOL * el.len {
                let node = (el.first_node..el.first_node + el.n_nodes).find(|&i| {
                    let q = self.node_pos[i];
                    (q[0] - p[0]).hypot(q[1] - p[1]) <= ON_BOUNDARY_TOL * el.len
                });
                return Err(StressError::OnBoundary { element: e, node });
            }
        }
        if self.winding(p) != 1 {
            return Err(StressError::OutsideBody);
        }
        // u₀: displacement of the node (of the nearest element) closest to p.
        let el0 = &self.els[nearest.1];
        let mut u0 = self.node_u[el0.first_node];
        let mut best = f64::INFINITY;
        for i in el0.first_node..el0.first_node + el0.n_nodes {
            let q = self.node_pos[i];
            let d = (q[0] - p[0]).hypot(q[1] - p[1]);
            if d < best {
                best = d;
                u0 = self.node_u[i];
            }
        }
        // Pass 2: integrate.
        let c = &self.c;
        let mut acc = [0.0; 3];
        for (e, el) in self.els.iter().enumerate() {
            let r = rho[e];
            if r >= RHO_ACCEPT {
                let n = self.orders.order(r);
                let start = self.far_off[e] + tri(n);
                for q in &self.far[start..start + n] {
                    let rv = [q.x[0] - p[0], q.x[1] - p[1]];
                    let uq = [q.u[0] - u0[0], q.u[1] - u0[1]];
                    accumulate(c, rv, q.n, uq, q.t, q.w, &mut acc);
                }
            } else {
                let sing = self.singularities(el, p, &circ);
                adaptive(-1.0, 1.0, &sing, MAX_DEPTH, &mut |xi, w| {
                    let (x, n, jac, uq, tq) = el.at(xi);
                    let rv = [x[0] - p[0], x[1] - p[1]];
                    accumulate(c, rv, n, [uq[0] - u0[0], uq[1] - u0[1]], tq, w * jac, &mut acc);
                });
            }
        }
        Ok(acc)
    }

    /// Stresses at every point of `points`, in order, on the calling thread.
    pub fn evaluate(&self, points: &[[f64; 2]]) -> Vec<Result<[f64; 3], StressError>> {
        let mut rho = Vec::with_capacity(self.els.len());
        points.iter().map(|&p| self.at_with(p, &mut rho)).collect()
    }

    /// [`InteriorStress::evaluate`] in parallel over the points (rayon's global pool); same results.
    pub fn evaluate_par(&self, points: &[[f64; 2]]) -> Vec<Result<[f64; 3], StressError>> {
        points.par_iter().map_init(|| Vec::with_capacity(self.els.len()), |rho, &p| self.at_with(p, rho)).collect()
    }
}

/// Adaptive Gauss–Legendre on [a, b] (same scheme as [`super::quadratic`]): halve until the nearest singularity
/// has Bernstein parameter ≥ [`RHO_ACCEPT`] relative to the piece, then ⌈ORDER_K/ln ρ⌉ points; calls
/// `f(ξ, weight)` per point.
fn adaptive<F: FnMut(f64, f64)>(a: f64, b: f64, sing: &[[f64; 2]], depth: u32, f: &mut F) {
    let mid = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let mut rho = f64::INFINITY;
    for s in sing {
        if s[0].is_finite() {
            rho = rho.min(bernstein_rho((s[0] - mid) / half, s[1] / half));
        }
    }
    if rho >= RHO_ACCEPT || depth == 0 {
        for (t, w) in gl(order_for(rho)).iter() {
            f(mid + half * t, half * w);
        }
    } else {
        adaptive(a, mid, sing, depth - 1, f);
        adaptive(mid, b, sing, depth - 1, f);
    }
}

/// Stresses `[σxx, σyy, σxy]` at interior `points` of the body bounded by `mesh`, from the boundary solution `u`,
/// `t` (one value per node, in node order), by the Somigliana identity (module docs). Units: those of the mesh
/// (lengths, and `u`) and of `k` (tractions and the returned stresses in the unit of Kelvin's modulus); tension
/// positive. Each point gets its own result: [`StressError::OutsideBody`] (also in a hole),
/// [`StressError::OnBoundary`] within [`ON_BOUNDARY_TOL`] element lengths of the boundary (use
/// [`boundary_stress`] there), [`StressError::NotFinite`]. Single-threaded; see [`InteriorStress`] to reuse the
/// precomputation or evaluate in parallel. Refused as [`InteriorStress::new`].
pub fn interior_stress(
    mesh: &Mesh,
    k: &Kelvin,
    u: &[[f64; 2]],
    t: &[[f64; 2]],
    points: &[[f64; 2]],
) -> Result<Vec<Result<[f64; 3], StressError>>, ArgumentError> {
    Ok(InteriorStress::new(mesh, k, u, t)?.evaluate(points))
}

/// A boundary solution `u`, `t` of one value per node of a mesh that holds together ([`Mesh::check`]), else the
/// error naming what does not fit.
fn check_solution(function: &'static str, mesh: &Mesh, u: &[[f64; 2]], t: &[[f64; 2]]) -> Result<(), ArgumentError> {
    mesh.check()?;
    for (name, v) in [("u", u.len()), ("t", t.len())] {
        if v != mesh.n_nodes() {
            return Err(ArgumentError::new(
                function,
                name,
                format!("has {v} entries, the mesh {} nodes", mesh.n_nodes()),
            ));
        }
    }
    Ok(())
}

/// Derivatives dN_j/dξ of the quadratic shape functions of [`super::quadratic::shape`].
fn shape_derivative(xi: f64) -> [f64; 3] {
    let x = XI_NODES;
    [
        (2.0 * xi - x[1] - x[2]) / ((x[0] - x[1]) * (x[0] - x[2])),
        (2.0 * xi - x[0] - x[2]) / ((x[1] - x[0]) * (x[1] - x[2])),
        (2.0 * xi - x[0] - x[1]) / ((x[2] - x[0]) * (x[2] - x[1])),
    ]
}

/// Boundary stress `[σxx, σyy, σxy]` at a point of element `element` (intrinsic coordinate `xi` ∈ [−1, 1] for an
/// arc element; ignored for a straight one, whose value is that of its node), recovered without any integral
/// ("boundary stress recovery"): with the outward normal n and the tangent s = (−n_y, n_x),
///
/// ```text
/// σ_nn = t·n,   σ_ns = t·s,   ε_ss = s·(du/ds),   σ_ss = 2G ε_ss/(1 − ν) + ν σ_nn/(1 − ν)   (plane strain)
/// ```
///
/// du/ds is the derivative of the quadratic interpolant on an arc element; on a straight (constant) element it is
/// the derivative at the node of the parabola through the previous, own and next nodes (neighbours found by shared
/// vertices), so it is only as good as that finite difference. Units and signs as [`interior_stress`].
///
/// Returns `Ok(None)` if a straight element has no neighbour at one of its ends (open boundary). Refused, naming
/// the argument, when `element` is out of range, `u` or `t` does not have one entry per node, or the mesh does not
/// hold together ([`Mesh::check`]).
pub fn boundary_stress(
    mesh: &Mesh,
    k: &Kelvin,
    u: &[[f64; 2]],
    t: &[[f64; 2]],
    element: usize,
    xi: f64,
) -> Result<Option<[f64; 3]>, ArgumentError> {
    check_solution("boundary_stress", mesh, u, t)?;
    let Some(e) = mesh.elements.get(element) else {
        return Err(ArgumentError::new(
            "boundary_stress",
            "element",
            format!("is {element}, the mesh has {} elements", mesh.elements.len()),
        ));
    };
    Ok(boundary_stress_of(mesh, k, u, t, e, xi))
}

/// [`boundary_stress`] of element `e` of a checked mesh and solution.
fn boundary_stress_of(
    mesh: &Mesh,
    k: &Kelvin,
    u: &[[f64; 2]],
    t: &[[f64; 2]],
    e: &crate::mesh::Element,
    xi: f64,
) -> Option<[f64; 3]> {
    let (n, tr, dudx) = match e.shape {
        Shape::Arc(arc) => {
            let nn = shape(xi);
            let dn = shape_derivative(xi);
            let mut tr = [0.0; 2];
            let mut du = [0.0; 2];
            for j in 0..3 {
                for m in 0..2 {
                    tr[m] += nn[j] * t[e.first_node + j][m];
                    du[m] += dn[j] * u[e.first_node + j][m] / arc.jacobian();
                }
            }
            (arc.normal(xi), tr, du)
        }
        Shape::Straight { a, b } => {
            let len = (b[0] - a[0]).hypot(b[1] - a[1]);
            let tol = 1e-9 * len;
            let close = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]) <= tol;
            let ends = |el: &crate::mesh::Element| match el.shape {
                Shape::Straight { a, b } => Some((a, b)),
                Shape::Arc(_) => None,
            };
            let prev = mesh.elements.iter().find(|o| ends(o).is_some_and(|(_, ob)| close(ob, a)))?;
            let next = mesh.elements.iter().find(|o| ends(o).is_some_and(|(oa, _)| close(oa, b)))?;
            let lp = ends(prev).map(|(pa, pb)| (pb[0] - pa[0]).hypot(pb[1] - pa[1]))?;
            let ln = ends(next).map(|(na, nb)| (nb[0] - na[0]).hypot(nb[1] - na[1]))?;
            // Arc-length distances from the own node to the neighbours' nodes.
            let (h1, h2) = (0.5 * (lp + len), 0.5 * (len + ln));
            let (up, u0, un) = (u[prev.first_node], u[e.first_node], u[next.first_node]);
            let mut du = [0.0; 2];
            for m in 0..2 {
                du[m] = -h2 / (h1 * (h1 + h2)) * up[m] + (h2 - h1) / (h1 * h2) * u0[m] + h1 / (h2 * (h1 + h2)) * un[m];
            }
            let tan = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
            ([tan[1], -tan[0]], t[e.first_node], du)
        }
    };
    let s = [-n[1], n[0]];
    let snn = tr[0] * n[0] + tr[1] * n[1];
    let sns = tr[0] * s[0] + tr[1] * s[1];
    let ess = s[0] * dudx[0] + s[1] * dudx[1];
    let nu = k.nu;
    let sss = 2.0 * k.shear_modulus * ess / (1.0 - nu) + nu * snn / (1.0 - nu);
    // σ = σ_nn n⊗n + σ_ss s⊗s + σ_ns (n⊗s + s⊗n).
    Some([
        snn * n[0] * n[0] + sss * s[0] * s[0] + 2.0 * sns * n[0] * s[0],
        snn * n[1] * n[1] + sss * s[1] * s[1] + 2.0 * sns * n[1] * s[1],
        snn * n[0] * n[1] + sss * s[0] * s[1] + sns * (n[0] * s[1] + s[0] * n[1]),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// D and S are Hooke's law applied to the source-point derivatives of kelvin.rs's U* and T* (the Somigliana
    /// displacement identity u_l(ξ) = ∫U*_lk t_k − ∫T*_lk u_k differentiated in ξ): central differences of U*, T*
    /// (step 1e-5 r, error O(1e-10) relative) against the closed forms, and the fused `accumulate` against the
    /// tensors contracted with arbitrary u, t.
    #[test]
    fn kernels_are_hooke_of_kelvin_source_derivatives() {
        for nu in [0.0, 0.3, 0.45] {
            let k = Kelvin::new(2.7, nu);
            let g = k.shear_modulus;
            let lam = 2.0 * g * nu / (1.0 - 2.0 * nu);
            let x: [f64; 2] = [0.7, -0.3];
            let nrm = [0.6, 0.8];
            for xi in [[0.1_f64, 0.2], [1.3, -0.9], [0.69, -0.28]] {
                let r = (x[0] - xi[0]).hypot(x[1] - xi[1]);
                let hstep = 1e-5 * r;
                // dU[m][l][k] = ∂U*_lk/∂ξ_m, same for T.
                let mut du = [[[0.0; 2]; 2]; 2];
                let mut dt = [[[0.0; 2]; 2]; 2];
                for m in 0..2 {
                    let mut xp = xi;
                    let mut xm = xi;
                    xp[m] += hstep;
                    xm[m] -= hstep;
                    let (up, um) = (k.u(x, xp), k.u(x, xm));
                    let (tp, tm) = (k.t(x, nrm, xp), k.t(x, nrm, xm));
                    for l in 0..2 {
                        for kk in 0..2 {
                            du[m][l][kk] = (up[l][kk] - um[l][kk]) / (2.0 * hstep);
                            dt[m][l][kk] = (tp[l][kk] - tm[l][kk]) / (2.0 * hstep);
                        }
                    }
                }
                let (dk, sk) = somigliana_kernels(&k, x, nrm, xi);
                let (mut dscale, mut sscale) = (0.0_f64, 0.0_f64);
                let mut errs = (0.0_f64, 0.0_f64);
                for kk in 0..2 {
                    for i in 0..2 {
                        for j in 0..2 {
                            let del = if i == j { 1.0 } else { 0.0 };
                            let dfd = lam * del * (du[0][0][kk] + du[1][1][kk]) + g * (du[j][i][kk] + du[i][j][kk]);
                            let sfd = lam * del * (dt[0][0][kk] + dt[1][1][kk]) + g * (dt[j][i][kk] + dt[i][j][kk]);
                            dscale = dscale.max(dfd.abs());
                            sscale = sscale.max(sfd.abs());
                            errs.0 = errs.0.max((dk[kk][i][j] - dfd).abs());
                            errs.1 = errs.1.max((sk[kk][i][j] - sfd).abs());
                        }
                    }
                }
                assert!(errs.0 < 1e-8 * dscale && errs.1 < 1e-8 * sscale, "nu {nu} xi {xi:?}: {errs:?}");
                // Fused evaluation.
                let (uu, tt) = ([0.3, -1.1], [-0.7, 0.25]);
                let c = Consts { cd: k.ct, cs: 2.0 * g * k.ct, nu, b12: k.b12, b14: 1.0 - 4.0 * nu };
                let mut acc = [0.0; 3];
                accumulate(&c, [x[0] - xi[0], x[1] - xi[1]], nrm, uu, tt, 1.0, &mut acc);
                for (q, (i, j)) in [(0, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                    let want: f64 = (0..2).map(|kk| dk[kk][i][j] * tt[kk] - sk[kk][i][j] * uu[kk]).sum();
                    assert!((acc[q] - want).abs() < 1e-13 * (dscale + sscale), "{q}: {} vs {want}", acc[q]);
                }
            }
        }
    }

    #[test]
    fn shape_derivative_matches_finite_differences() {
        for xi in [-1.0, -0.3, 0.0, 0.5, 1.0] {
            let h = 1e-6;
            let (p, m) = (shape(xi + h), shape(xi - h));
            let d = shape_derivative(xi);
            for j in 0..3 {
                assert!((d[j] - (p[j] - m[j]) / (2.0 * h)).abs() < 1e-8);
            }
        }
    }
}
