//! # Subsurface stresses of a half-space under piecewise-constant surface tractions
//!
//! The stress tensor at points inside one elastic half-space loaded on its surface by the tractions of a
//! [`ContactGrid`] — per element a uniform pressure `p` and shears `(q_x, q_y)` — in closed form: per element the
//! exact field of a uniformly loaded rectangle (Love 1929 for the pressure; Cerruti's point load integrated over the
//! rectangle for the shears), summed over the elements. The 3D counterpart of [`crate::stresses`]' half-plane field
//! (plane strain, [`crate::halfplane::strip_stress`]).
//!
//! ## Axes, signs, units
//!
//! [`super::kernel`]'s axes: the body occupies `z > 0`, `z` is the depth INTO the body, `x`, `y` run along the
//! surface. The tractions act ON the body: `p` along `+z` (pushing into it, positive in compression), `q_x`, `q_y`
//! along `+x`, `+y`. Stresses are **tension positive**, in the tractions' unit; the outward normal of the body is
//! `−z`, so on the loaded surface `σ_zz = −p`, `σ_zx = −q_x`, `σ_yz = −q_y`. The stresses of a traction-loaded
//! half-space depend on Poisson's ratio only, not on Young's modulus.
//!
//! **CONTACT's conventions map one to one**: CONTACT's body 1 is the upper body, its `z` axis points into body 1,
//! and its tractions `(pn, px, py)` act on body 1 (`reference/contact3d/README.md`, "Conventions"). So CONTACT's
//! `pn, px, py` are this module's `p, q_x, q_y` for body 1 ([`Subsurface::new`]), and its subsurface `sigxx …
//! sigzz` at depth `z` are this module's components at the same `(x, y, z)` (checked against CONTACT's
//! `subsurf.inp` in `tests/subsurface3d.rs`). For the counter-body (body 2, `z < 0`) use
//! [`Subsurface::counter_body`]: in body 2's own mirrored frame (`x' = x`, `y' = y`, depth `z' = −z` into body 2,
//! [`super::kernel`], "A pair of half-spaces") it receives the pressure `p` and the shears `−q`; its stresses are
//! returned in that frame (to global axes: `σ_yz`, `σ_zx` change sign, the others stay).
//!
//! ## Potentials (Boussinesq–Cerruti, Love)
//!
//! With `ρ = √((x−ξ)² + (y−η)² + z²)` and `Ω = z ln(ρ + z) − ρ` (harmonic in `z > 0`: `Ω_z = ln(ρ+z)`,
//! `Ω_zz = 1/ρ`), let `Φ(x, y, z) = ∬_R Ω dξ dη` over one rectangle `R` carrying unit traction. K.L. Johnson,
//! *Contact Mechanics* (1985) §3.2 (eqs. 3.7–3.10: `F₁ = q_x Φ`, `G₁ = q_y Φ`, `H₁ = p Φ`,
//! `ψ₁ = ∂F₁/∂x + ∂G₁/∂y + ∂H₁/∂z`, `ψ = ∂ψ₁/∂z`) gives the displacements
//!
//! ```text
//! 4πG u_x = 2 q_x Φ_zz − p Φ_xz + 2ν ψ₁_x − z ψ_x
//! 4πG u_y = 2 q_y Φ_zz − p Φ_yz + 2ν ψ₁_y − z ψ_y
//! 4πG u_z = p Φ_zz + (1 − 2ν) ψ − z ψ_z ,        ψ₁ = q_x Φ_x + q_y Φ_y + p Φ_z.
//! ```
//!
//! (For a point load, `Φ → Ω`, these are Boussinesq's and Cerruti's displacements, Johnson eqs. 3.19 and 3.86–3.87,
//! in full, not only on the surface: checked symbolically while deriving.) Hooke's law
//! `σ = λ tr(ε) I + 2Gε` and `∇²Φ = 0` then give every stress as `1/(2π)` times a combination of derivatives of `Φ`,
//! which are the potentials `V = Φ_zz = ∬ 1/ρ` (Newtonian potential of the loaded rectangle), `χ = Φ_z = ∬ ln(ρ+z)`
//! and `Φ`'s own mixed derivatives:
//!
//! ```text
//! pressure p:  2πσ_xx = −2ν χ_yy − χ_xx − z V_xx          2πσ_xy = −(1−2ν) χ_xy − z V_xy
//!              2πσ_yy = −2ν χ_xx − χ_yy − z V_yy          2πσ_yz = −z V_yz
//!              2πσ_zz = V_z + z (V_xx + V_yy)              2πσ_zx = −z V_xz
//! shear q_x:   2πσ_xx = −2ν Φ_xyy − z χ_xxx + 2 V_x        2πσ_xy = 2ν Φ_xxy − z χ_xxy + V_y
//!              2πσ_yy = 2ν (Φ_xyy + V_x) − z χ_xyy         2πσ_yz = −z V_xy
//!              2πσ_zz = −z V_xz                            2πσ_zx = V_z − z V_xx
//! shear q_y:   q_x's with x ↔ y (σ_xx ↔ σ_yy, σ_yz ↔ σ_zx; Φ_xyy ↔ Φ_xxy, χ_xxx ↔ χ_yyy, χ_xyy ↔ χ_xxy, V_x ↔ V_y).
//! ```
//!
//! On the surface `V_z → −2π` under the load, so `σ_zz → −p` and `σ_zx → −q_x` (tested).
//!
//! ## The rectangle in closed form
//!
//! With `X = x − ξ`, `Y = y − η`, every derivative above is the double difference `ΔΔf` of a corner function `f(X,
//! Y, z)` over the rectangle's corners ([`super::kernel`], "Rectangles": `ΔΔf = f(a1,b1) − f(a2,b1) − f(a1,b2) +
//! f(a2,b2)`), because `∂_x∂_y Φ = ΔΔΩ` and a further `x`, `y` or `z` derivative differentiates `f` (a term of `f`
//! depending on `X` alone or `Y` alone drops out). The corner functions, each checked by differentiation
//! (`corner_functions_are_antiderivatives` below):
//!
//! ```text
//! χ_xy  : ln(ρ+z)                 Φ_xxy : −X/(ρ+z)             Φ_xyy : −Y/(ρ+z)
//! χ_xxy : X/(ρ(ρ+z))              χ_xyy : Y/(ρ(ρ+z))
//! χ_xx  : T_x = atan(Y/X) − atan(zY/(Xρ)) = atan2(XY(X²+Y²), (ρ+z)(X²ρ + zY²))      (∂_Y T_x = X/(ρ(ρ+z)))
//! χ_xxx : ∂_X T_x = Y (zρ − X²)/(ρ (ρ+z)(X² + z²))                                  (χ_yy, χ_yyy: x ↔ y)
//! V_x   : ln(Y+ρ)      V_y : ln(X+ρ)      V_z : −atan2(XY, zρ)   (the solid angle; W = X ln(Y+ρ) + Y ln(X+ρ)
//!                                                                   − z atan(XY/(zρ)) has ∂_X∂_Y W = 1/ρ)
//! V_xx  : X/(ρ(ρ+Y))   V_yy : Y/(ρ(ρ+X))   V_xy : 1/ρ   V_xz : z/(ρ(ρ+Y))   V_yz : z/(ρ(ρ+X))
//! ```
//!
//! `T_x` as one `atan2`: `atan(Y/X)` and `atan(zY/(Xρ))` have the same sign and the first is the larger in
//! magnitude (`z < ρ`), so their difference lies in `(−π/2, π/2)`; the form is continuous across `X = 0`
//! (where it is 0) and its denominator is never negative. `χ_xx` follows from
//! `∫ X/(ρ(ρ+z)) dY = ∫ [X/(X²+Y²) − zX/(ρ(X²+Y²))] dY` (using `1/(ρ(ρ+z)) = (ρ−z)/(ρ(X²+Y²))`). Where `ρ + Y`
//! cancels (`Y < 0`) it is evaluated as `(X² + z²)/(ρ − Y)`. The identities `Φ_xxx = −Φ_xyy − V_x` and
//! `Φ_xxxx = −Φ_xxyy − V_xx` (harmonicity) are what keep the pure-`x` derivatives out of the list.
//!
//! ## Summation over the grid
//!
//! Adjacent elements share corners, so the sum over elements is a sum over the grid's nodes (the `(MX+1)(MY+1)`
//! element corners) of one corner function each, weighted by `w = t(i,j) − t(i−1,j) − t(i,j−1) + t(i−1,j−1)` (the
//! tractions `t` of the up to four elements meeting at node `(i, j)`, zero outside the grid): four times fewer
//! evaluations, and the nodes inside a region of uniform traction drop out (`w = 0`, skipped). **Cost**: N_nodes ×
//! N_points corner evaluations (17 corner functions, one square root, three logarithms, three `atan2` each), N_nodes
//! the nodes with a non-zero weight (about the elements in contact); points in parallel (rayon), each point's sum in
//! node order, so the result does not depend on the threads. Measured (`tests/subsurface3d.rs`): about 0.1–0.2 µs per
//! node and point per thread (a box of 4 961 points under 1 324 nodes: 0.5 s on two busy cores).
//!
//! ## Accuracy
//!
//! Exact for the piecewise-constant tractions up to rounding. The double differences lose digits with the distance
//! `R` from the element in units of its size `h`: about `(R/h)²` ulps of the element's own contribution (its corner
//! functions are `O(ln R)`, its stress `O(h²/R²)`): measured 5e-10 of it at `R = 10³ h`. Against an independent
//! Gauss–Legendre quadrature of Boussinesq's and Cerruti's point-load stresses (`tests/subsurface3d.rs`): 8e-14 of
//! the tractions above element interiors, edges and corners and beside the grid, at depths 10⁻³ … 5 element sizes.
//!
//! ## The surface (`z = 0`)
//!
//! `z = 0` is evaluated as the limit `z → 0⁺`. At a surface point exactly on an edge of a loaded element the field of
//! piecewise-constant tractions is discontinuous (the mean of the two sides is returned, e.g. `σ_zz = −p/2` on an
//! edge of an isolated element) or logarithmically infinite (`σ_xx` of a shear `q_x` on an edge `x = const`, `σ_xy`
//! of a pressure at a corner): such a point is refused with an [`ArgumentError`] naming it, never a non-finite value.
//! A surface row meant to stand for a continuous contact is best placed at element centres.

use super::kernel::HalfSpace;
use super::operator::ContactGrid;
use crate::error::ArgumentError;
use nalgebra::Matrix3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// A symmetric stress tensor (tension positive; axes of the module docs, `z` the depth into the body), in the
/// tractions' stress unit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct Stress {
    /// σ_xx.
    pub xx: f64,
    /// σ_yy.
    pub yy: f64,
    /// σ_zz (`−p` on the loaded surface).
    pub zz: f64,
    /// σ_xy.
    pub xy: f64,
    /// σ_yz (`−q_y` on the loaded surface).
    pub yz: f64,
    /// σ_zx (`−q_x` on the loaded surface).
    pub zx: f64,
}

impl Stress {
    /// The stress of the six components `[xx, yy, zz, xy, yz, zx]`.
    pub fn from_components(c: [f64; 6]) -> Stress {
        Stress { xx: c[0], yy: c[1], zz: c[2], xy: c[3], yz: c[4], zx: c[5] }
    }

    /// The components `[xx, yy, zz, xy, yz, zx]`.
    pub fn components(&self) -> [f64; 6] {
        [self.xx, self.yy, self.zz, self.xy, self.yz, self.zx]
    }

    /// The hydrostatic (mean) stress `(σ_xx + σ_yy + σ_zz)/3` (tension positive; CONTACT's `sighyd`).
    pub fn hydrostatic(&self) -> f64 {
        (self.xx + self.yy + self.zz) / 3.0
    }

    /// Von Mises' equivalent stress `√(½[(σxx−σyy)² + (σyy−σzz)² + (σzz−σxx)²] + 3(σxy² + σyz² + σzx²))`
    /// (CONTACT's `sigvm`).
    pub fn von_mises(&self) -> f64 {
        let (a, b, c) = (self.xx - self.yy, self.yy - self.zz, self.zz - self.xx);
        (0.5 * (a * a + b * b + c * c) + 3.0 * (self.xy * self.xy + self.yz * self.yz + self.zx * self.zx)).sqrt()
    }

    /// The principal stresses `σ1 ≥ σ2 ≥ σ3` (eigenvalues of the tensor).
    pub fn principal(&self) -> [f64; 3] {
        let m = Matrix3::new(self.xx, self.xy, self.zx, self.xy, self.yy, self.yz, self.zx, self.yz, self.zz);
        let e = m.symmetric_eigenvalues();
        let mut v = [e[0], e[1], e[2]];
        v.sort_by(|a, b| b.total_cmp(a));
        v
    }

    /// The maximum shear stress (Tresca) `(σ1 − σ3)/2`, the radius of the largest Mohr circle.
    pub fn max_shear(&self) -> f64 {
        let s = self.principal();
        0.5 * (s[0] - s[2])
    }
}

/// One grid node with a non-zero traction weight (module docs, "Summation over the grid").
#[derive(Clone, Copy, Debug)]
struct Node {
    x: f64,
    y: f64,
    /// The weights of the pressure and of the two shears.
    w: [f64; 3],
}

/// The subsurface field of one half-space under the tractions of a grid (module docs): built once from the
/// tractions, evaluated at any points of the body.
#[derive(Clone, Debug)]
pub struct Subsurface {
    nu: f64,
    scale: f64,
    nodes: Vec<Node>,
}

/// The corner functions of one node at one point (module docs, "The rectangle in closed form").
#[derive(Clone, Copy, Debug, Default)]
struct Corner {
    chi_xx: f64,
    chi_yy: f64,
    chi_xy: f64,
    chi_xxx: f64,
    chi_yyy: f64,
    chi_xxy: f64,
    chi_xyy: f64,
    phi_xxy: f64,
    phi_xyy: f64,
    v_x: f64,
    v_y: f64,
    v_z: f64,
    v_xx: f64,
    v_yy: f64,
    v_xy: f64,
    v_xz: f64,
    v_yz: f64,
}

impl Corner {
    /// The corner functions at `(X, Y, z)`, `z ≥ 0`. At `z = 0` the terms that enter multiplied by `z` are set to 0
    /// (their limit), so only the surface's genuine singularities remain non-finite.
    fn at(x: f64, y: f64, z: f64) -> Corner {
        let (x2, y2, z2) = (x * x, y * y, z * z);
        let rho = (x2 + y2 + z2).sqrt();
        let rz = rho + z;
        let num = x * y * (x2 + y2);
        // 1/(ρ+Y) and ln(ρ+Y) without cancellation for Y < 0 (and the same in X).
        let inv_ry = if y >= 0.0 { 1.0 / (rho + y) } else { (rho - y) / (x2 + z2) };
        let inv_rx = if x >= 0.0 { 1.0 / (rho + x) } else { (rho - x) / (y2 + z2) };
        let ln_ry = if y >= 0.0 { (rho + y).ln() } else { (x2 + z2).ln() - (rho - y).ln() };
        let ln_rx = if x >= 0.0 { (rho + x).ln() } else { (y2 + z2).ln() - (rho - x).ln() };
        let mut c = Corner {
            chi_xx: num.atan2(rz * (x2 * rho + z * y2)),
            chi_yy: num.atan2(rz * (y2 * rho + z * x2)),
            chi_xy: rz.ln(),
            chi_xxy: x / (rho * rz),
            chi_xyy: y / (rho * rz),
            phi_xxy: -x / rz,
            phi_xyy: -y / rz,
            v_x: ln_ry,
            v_y: ln_rx,
            v_z: -(x * y).atan2(z * rho),
            v_xy: 1.0 / rho,
            ..Corner::default()
        };
        if z > 0.0 {
            c.chi_xxx = y * (z * rho - x2) / (rho * rz * (x2 + z2));
            c.chi_yyy = x * (z * rho - y2) / (rho * rz * (y2 + z2));
            c.v_xx = x * inv_ry / rho;
            c.v_yy = y * inv_rx / rho;
            c.v_xz = z * inv_ry / rho;
            c.v_yz = z * inv_rx / rho;
        }
        c
    }
}

/// The sums `Σ w f` over the nodes of each corner function, per traction (pressure, q_x, q_y).
#[derive(Clone, Copy, Debug, Default)]
struct Sums([Corner; 3]);

impl Sums {
    fn add(&mut self, w: &[f64; 3], c: &Corner) {
        for (s, &w) in self.0.iter_mut().zip(w) {
            if w == 0.0 {
                continue;
            }
            s.chi_xx += w * c.chi_xx;
            s.chi_yy += w * c.chi_yy;
            s.chi_xy += w * c.chi_xy;
            s.chi_xxx += w * c.chi_xxx;
            s.chi_yyy += w * c.chi_yyy;
            s.chi_xxy += w * c.chi_xxy;
            s.chi_xyy += w * c.chi_xyy;
            s.phi_xxy += w * c.phi_xxy;
            s.phi_xyy += w * c.phi_xyy;
            s.v_x += w * c.v_x;
            s.v_y += w * c.v_y;
            s.v_z += w * c.v_z;
            s.v_xx += w * c.v_xx;
            s.v_yy += w * c.v_yy;
            s.v_xy += w * c.v_xy;
            s.v_xz += w * c.v_xz;
            s.v_yz += w * c.v_yz;
        }
    }
}

/// The stress of the summed potentials at depth `z` for Poisson's ratio `nu` (module docs, "Potentials").
fn stress_of(s: &Sums, nu: f64, z: f64) -> Stress {
    let [p, qx, qy] = &s.0;
    let normal = [
        -2.0 * nu * p.chi_yy - p.chi_xx - z * p.v_xx,
        -2.0 * nu * p.chi_xx - p.chi_yy - z * p.v_yy,
        p.v_z + z * (p.v_xx + p.v_yy),
        -(1.0 - 2.0 * nu) * p.chi_xy - z * p.v_xy,
        -z * p.v_yz,
        -z * p.v_xz,
    ];
    let shear_x = [
        -2.0 * nu * qx.phi_xyy - z * qx.chi_xxx + 2.0 * qx.v_x,
        2.0 * nu * (qx.phi_xyy + qx.v_x) - z * qx.chi_xyy,
        -z * qx.v_xz,
        2.0 * nu * qx.phi_xxy - z * qx.chi_xxy + qx.v_y,
        -z * qx.v_xy,
        qx.v_z - z * qx.v_xx,
    ];
    let shear_y = [
        2.0 * nu * (qy.phi_xxy + qy.v_y) - z * qy.chi_xxy,
        -2.0 * nu * qy.phi_xxy - z * qy.chi_yyy + 2.0 * qy.v_y,
        -z * qy.v_yz,
        2.0 * nu * qy.phi_xyy - z * qy.chi_xyy + qy.v_x,
        qy.v_z - z * qy.v_yy,
        -z * qy.v_xy,
    ];
    let mut c = [0.0; 6];
    for k in 0..6 {
        c[k] = (normal[k] + shear_x[k] + shear_y[k]) / (2.0 * PI);
    }
    Stress::from_components(c)
}

/// A regular box of points: `counts[0] × counts[1] × counts[2]` points from `lo` to `hi` (both included; a count
/// of 1 takes `lo`) along x, y and the depth z. Point `(i, j, k)` has index `i + nx·(j + ny·k)` (x fastest, then
/// y, then the depth).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct StressBox {
    /// `[x_lo, y_lo, z_lo]` (length; `z_lo ≥ 0`).
    pub lo: [f64; 3],
    /// `[x_hi, y_hi, z_hi]` (length; each ≥ its `lo`).
    pub hi: [f64; 3],
    /// Points along x, y, z (each ≥ 1).
    pub counts: [usize; 3],
}

impl StressBox {
    /// The box `[lo, hi]` with `counts` points per axis (validated when evaluated, [`Subsurface::evaluate_box`]).
    pub fn new(lo: [f64; 3], hi: [f64; 3], counts: [usize; 3]) -> StressBox {
        StressBox { lo, hi, counts }
    }

    /// The points in index order (see the type's docs).
    pub fn points(&self) -> Vec<[f64; 3]> {
        let at = |a: usize, i: usize| {
            let n = self.counts[a];
            if n <= 1 {
                self.lo[a]
            } else {
                self.lo[a] + (self.hi[a] - self.lo[a]) * i as f64 / (n - 1) as f64
            }
        };
        let [nx, ny, nz] = self.counts;
        let mut out = Vec::with_capacity(nx * ny * nz);
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    out.push([at(0, i), at(1, j), at(2, k)]);
                }
            }
        }
        out
    }
}

/// A largest value of a derived quantity and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Peak {
    /// The value (stress).
    pub value: f64,
    /// The point `[x, y, z]` (the first in index order if several share the value).
    pub at: [f64; 3],
}

/// A field evaluated at a list of points, with the maxima of von Mises' stress and of the maximum shear.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Field {
    /// The points `[x, y, z]`.
    pub points: Vec<[f64; 3]>,
    /// The stress at each point.
    pub stresses: Vec<Stress>,
    /// The largest von Mises stress ([`Stress::von_mises`]).
    pub von_mises: Peak,
    /// The largest maximum shear ([`Stress::max_shear`], Tresca).
    pub max_shear: Peak,
}

impl Subsurface {
    /// The field in the half-space `body` (body 1, `z > 0`) of the tractions `pn`, `px`, `py` acting on it, one per
    /// element of `grid` in grid order (`ix + MX·iy`; stress unit): CONTACT's `pn, px, py` (module docs). Only
    /// `body`'s Poisson's ratio matters.
    ///
    /// # Errors
    /// An [`ArgumentError`] naming the traction array of the wrong length or with a non-finite value.
    pub fn new(
        grid: &ContactGrid,
        body: &HalfSpace,
        pn: &[f64],
        px: &[f64],
        py: &[f64],
    ) -> Result<Subsurface, ArgumentError> {
        const F: &str = "halfspace::Subsurface::new";
        for (name, t) in [("pn", pn), ("px", px), ("py", py)] {
            if t.len() != grid.len() {
                return Err(ArgumentError::new(
                    F,
                    name,
                    format!("{} values, one per element, got {}", grid.len(), t.len()),
                ));
            }
            if let Some(i) = t.iter().position(|v| !v.is_finite()) {
                return Err(ArgumentError::new(F, name, format!("element {i} is not finite ({})", t[i])));
            }
        }
        let (mx, my) = (grid.mx(), grid.my());
        let t = |a: &[f64], i: isize, j: isize| {
            if i < 0 || j < 0 || i >= mx as isize || j >= my as isize {
                0.0
            } else {
                a[i as usize + mx * j as usize]
            }
        };
        let mut nodes = Vec::new();
        for j in 0..=my as isize {
            for i in 0..=mx as isize {
                let w = [pn, px, py].map(|a| t(a, i, j) - t(a, i - 1, j) - t(a, i, j - 1) + t(a, i - 1, j - 1));
                if w.iter().any(|&v| v != 0.0) {
                    let (cx, cy) = grid.centre(i as usize, j as usize);
                    nodes.push(Node { x: cx - 0.5 * grid.dx(), y: cy - 0.5 * grid.dy(), w });
                }
            }
        }
        let scale = grid.dx().min(grid.dy());
        Ok(Subsurface { nu: body.poisson_ratio(), scale, nodes })
    }

    /// The field in the counter-body `counter` (body 2, `z < 0`) of the same tractions `pn`, `px`, `py` (those on
    /// body 1, CONTACT's): body 2 receives the pressure `pn` and the shears `−px`, `−py` in its own mirrored frame,
    /// where its points and stresses are given (module docs, "Axes, signs, units").
    ///
    /// # Errors
    /// As [`Subsurface::new`].
    pub fn counter_body(
        grid: &ContactGrid,
        counter: &HalfSpace,
        pn: &[f64],
        px: &[f64],
        py: &[f64],
    ) -> Result<Subsurface, ArgumentError> {
        let neg = |a: &[f64]| a.iter().map(|v| -v).collect::<Vec<f64>>();
        Subsurface::new(grid, counter, pn, &neg(px), &neg(py))
    }

    /// Poisson's ratio of the body.
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }

    /// The grid nodes that carry a non-zero weight: the cost of one point is proportional to their number.
    pub fn active_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// The stress at `(x, y, z)`, `z ≥ 0` the depth (module docs; `z = 0` is the limit `z → 0⁺`).
    ///
    /// # Errors
    /// An [`ArgumentError`] for a non-finite coordinate, a point above the surface (`z < 0`), or a surface point on
    /// an edge of a loaded element where the field is singular (module docs, "The surface").
    pub fn stress(&self, x: f64, y: f64, z: f64) -> Result<Stress, ArgumentError> {
        const F: &str = "halfspace::Subsurface::stress";
        if !(x.is_finite() && y.is_finite() && z.is_finite()) {
            return Err(ArgumentError::new(F, "point", format!("({x}, {y}, {z}) must be finite")));
        }
        if z < 0.0 {
            return Err(ArgumentError::new(
                F,
                "point",
                format!("({x}, {y}, {z}) lies above the surface: the depth z must be ≥ 0"),
            ));
        }
        let mut sums = Sums::default();
        for n in &self.nodes {
            sums.add(&n.w, &Corner::at(x - n.x, y - n.y, z));
        }
        let s = stress_of(&sums, self.nu, z);
        if s.components().iter().all(|v| v.is_finite()) {
            Ok(s)
        } else {
            Err(ArgumentError::new(
                F,
                "point",
                format!(
                    "({x}, {y}, {z}) lies on the surface on an edge or corner of a loaded element, where the stress of \
                     piecewise-constant tractions is singular (element size {}): move it off the edge or below the \
                     surface",
                    self.scale
                ),
            ))
        }
    }

    /// The stresses at `points` (`[x, y, z]` each), in parallel.
    ///
    /// # Errors
    /// As [`Subsurface::stress`], for the first offending point (its index in the message).
    pub fn stresses(&self, points: &[[f64; 3]]) -> Result<Vec<Stress>, ArgumentError> {
        points
            .par_iter()
            .enumerate()
            .map(|(k, p)| {
                self.stress(p[0], p[1], p[2]).map_err(|mut e| {
                    e.message = format!("point {k}: {}", e.message);
                    e
                })
            })
            .collect()
    }

    /// The field at `points` with its maxima of von Mises' stress and of the maximum shear.
    ///
    /// # Errors
    /// As [`Subsurface::stresses`]; also an empty list of points.
    pub fn evaluate(&self, points: &[[f64; 3]]) -> Result<Field, ArgumentError> {
        if points.is_empty() {
            return Err(ArgumentError::new("halfspace::Subsurface::evaluate", "points", "at least one point"));
        }
        let stresses = self.stresses(points)?;
        let peak = |f: fn(&Stress) -> f64| {
            let mut best = Peak { value: f64::NEG_INFINITY, at: points[0] };
            for (p, s) in points.iter().zip(&stresses) {
                let v = f(s);
                if v > best.value {
                    best = Peak { value: v, at: *p };
                }
            }
            best
        };
        let (von_mises, max_shear) = (peak(Stress::von_mises), peak(Stress::max_shear));
        Ok(Field { points: points.to_vec(), stresses, von_mises, max_shear })
    }

    /// The field on the box `b` ([`StressBox`]: the points in its index order) with its maxima.
    ///
    /// # Errors
    /// An [`ArgumentError`] naming `box` for a bound not finite, `hi < lo`, a count of 0 or more than 10⁸ points in
    /// all, or `z_lo < 0`; otherwise as [`Subsurface::evaluate`].
    pub fn evaluate_box(&self, b: &StressBox) -> Result<Field, ArgumentError> {
        const F: &str = "halfspace::Subsurface::evaluate_box";
        for a in 0..3 {
            let (lo, hi, n) = (b.lo[a], b.hi[a], b.counts[a]);
            let axis = ["x", "y", "z"][a];
            if !(lo.is_finite() && hi.is_finite() && hi >= lo) {
                return Err(ArgumentError::new(F, "box", format!("{axis} range {lo} .. {hi}: finite, hi ≥ lo")));
            }
            if n == 0 {
                return Err(ArgumentError::new(F, "box", format!("{axis}: at least one point")));
            }
        }
        if b.lo[2] < 0.0 {
            return Err(ArgumentError::new(F, "box", format!("z from {} lies above the surface: z ≥ 0", b.lo[2])));
        }
        let total = b.counts.iter().try_fold(1usize, |acc, &n| acc.checked_mul(n)).unwrap_or(usize::MAX);
        if total > 100_000_000 {
            return Err(ArgumentError::new(F, "box", format!("{total} points: at most 10^8")));
        }
        self.evaluate(&b.points())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The corner functions are what the module docs say: each pair related by a derivative agrees with a central
    /// difference of the other (step 1e-5, relative agreement 1e-7), at points in every octant.
    #[test]
    fn corner_functions_are_antiderivatives() {
        let h = 1e-5;
        let pts = [(0.7, 0.4, 0.3), (-0.6, 0.9, 0.2), (0.5, -1.3, 0.8), (-0.9, -0.4, 1.5), (0.05, 0.3, 0.1)];
        for &(x, y, z) in &pts {
            let c = Corner::at(x, y, z);
            let d = |f: fn(&Corner) -> f64, dx: f64, dy: f64, dz: f64| {
                (f(&Corner::at(x + dx, y + dy, z + dz)) - f(&Corner::at(x - dx, y - dy, z - dz))) / (2.0 * h)
            };
            let rho = (x * x + y * y + z * z).sqrt();
            let checks = [
                ("dT_x/dY", d(|c| c.chi_xx, 0.0, h, 0.0), c.chi_xxy),
                ("dT_x/dX", d(|c| c.chi_xx, h, 0.0, 0.0), c.chi_xxx),
                ("dT_y/dX", d(|c| c.chi_yy, h, 0.0, 0.0), c.chi_xyy),
                ("dT_y/dY", d(|c| c.chi_yy, 0.0, h, 0.0), c.chi_yyy),
                ("dln(rho+z)/dX", d(|c| c.chi_xy, h, 0.0, 0.0), c.chi_xxy),
                ("dln(rho+z)/dz", d(|c| c.chi_xy, 0.0, 0.0, h), 1.0 / rho),
                ("dPhi_xxy/dY", d(|c| c.phi_xxy, 0.0, h, 0.0), x * y / (rho * (rho + z) * (rho + z))),
                ("dPhi_xxy/dz", d(|c| c.phi_xxy, 0.0, 0.0, h), c.chi_xxy),
                ("dPhi_xyy/dz", d(|c| c.phi_xyy, 0.0, 0.0, h), c.chi_xyy),
                ("dV_x/dX", d(|c| c.v_x, h, 0.0, 0.0), c.v_xx),
                ("dV_x/dY", d(|c| c.v_x, 0.0, h, 0.0), c.v_xy),
                ("dV_x/dz", d(|c| c.v_x, 0.0, 0.0, h), c.v_xz),
                ("dV_y/dY", d(|c| c.v_y, 0.0, h, 0.0), c.v_yy),
                ("dV_y/dz", d(|c| c.v_y, 0.0, 0.0, h), c.v_yz),
            ];
            for (name, num, exact) in checks {
                assert!(
                    (num - exact).abs() <= 1e-7 * exact.abs().max(1.0),
                    "{name} at ({x}, {y}, {z}): {num} vs {exact}"
                );
            }
            // ∂_X∂_Y of V_z's corner is ∂_z(1/ρ) = −z/ρ³ (the solid angle).
            let dxy =
                (Corner::at(x + h, y + h, z).v_z - Corner::at(x + h, y - h, z).v_z - Corner::at(x - h, y + h, z).v_z
                    + Corner::at(x - h, y - h, z).v_z)
                    / (4.0 * h * h);
            assert!((dxy + z / rho.powi(3)).abs() <= 1e-5, "V_z corner: {dxy}");
        }
    }

    /// At the surface, inside a loaded element, the tractions come back: `σ_zz = −p`, `σ_zx = −q_x`, `σ_yz = −q_y`;
    /// at the centre of an isolated square under pressure `σ_xx = σ_yy = −(1+2ν)p/2` (the surface trace
    /// `σ_xx + σ_yy = −(1+2ν)p` of a uniformly loaded region, Johnson §3.4).
    #[test]
    fn surface_values_return_the_tractions() {
        let grid = ContactGrid::new(1, 1, 1.0, 1.0, 0.0, 0.0).unwrap();
        let body = HalfSpace::new(1.0, 0.3).unwrap();
        let s = Subsurface::new(&grid, &body, &[2.0], &[0.5], &[-0.25]).unwrap();
        let t = s.stress(0.1, -0.2, 0.0).unwrap();
        assert!((t.zz + 2.0).abs() < 1e-14 && (t.zx + 0.5).abs() < 1e-14 && (t.yz - 0.25).abs() < 1e-14, "{t:?}");
        let p = Subsurface::new(&grid, &body, &[1.0], &[0.0], &[0.0]).unwrap().stress(0.0, 0.0, 0.0).unwrap();
        assert!((p.xx + 0.8).abs() < 1e-14 && (p.yy + 0.8).abs() < 1e-14 && p.xy.abs() < 1e-14, "{p:?}");
    }

    /// Bad input is refused by name; a surface point on a sheared element's edge is refused as singular.
    #[test]
    fn bad_input_is_refused() {
        let grid = ContactGrid::new(2, 1, 1.0, 1.0, 0.0, 0.0).unwrap();
        let body = HalfSpace::new(1.0, 0.3).unwrap();
        let e = Subsurface::new(&grid, &body, &[1.0], &[0.0, 0.0], &[0.0, 0.0]).unwrap_err();
        assert_eq!(e.argument, "pn");
        let e = Subsurface::new(&grid, &body, &[1.0, 1.0], &[0.0, f64::NAN], &[0.0, 0.0]).unwrap_err();
        assert_eq!(e.argument, "px");
        let s = Subsurface::new(&grid, &body, &[1.0, 1.0], &[0.3, 0.3], &[0.0, 0.0]).unwrap();
        assert!(s.stress(0.0, 0.0, -1e-9).unwrap_err().message.contains("above the surface"));
        assert!(s.stress(f64::NAN, 0.0, 1.0).is_err());
        assert!(s.stress(-0.5, 0.0, 0.0).unwrap_err().message.contains("singular"));
        assert!(s.stress(-0.5, 0.0, 1e-3).is_ok());
        let b = StressBox::new([0.0, 0.0, -1.0], [1.0, 1.0, 1.0], [2, 2, 2]);
        assert_eq!(s.evaluate_box(&b).unwrap_err().argument, "box");
        let b = StressBox::new([0.0, 0.0, 0.1], [1.0, 1.0, 1.0], [2, 0, 2]);
        assert_eq!(s.evaluate_box(&b).unwrap_err().argument, "box");
        assert!(s.evaluate(&[]).is_err());
    }

    /// Principal stresses, Tresca and von Mises on a tensor with known eigenvalues (a rotation of diag(3, 1, −2)
    /// about z by 30°: σ_xx = 3cos² + sin², σ_yy = 3 sin² + cos², σ_xy = 2 sin cos).
    #[test]
    fn derived_quantities() {
        let (s, c) = (0.5f64, 0.75f64.sqrt());
        let t = Stress::from_components([3.0 * c * c + s * s, 3.0 * s * s + c * c, -2.0, 2.0 * s * c, 0.0, 0.0]);
        let p = t.principal();
        assert!((p[0] - 3.0).abs() < 1e-13 && (p[1] - 1.0).abs() < 1e-13 && (p[2] + 2.0).abs() < 1e-13, "{p:?}");
        assert!((t.max_shear() - 2.5).abs() < 1e-13);
        let vm = (0.5 * ((3.0f64 - 1.0).powi(2) + 3.0f64.powi(2) + 5.0f64.powi(2))).sqrt();
        assert!((t.von_mises() - vm).abs() < 1e-13 && (t.hydrostatic() - 2.0 / 3.0).abs() < 1e-15);
    }
}
