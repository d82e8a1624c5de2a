//! # Elastic half-plane in plane strain: line loads, uniform strips, surface influence matrices
//!
//! Building blocks for the 2D frictional contact of a wheel on a flat (rollbem): the Flamant
//! normal and tangential line loads, uniformly loaded surface strips in closed form, dense
//! surface influence matrices (general and Toeplitz fast path), the counter-body (mirror)
//! mapping and Dundurs' β.
//!
//! ## Axes, signs, units
//!
//! The body occupies `z > 0`: `x` runs along the surface, `z` is the depth INTO the body.
//! Surface tractions act ON the body (applied by a counter-body):
//! * pressure `p(x) ≥ 0` pushes into the body (along `+z`),
//! * shear `q(x)` acts along `+x`.
//!
//! Line loads `P` (normal, along `+z`) and `Q` (tangential, along `+x`) are forces per unit
//! thickness. Displacements `u_x` (along `+x`) and `u_z` (along `+z`, i.e. into the body).
//! Stresses `σ_xx, σ_zz, τ_xz` are tension-positive. On the surface the outward normal of the
//! body is `−z`, so the traction `(−τ_xz, −σ_zz)` equals the applied `(q, p)`: under the load
//! `σ_zz = −p`, `τ_xz = −q`.
//!
//! Units: any consistent set, e.g. lengths in m, `E`, `p`, `q` and stresses in Pa, `P`, `Q` in
//! N/m, displacements in m. Influence coefficients are displacement per unit traction (m/Pa).
//!
//! ## Datum (2D displacements are logarithmic)
//!
//! A 2D line-load displacement field grows like `ln r` and is only defined up to a rigid
//! motion `(c_x + ω z, c_z − ω x)`. Every displacement returned here is RELATIVE to the interior
//! material point `(0, D)` (depth `D > 0` below the ORIGIN, fixed for all loads):
//! `u_rel(x, z) = u(x, z) − u(0, D)`. This fixes the translation `(c_x, c_z)`. The rotation `ω`
//! is fixed by symmetry about the load's line of action: for a normal load `u_x` is odd in
//! `ξ = x − s` (and `u_z` even), for a tangential load `u_z` is odd (and `u_x` even); a rigid
//! rotation would add an even part `ω z` to `u_x` and an odd part `−ω x` to `u_z`, so `ω = 0`.
//! Because the datum is a fixed material point, the superposition of many loads is again the
//! true field minus ONE rigid translation (a datum moving with each load would not be).
//!
//! ## Line loads (Johnson, *Contact Mechanics*, §2.2–2.3, eqs. 2.15, 2.19, 2.20, 2.22; Barber, *Elasticity*, ch. 12)
//!
//! With `ξ = x − s`, `r² = ξ² + z²` and `θ = atan2(ξ, z)` (angle from the `+z` axis, positive
//! towards `+x`), the Flamant stress field is purely radial, `σ_rr = −(2/π)(P cos θ + Q sin θ)/r`:
//!
//! ```text
//! σ_xx = −(2/π) ξ² (P z + Q ξ) / r⁴
//! σ_zz = −(2/π) z² (P z + Q ξ) / r⁴
//! τ_xz = −(2/π) ξ z (P z + Q ξ) / r⁴
//! ```
//!
//! Displacements: integrate the plane-strain Hooke's law `ε_rr = (1−ν²)σ_rr/E`,
//! `ε_θθ = −ν(1+ν)σ_rr/E`, `γ_rθ = 0` in polar coordinates (the classic Barber ch. 12 route; the
//! compatibility ODE is `F'' + F = ∓(1+ν)(1−2ν)(2/π)(P sin θ, Q cos θ)/E`, particular solution
//! `∝ θ cos θ`, `θ sin θ`). Back in Cartesian components, with `K = (1+ν)/(πE)`:
//!
//! ```text
//! u_x = K [  P ( ξz/r² − (1−2ν) θ )        − Q ( 2(1−ν) ln r − ξ²/r² ) ] + rigid
//! u_z = K [ −P ( 2(1−ν) ln r + ξ²/r² )     + Q ( ξz/r² + (1−2ν) θ )    ] + rigid
//! ```
//!
//! and the returned field is this expression minus its value at `(0, D)`, i.e. at
//! `ξ_d = −s`, `r_d² = s² + D²`, `θ_d = atan2(−s, D)`. On the surface (`z = 0`, `θ = ±π/2`), in
//! THESE axes (z into the body; identical to Johnson's):
//!
//! ```text
//! normal P:      u_x = −(1−2ν)(1+ν)/(2E) · P · sgn ξ          (points move towards the load)
//!                u_z = −2(1−ν²)/(πE) · P · ln|ξ| + C           (surface sinks into the body near the load)
//! tangential Q:  u_x = −2(1−ν²)/(πE) · Q · ln|ξ| + C
//!                u_z = +(1−2ν)(1+ν)/(2E) · Q · sgn ξ            (Betti reciprocity with the u_x of P)
//! ```
//!
//! ## Uniform strips
//!
//! Strip `[x1, x2]`, `w = x2 − x1`, uniform `p` (or `q`). Surface displacement: integrate the
//! line-load surface field over `s`. With `t_a = x − x1`, `t_b = x − x2`,
//! `L = t_a ln(|t_a|/D) − t_b ln(|t_b|/D)` (`0·ln 0 = 0`, so edges and centre are regular) and
//! `S = |t_a| − |t_b| = ∫ sgn(x − s) ds`, the coefficients (per unit traction) split into a part
//! depending on `(x − x1, x − x2)` only and a DATUM part depending on the strip only:
//!
//! ```text
//! C_xx = u_x/q = −2(1−ν)K·L                 + K [ 2(1−ν)ΔH + (3−2ν) D Δθ ]
//! C_zz = u_z/p = −2(1−ν)K·L                 + K [ 2(1−ν)ΔH + (1−2ν) D Δθ ]
//! C_xz = u_x/p = −(1−2ν)(π/2)K·S            + K [ (1−ν) D lnR − (1−2ν) M ]
//! C_zx = u_z/q = +(1−2ν)(π/2)K·S            + K [    ν  D lnR + (1−2ν) M ]
//! ΔH  = ½[ s ln(1 + s²/D²) ]_{x1}^{x2},  Δθ = atan(x2/D) − atan(x1/D) = atan2(wD, D² + x1 x2),
//! lnR = ln((x2² + D²)/(x1² + D²)),     M  = [ s atan(s/D) ]_{x1}^{x2} = w atan(x2/D) + x1 Δθ.
//! ```
//!
//! (From `∫ ln|x−s| ds = [t ln|t| − t]`, `∫ ½ ln(s²+D²) ds = ½ s ln(s²+D²) − s + D atan(s/D)`,
//! `∫ D²/(s²+D²) ds = D atan(s/D)`, `∫ sD/(s²+D²) ds = (D/2) ln(s²+D²)`; the linear `−t`, `−s`
//! terms cancel.) All pieces are evaluated in cancellation-free forms (`ln_1p`, `atan2` of
//! the angle difference, `t_b ln(1 + w/t_b)` in the far field).
//!
//! Interior stresses (Johnson §2.6–2.7): integrate the Flamant stresses with `ξ = z tan φ`.
//! With `φ_k = atan2(x − x_k, z)`, `r_k² = (x − x_k)² + z²`:
//!
//! ```text
//! pressure p: σ_xx = −(p/π)[ (φ1−φ2) − ½(sin2φ1 − sin2φ2) ]
//!             σ_zz = −(p/π)[ (φ1−φ2) + ½(sin2φ1 − sin2φ2) ]
//!             τ_xz = −(p/π)(sin²φ1 − sin²φ2)
//! shear q:    σ_xx = −(q/π)[ 2 ln(r1/r2) − (sin²φ1 − sin²φ2) ]
//!             σ_zz = −(q/π)(sin²φ1 − sin²φ2)
//!             τ_xz = −(q/π)[ (φ1−φ2) − ½(sin2φ1 − sin2φ2) ]
//! ```
//!
//! evaluated as `φ1−φ2 = atan2(z w, (x−x1)(x−x2) + z²)`,
//! `sin²φ1 − sin²φ2 = z² w (2x−x1−x2)/(r1² r2²)`, `sin2φ1 − sin2φ2 = 2 z w (z² − (x−x1)(x−x2))/(r1² r2²)`.
//! At `z = 0` this gives the limits `z → 0⁺` at fixed `x`: inside the strip `σ_zz = σ_xx = −p`,
//! `τ_xz = −q`; outside only the shear strip's `σ_xx = −(2q/π) ln|(x−x1)/(x−x2)|` remains.
//! Exactly at an edge on the surface the field is discontinuous and the value returned is the
//! vertical-approach limit (e.g. `σ_zz = −p/2`, `τ_xz = ±p/π`), except `σ_xx` of a shear strip,
//! which has a genuine logarithmic singularity there and is returned as `±∞` (never NaN).
//!
//! ## Influence matrices
//!
//! Elements `j` = strips `[a_j, b_j]` with uniform `(q_j, p_j)`, collocation points `x_i`:
//! `u_x(x_i) = Σ_j Cxx_ij q_j + Cxz_ij p_j`, `u_z(x_i) = Σ_j Czx_ij q_j + Czz_ij p_j`, blocks dense
//! row-major (row = collocation point). On a uniform mesh the `L`, `S` parts depend on `i − j`
//! only (Toeplitz, `2N−1` values) and the datum part on `j` only (a column term, `N` values):
//! `C_ij = T(i−j) + d(j)`. The fast path computes those and fills; it is bit-identical to the
//! general path whenever the mesh coordinates and their differences are exact (dyadic `x0`, `h`;
//! tested). Otherwise the general path sees coordinates rounded to `ε·max|x|`, and the two differ
//! by that input rounding only (≲ `ε·max|x|/h` relative to the block's scale; the fast path is
//! the more accurate one).
//!
//! Cost, N = 1000, release build, this 2-core machine (test `timing_influence_blocks`, noisy):
//! into REUSED buffers ([`HalfPlane::influence_blocks_uniform_into`]) the fast path takes
//! ≈ 1.9–3.3 ms against ≈ 1.1–1.6 ms for merely writing 4·N² f64 into the same buffers (≈ 1.5–2×);
//! into FRESH allocations both take ≈ 20–35 ms, dominated by first-touch page faults of the
//! 32 MB (fast path ≈ 1.0–1.1× the plain write). The general path (two logarithms per entry)
//! takes ≈ 45–65 ms.
//!
//! ## Strip of half-spaces (CONTACT's 2D model)
//!
//! CONTACT (Vollebregt) poses a 2D case as ONE row of rectangular elements `dx × w` on two elastic half-SPACES
//! (its `MY = 1`, `DY = w`), with the displacements at the elements' centres (Boussinesq–Cerruti over rectangles,
//! Love's closed forms). [`HalfPlane::strip`] poses the same: the tractions are uniform across the strip, the loads
//! are per unit of its width, and `u(x)` is the displacement at `(x, 0)` on its centre line. From Johnson's point
//! loads on a half-space (*Contact Mechanics* §3.2, eqs. 3.19, 3.86–3.87; `G = E/(2(1+ν))`, `K = 1/(2πG)`, `z`
//! into the body, `ρ² = X² + Y²`, `X = x − s`):
//!
//! ```text
//! pressure P: u_z = (1−ν) K P / ρ,                 u_x = −(1−2ν) K P X / (2ρ²)
//! shear Q:    u_x = K Q [ (1−ν)/ρ + ν X²/ρ³ ],     u_z = +(1−2ν) K Q X / (2ρ²)
//! ```
//!
//! Integrated over `s ∈ [a, b]` (`X ∈ [t_b, t_a]`) and `Y ∈ [−h, h]`, `h = w/2`:
//!
//! ```text
//! C_zz = (1−ν) K I1,   C_xx = K [ (1−ν) I1 + ν I2 ],   C_zx = −C_xz = (1−2ν) K I3 / 2
//! I1 = ∬ 1/ρ    = 2 [ t_a asinh(h/|t_a|) − t_b asinh(h/|t_b|) + h (asinh(t_a/h) − asinh(t_b/h)) ]
//! I2 = ∬ X²/ρ³  = 2 h (asinh(t_a/h) − asinh(t_b/h))
//! I3 = ∬ X/ρ²   = 2 [ h ln(ρ_a/ρ_b) + |t_a| atan(h/|t_a|) − |t_b| atan(h/|t_b|) ],   ρ_k² = t_k² + h²
//! ```
//!
//! (antiderivatives `X ln(Y+ρ) + Y ln(X+ρ)`, `Y ln(X+ρ)` and `Y ln ρ + X atan(Y/X)`; `ln(X + ρ) = asinh(X/h) + ln h`
//! at `Y = h`, and the `ln h` cancels between the ends). These are CONTACT's `elascf_pcwcns` coefficients (its
//! `A^wz`, `A^ux`, `A^uz`), derived here from the point loads. They depend on `(x − a, x − b)` only: the blocks are
//! Toeplitz on a uniform grid with no datum part. As `h → ∞` they tend to the plane-strain coefficients plus a
//! constant per element (`I1 → −2L + const`, `I2 → const`, `I3 → π S`): only the constant, which a load or a
//! rigid motion absorbs, and terms of order `(x/h)²` differ (tested). `C_xx ≠ C_zz` in the strip, by those terms.
//!
//! ## Counter-body: the flat as a mirrored half-plane
//!
//! The wheel is modelled as the half-plane above the contact line, its own `z` pointing UP into
//! it. The flat occupies the region below; it is described by the same formulas in its own
//! mirrored frame `x' = x`, `z' = −z` (depth into the flat; isotropic elasticity is invariant
//! under the reflection), with its own `E2, ν2, D2` (datum `(0, D2)` in its frame).
//! Newton's third law: the wheel receives `(q, p)` in the wheel frame, so the flat receives
//! `(−q, −p)` in global components = shear `q' = −q` and pressure `p' = +p` in its own frame
//! (still pushing into it). Its displacement in its frame: `u'_x = C'xx q' + C'xz p'`,
//! `u'_z = C'zx q' + C'zz p'`; globally `u_x,flat = u'_x`, `u_up,flat = −u'_z`. Then
//!
//! ```text
//! slip       = u_x,wheel − u_x,flat = (Cxx + C'xx) q + (Cxz − C'xz) p
//! gap change = u_z,wheel − u_up,flat = u_z,wheel + u'_z = (Czx − C'zx) q + (Czz + C'zz) p
//! ```
//!
//! (the gap increases when the wheel surface moves into the wheel, `+z`, and when the flat
//! surface moves into the flat, away from the wheel). So the blocks to ADD to the wheel's are
//! `(+C'xx, −C'xz, −C'zx, +C'zz)` ([`InfluenceBlocks::into_counter_body`]). For identical
//! materials and `D2 = D` the coupling blocks cancel exactly (`a + (−a) = 0` bitwise) and the
//! direct blocks double. The surviving coupling, `∝ (1−2ν1)/G1 − (1−2ν2)/G2`, is what Dundurs'
//! `β` measures ([`crate::material::dundurs_beta`] of [`HalfPlane::material`]s; body 1 = wheel).

use crate::error::ArgumentError;
use crate::material::Material;
use crate::viscoelastic::{memory_integral, Memory};
use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, PI};

/// A displacement `(u_x, u_z)` in the body's own axes (`u_z` positive INTO the body), relative to
/// the datum point `(0, D)`. Units of length.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[non_exhaustive]
pub struct Displacement {
    /// Displacement along `+x` (along the surface).
    pub ux: f64,
    /// Displacement along `+z` (into the body).
    pub uz: f64,
}

/// The in-plane stress components `(σ_xx, σ_zz, τ_xz)` (plane strain; `σ_yy = ν(σ_xx + σ_zz)` is
/// not returned), tension positive. Units of traction (e.g. Pa).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[non_exhaustive]
pub struct Stress {
    /// Normal stress along `x`.
    pub sxx: f64,
    /// Normal stress along `z` (`= −p` under the pressure on the surface).
    pub szz: f64,
    /// Shear stress (`= −q` under the shear on the surface).
    pub txz: f64,
}

/// An isotropic elastic half-plane in plane strain with its displacement datum.
///
/// Invariants (checked by [`HalfPlane::new`], which refuses other values): `E > 0` (`E = +∞` is allowed and models
/// a RIGID body: all its displacements are zero), `0 ≤ ν ≤ 0.5`, `0 < D < ∞`; on a strip ([`HalfPlane::strip`]) a
/// finite width `> 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfPlane {
    e: f64,
    nu: f64,
    datum_depth: f64,
    /// The strip's width across the rolling direction ([`HalfPlane::strip`]); `None` in plane strain.
    strip_width: Option<f64>,
    /// A viscoelastic body's steady-rolling memory ([`HalfPlane::viscoelastic`]); `None`: elastic.
    memory: Option<Memory>,
}

/// A mesh of contiguous surface strips with their collocation points.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct StripMesh {
    /// Left ends `a_j` of the strips.
    pub a: Vec<f64>,
    /// Right ends `b_j` of the strips (`b_j > a_j`).
    pub b: Vec<f64>,
    /// Collocation points `x_i`.
    pub xc: Vec<f64>,
}

/// The signs with which a counter-body's blocks (cxx, cxz, czx, czz) add to the wheel's
/// ([`InfluenceBlocks::into_counter_body`]); index it with [`Block::index`].
pub const COUNTER_BODY_SIGN: [f64; 4] = [1.0, -1.0, -1.0, 1.0];

/// One of the four influence blocks ([`InfluenceBlocks`]), for [`HalfPlane::influence_block_uniform`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Block {
    /// `u_x` per unit shear (`cxx`).
    Xx,
    /// `u_x` per unit pressure (`cxz`).
    Xz,
    /// `u_z` per unit shear (`czx`).
    Zx,
    /// `u_z` per unit pressure (`czz`).
    Zz,
}

impl Block {
    /// Its place in the order cxx, cxz, czx, czz (0..4), e.g. in [`COUNTER_BODY_SIGN`].
    pub fn index(self) -> usize {
        match self {
            Block::Xx => 0,
            Block::Xz => 1,
            Block::Zx => 2,
            Block::Zz => 3,
        }
    }
}

/// `n · n` entries of an n × n block, refused when the count overflows (no such block fits in memory).
fn block_entries(function: &'static str, rows: usize, cols: usize) -> Result<usize, ArgumentError> {
    rows.checked_mul(cols)
        .filter(|&e| e <= isize::MAX as usize / std::mem::size_of::<f64>())
        .ok_or_else(|| ArgumentError::new(function, "n", format!("{rows} × {cols} entries do not fit in memory")))
}

/// The element width of a uniform mesh: finite and `> 0`.
fn check_width(function: &'static str, h: f64) -> Result<(), ArgumentError> {
    if h > 0.0 && h.is_finite() {
        Ok(())
    } else {
        Err(ArgumentError::new(function, "h", format!("(the element width) must be finite and > 0, got {h}")))
    }
}

/// A row-major n × n block with entries t[n−1−i+j] + d[j], written into `dst` (overwritten in place when it has the
/// size already, so a repeated assembly allocates nothing).
fn fill_toeplitz(dst: &mut Vec<f64>, t: &[f64], d: &[f64], n: usize) {
    if dst.len() == n * n {
        for (i, row) in dst.chunks_exact_mut(n.max(1)).enumerate() {
            let o = n - 1 - i;
            row.iter_mut().zip(&t[o..o + n]).zip(d.iter()).for_each(|((c, t), d)| *c = t + d);
        }
    } else {
        dst.clear();
        dst.reserve_exact(n * n);
        for i in 0..n {
            let o = n - 1 - i;
            dst.extend(t[o..o + n].iter().zip(d.iter()).map(|(t, d)| t + d));
        }
    }
}

/// Uniform mesh of `n` strips of width `h` starting at `x0`: `a_j = x0 + j·h`,
/// `b_j = x0 + (j+1)·h` (so `b_j == a_{j+1}` bitwise), midpoints `x_j = x0 + (j + ½)·h`.
/// This is exactly the mesh that [`HalfPlane::influence_blocks_uniform`] assumes.
pub fn uniform_mesh(x0: f64, h: f64, n: usize) -> StripMesh {
    let a = (0..n).map(|j| x0 + j as f64 * h).collect();
    let b = (0..n).map(|j| x0 + (j + 1) as f64 * h).collect();
    let xc = (0..n).map(|j| x0 + (j as f64 + 0.5) * h).collect();
    StripMesh { a, b, xc }
}

/// Four dense row-major influence blocks (rows = collocation points `i`, columns = elements `j`),
/// displacement per unit TRACTION (e.g. m/Pa):
/// `u_x(x_i) = Σ_j cxx[i·cols+j]·q_j + cxz[i·cols+j]·p_j`, `u_z(x_i) = Σ_j czx·q_j + czz·p_j`.
///
/// For a single body `(u_x, u_z)` are its own displacements relative to its datum; after adding
/// a counter-body ([`pair_blocks`]) they are (slip, gap change) of the wheel relative to the flat.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct InfluenceBlocks {
    /// Number of collocation points (rows).
    pub rows: usize,
    /// Number of elements (columns).
    pub cols: usize,
    /// `u_x` per unit shear `q_j`.
    pub cxx: Vec<f64>,
    /// `u_x` per unit pressure `p_j`.
    pub cxz: Vec<f64>,
    /// `u_z` per unit shear `q_j`.
    pub czx: Vec<f64>,
    /// `u_z` per unit pressure `p_j`.
    pub czz: Vec<f64>,
}

impl InfluenceBlocks {
    /// Mirror mapping for a counter-body below the contact line (see module docs): negates the
    /// coupling blocks, giving `(+Cxx, −Cxz, −Czx, +Czz)`, the blocks to ADD to the wheel's so that
    /// the sum maps the wheel's tractions `(q, p)` to (slip, gap change).
    pub fn into_counter_body(mut self) -> Self {
        for (block, sign) in
            [&mut self.cxx, &mut self.cxz, &mut self.czx, &mut self.czz].into_iter().zip(COUNTER_BODY_SIGN)
        {
            if sign < 0.0 {
                block.iter_mut().for_each(|v| *v = -*v);
            }
        }
        self
    }

    /// Whether the four blocks hold `rows × cols` entries each (their fields are public: a caller can break it).
    fn check_shape(&self, function: &'static str) -> Result<(), ArgumentError> {
        let entries = block_entries(function, self.rows, self.cols)?;
        let blocks = [&self.cxx, &self.cxz, &self.czx, &self.czz];
        match blocks.iter().find(|b| b.len() != entries) {
            None => Ok(()),
            Some(b) => Err(ArgumentError::new(
                function,
                "blocks",
                format!("hold {} entries where rows × cols = {} × {} = {entries}", b.len(), self.rows, self.cols),
            )),
        }
    }

    /// Matrix-vector product: `(u_x, u_z)` at the collocation points for element tractions
    /// `q` (shear) and `p` (pressure), each of length `cols`. Refused when `q` or `p` has another length, or the
    /// blocks do not hold `rows × cols` entries each.
    pub fn apply(&self, q: &[f64], p: &[f64]) -> Result<(Vec<f64>, Vec<f64>), ArgumentError> {
        const F: &str = "InfluenceBlocks::apply";
        self.check_shape(F)?;
        for (name, v) in [("q", q), ("p", p)] {
            if v.len() != self.cols {
                return Err(ArgumentError::new(
                    F,
                    name,
                    format!("has {} entries, the blocks {} columns", v.len(), self.cols),
                ));
            }
        }
        let dot = |row: &[f64], v: &[f64]| row.iter().zip(v).map(|(a, b)| a * b).sum::<f64>();
        let (mut ux, mut uz) = (Vec::with_capacity(self.rows), Vec::with_capacity(self.rows));
        for i in 0..self.rows {
            let r = i * self.cols..(i + 1) * self.cols;
            ux.push(dot(&self.cxx[r.clone()], q) + dot(&self.cxz[r.clone()], p));
            uz.push(dot(&self.czx[r.clone()], q) + dot(&self.czz[r], p));
        }
        Ok((ux, uz))
    }

    /// Add `other`'s blocks entry by entry (a counter-body's to a wheel's: [`pair_blocks`]). Refused, and `self`
    /// left as it was, when the two do not have the same shape.
    pub fn add_blocks(&mut self, other: &InfluenceBlocks) -> Result<(), ArgumentError> {
        const F: &str = "InfluenceBlocks::add_blocks";
        self.check_shape(F)?;
        other.check_shape(F)?;
        if (self.rows, self.cols) != (other.rows, other.cols) {
            return Err(ArgumentError::new(
                F,
                "other",
                format!("is {} × {}, the blocks {} × {}", other.rows, other.cols, self.rows, self.cols),
            ));
        }
        let add = |a: &mut Vec<f64>, b: &Vec<f64>| a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
        add(&mut self.cxx, &other.cxx);
        add(&mut self.cxz, &other.cxz);
        add(&mut self.czx, &other.czx);
        add(&mut self.czz, &other.czz);
        Ok(())
    }
}

/// `t·ln(|t|/d)` with the limit `0` at `t = 0`.
fn xlog(t: f64, d: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * (t.abs() / d).ln()
    }
}

/// `L = ta·ln(|ta|/d) − tb·ln(|tb|/d)`, cancellation-free in the far field where `ta ≈ tb`
/// (there `L = (ta−tb)·ln(|ta|/d) + tb·ln(1 + (ta−tb)/tb)`, `ta − tb` exact by Sterbenz).
fn log_term(ta: f64, tb: f64, d: f64) -> f64 {
    log_term_w(ta, tb, ta - tb, d)
}

/// [`log_term`] with the element's width `w = ta − tb` given (the memory integral shifts `ta` and `tb` by a
/// distance that can dwarf `w`: the width is then taken from before the shift, not from the rounded difference).
fn log_term_w(ta: f64, tb: f64, w: f64, d: f64) -> f64 {
    if ta * tb > 0.0 && w.abs() <= 0.5 * tb.abs() {
        w * (ta.abs() / d).ln() + tb * (w / tb).ln_1p()
    } else {
        xlog(ta, d) - xlog(tb, d)
    }
}

/// Material constants of the strip kernels.
#[derive(Clone, Copy, Debug)]
struct Kernel {
    k: f64,
    nu: f64,
    d: f64,
    /// `−2(1−ν)K`: coefficient of `L` in `C_xx` and `C_zz`.
    c_log: f64,
    /// `(1−2ν)(π/2)K`: coefficient of `S` in `C_zx` (and minus it in `C_xz`).
    c_sgn: f64,
    /// Half the strip's width, `h = w/2` ([`HalfPlane::strip`]); `None` in plane strain.
    strip_half: Option<f64>,
    /// The viscoelastic memory ([`HalfPlane::viscoelastic`]) when it changes anything (`f > 0`, a deformable body).
    memory: Option<Memory>,
}

/// `X·asinh(h/|X|)` with the limit `0` at `X = 0`; past `h/|X| = 1e150` (where `h/|X|` may overflow) by
/// `asinh(r) = ln 2 + ln r` to within `1/(4r²)`.
fn x_asinh(x: f64, h: f64) -> f64 {
    if x == 0.0 {
        return 0.0;
    }
    let r = h / x.abs();
    if r < 1e150 {
        x * r.asinh()
    } else {
        x * (std::f64::consts::LN_2 + h.ln() - x.abs().ln())
    }
}

/// `|X|·atan(h/|X|)` with the limit `0` at `X = 0`.
fn x_atan(x: f64, h: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x.abs() * (h / x.abs()).atan()
    }
}

impl Kernel {
    /// Position-dependent (Toeplitz) parts `[T_xx, T_xz, T_zx, T_zz]` for `ta = x − a`, `tb = x − b`: the elastic
    /// ones, plus the viscoelastic memory `f ∫₀^∞ e^{−η} T(ta + Lη, tb + Lη) dη` of a viscoelastic body
    /// ([`crate::viscoelastic`]; the integrand has kinks where an element end passes the point, `η = −t/L`).
    fn toeplitz(&self, ta: f64, tb: f64) -> [f64; 4] {
        let elastic = self.elastic_toeplitz(ta, tb);
        let Some(Memory { ratio, distance }) = self.memory else { return elastic };
        let memory = if distance == 0.0 {
            elastic
        } else if distance.is_infinite() {
            // Frozen creep: the far field, the same for every point; a constant the approach absorbs (module docs
            // of crate::viscoelastic). Its x-independent value is dropped.
            [0.0; 4]
        } else {
            let w = ta - tb;
            memory_integral(
                |eta| self.shifted_toeplitz(ta + distance * eta, tb + distance * eta, w),
                &[-ta / distance, -tb / distance],
            )
        };
        std::array::from_fn(|i| elastic[i] + ratio * memory[i])
    }

    /// The elastic Toeplitz parts at `(ta, tb)` shifted far from the element, whose width `w` is given: in plane
    /// strain the far field `w ln|t|` keeps `w` exact (the strip's far field decays, its rounding stays below its
    /// own size, which is negligible there).
    fn shifted_toeplitz(&self, ta: f64, tb: f64, w: f64) -> [f64; 4] {
        if self.strip_half.is_some() {
            return self.elastic_toeplitz(ta, tb);
        }
        let tl = self.c_log * log_term_w(ta, tb, w, self.d);
        let s = if ta * tb > 0.0 { ta.signum() * w } else { ta.abs() - tb.abs() };
        let ts = self.c_sgn * s;
        [tl, -ts, ts, tl]
    }

    /// The elastic Toeplitz parts (see [`Kernel::toeplitz`]).
    fn elastic_toeplitz(&self, ta: f64, tb: f64) -> [f64; 4] {
        if let Some(h) = self.strip_half {
            return self.strip(ta, tb, h);
        }
        let tl = self.c_log * log_term(ta, tb, self.d);
        let ts = self.c_sgn * (ta.abs() - tb.abs());
        [tl, -ts, ts, tl]
    }

    /// The strip's coefficients (module docs, "Strip of half-spaces"): the rectangle integrals `I1 = ∬ 1/r`,
    /// `I2 = ∬ X²/r³` and `I3 = ∬ X/r²` over `X ∈ [tb, ta]`, `Y ∈ [−h, h]`, in closed form, written with `asinh`
    /// so that the large `ln h` common to every entry never enters. Far from the element the terms still cancel
    /// to `ε·|X|/dx` relative (checked against 60-digit arithmetic by a review: 1.7e-10 at 1e6 elements, ≤ 1e-12
    /// within 6 000), where plane strain's `log_term` keeps `ε`.
    fn strip(&self, ta: f64, tb: f64, h: f64) -> [f64; 4] {
        let (k, nu) = (self.k, self.nu);
        let da = (ta / h).asinh() - (tb / h).asinh();
        let i1 = 2.0 * (x_asinh(ta, h) - x_asinh(tb, h) + h * da);
        let i2 = 2.0 * h * da;
        // h ln(ρ_a/ρ_b) = (h/2) ln(1 + (ta² − tb²)/(tb² + h²)), the ln_1p form where the ratio is near 1 (far
        // from the element); the plain ratio where it is not (a narrow strip at an element's end, where the
        // argument rounds to −1).
        let arg = (ta - tb) * (ta + tb) / (tb * tb + h * h);
        let ln_ratio = if arg.abs() <= 0.5 { 0.5 * arg.ln_1p() } else { (ta.hypot(h) / tb.hypot(h)).ln() };
        let i3 = 2.0 * (h * ln_ratio + x_atan(ta, h) - x_atan(tb, h));
        let c = 0.5 * (1.0 - 2.0 * nu) * k * i3;
        [k * ((1.0 - nu) * i1 + nu * i2), -c, c, (1.0 - nu) * k * i1]
    }

    /// Datum parts `[d_xx, d_xz, d_zx, d_zz]` of strip `[a, b]` (depend on the strip only; none for a strip of
    /// half-spaces, whose displacements vanish far away).
    fn datum(&self, a: f64, b: f64) -> [f64; 4] {
        if self.strip_half.is_some() {
            return [0.0; 4];
        }
        let scale = self.memory.map_or(1.0, |m| 1.0 + m.ratio);
        self.elastic_datum(a, b).map(|v| scale * v)
    }

    /// The elastic datum parts (see [`Kernel::datum`]).
    fn elastic_datum(&self, a: f64, b: f64) -> [f64; 4] {
        let (d, nu, k) = (self.d, self.nu, self.k);
        let w = b - a;
        let dh = 0.5 * (b * (b / d).powi(2).ln_1p() - a * (a / d).powi(2).ln_1p());
        let dth = (d * w).atan2(d * d + a * b);
        let ln_r = (w * (a + b) / (a * a + d * d)).ln_1p();
        let m = w * (b / d).atan() + a * dth;
        let (one_m_nu, one_m_2nu) = (1.0 - nu, 1.0 - 2.0 * nu);
        [
            k * (2.0 * one_m_nu * dh + (3.0 - 2.0 * nu) * d * dth),
            k * (one_m_nu * d * ln_r - one_m_2nu * m),
            k * (nu * d * ln_r + one_m_2nu * m),
            k * (2.0 * one_m_nu * dh + one_m_2nu * d * dth),
        ]
    }
}

/// The four coefficients `[Cxx, Cxz, Czx, Czz]` from their Toeplitz and datum parts. Both the
/// general and the uniform path use exactly this arithmetic.
#[inline]
fn combine(t: &[f64; 4], d: &[f64; 4]) -> [f64; 4] {
    [t[0] + d[0], t[1] + d[1], t[2] + d[2], t[3] + d[3]]
}

impl HalfPlane {
    /// A half-plane with Young's modulus `e` (`> 0`; `f64::INFINITY` = rigid), Poisson ratio
    /// `nu ∈ [0, 0.5]` and datum depth `datum_depth = D ∈ (0, ∞)` (same length unit as all
    /// coordinates). Another value (NaN included) is refused, naming the argument.
    pub fn new(e: f64, nu: f64, datum_depth: f64) -> Result<Self, ArgumentError> {
        const F: &str = "HalfPlane::new";
        if e.is_nan() || e <= 0.0 {
            return Err(ArgumentError::new(F, "e", format!("(Young's modulus) must be > 0 (+inf: rigid), got {e}")));
        }
        if !(0.0..=0.5).contains(&nu) {
            return Err(ArgumentError::new(F, "nu", format!("(Poisson's ratio) must lie in [0, 0.5], got {nu}")));
        }
        if !(datum_depth > 0.0 && datum_depth.is_finite()) {
            return Err(ArgumentError::new(F, "datum_depth", format!("must be finite and > 0, got {datum_depth}")));
        }
        Ok(Self { e, nu, datum_depth, strip_width: None, memory: None })
    }

    /// The same material as a strip of `width` (`> 0`, finite, the unit of all coordinates) across the rolling
    /// direction on an elastic half-SPACE: CONTACT's model of a 2D case (one row of rectangular elements, length ×
    /// `width`, displacements at the strip's centre line; module docs, "Strip of half-spaces"). Its surface
    /// displacements are absolute (they vanish far away), so the datum plays no part. Another width (NaN included)
    /// is refused, naming the argument.
    pub fn strip(self, width: f64) -> Result<Self, ArgumentError> {
        if !(width > 0.0 && width.is_finite()) {
            return Err(ArgumentError::new(
                "HalfPlane::strip",
                "width",
                format!("must be finite and > 0, got {width}"),
            ));
        }
        Ok(Self { strip_width: Some(width), ..self })
    }

    /// The same body as a viscoelastic standard linear solid in steady rolling ([`crate::viscoelastic`]): its
    /// glassy modulus is this `E`, and every surface coefficient becomes `A(x) + f ∫₀^∞ e^{−η} A(x + Lη) dη` with
    /// `memory.ratio = f` (finite, `≥ 0`) and `memory.distance = L` (the signed relaxation distance, in the unit of
    /// the coordinates; not NaN, `±∞` allowed). The datum part, a constant per element, is multiplied by `1 + f`.
    /// [`HalfPlane::line_load_displacement`] and the interior stresses stay elastic. Another value is refused.
    pub fn viscoelastic(self, memory: Memory) -> Result<Self, ArgumentError> {
        const F: &str = "HalfPlane::viscoelastic";
        if !(memory.ratio >= 0.0 && memory.ratio.is_finite()) {
            return Err(ArgumentError::new(F, "memory.ratio", format!("must be finite and ≥ 0, got {}", memory.ratio)));
        }
        if memory.distance.is_nan() {
            return Err(ArgumentError::new(F, "memory.distance", "must not be NaN"));
        }
        Ok(Self { memory: Some(memory), ..self })
    }

    /// The viscoelastic memory ([`HalfPlane::viscoelastic`]), `None` for an elastic body.
    pub fn memory(&self) -> Option<Memory> {
        self.memory
    }

    /// The strip's width ([`HalfPlane::strip`]), `None` in plane strain.
    pub fn strip_width(&self) -> Option<f64> {
        self.strip_width
    }

    /// Young's modulus `E`.
    pub fn youngs_modulus(&self) -> f64 {
        self.e
    }

    /// Poisson ratio `ν`.
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }

    /// Datum depth `D` (the datum is the material point `(0, D)`).
    pub fn datum_depth(&self) -> f64 {
        self.datum_depth
    }

    /// The half-plane's material (`E`, `ν`).
    pub fn material(&self) -> Material {
        Material::new(self.e, self.nu)
    }

    /// Shear modulus `G = E / (2(1+ν))` ([`Material::shear_modulus`]).
    pub fn shear_modulus(&self) -> f64 {
        self.material().shear_modulus()
    }

    /// Plane-strain modulus `E/(1−ν²)` (the `E*` of Hertz theory against a rigid flat;
    /// [`Material::plane_strain_modulus`]).
    pub fn plane_strain_modulus(&self) -> f64 {
        self.material().plane_strain_modulus()
    }

    /// Whether the normal–tangential cross influence of this half-plane (body 1) pressed on `counter` (body 2;
    /// `None`: a rigid counter-body) cancels, so that the pair's cross blocks `C_xz − C'_xz` and `C_zx − C'_zx`
    /// vanish identically and need not be built ([`InfluenceBlocks::into_counter_body`]).
    ///
    /// From the closed forms in the module docs, with `K = (1+ν)/(πE)`: in plane strain the cross coefficients are
    /// `(1−2ν)K` times a function of the grid and `D`, plus the datum terms `(1−ν)K·D lnR` and `νK·D lnR` (`lnR` a
    /// function of `D`); they cancel for every grid exactly when both bodies have the same datum depth and the same
    /// `(1−2ν)K`, `(1−ν)K` and `νK`, i.e. the same material (a rigid counter-body, `K = 0`, never cancels a datum
    /// term). On a strip of half-spaces the only cross coefficient is `(1−2ν)K·I3/2`, so they cancel when
    /// `(1−2ν₁)K₁ = (1−2ν₂)K₂`: Dundurs' β = 0 (a rigid counter-body: ν₁ = 0.5). Factors are compared to 4 ulps
    /// of the larger: what is then dropped is round-off of the blocks, not physics.
    pub fn cross_influence_cancels(&self, counter: Option<&HalfPlane>) -> bool {
        fn factors(h: Option<&HalfPlane>) -> [f64; 3] {
            match h {
                Some(h) if h.e.is_finite() => {
                    let k = (1.0 + h.nu) / (PI * h.e);
                    [(1.0 - 2.0 * h.nu) * k, (1.0 - h.nu) * k, h.nu * k]
                }
                _ => [0.0; 3],
            }
        }
        let same = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs());
        let (f1, f2) = (factors(Some(self)), factors(counter));
        if counter.is_some_and(|c| c.strip_width != self.strip_width || c.memory != self.memory) {
            return false;
        }
        match self.strip_width {
            Some(_) => same(f1[0], f2[0]),
            None => {
                let datum_same = counter.is_some_and(|c| c.datum_depth == self.datum_depth);
                datum_same && f1.iter().zip(&f2).all(|(a, b)| same(*a, *b))
            }
        }
    }

    fn kernel(&self) -> Kernel {
        let k = (1.0 + self.nu) / (PI * self.e);
        Kernel {
            k,
            nu: self.nu,
            d: self.datum_depth,
            c_log: -2.0 * (1.0 - self.nu) * k,
            c_sgn: (1.0 - 2.0 * self.nu) * FRAC_PI_2 * k,
            strip_half: self.strip_width.map(|w| 0.5 * w),
            memory: self.memory.filter(|m| m.ratio > 0.0 && self.e.is_finite()),
        }
    }

    /// Displacement at `(x, z)` (`z ≥ 0`, `(x, z) ≠ (s, 0)`) due to a normal line load `p`
    /// (force per unit thickness, pushing into the body, `+z`) and a tangential line load `q`
    /// (along `+x`) applied at the surface point `s`; relative to the datum `(0, D)`, so it
    /// vanishes exactly at `(0, D)`. Formulas in the module docs. Plane strain always: a strip's width
    /// ([`HalfPlane::strip`]) plays no part here.
    pub fn line_load_displacement(&self, s: f64, p: f64, q: f64, x: f64, z: f64) -> Displacement {
        let d = self.datum_depth;
        let k = (1.0 + self.nu) / (PI * self.e);
        let (a, b) = (1.0 - 2.0 * self.nu, 1.0 - self.nu);
        let xi = x - s;
        let r2 = xi * xi + z * z;
        let th = xi.atan2(z);
        let xid = -s;
        let rd2 = s * s + d * d;
        let thd = xid.atan2(d);
        let lnr = (r2 / rd2).ln(); // 2 ln(r/r_d)
        let (xz, xx) = (xi * z / r2, xi * xi / r2);
        let (xzd, xxd) = (xid * d / rd2, xid * xid / rd2);
        let ux = k * (p * (xz - a * th - (xzd - a * thd)) - q * (b * lnr - xx + xxd));
        let uz = k * (-p * (b * lnr + xx - xxd) + q * (xz + a * th - (xzd + a * thd)));
        Displacement { ux, uz }
    }

    /// Surface displacement at the surface point `x` due to uniform pressure `p` and shear `q`
    /// on the strip `[x1, x2]` (`x1 < x2`), relative to the datum `(0, D)`. Closed form, finite
    /// and continuous everywhere including the strip's centre and edges. Equal (bitwise) to the
    /// corresponding influence-block entries times the tractions. On a strip ([`HalfPlane::strip`]): the rectangle
    /// `[x1, x2] × [−w/2, w/2]` of half-spaces, at `(x, 0)`, absolute. Ends given the other way round (`x1 > x2`)
    /// give the integral taken the other way: the negative of the strip `[x2, x1]`'s.
    pub fn strip_surface_displacement(&self, x1: f64, x2: f64, p: f64, q: f64, x: f64) -> Displacement {
        if x1 > x2 {
            let d = self.strip_surface_displacement(x2, x1, p, q, x);
            return Displacement { ux: -d.ux, uz: -d.uz };
        }
        let kern = self.kernel();
        let c = combine(&kern.toeplitz(x - x1, x - x2), &kern.datum(x1, x2));
        Displacement { ux: c[0] * q + c[1] * p, uz: c[2] * q + c[3] * p }
    }

    /// General influence blocks for strips `[a_j, b_j]` (`a.len() == b.len()` = columns) at
    /// collocation points `xc` (rows; any points on the surface, typically the midpoints). Per
    /// unit traction, relative to this body's datum. Cost: two logarithms per entry. Refused when `a` and `b` differ
    /// in length.
    pub fn influence_blocks(&self, a: &[f64], b: &[f64], xc: &[f64]) -> Result<InfluenceBlocks, ArgumentError> {
        const F: &str = "HalfPlane::influence_blocks";
        if a.len() != b.len() {
            return Err(ArgumentError::new(F, "b", format!("has {} entries, `a` {}", b.len(), a.len())));
        }
        block_entries(F, xc.len(), a.len())?;
        let kern = self.kernel();
        let datum: Vec<[f64; 4]> = a.iter().zip(b).map(|(&aj, &bj)| kern.datum(aj, bj)).collect();
        let (rows, cols) = (xc.len(), a.len());
        let mut out = InfluenceBlocks {
            rows,
            cols,
            cxx: Vec::with_capacity(rows * cols),
            cxz: Vec::with_capacity(rows * cols),
            czx: Vec::with_capacity(rows * cols),
            czz: Vec::with_capacity(rows * cols),
        };
        for &x in xc {
            for ((&aj, &bj), dj) in a.iter().zip(b).zip(&datum) {
                let c = combine(&kern.toeplitz(x - aj, x - bj), dj);
                out.cxx.push(c[0]);
                out.cxz.push(c[1]);
                out.czx.push(c[2]);
                out.czz.push(c[3]);
            }
        }
        Ok(out)
    }

    /// Fast path for the uniform mesh [`uniform_mesh`]`(x0, h, n)` (collocation at midpoints):
    /// `C_ij = T(i−j) + d(j)`, computing `2n−1` Toeplitz values and `n` datum values, then filling.
    /// Bit-identical to [`HalfPlane::influence_blocks`] on the same mesh when `x0` and `h` are
    /// dyadic (coordinates exact); otherwise equal up to the rounding of the general path's input
    /// coordinates (see module docs). Refused when `h` is not finite and `> 0` or `n × n` entries cannot exist.
    pub fn influence_blocks_uniform(&self, x0: f64, h: f64, n: usize) -> Result<InfluenceBlocks, ArgumentError> {
        let mut out =
            InfluenceBlocks { rows: 0, cols: 0, cxx: Vec::new(), cxz: Vec::new(), czx: Vec::new(), czz: Vec::new() };
        self.influence_blocks_uniform_into(x0, h, n, &mut out)?;
        Ok(out)
    }

    /// One block of [`HalfPlane::influence_blocks_uniform`], row-major, computed alone (the same entries bit for
    /// bit). A flexibility that needs two of the four blocks then never holds the other two. Refused as
    /// [`HalfPlane::influence_blocks_uniform`].
    pub fn influence_block_uniform(&self, x0: f64, h: f64, n: usize, which: Block) -> Result<Vec<f64>, ArgumentError> {
        const F: &str = "HalfPlane::influence_block_uniform";
        check_width(F, h)?;
        block_entries(F, n, n)?;
        let (d, t) = self.uniform_parts(x0, h, n);
        let mut out = Vec::new();
        fill_toeplitz(&mut out, &t[which.index()], &d[which.index()], n);
        Ok(out)
    }

    /// The datum columns and the Toeplitz sequences (per block: cxx, cxz, czx, czz) of the uniform mesh's blocks.
    /// Offsets are stored reversed: index m = (n−1) − (i−j), so row i reads m = n−1−i .. 2n−2−i. The callers have
    /// checked `h` ([`check_width`]) and `n` ([`block_entries`]).
    fn uniform_parts(&self, x0: f64, h: f64, n: usize) -> ([Vec<f64>; 4], [Vec<f64>; 4]) {
        let kern = self.kernel();
        let mesh = uniform_mesh(x0, h, n);
        let mut d: [Vec<f64>; 4] = std::array::from_fn(|_| Vec::with_capacity(n));
        for (&aj, &bj) in mesh.a.iter().zip(&mesh.b) {
            let v = kern.datum(aj, bj);
            d.iter_mut().zip(v).for_each(|(col, x)| col.push(x));
        }
        let len = (2 * n).saturating_sub(1);
        let mut t: [Vec<f64>; 4] = std::array::from_fn(|_| Vec::with_capacity(len));
        for m in 0..len {
            let k = (n as f64 - 1.0) - m as f64;
            let v = kern.toeplitz((k + 0.5) * h, (k - 0.5) * h);
            t.iter_mut().zip(v).for_each(|(seq, x)| seq.push(x));
        }
        (d, t)
    }

    /// As [`HalfPlane::influence_blocks_uniform`], but refilling `out` in place (its vectors are
    /// cleared and reused, so a repeated assembly allocates nothing and does not page-fault). Refused as
    /// [`HalfPlane::influence_blocks_uniform`], `out` then untouched.
    pub fn influence_blocks_uniform_into(
        &self,
        x0: f64,
        h: f64,
        n: usize,
        out: &mut InfluenceBlocks,
    ) -> Result<(), ArgumentError> {
        const F: &str = "HalfPlane::influence_blocks_uniform";
        check_width(F, h)?;
        block_entries(F, n, n)?;
        let (d, t) = self.uniform_parts(x0, h, n);
        out.rows = n;
        out.cols = n;
        for (which, dst) in [&mut out.cxx, &mut out.cxz, &mut out.czx, &mut out.czz].into_iter().enumerate() {
            fill_toeplitz(dst, &t[which], &d[which], n);
        }
        Ok(())
    }

    /// This half-plane used as the FLAT counter-body (below the contact line, mirrored frame,
    /// loaded by the reactions): the blocks to ADD to the wheel's blocks so that the sum maps the
    /// wheel's tractions `(q, p)` to (slip, gap change). Equals
    /// `self.influence_blocks(a, b, xc).into_counter_body()`; see the module docs for the mapping. Refused as
    /// [`HalfPlane::influence_blocks`].
    pub fn counter_body_blocks(&self, a: &[f64], b: &[f64], xc: &[f64]) -> Result<InfluenceBlocks, ArgumentError> {
        Ok(self.influence_blocks(a, b, xc)?.into_counter_body())
    }

    /// Uniform-mesh fast path of [`HalfPlane::counter_body_blocks`]. Refused as
    /// [`HalfPlane::influence_blocks_uniform`].
    pub fn counter_body_blocks_uniform(&self, x0: f64, h: f64, n: usize) -> Result<InfluenceBlocks, ArgumentError> {
        Ok(self.influence_blocks_uniform(x0, h, n)?.into_counter_body())
    }
}

/// Stress at `(x, z)` (`z ≥ 0`, `(x, z) ≠ (s, 0)`) due to line loads `p` (normal, into the body)
/// and `q` (tangential, `+x`) at the surface point `s` (Flamant). Material independent. On the
/// surface away from the load `σ_zz = τ_xz = 0` exactly.
pub fn line_load_stress(s: f64, p: f64, q: f64, x: f64, z: f64) -> Stress {
    let xi = x - s;
    let inv = 1.0 / (xi * xi + z * z);
    let c = -FRAC_2_PI * inv * inv * (p * z + q * xi);
    Stress { sxx: c * xi * xi, szz: c * z * z, txz: c * xi * z }
}

/// Stress at `(x, z)`, `z ≥ 0`, due to uniform pressure `p` and shear `q` on the surface strip
/// `[x1, x2]` (`x1 < x2`), closed form (module docs). At `z = 0` returns the limit `z → 0⁺` at fixed
/// `x` (inside: `σ_zz = −p`, `τ_xz = −q`). The only non-finite value is `σ_xx = ±∞` of a
/// nonzero shear exactly at a strip edge on the surface (a true log singularity). Ends given the other way round
/// (`x1 > x2`) give the negative of the strip `[x2, x1]`'s stress; a point outside the body (`z < 0`) has none
/// (every component NaN).
pub fn strip_stress(x1: f64, x2: f64, p: f64, q: f64, x: f64, z: f64) -> Stress {
    if z < 0.0 {
        return Stress { sxx: f64::NAN, szz: f64::NAN, txz: f64::NAN };
    }
    if x1 > x2 {
        let s = strip_stress(x2, x1, p, q, x, z);
        return Stress { sxx: -s.sxx, szz: -s.szz, txz: -s.txz };
    }
    let z = if z == 0.0 { 0.0 } else { z }; // normalise −0.0
    let w = x2 - x1;
    let (e1, e2) = (x - x1, x - x2);
    let (r1, r2) = (e1 * e1 + z * z, e2 * e2 + z * z); // squared distances to the edges
                                                       // φ1 − φ2 ∈ [0, π]: the angle subtended by the strip at (x, z).
    let (num, den) = (z * w, e1 * e2 + z * z);
    let dphi = if num == 0.0 && den == 0.0 {
        if w == 0.0 {
            0.0
        } else {
            FRAC_PI_2
        } // on the surface exactly at an edge: vertical approach
    } else {
        num.atan2(den)
    };
    // Δsin²φ = sin²φ1 − sin²φ2 and Δsin2φ = sin2φ1 − sin2φ2.
    let rr = r1 * r2;
    let (dsq, ds2) = if rr > 0.0 && rr.is_finite() {
        (z * z * w * (e1 + e2) / rr, 2.0 * z * w * (z * z - e1 * e2) / rr)
    } else {
        let f = |e: f64, r: f64| if r > 0.0 { (e * e / r, 2.0 * e * z / r) } else { (0.0, 0.0) };
        let ((sq1, s21), (sq2, s22)) = (f(e1, r1), f(e2, r2));
        (sq1 - sq2, s21 - s22)
    };
    let mut st = Stress::default();
    if p != 0.0 {
        let c = p / PI;
        st.sxx -= c * (dphi - 0.5 * ds2);
        st.szz -= c * (dphi + 0.5 * ds2);
        st.txz -= c * dsq;
    }
    if q != 0.0 {
        // ln(r1/r2) = ½ ln(r1²/r2²); ln_1p form when the ratio is near 1 (r1² − r2² = w(e1 + e2)).
        let ln_ratio = if r1 == 0.0 {
            f64::NEG_INFINITY
        } else if r2 == 0.0 {
            f64::INFINITY
        } else {
            let ratio = r1 / r2;
            if (0.5..=2.0).contains(&ratio) {
                0.5 * (w * (e1 + e2) / r2).ln_1p()
            } else {
                0.5 * ratio.ln()
            }
        };
        let c = q / PI;
        st.sxx -= c * (2.0 * ln_ratio - dsq);
        st.szz -= c * dsq;
        st.txz -= c * (dphi - 0.5 * ds2);
    }
    st
}

/// Blocks of the wheel–flat pair: the wheel's own blocks plus the flat's counter-body blocks.
/// Maps the wheel's element tractions `(q, p)` to (slip `u_x,wheel − u_x,flat`, gap change
/// `u_z,wheel + u'_z,flat`) at the collocation points. Refused as [`HalfPlane::influence_blocks`].
pub fn pair_blocks(
    wheel: &HalfPlane,
    flat: &HalfPlane,
    a: &[f64],
    b: &[f64],
    xc: &[f64],
) -> Result<InfluenceBlocks, ArgumentError> {
    let mut blocks = wheel.influence_blocks(a, b, xc)?;
    blocks.add_blocks(&flat.counter_body_blocks(a, b, xc)?)?;
    Ok(blocks)
}

/// Uniform-mesh fast path of [`pair_blocks`] (mesh [`uniform_mesh`]`(x0, h, n)`). Refused as
/// [`HalfPlane::influence_blocks_uniform`].
pub fn pair_blocks_uniform(
    wheel: &HalfPlane,
    flat: &HalfPlane,
    x0: f64,
    h: f64,
    n: usize,
) -> Result<InfluenceBlocks, ArgumentError> {
    let mut blocks = wheel.influence_blocks_uniform(x0, h, n)?;
    blocks.add_blocks(&flat.counter_body_blocks_uniform(x0, h, n)?)?;
    Ok(blocks)
}

#[cfg(test)]
mod tests {
    use super::*;

    // ------------------------------------------------------------------------------------------
    // Independent numerical quadrature: Gauss–Legendre (nodes by Newton on P_n, nothing shared with
    // the code under test), adaptive bisection, user breakpoints at kinks/jumps/log singularities.
    // ------------------------------------------------------------------------------------------
    struct Gl {
        x: Vec<f64>,
        w: Vec<f64>,
    }

    impl Gl {
        fn new(n: usize) -> Self {
            let legendre = |t: f64| {
                let (mut p0, mut p1) = (1.0, t);
                for k in 1..n {
                    let kf = k as f64;
                    let p2 = ((2.0 * kf + 1.0) * t * p1 - kf * p0) / (kf + 1.0);
                    p0 = p1;
                    p1 = p2;
                }
                (p1, n as f64 * (t * p1 - p0) / (t * t - 1.0))
            };
            let (mut x, mut w) = (Vec::new(), Vec::new());
            for i in 0..n {
                let mut t = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
                for _ in 0..100 {
                    let (p, dp) = legendre(t);
                    let dt = p / dp;
                    t -= dt;
                    if dt.abs() < 1e-16 {
                        break;
                    }
                }
                let (_, dp) = legendre(t);
                x.push(t);
                w.push(2.0 / ((1.0 - t * t) * dp * dp));
            }
            Gl { x, w }
        }

        fn panel(&self, f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
            let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
            h * self.x.iter().zip(&self.w).map(|(x, w)| w * f(c + h * x)).sum::<f64>()
        }

        /// Bisection until the two halves agree with the whole to `tol`, or the panel is narrower
        /// than `min_w` (only near a log singularity at a breakpoint; the neglected error there is
        /// ~1e-3·min_w·|ln min_w|, far below the targets).
        /// `lim = (tol, min_w)`.
        fn rec(&self, f: &dyn Fn(f64) -> f64, a: f64, b: f64, whole: f64, lim: (f64, f64), depth: u32) -> f64 {
            let (tol, min_w) = lim;
            let m = 0.5 * (a + b);
            let (l, r) = (self.panel(f, a, m), self.panel(f, m, b));
            if depth >= 3 && ((l + r - whole).abs() <= tol || b - a <= min_w) {
                l + r
            } else {
                self.rec(f, a, m, l, lim, depth + 1) + self.rec(f, m, b, r, lim, depth + 1)
            }
        }

        /// ∫_a^b f, split at the given breakpoints; absolute tolerance 1e-15·∫|f| per panel.
        fn integrate(&self, f: &dyn Fn(f64) -> f64, a: f64, b: f64, splits: &[f64]) -> f64 {
            let mut pts = vec![a];
            pts.extend(splits.iter().copied().filter(|&s| s > a && s < b));
            pts.push(b);
            pts.sort_by(f64::total_cmp);
            let g = |t: f64| f(t).abs();
            let rough: f64 = pts.windows(2).map(|p| self.panel(&g, p[0], p[1])).sum();
            let min_w = 1e-13 * (b - a);
            let l1: f64 = pts
                .windows(2)
                .map(|p| self.rec(&g, p[0], p[1], self.panel(&g, p[0], p[1]), (1e-8 * rough, min_w), 0))
                .sum();
            let tol = 1e-15 * l1.max(f64::MIN_POSITIVE);
            pts.windows(2).map(|p| self.rec(f, p[0], p[1], self.panel(f, p[0], p[1]), (tol, min_w), 0)).sum()
        }
    }

    /// 4th-order central difference.
    fn diff(f: &dyn Fn(f64) -> f64, x: f64, h: f64) -> f64 {
        (f(x - 2.0 * h) - 8.0 * f(x - h) + 8.0 * f(x + h) - f(x + 2.0 * h)) / (12.0 * h)
    }

    fn max_abs(v: &[f64]) -> f64 {
        v.iter().fold(0.0, |m, x| m.max(x.abs()))
    }

    /// A strip of half-spaces ([`HalfPlane::strip`]) against a double quadrature of Johnson's point loads on a
    /// half-space (*Contact Mechanics* eqs. 3.19, 3.86–3.87, written out here, nothing shared with the closed forms)
    /// over the rectangle `[x1, x2] × [−w/2, w/2]`; points inside, on the edges and outside, narrow and wide strips.
    #[test]
    fn strip_of_half_spaces_matches_quadrature_of_point_loads() {
        let gl = Gl::new(20);
        let (e, nu) = (3.0e3, 0.28);
        let g = e / (2.0 * (1.0 + nu));
        let k = 1.0 / (2.0 * PI * g);
        // Point-load surface displacements at (X, Y) from the load: [u_x(P), u_z(P), u_x(Q), u_z(Q)].
        let point = |x: f64, y: f64| {
            let r2 = x * x + y * y;
            let r = r2.sqrt();
            [
                -(1.0 - 2.0 * nu) * k * x / (2.0 * r2),
                (1.0 - nu) * k / r,
                k * ((1.0 - nu) / r + nu * x * x / (r2 * r)),
                (1.0 - 2.0 * nu) * k * x / (2.0 * r2),
            ]
        };
        let mut worst = 0.0_f64;
        // (x1, x2, width)
        for &(x1, x2, width) in &[(-0.4, 0.6, 0.5), (-0.02, 0.02, 200.0), (0.3, 1.3, 3.0), (0.0, 1.0, 1e-3)] {
            let hp = HalfPlane::new(e, nu, 1.0).unwrap().strip(width).unwrap();
            let hw = 0.5 * width;
            for t in [0.5, 0.3, 0.0, 1.0, -0.5, 3.0, -20.0] {
                let x = x1 + t * (x2 - x1);
                for (p, q, cx, cz) in [(1.0, 0.0, 0, 1), (0.0, 1.0, 2, 3)] {
                    let u = hp.strip_surface_displacement(x1, x2, p, q, x);
                    for (comp, closed) in [(cx, u.ux), (cz, u.uz)] {
                        // ∫ over Y (even in Y: twice the half), then over s, splitting at the observation point.
                        let inner = |s: f64| {
                            let xx = x - s;
                            let f = |y: f64| point(xx, y)[comp];
                            2.0 * gl.integrate(&f, 0.0, hw, &[xx.abs().min(hw)])
                        };
                        let num = gl.integrate(&inner, x1, x2, &[x]);
                        let scale = k * (x2 - x1);
                        let err = (closed - num).abs() / scale;
                        assert!(
                            err < 1e-11,
                            "x1 {x1} x2 {x2} w {width} x {x} comp {comp}: {closed} vs {num} ({err:.1e})"
                        );
                        worst = worst.max(err);
                    }
                }
            }
        }
        eprintln!("strip vs point-load quadrature: worst {worst:.1e} of K·(x2 − x1)");
    }

    /// Extreme strips stay finite everywhere, element ends included: a strip 1e-8 and 1e12 element lengths wide
    /// (the range the scene accepts) and beyond it (the closed forms' own limits, `h/|X|` overflowing).
    #[test]
    fn extreme_strips_are_finite() {
        for width in [1e-12, 1e-8, 1.0, 1e12, 1e300] {
            let hp = HalfPlane::new(1.0, 0.3, 1.0).unwrap().strip(width).unwrap();
            for x in [0.0, 1e-9, 0.5, 1.0, 1.0 + 1e-12, -3.0, 1e-300] {
                let u = hp.strip_surface_displacement(0.0, 1.0, 1.0, 1.0, x);
                assert!(u.ux.is_finite() && u.uz.is_finite(), "w = {width:e}, x = {x:e}: {u:?}");
            }
        }
    }

    /// As the strip widens, its coefficients tend to plane strain's (the closed forms checked against the line
    /// loads below) up to a constant per element, which a load or a rigid motion absorbs: the differences between
    /// rows of one column converge, the direct blocks as 1/w², the coupling blocks as 1/w. Grid: carter2d's.
    #[test]
    fn a_wide_strip_tends_to_plane_strain() {
        let (x0, h, n) = (-1.05, 0.04, 55);
        // Largest row difference of (strip − plane strain) over the direct blocks (xx, zz) and the coupling
        // blocks (xz, zx), in units of K·h.
        let deviation = |nu: f64, width: f64| {
            let plane = HalfPlane::new(1.0, nu, 3.0).unwrap().influence_blocks_uniform(x0, h, n).unwrap();
            let strip =
                HalfPlane::new(1.0, nu, 3.0).unwrap().strip(width).unwrap().influence_blocks_uniform(x0, h, n).unwrap();
            let k = (1.0 + nu) / PI;
            let worst = |a: &[f64], b: &[f64]| {
                let mut m = 0.0_f64;
                for j in 0..n {
                    for i in 1..n {
                        m = m.max(((a[i * n + j] - a[j]) - (b[i * n + j] - b[j])).abs() / (k * h));
                    }
                }
                m
            };
            let direct = worst(&plane.cxx, &strip.cxx).max(worst(&plane.czz, &strip.czz));
            let coupling = worst(&plane.cxz, &strip.cxz).max(worst(&plane.czx, &strip.czx));
            (direct, coupling)
        };
        for nu in [0.0, 0.28, 0.5] {
            let (d1, c1) = deviation(nu, 2.0e2);
            let (d2, c2) = deviation(nu, 2.0e3);
            eprintln!("nu {nu}: direct {d1:.2e} -> {d2:.2e}, coupling {c1:.2e} -> {c2:.2e}");
            // O((x/h)²) for the direct blocks, O(x/h) for the coupling ones (the `h ln(ρ_a/ρ_b)` and
            // `|t| atan(h/|t|)` terms of I3 leave −(t_a² − t_b²)/(2h)): both vanish as the strip widens.
            assert!(d1 < 5e-4 && d2 < d1 / 90.0, "nu {nu}: direct blocks {d1:.1e} -> {d2:.1e}");
            assert!(c1 < 5e-2 && (c2 < c1 / 9.0 || c1 == 0.0), "nu {nu}: coupling blocks {c1:.1e} -> {c2:.1e}");
        }
    }

    /// The centre of a uniformly loaded rectangle, half-sides a and b (Love; Timoshenko & Goodier §138):
    /// u_z = 4(1−ν²) p/(πE) · [a asinh(b/a) + b asinh(a/b)]; for a square the textbook's 2.24 (1−ν²) p a / E.
    #[test]
    fn a_strip_elements_centre_is_loves() {
        let (e, nu, a, b): (f64, f64, f64, f64) = (2.0, 0.3, 0.02, 100.0);
        let love = 4.0 * (1.0 - nu * nu) / (PI * e) * (a * (b / a).asinh() + b * (a / b).asinh());
        let u = HalfPlane::new(e, nu, 1.0)
            .unwrap()
            .strip(2.0 * b)
            .unwrap()
            .strip_surface_displacement(-a, a, 1.0, 0.0, 0.0);
        assert!((u.uz - love).abs() <= 1e-14 * love, "{} vs {love}", u.uz);
        assert_eq!(u.ux, 0.0);
        let square = HalfPlane::new(e, nu, 1.0)
            .unwrap()
            .strip(2.0 * a)
            .unwrap()
            .strip_surface_displacement(-a, a, 1.0, 0.0, 0.0);
        let textbook = 2.24 * (1.0 - nu * nu) * a / e;
        assert!((square.uz - textbook).abs() < 0.005 * textbook, "{} vs {textbook}", square.uz);
    }

    /// Strip closed forms vs quadrature of the line-load solution over the strip
    /// (expected values: ∫ line_load_displacement(s, p ds) ds, computed numerically).
    #[test]
    fn strip_surface_displacement_matches_quadrature() {
        let gl = Gl::new(20);
        // (nu, D, x1, x2)
        let cases = [(0.3, 5.0, -0.4, 0.6), (0.0, 100.0, 0.3, 1.3), (0.5, 2.0, -1.0, -0.2), (0.25, 1e6, 2.0, 2.5)];
        let (mut worst_rel, mut worst_floor) = (0.0_f64, 0.0_f64);
        for &(nu, d, x1, x2) in &cases {
            let hp = HalfPlane::new(2.0e3, nu, d).unwrap();
            let w = x2 - x1;
            let k = (1.0 + nu) / (PI * 2.0e3);
            let scale = k * w * (1.0 + 2.0 * (1.0 - nu) * (d / w).ln().abs());
            // inside, centre, both edges, just outside, outside, far (both sides)
            for t in [0.3, 0.5, 0.0, 1.0, -0.01, 1.5, 4.0, -50.0] {
                let x = x1 + t * w;
                for (p, q) in [(1.0, 0.0), (0.0, 1.0)] {
                    let cf = hp.strip_surface_displacement(x1, x2, p, q, x);
                    let fx = |s: f64| hp.line_load_displacement(s, p, q, x, 0.0).ux;
                    let fz = |s: f64| hp.line_load_displacement(s, p, q, x, 0.0).uz;
                    let nx = gl.integrate(&fx, x1, x2, &[x]);
                    let nz = gl.integrate(&fz, x1, x2, &[x]);
                    for (c, n) in [(cf.ux, nx), (cf.uz, nz)] {
                        let err = (c - n).abs();
                        assert!(c.is_finite());
                        // relative 1e-10, with an absolute floor 1e-14·scale for values that are
                        // themselves ~1e-7 of the scale (pure datum terms at the strip centre, huge D)
                        assert!(err <= 1e-10 * n.abs() + 1e-14 * scale, "nu={nu} D={d} x={x} p={p} q={q}: {c} vs {n}");
                        if n.abs() > 1e-6 * scale {
                            worst_rel = worst_rel.max(err / n.abs());
                        } else {
                            worst_floor = worst_floor.max(err / scale);
                        }
                    }
                }
            }
        }
        println!(
            "strip surface displacement vs quadrature: max rel err {worst_rel:.2e}; tiny values: max err/scale {worst_floor:.2e}"
        );
    }

    /// Strip stress closed forms vs quadrature of the Flamant stresses over the strip.
    #[test]
    fn strip_stress_matches_quadrature() {
        let gl = Gl::new(20);
        let (x1, x2) = (-0.5, 0.7);
        let pts = [
            (0.1, 0.5),    // under the centre
            (-0.5, 0.1),   // under an edge
            (0.3, 1e-3),   // just below the surface, inside
            (0.7, 1e-2),   // shallow, at the other edge
            (1.5, 0.3),    // outside
            (-0.9, 2e-3),  // shallow, outside
            (30.0, 5.0),   // far
            (0.2, 20.0),   // deep
            (-400.0, 1.0), // very far, shallow
        ];
        let mut worst = 0.0_f64;
        for &(x, z) in &pts {
            for (p, q) in [(1.0, 0.0), (0.0, 1.0), (0.7, -1.3)] {
                let cf = strip_stress(x1, x2, p, q, x, z);
                let comp = |f: fn(&Stress) -> f64| {
                    let g = |s: f64| f(&line_load_stress(s, p, q, x, z));
                    gl.integrate(&g, x1, x2, &[x, x - z, x + z])
                };
                let n = [comp(|s| s.sxx), comp(|s| s.szz), comp(|s| s.txz)];
                let c = [cf.sxx, cf.szz, cf.txz];
                let norm = max_abs(&n);
                for (ci, ni) in c.iter().zip(&n) {
                    let rel = (ci - ni).abs() / norm;
                    worst = worst.max(rel);
                    assert!(rel <= 1e-10, "({x},{z}) p={p} q={q}: closed {c:?} vs quad {n:?}");
                }
            }
        }
        println!("strip stress vs quadrature: max err / |sigma| = {worst:.2e}");
    }

    /// (i) symmetric gradient of the displacement field (finite differences) = plane-strain
    /// Hooke's law applied to the Flamant stresses.
    #[test]
    fn line_load_strain_matches_hooke() {
        let mut worst = 0.0_f64;
        for nu in [0.0, 0.3, 0.5] {
            let e = 2.1;
            let hp = HalfPlane::new(e, nu, 4.0).unwrap();
            let (s, pp, qq) = (0.25_f64, 1.3, -0.7);
            for &(x, z) in &[(0.7, 0.4), (-1.3, 2.0), (0.3, 0.02), (3.0, 0.5), (-0.4, 5.0), (40.0, 3.0)] {
                let r = ((x - s) * (x - s) + z * z).sqrt();
                let h = 1e-3 * r;
                let u = |x: f64, z: f64| hp.line_load_displacement(s, pp, qq, x, z);
                let exx = diff(&|t| u(t, z).ux, x, h);
                let ezz = diff(&|t| u(x, t).uz, z, h);
                let exz = 0.5 * (diff(&|t| u(x, t).ux, z, h) + diff(&|t| u(t, z).uz, x, h));
                let sg = line_load_stress(s, pp, qq, x, z);
                let hxx = ((1.0 - nu * nu) * sg.sxx - nu * (1.0 + nu) * sg.szz) / e;
                let hzz = ((1.0 - nu * nu) * sg.szz - nu * (1.0 + nu) * sg.sxx) / e;
                let hxz = (1.0 + nu) * sg.txz / e;
                let scale = max_abs(&[hxx, hzz, hxz]);
                for (a, b) in [(exx, hxx), (ezz, hzz), (exz, hxz)] {
                    let rel = (a - b).abs() / scale;
                    worst = worst.max(rel);
                    assert!(rel <= 1e-7, "nu={nu} ({x},{z}): FD {a} vs Hooke {b}");
                }
            }
        }
        println!("line load: strain (FD of u) vs Hooke(Flamant stresses): max rel err {worst:.2e}");
    }

    /// (ii) equilibrium (divergence of the Flamant stress by finite differences) and a
    /// traction-free surface away from the load.
    #[test]
    fn line_load_equilibrium_and_free_surface() {
        let (s, pp, qq) = (-0.4_f64, 2.0, 0.9);
        let mut worst = 0.0_f64;
        for &(x, z) in &[(0.7, 0.4), (-1.3, 2.0), (-0.3, 0.02), (3.0, 0.5), (-0.4, 5.0)] {
            let r = ((x - s) * (x - s) + z * z).sqrt();
            let h = 1e-3 * r;
            let st = |x: f64, z: f64| line_load_stress(s, pp, qq, x, z);
            let d1 = diff(&|t| st(t, z).sxx, x, h) + diff(&|t| st(x, t).txz, z, h);
            let d2 = diff(&|t| st(t, z).txz, x, h) + diff(&|t| st(x, t).szz, z, h);
            let c = st(x, z);
            let scale = max_abs(&[c.sxx, c.szz, c.txz]) / r;
            worst = worst.max(d1.abs().max(d2.abs()) / scale);
            assert!(d1.abs() <= 1e-7 * scale && d2.abs() <= 1e-7 * scale, "({x},{z}): div = ({d1}, {d2})");
        }
        for x in [-3.0, -0.41, 0.2, 7.0] {
            let c = line_load_stress(s, pp, qq, x, 0.0);
            assert_eq!((c.szz, c.txz), (0.0, 0.0), "surface not traction-free at x={x}");
            assert!(c.sxx.is_finite());
        }
        println!("line load: |div sigma| / (|sigma|/r) max {worst:.2e}");
    }

    /// (iii) the symmetries that fix the rigid rotation (load at s = 0, so the datum is on the
    /// axis): normal load u_x odd / u_z even, tangential load u_z odd / u_x even, zero rotation on the
    /// axis of a normal load; and zero displacement at the datum for any load position.
    #[test]
    fn line_load_symmetry_and_datum() {
        let hp = HalfPlane::new(3.0, 0.27, 2.5).unwrap();
        for &(x, z) in &[(0.3, 0.2), (1.7, 0.0), (4.0, 9.0), (0.01, 3.0)] {
            let (pp, pm) =
                (hp.line_load_displacement(0.0, 1.0, 0.0, x, z), hp.line_load_displacement(0.0, 1.0, 0.0, -x, z));
            let (qp, qm) =
                (hp.line_load_displacement(0.0, 0.0, 1.0, x, z), hp.line_load_displacement(0.0, 0.0, 1.0, -x, z));
            let tol = |v: f64| 1e-15 * v.abs().max(1e-300);
            assert!((pp.ux + pm.ux).abs() <= tol(pp.ux), "P: u_x not odd");
            assert!((pp.uz - pm.uz).abs() <= tol(pp.uz), "P: u_z not even");
            assert!((qp.uz + qm.uz).abs() <= tol(qp.uz), "Q: u_z not odd");
            assert!((qp.ux - qm.ux).abs() <= tol(qp.ux), "Q: u_x not even");
        }
        for z in [0.5, 2.0, 7.0] {
            let h = 1e-3 * z;
            let u = |x: f64, z: f64| hp.line_load_displacement(0.0, 1.0, 0.0, x, z);
            let omega = 0.5 * (diff(&|t| u(0.0, t).ux, z, h) - diff(&|t| u(t, z).uz, 0.0, h));
            assert!(omega.abs() < 1e-12, "rotation on the axis {omega}");
        }
        for s in [-3.0, 0.0, 0.7, 1e3] {
            let u = hp.line_load_displacement(s, 1.3, -0.4, 0.0, hp.datum_depth());
            assert_eq!((u.ux, u.uz), (0.0, 0.0), "nonzero at the datum for s={s}");
        }
    }

    /// (iv) surface displacements vs Johnson eqs. 2.19 (normal) and 2.22 (tangential), our axes
    /// (z into the body, as Johnson's): jumps and log slopes.
    #[test]
    fn line_load_surface_matches_johnson() {
        for nu in [0.0, 0.3, 0.5] {
            let e = 7.0;
            let hp = HalfPlane::new(e, nu, 3.0).unwrap();
            let jump = (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * e); // Johnson 2.19a / 2.22b coefficient
            let slope = 2.0 * (1.0 - nu * nu) / (PI * e); // Johnson 2.19b / 2.22a coefficient
            let (pp, qq) = (1.7, -0.6);
            // load at s = 0: the datum is on the load axis, u_x(P) is exactly the textbook value
            for x in [0.2_f64, -0.9, 5.0] {
                let u = hp.line_load_displacement(0.0, pp, 0.0, x, 0.0);
                let expect = -jump * pp * x.signum();
                assert!((u.ux - expect).abs() <= 1e-14 * (expect.abs() + 1e-300), "nu={nu}: {} vs {expect}", u.ux);
                let v = hp.line_load_displacement(0.0, 0.0, qq, x, 0.0);
                let expect = jump * qq * x.signum();
                assert!((v.uz - expect).abs() <= 1e-14 * (expect.abs() + 1e-300), "nu={nu}: {} vs {expect}", v.uz);
            }
            // any load position: differences (the datum constant drops out)
            let s = 0.6;
            for (x1, x2) in [(0.9, 2.6), (-0.4, 0.7), (-3.0, 11.0)] {
                let (a, b) =
                    (hp.line_load_displacement(s, pp, qq, x1, 0.0), hp.line_load_displacement(s, pp, qq, x2, 0.0));
                let lr = ((x1 - s).abs() / (x2 - s).abs()).ln();
                let duz = -slope * pp * lr + jump * qq * ((x1 - s).signum() - (x2 - s).signum());
                let dux = -slope * qq * lr - jump * pp * ((x1 - s).signum() - (x2 - s).signum());
                assert!((a.uz - b.uz - duz).abs() <= 1e-13 * duz.abs().max(slope), "nu={nu}");
                assert!((a.ux - b.ux - dux).abs() <= 1e-13 * dux.abs().max(slope), "nu={nu}");
            }
        }
    }

    /// Resultants: the strip stresses integrated over the horizontal line at depth z equal
    /// (∫σ_zz dx, ∫τ_xz dx) = (−p·w, −q·w) (equilibrium of the layer above the line).
    #[test]
    fn strip_stress_resultants() {
        let gl = Gl::new(20);
        let (x1, x2, p, q) = (-0.3_f64, 0.5, 1.7, 0.6);
        let w = x2 - x1;
        let mut worst = 0.0_f64;
        for z in [0.05, 1.0, 20.0] {
            let (c, l) = (0.5 * (x1 + x2), w.max(z));
            let br = [((x1 - c) / l).atan(), ((x2 - c) / l).atan()];
            let integ = |f: fn(&Stress) -> f64| {
                let g = |phi: f64| {
                    let cs = phi.cos();
                    f(&strip_stress(x1, x2, p, q, c + l * phi.tan(), z)) * l / (cs * cs)
                };
                gl.integrate(&g, -FRAC_PI_2, FRAC_PI_2, &br)
            };
            let (fz, fx) = (integ(|s| s.szz), integ(|s| s.txz));
            let (ez, ex) = ((fz + p * w).abs() / (p * w), (fx + q * w).abs() / (q * w));
            worst = worst.max(ez).max(ex);
            assert!(ez <= 1e-10 && ex <= 1e-10, "z={z}: {fz} vs {}, {fx} vs {}", -p * w, -q * w);
        }
        println!("strip resultants at depth: max rel err {worst:.2e}");
    }

    /// Hertz: the 2D Hertz pressure p0·sqrt(1 − x²/a²) gives, inside the contact,
    /// u_z(x) − u_z(0) = −p0 x²/(E* a) exactly (PV ∫ sqrt(a²−s²)/(x−s) ds = π x), i.e. the profile
    /// −x²/(2R) of a cylinder with 1/R = 2 p0/(E* a), equivalent to a² = 4PR/(πE*), P = π a p0/2.
    /// Discretised with N uniform strips carrying the exact cell averages: error ~1e-3 at N = 400,
    /// decreasing with N.
    #[test]
    fn hertz_pressure_gives_parabolic_displacement() {
        let hp = HalfPlane::new(1.0, 0.3, 10.0).unwrap();
        let (a, p0) = (1.0_f64, 1.0);
        let es = hp.plane_strain_modulus();
        let prim =
            |s: f64| p0 / a * 0.5 * (s * (a * a - s * s).max(0.0).sqrt() + a * a * (s / a).clamp(-1.0, 1.0).asin());
        let mut errs = Vec::new();
        for n in [100, 200, 400, 800] {
            let h = 2.0 * a / n as f64;
            let mesh = uniform_mesh(-a, h, n);
            let pbar: Vec<f64> = mesh.a.iter().zip(&mesh.b).map(|(&l, &r)| (prim(r) - prim(l)) / (r - l)).collect();
            let blocks = hp.influence_blocks_uniform(-a, h, n).unwrap();
            let (_, uz) = blocks.apply(&vec![0.0; n], &pbar).unwrap();
            let u0: f64 = mesh
                .a
                .iter()
                .zip(&mesh.b)
                .zip(&pbar)
                .map(|((&l, &r), &pj)| hp.strip_surface_displacement(l, r, pj, 0.0, 0.0).uz)
                .sum();
            let exact: Vec<f64> = mesh.xc.iter().map(|x| -p0 * x * x / (es * a)).collect();
            let err = uz.iter().zip(&exact).map(|(u, e)| (u - u0 - e).abs()).fold(0.0, f64::max) / max_abs(&exact);
            // curvature fit -> R -> Hertz a² = 4PR/(πE*)
            let (sxy, sxx) =
                mesh.xc.iter().zip(&uz).fold((0.0, 0.0), |(sy, sx), (x, u)| (sy + (u - u0) * x * x, sx + x.powi(4)));
            let r_fit = -sxx / (2.0 * sxy);
            let load = crate::theory::Hertz2D::new(a, p0).load;
            let a2 = crate::theory::Hertz2D::from_load(load, r_fit, es).a.powi(2);
            println!("Hertz N={n}: max |du_z - exact| / max|exact| = {err:.3e}, a² from fitted R = {a2:.6}");
            errs.push((err, (a2 - a * a).abs()));
        }
        assert!(errs[2].0 <= 1e-3, "N=400 error {}", errs[2].0);
        assert!(errs[2].1 <= 1e-3, "N=400 Hertz a² error {}", errs[2].1);
        assert!(errs.windows(2).all(|w| w[1].0 < 0.8 * w[0].0), "no convergence: {errs:?}");
    }

    /// Toeplitz fast path vs general path: bit-identical on a dyadic mesh; on a non-dyadic one the
    /// difference is the rounding of the general path's input coordinates.
    #[test]
    fn uniform_fast_path_matches_general() {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        for nu in [0.0, 0.3, 0.5] {
            let hp = HalfPlane::new(5.0, nu, 16.0).unwrap();
            let (x0, h, n) = (-4.0, 0.125, 64);
            let m = uniform_mesh(x0, h, n);
            let (f, g) =
                (hp.influence_blocks_uniform(x0, h, n).unwrap(), hp.influence_blocks(&m.a, &m.b, &m.xc).unwrap());
            for (a, b) in [(&f.cxx, &g.cxx), (&f.cxz, &g.cxz), (&f.czx, &g.czx), (&f.czz, &g.czz)] {
                assert_eq!(bits(a), bits(b), "dyadic mesh: fast path not bit-identical (nu={nu})");
            }
        }
        // the in-place refill (both its branches: reallocation and overwrite) gives the same bits
        let hp = HalfPlane::new(5.0, 0.3, 3.3).unwrap();
        let fresh = hp.influence_blocks_uniform(-1.2345, 0.0371, 40).unwrap();
        let mut reused = hp.influence_blocks_uniform(0.0, 1.0, 7).unwrap();
        hp.influence_blocks_uniform_into(-1.2345, 0.0371, 40, &mut reused).unwrap();
        assert_eq!(bits(&reused.czz), bits(&fresh.czz));
        let mut again = hp.influence_blocks_uniform(3.0, 0.5, 40).unwrap();
        hp.influence_blocks_uniform_into(-1.2345, 0.0371, 40, &mut again).unwrap();
        for (a, b) in
            [(&again.cxx, &fresh.cxx), (&again.cxz, &fresh.cxz), (&again.czx, &fresh.czx), (&again.czz, &fresh.czz)]
        {
            assert_eq!(bits(a), bits(b), "in-place refill differs");
        }
        for (x0, h) in [(-1.2345, 0.0371), (10.1, 0.0371)] {
            let n = 64;
            let m = uniform_mesh(x0, h, n);
            let (f, g) =
                (hp.influence_blocks_uniform(x0, h, n).unwrap(), hp.influence_blocks(&m.a, &m.b, &m.xc).unwrap());
            let xmax = max_abs(&m.b).max(max_abs(&m.a));
            for (name, a, b) in
                [("cxx", &f.cxx, &g.cxx), ("cxz", &f.cxz, &g.cxz), ("czx", &f.czx, &g.czx), ("czz", &f.czz, &g.czz)]
            {
                let diff = a.iter().zip(b.iter()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
                let rel = diff / max_abs(b);
                println!(
                    "non-dyadic x0={x0} h={h}: {name} max|fast-general|/max|C| = {rel:.2e} (eps*max|x|/h = {:.2e})",
                    f64::EPSILON * xmax / h
                );
                assert!(rel <= 20.0 * f64::EPSILON * xmax / h, "{name}: {rel}");
            }
        }
    }

    /// Block entries are exactly the strip function (same arithmetic).
    #[test]
    fn blocks_equal_strip_function() {
        let hp = HalfPlane::new(1.5, 0.22, 6.0).unwrap();
        let (a, b) = (vec![-1.0, -0.3, 0.05, 0.9], vec![-0.3, 0.05, 0.9, 1.0]);
        let xc = vec![-0.65, -0.3, 0.47, 0.95, 3.0];
        let bl = hp.influence_blocks(&a, &b, &xc).unwrap();
        for (i, &x) in xc.iter().enumerate() {
            for j in 0..a.len() {
                let up = hp.strip_surface_displacement(a[j], b[j], 1.0, 0.0, x);
                let uq = hp.strip_surface_displacement(a[j], b[j], 0.0, 1.0, x);
                let ij = i * a.len() + j;
                assert_eq!([bl.cxx[ij], bl.cxz[ij], bl.czx[ij], bl.czz[ij]], [uq.ux, up.ux, uq.uz, up.uz]);
            }
        }
    }

    /// Identical materials (and D2 = D): coupling blocks of the pair are exactly zero, direct
    /// blocks exactly double.
    #[test]
    fn counter_body_identical_materials() {
        let hp = HalfPlane::new(210e9, 0.3, 0.05).unwrap();
        let (a, b) = (vec![-1e-3, -4e-4, 1e-4, 7e-4], vec![-4e-4, 1e-4, 7e-4, 1.3e-3]);
        let xc = vec![-7e-4, -1.5e-4, 4e-4, 1e-3, -4e-4];
        let w = hp.influence_blocks(&a, &b, &xc).unwrap();
        for pair in
            [pair_blocks(&hp, &hp, &a, &b, &xc).unwrap(), pair_blocks_uniform(&hp, &hp, -1e-3, 1e-4, 20).unwrap()]
        {
            let w =
                if pair.cols == a.len() { w.clone() } else { hp.influence_blocks_uniform(-1e-3, 1e-4, 20).unwrap() };
            assert!(pair.cxz.iter().chain(&pair.czx).all(|v| v.to_bits() == 0), "coupling not exactly +0");
            for (s, o) in [(&pair.cxx, &w.cxx), (&pair.czz, &w.czz)] {
                assert!(s.iter().zip(o.iter()).all(|(x, y)| x.to_bits() == (2.0 * y).to_bits()), "direct not doubled");
            }
        }
    }

    /// The pair blocks implement the mirror mapping: slip = u_x,wheel − u'_x,flat and gap change =
    /// u_z,wheel + u'_z,flat, with the flat (own frame) loaded by q' = −q, p' = +p, evaluated here
    /// explicitly from the strip function.
    #[test]
    fn counter_body_mapping_matches_explicit_reactions() {
        let wheel = HalfPlane::new(1.0, 0.29, 3.0).unwrap();
        let flat = HalfPlane::new(0.4, 0.45, 1.7).unwrap();
        let m = uniform_mesh(-0.9, 0.15, 12);
        let q: Vec<f64> = (0..12).map(|j| 0.3 * (j as f64).sin()).collect();
        let p: Vec<f64> = (0..12).map(|j| 1.0 + 0.1 * j as f64).collect();
        let (slip, gap) = pair_blocks(&wheel, &flat, &m.a, &m.b, &m.xc).unwrap().apply(&q, &p).unwrap();
        for (i, &x) in m.xc.iter().enumerate() {
            let (mut uw, mut uf) = (Displacement::default(), Displacement::default());
            for j in 0..12 {
                let a = wheel.strip_surface_displacement(m.a[j], m.b[j], p[j], q[j], x);
                let b = flat.strip_surface_displacement(m.a[j], m.b[j], p[j], -q[j], x);
                uw = Displacement { ux: uw.ux + a.ux, uz: uw.uz + a.uz };
                uf = Displacement { ux: uf.ux + b.ux, uz: uf.uz + b.uz };
            }
            let (es, eg) = (uw.ux - uf.ux, uw.uz + uf.uz);
            assert!((slip[i] - es).abs() <= 1e-13 * es.abs().max(1.0), "slip {} vs {es}", slip[i]);
            assert!((gap[i] - eg).abs() <= 1e-13 * eg.abs().max(1.0), "gap {} vs {eg}", gap[i]);
            assert!(gap[i] > 0.0, "compression must open the gap relative to the data");
        }
    }

    /// β of the pair (E1, ν1) on (E2, ν2), by [`crate::material::dundurs_beta`].
    fn dundurs_beta(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
        crate::material::dundurs_beta(&Material::new(e1, nu1), &Material::new(e2, nu2))
    }

    /// Dundurs β: reference values (rigid counter-body: β = (1−2ν)/(2(1−ν)) = 4/9 at ν = 0.1, 0 at
    /// ν = 0.5), antisymmetry, and consistency with the pair blocks: β = (slip jump across a strip
    /// per unit p) / (π · log coefficient of the gap change per unit p).
    #[test]
    fn dundurs_beta_values_and_pair_consistency() {
        let inf = f64::INFINITY;
        assert!((dundurs_beta(210e9, 0.1, inf, 0.3) - 4.0 / 9.0).abs() < 1e-15);
        assert!((dundurs_beta(210e9, 0.1, inf, 0.3).abs() - 0.444).abs() < 5e-4);
        assert_eq!(dundurs_beta(1.0, 0.5, inf, 0.2), 0.0);
        assert!((dundurs_beta(inf, 0.2, 3.0, 0.1) + 4.0 / 9.0).abs() < 1e-15);
        assert_eq!(dundurs_beta(2.0, 0.3, 2.0, 0.3), 0.0);
        let (b12, b21) = (dundurs_beta(1.0, 0.2, 3.0, 0.4), dundurs_beta(3.0, 0.4, 1.0, 0.2));
        assert_eq!(b12, -b21);
        for (e1, n1, e2, n2) in
            [(1.0, 0.2, 3.0, 0.4), (70.0, 0.33, 210.0, 0.3), (1.0, 0.1, inf, 0.3), (5.0, 0.5, 1.0, 0.0)]
        {
            let (wheel, flat) = (HalfPlane::new(e1, n1, 5.0).unwrap(), HalfPlane::new(e2, n2, 2.0).unwrap());
            let w = 1e-3;
            let (a, b) = ([-0.5 * w], [0.5 * w]);
            let bl = pair_blocks(&wheel, &flat, &a, &b, &[1.0, -1.0, 2.0]).unwrap();
            let jump = (bl.cxz[0] - bl.cxz[1]) / w;
            let logc = (bl.czz[0] - bl.czz[2]) / (w * 0.5_f64.ln());
            let beta = jump / (PI * logc);
            let exact = dundurs_beta(e1, n1, e2, n2);
            assert!((beta - exact).abs() <= 1e-5, "{beta} vs {exact}");
        }
    }

    /// Edge cases: collocation exactly at element edges (finite and continuous), z → 0⁺ limits of
    /// the strip stresses, huge datum depth, ν = 0 and 0.5, rigid body, no NaN anywhere.
    #[test]
    fn edge_cases_are_finite() {
        let (x1, x2) = (-0.2, 0.3);
        for nu in [0.0, 0.5] {
            for d in [1.0, 0.5e6] {
                let hp = HalfPlane::new(1.0, nu, d).unwrap();
                for x in [x1, x2, 0.05] {
                    let u0 = hp.strip_surface_displacement(x1, x2, 1.0, 1.0, x);
                    assert!(u0.ux.is_finite() && u0.uz.is_finite());
                    for dx in [-1e-12, 1e-12] {
                        let u = hp.strip_surface_displacement(x1, x2, 1.0, 1.0, x + dx);
                        let tol = 1e-9 * (u0.uz.abs() + 1.0);
                        assert!((u.ux - u0.ux).abs() <= tol && (u.uz - u0.uz).abs() <= tol, "discontinuous at {x}");
                    }
                }
                let m = uniform_mesh(-0.5, 0.1, 10);
                let mut xs = m.xc.clone();
                xs.extend_from_slice(&m.a); // collocation exactly on element edges
                let bl = hp.influence_blocks(&m.a, &m.b, &xs).unwrap();
                assert!(bl.cxx.iter().chain(&bl.cxz).chain(&bl.czx).chain(&bl.czz).all(|v| v.is_finite()));
                let bu = hp.influence_blocks_uniform(-0.5, 0.1, 10).unwrap();
                assert!(bu.cxx.iter().chain(&bu.cxz).chain(&bu.czx).chain(&bu.czz).all(|v| v.is_finite()));
                if nu == 0.5 {
                    // incompressible: no normal–tangential coupling apart from the datum column term
                    for i in 1..10 {
                        for j in 0..10 {
                            assert_eq!(bu.cxz[i * 10 + j], bu.cxz[j]);
                        }
                    }
                }
            }
        }
        // z → 0⁺ limits of the strip stresses (inside, outside, at an edge: vertical approach)
        for x in [0.05, 0.29, 0.8, -3.0, x1, x2] {
            let s0 = strip_stress(x1, x2, 1.0, 0.0, x, 0.0);
            let se = strip_stress(x1, x2, 1.0, 0.0, x, 1e-13);
            for (a, b) in [(s0.sxx, se.sxx), (s0.szz, se.szz), (s0.txz, se.txz)] {
                assert!(a.is_finite() && (a - b).abs() <= 1e-10, "pressure strip at x={x}: {a} vs {b}");
            }
            let t0 = strip_stress(x1, x2, 0.0, 1.0, x, 0.0);
            let te = strip_stress(x1, x2, 0.0, 1.0, x, 1e-13);
            assert!((t0.szz - te.szz).abs() <= 1e-10 && (t0.txz - te.txz).abs() <= 1e-10, "shear strip at x={x}");
            if x != x1 && x != x2 {
                assert!((t0.sxx - te.sxx).abs() <= 1e-10, "shear strip sxx at x={x}");
            } else {
                assert!(t0.sxx.is_infinite() && !te.sxx.is_nan(), "log singularity at the edge");
            }
        }
        let inside = strip_stress(x1, x2, 2.0, 0.5, 0.0, 0.0);
        assert_eq!((inside.szz, inside.txz), (-2.0, -0.5));
        assert!((inside.sxx - (-2.0 - 2.0 * 0.5 / PI * (0.2_f64 / 0.3).ln())).abs() < 1e-15);
        let edge = strip_stress(x1, x2, 2.0, 0.0, x1, 0.0);
        assert_eq!((edge.szz, edge.txz), (-1.0, 2.0 / PI));
        let nan_free = strip_stress(x1, x2, 1.0, 0.0, x2, 0.0); // q = 0: no 0·∞
        assert!(nan_free.sxx.is_finite() && nan_free.szz.is_finite() && nan_free.txz.is_finite());
        // rigid counter-body: zero blocks
        let rigid = HalfPlane::new(f64::INFINITY, 0.3, 1.0).unwrap().influence_blocks_uniform(-0.5, 0.1, 10).unwrap();
        assert!(rigid.cxx.iter().chain(&rigid.cxz).chain(&rigid.czx).chain(&rigid.czz).all(|&v| v == 0.0));
    }

    /// Timing of the influence-matrix builders (run with
    /// `cargo test --release -- --ignored --nocapture timing`).
    #[test]
    #[ignore]
    fn timing_influence_blocks() {
        use std::hint::black_box;
        use std::time::Instant;
        let n = 1000;
        let hp = HalfPlane::new(210e9, 0.3, 0.05).unwrap();
        let (x0, h) = (-1e-3, 2e-6);
        let m = uniform_mesh(x0, h, n);
        let time = |f: &dyn Fn()| {
            let mut t: Vec<f64> = (0..15)
                .map(|_| {
                    let s = Instant::now();
                    f();
                    s.elapsed().as_secs_f64() * 1e3
                })
                .collect();
            t.sort_by(f64::total_cmp);
            (t[0], t[t.len() / 2])
        };
        let write = time(&|| {
            let v: Vec<Vec<f64>> = (0..4)
                .map(|k| {
                    let mut v = Vec::with_capacity(n * n);
                    v.extend(std::iter::repeat_n(k as f64, n * n));
                    v
                })
                .collect();
            black_box(v);
        });
        let fast = time(&|| {
            black_box(hp.influence_blocks_uniform(black_box(x0), h, n).unwrap());
        });
        let general = time(&|| {
            black_box(hp.influence_blocks(black_box(&m.a), &m.b, &m.xc).unwrap());
        });
        // Reused (already faulted-in) buffers: the plain write vs the fast-path refill.
        let bufs = std::cell::RefCell::new(vec![vec![0.0_f64; n * n]; 4]);
        let write_reuse = time(&|| {
            for (k, v) in bufs.borrow_mut().iter_mut().enumerate() {
                v.clear();
                v.extend(std::iter::repeat_n(k as f64, n * n));
            }
            black_box(&bufs);
        });
        let out = std::cell::RefCell::new(hp.influence_blocks_uniform(x0, h, n).unwrap());
        let fast_reuse = time(&|| {
            hp.influence_blocks_uniform_into(black_box(x0), h, n, &mut out.borrow_mut()).unwrap();
            black_box(&out);
        });
        println!("N={n}: fresh allocation: write 4·N² f64 min {:.2} / median {:.2} ms", write.0, write.1);
        println!("N={n}: fresh allocation: uniform fast path min {:.2} / median {:.2} ms", fast.0, fast.1);
        println!("N={n}: reused buffers:   write 4·N² f64 min {:.2} / median {:.2} ms", write_reuse.0, write_reuse.1);
        println!(
            "N={n}: reused buffers:   uniform fast path (_into) min {:.2} / median {:.2} ms",
            fast_reuse.0, fast_reuse.1
        );
        println!("N={n}: general path (fresh) min {:.2} / median {:.2} ms", general.0, general.1);
    }
    /// The pair's cross blocks (the wheel's plus the counter-body's, [`pair_blocks`]) against
    /// [`HalfPlane::cross_influence_cancels`]: where it says they cancel, they are round-off of the direct blocks
    /// (an independent computation: the blocks themselves, on a non-uniform grid); where it says not, they are not.
    #[test]
    fn cross_influence_cancels_exactly_when_the_pair_blocks_vanish() {
        let m = StripMesh { a: vec![-0.31, -0.2, -0.05, 0.07, 0.2], b: vec![-0.2, -0.05, 0.07, 0.2, 0.29], xc: vec![] };
        let xc: Vec<f64> = m.a.iter().zip(&m.b).map(|(a, b)| 0.5 * (a + b)).collect();
        let rigid = HalfPlane::new(f64::INFINITY, 0.3, 0.5).unwrap();
        let cases: Vec<(&str, HalfPlane, HalfPlane)> = vec![
            (
                "same material and datum",
                HalfPlane::new(1.0, 0.28, 0.5).unwrap(),
                HalfPlane::new(1.0, 0.28, 0.5).unwrap(),
            ),
            (
                "same material, other datum",
                HalfPlane::new(1.0, 0.28, 0.5).unwrap(),
                HalfPlane::new(1.0, 0.28, 0.7).unwrap(),
            ),
            ("other material", HalfPlane::new(1.0, 0.28, 0.5).unwrap(), HalfPlane::new(0.4, 0.35, 0.5).unwrap()),
            ("nu = 0.5 on rigid, plane strain", HalfPlane::new(1.0, 0.5, 0.5).unwrap(), rigid),
            (
                "strip, same material",
                HalfPlane::new(1.0, 0.28, 0.5).unwrap().strip(0.3).unwrap(),
                HalfPlane::new(1.0, 0.28, 0.9).unwrap().strip(0.3).unwrap(),
            ),
            // Dundurs' β = 0 with another material ([`beta_zero_partner`]).
            (
                "strip, beta = 0, other material",
                HalfPlane::new(1.0, 0.2, 0.5).unwrap().strip(0.3).unwrap(),
                beta_zero_partner().strip(0.3).unwrap(),
            ),
            (
                "strip, other material",
                HalfPlane::new(1.0, 0.28, 0.5).unwrap().strip(0.3).unwrap(),
                HalfPlane::new(0.4, 0.35, 0.5).unwrap().strip(0.3).unwrap(),
            ),
            (
                "strip, nu = 0.5 on rigid",
                HalfPlane::new(1.0, 0.5, 0.5).unwrap().strip(0.3).unwrap(),
                rigid.strip(0.3).unwrap(),
            ),
            (
                "strip, nu = 0.3 on rigid",
                HalfPlane::new(1.0, 0.3, 0.5).unwrap().strip(0.3).unwrap(),
                rigid.strip(0.3).unwrap(),
            ),
        ];
        let expect = [true, false, false, false, true, true, false, true, false];
        for ((name, wheel, flat), want) in cases.iter().zip(expect) {
            let pair = pair_blocks(wheel, flat, &m.a, &m.b, &xc).unwrap();
            let direct = pair.czz.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let cross = pair.cxz.iter().chain(&pair.czx).map(|v| v.abs()).fold(0.0, f64::max);
            let counter = flat.youngs_modulus().is_finite().then_some(flat);
            assert_eq!(wheel.cross_influence_cancels(counter), want, "{name}");
            if want {
                assert!(cross <= 1e-14 * direct, "{name}: cross {cross:e} vs direct {direct:e}");
            } else {
                assert!(cross > 1e-6 * direct, "{name}: cross {cross:e} vs direct {direct:e}");
            }
        }
    }

    /// A material of ν = 0.35 whose (1−2ν)(1+ν)/E equals that of (E = 1, ν = 0.2): Dundurs' β = 0 with another
    /// material (0.6·1.2 = 0.72 = 0.3·1.35/E → E = 0.5625).
    fn beta_zero_partner() -> HalfPlane {
        HalfPlane::new(0.5625, 0.35, 0.5).unwrap()
    }
}
