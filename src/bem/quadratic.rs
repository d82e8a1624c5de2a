//! Discontinuous quadratic boundary elements on circular arcs, and the element integrals of the Kelvin kernels.
//!
//! Each element carries three collocation nodes at the intrinsic coordinates [`XI_NODES`] = (−2/3, 0, 2/3), and
//! displacements/tractions are interpolated by the Lagrange [`shape`] functions through them. Geometry is exact:
//! an arc of a circle parametrised linearly in angle, so the Jacobian ds/dξ is constant.
//!
//! # Quadrature strategy (`integrate`)
//! * **Off-element source** (`self_node = None`): the integrands are analytic in ξ except where r² = 0 continued
//!   to complex ξ. For an arc of centre c and radius R and a source at polar position (ρ_s, φ) about c, these
//!   singularities are exactly θ* = φ ± i ln(ρ_s / R) (+ 2πk), i.e. ξ* = (θ* − θm)/h with h = (θ1 − θ0)/2. The
//!   interval is halved recursively until, on each piece, the Bernstein-ellipse parameter ρ of the nearest
//!   singularity (ρ + 1/ρ = |z − 1| + |z + 1|, z the singularity in the piece's normalised coordinate) exceeds
//!   [`RHO_ACCEPT`]; the piece then gets a Gauss–Legendre rule of n = ⌈K / ln ρ⌉ points (error ∝ ρ^(−2n)).
//!   Far sources therefore get a single 6–8 point rule, near ones (e.g. a neighbour's node at 1/6 of an element
//!   length) a few pieces.
//! * **Self source** (`self_node = Some(i)`): the interval is split at ξ_s = XI_NODES\[i\]. The h blocks j ≠ i
//!   are analytic on each side (N_j vanishes at the source, r = 2R|sin(h(ξ − ξ_s)/2)| is analytic on each side);
//!   h\[i\] is returned as zero (set by the caller from rigid-body motion). For g,
//!   ln r = ln|ξ − ξ_s| + ln(r/|ξ − ξ_s|): the first part (times the polynomial N_j) is integrated exactly with the
//!   logarithmic Gauss rule of `crate::bem::quadrature::lg`, the smooth remainder with Gauss–Legendre (same
//!   adaptive rule, singularities at the periodic images ξ_s ± 2π/h). Field-minus-source vectors are formed with
//!   the chord formula, so no cancellation occurs near the source.
//!
//! No allocation happens in `integrate` (quadrature rules are cached statics).

use super::kelvin::Kelvin;
use super::quadrature::{gl, lg};
pub use crate::mesh::{ArcElement, XI_NODES};
use std::f64::consts::PI;

/// Denominators of the Lagrange basis through [`XI_NODES`]: ∏_{m≠j} (ξ_j − ξ_m).
const LAGRANGE_DEN: [f64; 3] = [
    (XI_NODES[0] - XI_NODES[1]) * (XI_NODES[0] - XI_NODES[2]),
    (XI_NODES[1] - XI_NODES[0]) * (XI_NODES[1] - XI_NODES[2]),
    (XI_NODES[2] - XI_NODES[0]) * (XI_NODES[2] - XI_NODES[1]),
];

/// Lagrange shape functions through [`XI_NODES`] at intrinsic coordinate `xi`: `[N0, N1, N2]`, with
/// N_j(XI_NODES\[i\]) = δ_ij and Σ N_j = 1. Evaluated in factored form, so N_j is accurate (relatively) near its
/// zeros.
#[inline]
pub fn shape(xi: f64) -> [f64; 3] {
    let d0 = xi - XI_NODES[0];
    let d1 = xi - XI_NODES[1];
    let d2 = xi - XI_NODES[2];
    [d1 * d2 / LAGRANGE_DEN[0], d0 * d2 / LAGRANGE_DEN[1], d0 * d1 / LAGRANGE_DEN[2]]
}

/// Three 2×2 blocks, one per element node j: `blocks[j][l][k]` (l = load direction at the source, k = component at
/// the field point), as returned by `integrate`.
pub type NodeBlocks = [[[f64; 2]; 2]; 3];

/// Pieces are integrated without further halving once the Bernstein-ellipse parameter of the nearest integrand
/// singularity reaches this value (then at most ⌈K / ln ρ⌉ ≈ 16 Gauss points are used on the piece).
pub const RHO_ACCEPT: f64 = 3.0;

/// Gauss order constant: n = ⌈ORDER_K / ln ρ⌉, nominal ρ^(−2n) = e^(−2K) ≈ 1e-18; calibrated so that the
/// actual error (which carries a large constant: the kernels have double poles at the singularities) is ≲ 1e-13.
const ORDER_K: f64 = 20.5;
/// Minimum and maximum Gauss orders per piece.
const N_MIN: usize = 6;
const N_MAX: usize = 24;
/// Maximum halving depth of the adaptive subdivision.
const MAX_DEPTH: u32 = 40;

/// Integrals of the Kelvin kernels times the shape functions over one element, for one source point:
///
/// ```text
/// h[j][l][k] = ∫ T*_lk(x(ξ), n(ξ); source) N_j(ξ) J dξ,    g[j][l][k] = ∫ U*_lk(x(ξ); source) N_j(ξ) J dξ
/// ```
///
/// (kernels from [`Kelvin::t`] / [`Kelvin::u`], J = [`ArcElement::jacobian`]). Returns `(h, g)`.
///
/// * `self_node = Some(i)`: the source is this element's collocation node i (`source` must equal
///   `el.nodes()[i]` up to rounding; the kernels are evaluated with the exact chord x(ξ) − x(ξ_i)). `h[i]` is
///   returned as zeros (the strongly singular block is set by the caller from the rigid-body condition); the other
///   h blocks and all g blocks (weakly, log-singular) are integrated to ~1e-14 relative.
/// * `self_node = None`: the source is off the element (it must not lie on it); near sources are handled by
///   adaptive subdivision, accuracy ~1e-13 relative to the largest entry of the block set.
///
/// An internal kernel of the assembly, which passes `self_node = Some(i)` only with i < 3 and a source at that node
/// (another would panic).
pub(crate) fn integrate(
    el: &ArcElement,
    source: [f64; 2],
    self_node: Option<usize>,
    k: &Kelvin,
) -> (NodeBlocks, NodeBlocks) {
    let mut h = [[[0.0; 2]; 2]; 3];
    let mut g = [[[0.0; 2]; 2]; 3];
    match self_node {
        None => integrate_off_element(el, source, k, &mut h, &mut g),
        Some(i) => {
            assert!(i < 3, "integrate: self_node must be 0, 1 or 2");
            let xs = XI_NODES[i];
            debug_assert!({
                let p = el.position(xs);
                let d = ((p[0] - source[0]).powi(2) + (p[1] - source[1]).powi(2)).sqrt();
                d <= 1e-9 * (el.radius + p[0].abs() + p[1].abs())
            });
            for (a, b) in [(-1.0, xs), (xs, 1.0)] {
                integrate_self_regular(el, i, (a, b), k, &mut h, &mut g);
                add_self_log_part(el, xs, (a, b), k, &mut g);
            }
        }
    }
    (h, g)
}

/// Add one quadrature point's contribution `t·N_j·w·J` to `h` and `u·N_j·w·J` to `g` for every node j, the
/// h block of node `skip_h` excepted (the self node's strongly singular block, set by the caller).
#[inline]
fn accumulate(
    h: &mut NodeBlocks,
    g: &mut NodeBlocks,
    (t, u): (&[[f64; 2]; 2], &[[f64; 2]; 2]),
    nn: [f64; 3],
    wj: f64,
    skip_h: Option<usize>,
) {
    for j in 0..3 {
        let f = nn[j] * wj;
        let add_h = skip_h != Some(j);
        for l in 0..2 {
            for m in 0..2 {
                if add_h {
                    h[j][l][m] += t[l][m] * f;
                }
                g[j][l][m] += u[l][m] * f;
            }
        }
    }
}

/// The off-element case of [`integrate`]: adaptive Gauss–Legendre guided by the integrands' complex
/// singularities ([`off_element_singularities`]), all h and g blocks added to `h`, `g`.
fn integrate_off_element(el: &ArcElement, source: [f64; 2], k: &Kelvin, h: &mut NodeBlocks, g: &mut NodeBlocks) {
    let (jac, hang, thm, sg, r_el) = (el.jacobian(), el.half_angle(), el.theta_mid(), el.orientation(), el.radius);
    let sing = off_element_singularities(el, source);
    let cs = [el.centre[0] - source[0], el.centre[1] - source[1]];
    adaptive(-1.0, 1.0, &sing, MAX_DEPTH, &mut |xi, w| {
        let (s, c) = (thm + hang * xi).sin_cos();
        // r = x − source = (centre − source) + R (cos θ, sin θ); kernels depend on x − ξ only.
        let r = [cs[0] + r_el * c, cs[1] + r_el * s];
        let n = [sg * c, sg * s];
        let t = k.t(r, n, [0.0, 0.0]);
        let u = k.u(r, [0.0, 0.0]);
        accumulate(h, g, (&t, &u), shape(xi), w * jac, None);
    });
}

/// The regular part of the self case of [`integrate`] on the side `(a, b)` of the source node `i`: adaptive
/// Gauss–Legendre of T* (h blocks j ≠ i) and of U* less its `ln|ξ − ξ_s|` part (added by [`add_self_log_part`]),
/// with the field-minus-source vector formed by the chord formula.
fn integrate_self_regular(
    el: &ArcElement,
    i: usize,
    (a, b): (f64, f64),
    k: &Kelvin,
    h: &mut NodeBlocks,
    g: &mut NodeBlocks,
) {
    let (jac, hang, thm, sg, r_el) = (el.jacobian(), el.half_angle(), el.theta_mid(), el.orientation(), el.radius);
    let xs = XI_NODES[i];
    let ths = thm + hang * xs;
    // Periodic images of the source along the circle: θ = θ_s ± 2π.
    let period = 2.0 * PI / hang.abs();
    let sing = [[xs - period, 0.0], [xs + period, 0.0], [f64::INFINITY, 0.0]];
    let log_coef = k.cu * k.a34;
    adaptive(a, b, &sing, MAX_DEPTH, &mut |xi, w| {
        let th = thm + hang * xi;
        let (s, c) = th.sin_cos();
        // Chord x(ξ) − x(ξ_s) = 2R sin(Δ/2) (−sin θ̄, cos θ̄), Δ = θ − θ_s, θ̄ = (θ + θ_s)/2.
        let (sb, cb) = (0.5 * (th + ths)).sin_cos();
        let amp = 2.0 * r_el * (0.5 * (th - ths)).sin();
        let r = [-amp * sb, amp * cb];
        let n = [sg * c, sg * s];
        let t = k.t(r, n, [0.0, 0.0]);
        let mut u = k.u(r, [0.0, 0.0]);
        // Remove the ln|ξ − ξ_s| part (integrated by `add_self_log_part`): U* has −cu·a34·ln r δ_lk.
        let lnd = log_coef * (xi - xs).abs().ln();
        u[0][0] += lnd;
        u[1][1] += lnd;
        accumulate(h, g, (&t, &u), shape(xi), w * jac, Some(i));
    });
}

/// The singular part of the self case of [`integrate`] on the side `(a, b)` of the source at `xs`, added to the
/// diagonal of the g blocks: −cu·a34·δ_lk ∫_a^b ln|ξ − ξ_s| N_j(ξ) J dξ. With ξ = ξ_s ± L τ (L = b − a,
/// τ ∈ [0, 1]): ∫ ln(Lτ) N_j L dτ = L ln L ∫₀¹ N_j dτ − L ∫₀¹ (−ln τ) N_j dτ; both exact for the quadratic N_j
/// (2-point Gauss–Legendre and logarithmic Gauss rules).
fn add_self_log_part(el: &ArcElement, xs: f64, (a, b): (f64, f64), k: &Kelvin, g: &mut NodeBlocks) {
    let jac = el.jacobian();
    let log_coef = k.cu * k.a34;
    let len = b - a;
    let dir = if a < xs { -1.0 } else { 1.0 };
    let mut plain = [0.0; 3];
    for (tq, wq) in gl(2).iter() {
        let nn = shape(xs + dir * len * 0.5 * (tq + 1.0));
        for j in 0..3 {
            plain[j] += 0.5 * wq * nn[j];
        }
    }
    let mut logw = [0.0; 3];
    for (tq, wq) in lg(2).iter() {
        let nn = shape(xs + dir * len * tq);
        for j in 0..3 {
            logw[j] += wq * nn[j];
        }
    }
    for j in 0..3 {
        let val = -log_coef * jac * len * (len.ln() * plain[j] - logw[j]);
        g[j][0][0] += val;
        g[j][1][1] += val;
    }
}

/// Complex singularities (re, im) of the integrands in the element's ξ coordinate for an off-element source:
/// ξ* = (φ + 2πk − θm ± i ln(ρ_s/R)) / h, k = −1, 0, 1 (only |im| matters for the Bernstein parameter).
fn off_element_singularities(el: &ArcElement, source: [f64; 2]) -> [[f64; 2]; 3] {
    let dx = source[0] - el.centre[0];
    let dy = source[1] - el.centre[1];
    let rho_s = dx.hypot(dy);
    let h = el.half_angle();
    let thm = el.theta_mid();
    if rho_s <= 1e-300 {
        // Source at the centre: the integrands are entire in ξ.
        return [[f64::INFINITY, 0.0]; 3];
    }
    let im = ((rho_s / el.radius).ln() / h).abs();
    // φ reduced to within π of θm.
    let phi = dy.atan2(dx);
    let dphi = (phi - thm).rem_euclid(2.0 * PI);
    let dphi = if dphi > PI { dphi - 2.0 * PI } else { dphi };
    [[(dphi - 2.0 * PI) / h, im], [dphi / h, im], [(dphi + 2.0 * PI) / h, im]]
}

/// Bernstein-ellipse parameter ρ ≥ 1 of the point `z` (re, im) relative to the interval [−1, 1]:
/// ρ + 1/ρ = |z − 1| + |z + 1|.
#[inline]
fn bernstein_rho(zr: f64, zi: f64) -> f64 {
    let sum = (zr - 1.0).hypot(zi) + (zr + 1.0).hypot(zi);
    0.5 * (sum + (sum * sum - 4.0).max(0.0).sqrt())
}

/// Adaptive Gauss–Legendre on [a, b]: calls `f(ξ, weight)` for every quadrature point. `sing` are the complex
/// singularities of the integrand in the same coordinate (entries with infinite re are ignored).
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
        let n = if rho.is_finite() { ((ORDER_K / rho.ln()).ceil() as usize).clamp(N_MIN, N_MAX) } else { N_MIN };
        for (t, w) in gl(n).iter() {
            f(mid + half * t, half * w);
        }
    } else {
        adaptive(a, mid, sing, depth - 1, f);
        adaptive(mid, b, sing, depth - 1, f);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bem::quadrature::gauss_legendre;

    fn kel() -> Kelvin {
        Kelvin::new(1.0, 0.3)
    }

    /// Element 0 of an 8-element CCW unit circle: θ ∈ [0, π/4].
    fn el8() -> ArcElement {
        ArcElement { centre: [0.0, 0.0], radius: 1.0, theta0: 0.0, theta1: PI / 4.0 }
    }

    /// Brute force: composite Gauss rule, `pieces` equal sub-intervals of ξ ∈ [−1, 1] × `npts` points, kernels
    /// evaluated directly from `el.position`/`el.normal` and `Kelvin::{t, u}` at the given source.
    fn brute(el: &ArcElement, src: [f64; 2], k: &Kelvin, pieces: usize, npts: usize) -> (NodeBlocks, NodeBlocks) {
        let rule = gauss_legendre(npts).unwrap();
        let mut h = [[[0.0; 2]; 2]; 3];
        let mut g = [[[0.0; 2]; 2]; 3];
        let len = 2.0 / pieces as f64;
        for p in 0..pieces {
            let a = -1.0 + p as f64 * len;
            for (t, w) in rule.iter() {
                let xi = a + 0.5 * len * (t + 1.0);
                let wj = 0.5 * len * w * el.jacobian();
                let x = el.position(xi);
                let tt = k.t(x, el.normal(xi), src);
                let uu = k.u(x, src);
                let nn = shape(xi);
                for j in 0..3 {
                    for l in 0..2 {
                        for m in 0..2 {
                            h[j][l][m] += tt[l][m] * nn[j] * wj;
                            g[j][l][m] += uu[l][m] * nn[j] * wj;
                        }
                    }
                }
            }
        }
        (h, g)
    }

    /// max |a − b| / max |b| over all 12 entries (error relative to the block set's scale).
    fn rel_err(a: &NodeBlocks, b: &NodeBlocks) -> f64 {
        let mut num: f64 = 0.0;
        let mut den: f64 = 0.0;
        for j in 0..3 {
            for l in 0..2 {
                for m in 0..2 {
                    num = num.max((a[j][l][m] - b[j][l][m]).abs());
                    den = den.max(b[j][l][m].abs());
                }
            }
        }
        num / den
    }

    /// Shape functions: Kronecker property at the nodes and partition of unity (both exact properties of the
    /// Lagrange basis); node weights (0.75, 0.5, 0.75)·J sum to the arc length R|Δθ|, and agree with a direct
    /// Gauss integration of N_j.
    #[test]
    fn shape_functions_and_node_weights() {
        for (i, &xi) in XI_NODES.iter().enumerate() {
            let n = shape(xi);
            for (j, &v) in n.iter().enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((v - want).abs() < 1e-15, "N_{j}(xi_{i}) = {v}");
            }
        }
        for p in 0..=200 {
            let xi = -1.0 + p as f64 / 100.0;
            let s: f64 = shape(xi).iter().sum();
            assert!((s - 1.0).abs() < 1e-14);
        }
        let el = ArcElement { centre: [0.3, -0.2], radius: 2.5, theta0: 1.0, theta1: 0.6 };
        let w = el.node_weights();
        let arc = 2.5 * 0.4;
        assert!((w.iter().sum::<f64>() - arc).abs() < 1e-15);
        let mut direct = [0.0; 3];
        for (t, wq) in gauss_legendre(3).unwrap().iter() {
            let n = shape(t);
            for j in 0..3 {
                direct[j] += wq * n[j] * el.jacobian();
            }
        }
        for j in 0..3 {
            assert!((direct[j] - w[j]).abs() < 1e-15);
        }
    }

    /// Geometry: positions on the circle, normal = +radial for CCW and −radial for CW (brief's convention
    /// n = (t_y, −t_x) with t the unit tangent, checked against a finite-difference tangent).
    #[test]
    fn geometry_and_normals() {
        for (t0, t1, sgn) in [(0.2, 0.9, 1.0), (0.9, 0.2, -1.0)] {
            let el = ArcElement { centre: [1.0, 2.0], radius: 0.7, theta0: t0, theta1: t1 };
            assert!((el.position(-1.0)[0] - (1.0 + 0.7 * f64::cos(t0))).abs() < 1e-15);
            assert!((el.position(1.0)[1] - (2.0 + 0.7 * f64::sin(t1))).abs() < 1e-15);
            for xi in [-0.9, 0.1, 0.8] {
                let e = 1e-6;
                let (p, q) = (el.position(xi + e), el.position(xi - e));
                let tl = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
                let tan = [(p[0] - q[0]) / tl, (p[1] - q[1]) / tl];
                let n = el.normal(xi);
                assert!((n[0] - tan[1]).abs() < 1e-8 && (n[1] + tan[0]).abs() < 1e-8);
                let x = el.position(xi);
                let radial = [(x[0] - 1.0) / 0.7, (x[1] - 2.0) / 0.7];
                assert!((n[0] - sgn * radial[0]).abs() < 1e-14);
                assert!((n[1] - sgn * radial[1]).abs() < 1e-14);
                // ds/dξ from finite differences
                assert!((tl / (2.0 * e) - el.jacobian()).abs() < 1e-8);
            }
        }
    }

    /// Far and near off-element sources against a brute-force composite Gauss rule (400 pieces × 20 points; for
    /// the nearest source here the pieces are ≥ 8 piece-lengths away, so the reference is converged to ~1e-16).
    #[test]
    fn off_element_vs_brute_force() {
        let k = kel();
        let el = el8();
        let len = el.length();
        let neighbour_node =
            ArcElement { centre: [0.0, 0.0], radius: 1.0, theta0: PI / 4.0, theta1: PI / 2.0 }.nodes()[0];
        let cases: [(&str, [f64; 2]); 5] = [
            ("far (3 lengths)", [1.0 + 3.0 * len, 0.1]),
            ("interior point", [0.2, 0.3]),
            ("neighbour node, 1/6 length", neighbour_node),
            ("0.05 length inside", {
                let p = el.position(0.3);
                [p[0] * (1.0 - 0.05 * len), p[1] * (1.0 - 0.05 * len)]
            }),
            ("0.05 length outside, near end", {
                let p = el.position(1.0);
                [p[0] * (1.0 + 0.05 * len), p[1] * (1.0 + 0.05 * len)]
            }),
        ];
        for (name, src) in cases {
            let (h, g) = integrate(&el, src, None, &k);
            let (hr, gr) = brute(&el, src, &k, 400, 20);
            let (eh, eg) = (rel_err(&h, &hr), rel_err(&g, &gr));
            eprintln!("off-element {name}: rel err h {eh:.2e}, g {eg:.2e}");
            assert!(eh < 1e-12 && eg < 1e-12, "{name}: {eh:e} {eg:e}");
        }
    }

    /// Sweep of sources at distances 0.01–10 element lengths from several points of the element, inside and
    /// outside the circle, on a CCW and a CW (hole) element: brute-force composite reference (1000 pieces × 16
    /// points, converged for distances ≥ 0.01 length).
    #[test]
    fn off_element_sweep() {
        let k = Kelvin::new(1.0, 0.45);
        let els = [el8(), ArcElement { centre: [0.5, -0.25], radius: 0.3, theta0: 2.0, theta1: 2.0 - PI / 6.0 }];
        let mut worst: f64 = 0.0;
        for el in els {
            let len = el.length();
            for xi0 in [-1.0, -0.55, 0.0, 0.9, 1.0] {
                let p = el.position(xi0);
                for dist in [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0] {
                    for side in [-1.0, 1.0] {
                        let rad = [(p[0] - el.centre[0]) / el.radius, (p[1] - el.centre[1]) / el.radius];
                        let src = [p[0] + side * dist * len * rad[0], p[1] + side * dist * len * rad[1]];
                        let (h, g) = integrate(&el, src, None, &k);
                        let (hr, gr) = brute(&el, src, &k, 1000, 16);
                        let e = rel_err(&h, &hr).max(rel_err(&g, &gr));
                        worst = worst.max(e);
                        assert!(e < 1e-12, "xi0 {xi0} dist {dist} side {side}: {e:e}");
                    }
                }
            }
        }
        eprintln!("off-element sweep worst rel err: {worst:.2e}");
    }

    /// Self case against an independent reference: on each side of ξ_s substitute ξ = ξ_s ± L s⁶ (s ∈ [0, 1]),
    /// which turns the log singularity into s⁵ ln s (integrable, C⁴), then a fine composite Gauss rule (200 × 20)
    /// on s, with the kernels evaluated directly by `Kelvin::{t, u}` (no singularity subtraction; the field-minus-
    /// source vector from the exact chord formula, since ξ − ξ_s reaches 1e-30 here). h[i] must be exactly zero.
    #[test]
    fn self_case_vs_substitution_reference() {
        let k = kel();
        let els = [el8(), ArcElement { centre: [0.4, 0.1], radius: 2.0, theta0: 1.0, theta1: 0.2 }];
        let rule = gauss_legendre(20).unwrap();
        let pieces = 200;
        for el in els {
            for i in 0..3 {
                let xs = XI_NODES[i];
                let src = el.position(xs);
                let (h, g) = integrate(&el, src, Some(i), &k);
                assert_eq!(h[i], [[0.0; 2]; 2]);
                let mut hr = [[[0.0; 2]; 2]; 3];
                let mut gr = [[[0.0; 2]; 2]; 3];
                for (a, b) in [(-1.0, xs), (xs, 1.0)] {
                    let lside: f64 = b - a;
                    let dir = if a < xs { -1.0 } else { 1.0 };
                    for p in 0..pieces {
                        let s0 = p as f64 / pieces as f64;
                        let ds = 1.0 / pieces as f64;
                        for (t, w) in rule.iter() {
                            let s = s0 + 0.5 * ds * (t + 1.0);
                            let u = dir * lside * s.powi(6);
                            let xi = xs + u;
                            let wj = 0.5 * ds * w * lside * 6.0 * s.powi(5) * el.jacobian();
                            // x − src without cancellation (u can be ~1e-30): chord of angle Δ = h u from θ_s,
                            // 2R sin(Δ/2) (−sin θ̄, cos θ̄) with θ̄ = θ_s + Δ/2.
                            let dth = 0.5 * (el.theta1 - el.theta0) * u;
                            let thb = el.theta(xs) + 0.5 * dth;
                            let amp = 2.0 * el.radius * (0.5 * dth).sin();
                            let r = [-amp * thb.sin(), amp * thb.cos()];
                            let tt = k.t(r, el.normal(xi), [0.0, 0.0]);
                            let uu = k.u(r, [0.0, 0.0]);
                            let nn = shape(xi);
                            for j in 0..3 {
                                for l in 0..2 {
                                    for m in 0..2 {
                                        if j != i {
                                            hr[j][l][m] += tt[l][m] * nn[j] * wj;
                                        }
                                        gr[j][l][m] += uu[l][m] * nn[j] * wj;
                                    }
                                }
                            }
                        }
                    }
                }
                let (eh, eg) = (rel_err(&h, &hr), rel_err(&g, &gr));
                eprintln!("self node {i} (R={}): rel err h {eh:.2e}, g {eg:.2e}", el.radius);
                assert!(eh < 1e-12 && eg < 1e-12, "node {i}: {eh:e} {eg:e}");
            }
        }
    }

    /// Rigid-body identity: with c_lk = δ_lk at an interior source, a rigid translation (u = const, t = 0) in
    /// c u + ∫T* u ds = ∫U* t ds gives ∫_Γ T*_lk ds = −δ_lk (kelvin.rs convention, T* with the outward normal);
    /// for an exterior source (c = 0) the sum is 0. Checked on a CCW unit circle (8 elements) and on an annulus
    /// (outer CCW, hole CW).
    #[test]
    fn rigid_body_identity_closed_boundaries() {
        let k = kel();
        let circle: Vec<ArcElement> = (0..8)
            .map(|e| ArcElement {
                centre: [0.0, 0.0],
                radius: 1.0,
                theta0: e as f64 * PI / 4.0,
                theta1: (e + 1) as f64 * PI / 4.0,
            })
            .collect();
        let mut annulus: Vec<ArcElement> = circle.clone();
        annulus.extend((0..6).map(|e| ArcElement {
            centre: [0.0, 0.0],
            radius: 0.4,
            theta0: -(e as f64) * PI / 3.0,
            theta1: -((e + 1) as f64) * PI / 3.0,
        }));
        let sum_h = |els: &[ArcElement], src: [f64; 2]| {
            let mut s = [[0.0; 2]; 2];
            for el in els {
                let (h, _) = integrate(el, src, None, &k);
                for hj in h {
                    for l in 0..2 {
                        for m in 0..2 {
                            s[l][m] += hj[l][m];
                        }
                    }
                }
            }
            s
        };
        let cases: [(&str, &[ArcElement], [f64; 2], f64); 6] = [
            ("circle, interior", &circle, [0.3, -0.2], -1.0),
            ("circle, centre", &circle, [0.0, 0.0], -1.0),
            ("circle, near boundary", &circle, [0.0, 0.97], -1.0),
            ("circle, exterior", &circle, [1.3, 0.4], 0.0),
            ("annulus, in material", &annulus, [0.55, 0.3], -1.0),
            ("annulus, in hole", &annulus, [0.1, -0.1], 0.0),
        ];
        for (name, els, src, diag) in cases {
            let s = sum_h(els, src);
            let err = (s[0][0] - diag).abs().max((s[1][1] - diag).abs()).max(s[0][1].abs()).max(s[1][0].abs());
            eprintln!("rigid body {name}: sum h = {s:?}, err {err:.2e}");
            assert!(err < 1e-10, "{name}: {s:?}");
        }
    }
}
