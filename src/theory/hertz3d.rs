//! Hertz's elliptic contact of two elastic bodies (3D; Johnson, *Contact Mechanics* §4.2(b), eqs. 4.36–4.40): the
//! initial separation `h = A x² + B y²` (A, B > 0: the pair's relative curvatures, `A = 1/(2R)` for a sphere of radius
//! R on a flat), contact modulus `E*` (`1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂`), normal load P. The pressure is
//! `p = p₀ √(1 − x²/a² − y²/b²)` on the ellipse of semi-axes a along x and b along y, with (e the eccentricity of the
//! ellipse, e² = 1 − (b/a)² when b ≤ a, K(e), E(e) the complete elliptic integrals of modulus e):
//!
//! ```text
//!   A = (p₀/E*) (b/(e² a²)) [K(e) − E(e)]
//!   B = (p₀/E*) (b/(e² a²)) [(a²/b²) E(e) − K(e)]
//!   δ = (p₀/E*) b K(e),      P = (2/3) π a b p₀
//! ```
//!
//! so `B/A = [(a²/b²) E − K] / [K − E]` fixes e (monotone in e: solved by bisection), and then
//! `a³ = 3 P (K − E) / (2π E* e² A)`. The axis of the smaller curvature carries the longer semi-axis; when A > B the
//! roles of x and y swap. In the circular limit e → 0 (`K − E → π e²/4`, `(a²/b²)E − K → π e²/4`): `a³ = 3PR/(4E*)`,
//! `p₀ = 3P/(2π a²)`, `δ = a²/R` with `R = 1/(2A)` (Johnson eqs. 4.22–4.23): tested.

use super::special::elliptic_e;
use super::special::elliptic_k;
use std::f64::consts::PI;

/// Hertz's elliptic contact: the semi-axes along x and y, the peak pressure and the approach.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Hertz3D {
    /// Semi-axis along x (length).
    pub a_x: f64,
    /// Semi-axis along y (length).
    pub a_y: f64,
    /// Peak pressure p₀ (force / length²).
    pub p0: f64,
    /// The bodies' approach δ (length).
    pub approach: f64,
    /// The normal load P (force).
    pub load: f64,
}

impl Hertz3D {
    /// Hertz's solution for the separation `A x² + B y²` (1/length, both > 0), contact modulus `e_star` and load
    /// `load` (> 0); `None` for arguments out of range.
    pub fn from_load(curv_a: f64, curv_b: f64, e_star: f64, load: f64) -> Option<Hertz3D> {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        if !(ok(curv_a) && ok(curv_b) && ok(e_star) && ok(load)) {
            return None;
        }
        // Work with the smaller curvature along the long semi-axis (a ≥ b), then map back.
        let (small, large) = (curv_a.min(curv_b), curv_a.max(curv_b));
        let ratio = large / small;
        let e = eccentricity(ratio);
        let (k, ee) = (elliptic_k(e), elliptic_e(e));
        let e2 = e * e;
        // (K − E)/e², continuous at e = 0 (π/4), by its series there: K − E = (π/4) e² (1 + 3e²/8 + O(e⁴)).
        let k_minus_e_over_e2 = if e2 < 1e-6 { PI / 4.0 * (1.0 + 3.0 * e2 / 8.0) } else { (k - ee) / e2 };
        let a = (3.0 * load * k_minus_e_over_e2 / (2.0 * PI * e_star * small)).cbrt();
        let b = a * ((1.0 - e) * (1.0 + e)).sqrt();
        let p0 = 3.0 * load / (2.0 * PI * a * b);
        let approach = p0 / e_star * b * k;
        let (a_x, a_y) = if curv_a <= curv_b { (a, b) } else { (b, a) };
        Some(Hertz3D { a_x, a_y, p0, approach, load })
    }

    /// The curvatures `(A, B)` of the separation `A x² + B y²` (1/length) whose Hertz ellipse at contact modulus
    /// `e_star` and load `load` has the semi-axes `a_x` along x and `a_y` along y (the inverse of [`Self::from_load`],
    /// as CONTACT's IPOTCN = −3 poses a contact): the ratio `B/A` by bisection on the semi-axes' ratio (monotone),
    /// then the scale from `a ∝ A^(−1/3)` at a fixed ratio. `None` for arguments out of range.
    pub fn curvatures_for(a_x: f64, a_y: f64, e_star: f64, load: f64) -> Option<(f64, f64)> {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        if !(ok(a_x) && ok(a_y) && ok(e_star) && ok(load)) {
            return None;
        }
        let target = a_x / a_y;
        // a_x/a_y grows with B/A: 1 at B = A; bracket the root in log B/A.
        let ratio_of = |k: f64| Hertz3D::from_load(1.0, k, e_star, load).map(|h| h.a_x / h.a_y);
        let (mut lo, mut hi) = (1e-12_f64, 1e12_f64);
        for _ in 0..200 {
            let mid = (lo * hi).sqrt();
            if ratio_of(mid)? < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let k = (lo * hi).sqrt();
        let curv_a = (Hertz3D::from_load(1.0, k, e_star, load)?.a_x / a_x).powi(3);
        Some((curv_a, k * curv_a))
    }
}

/// The eccentricity e of the contact ellipse whose curvature ratio is `ratio = B/A ≥ 1`: the root of
/// `[(1/(1 − e²)) E(e) − K(e)] / [K(e) − E(e)] = ratio` (1 at e = 0, growing to ∞ as e → 1), by bisection.
fn eccentricity(ratio: f64) -> f64 {
    if ratio <= 1.0 + 1e-15 {
        return 0.0;
    }
    let f = |e: f64| {
        let (k, ee) = (elliptic_k(e), elliptic_e(e));
        (ee / ((1.0 - e) * (1.0 + e)) - k) / (k - ee) - ratio
    };
    let (mut lo, mut hi) = (1e-8_f64, 1.0 - 1e-15);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-16 {
            break;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The circle (Johnson eqs. 4.22–4.23, a sphere of radius R on a flat): a³ = 3PR/(4E*), p₀ = 3P/(2πa²), δ = a²/R.
    #[test]
    fn the_circle_is_hertz_circular_contact() {
        let (r, e_star, p) = (10.0, 1.1e5, 500.0);
        let h = Hertz3D::from_load(0.5 / r, 0.5 / r, e_star, p).unwrap();
        let a = (3.0 * p * r / (4.0 * e_star)).cbrt();
        assert!((h.a_x - a).abs() <= 1e-12 * a && (h.a_y - a).abs() <= 1e-12 * a);
        assert!((h.p0 - 3.0 * p / (2.0 * PI * a * a)).abs() <= 1e-12 * h.p0);
        assert!((h.approach - a * a / r).abs() <= 1e-12 * h.approach);
    }

    /// An ellipse: the defining relations above hold at the answer (an independent check of the root and of a, b:
    /// the curvatures recomputed from (a, b, p₀) by the formulas as printed); swapping A and B swaps the axes; the
    /// continuity at the circle (a ratio of 1 + 1e-9).
    #[test]
    fn an_ellipse_satisfies_hertz_relations() {
        let (e_star, p) = (2.3e5, 1.0e4);
        for (ca, cb) in [(1.0 / 200.0, 1.0 / 60.0), (1.0 / 50.0, 1.0 / 450.0), (0.01, 0.09)] {
            let h = Hertz3D::from_load(ca, cb, e_star, p).unwrap();
            let (a, b) = (h.a_x.max(h.a_y), h.a_x.min(h.a_y));
            let e2 = 1.0 - (b / a) * (b / a);
            let e = e2.sqrt();
            let (k, ee) = (elliptic_k(e), elliptic_e(e));
            let small = h.p0 / e_star * b / (e2 * a * a) * (k - ee);
            let large = h.p0 / e_star * b / (e2 * a * a) * (a * a / (b * b) * ee - k);
            assert!((small - ca.min(cb)).abs() <= 1e-9 * small, "{small} vs {}", ca.min(cb));
            assert!((large - ca.max(cb)).abs() <= 1e-9 * large, "{large} vs {}", ca.max(cb));
            assert!((2.0 / 3.0 * PI * a * b * h.p0 - p).abs() <= 1e-12 * p);
            let swapped = Hertz3D::from_load(cb, ca, e_star, p).unwrap();
            assert!((swapped.a_x - h.a_y).abs() <= 1e-12 * a && (swapped.a_y - h.a_x).abs() <= 1e-12 * a);
            assert_eq!(ca < cb, h.a_x > h.a_y, "the smaller curvature carries the longer axis");
        }
        let c = Hertz3D::from_load(0.05, 0.05, 1e5, 100.0).unwrap();
        let n = Hertz3D::from_load(0.05, 0.05 * (1.0 + 1e-9), 1e5, 100.0).unwrap();
        assert!((c.p0 - n.p0).abs() <= 1e-8 * c.p0 && (c.a_x - n.a_x).abs() <= 1e-8 * c.a_x);
        assert!(Hertz3D::from_load(0.0, 1.0, 1.0, 1.0).is_none());
    }

    /// `curvatures_for` inverts `from_load`: the semi-axes of the curvatures it returns are those asked for, at
    /// a/b from 0.1 to 10 (a round trip through the closed form), to 1e-8 (measured 2.3e-9 at a/b = 1, where a/b is
    /// flat in the eccentricity that `from_load` finds by bisection).
    #[test]
    fn curvatures_for_inverts_from_load() {
        for (ax, ay) in [(8.0, 4.0), (6.304, 12.61), (1.0, 1.0), (0.3, 3.0), (10.0, 1.0)] {
            let (ca, cb) = Hertz3D::curvatures_for(ax, ay, 113_888.0, 82_000.0).unwrap();
            let h = Hertz3D::from_load(ca, cb, 113_888.0, 82_000.0).unwrap();
            assert!((h.a_x - ax).abs() <= 1e-8 * ax && (h.a_y - ay).abs() <= 1e-8 * ay, "{ax} {ay}: {h:?}");
        }
        assert!(Hertz3D::curvatures_for(-1.0, 1.0, 1.0, 1.0).is_none());
    }
}
