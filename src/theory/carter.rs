//! Carter, steady rolling with traction, β = 0 ([`carter_traction`], [`carter_creepage`], [`carter_slip`])
//!
//! Rolling towards `+x` (leading edge `x = +a`); in the contact frame material flows from `+x` to
//! `−x` at speed `V`. A cylinder surface particle moves at `−V1(1 + ∂u_x/∂x)`, a flat particle at
//! `−V2`, so the slip velocity of the cylinder relative to the flat, normalised by `V`, is
//!
//! ```text
//!   s(x) = ξ − ∂u_x/∂x,        ξ = (V2 − V1)/V = (V − ΩR)/V   (ground frame: centre speed V, spin Ω)
//! ```
//!
//! with `u_x` the cylinder surface displacement and `∂u_x/∂x = −(2/(πE*)) PV∫ q(t)/(x − t) dt`
//! (`E*` of the cylinder if the flat is rigid; β = 0 so `p` contributes nothing). Coulomb:
//! `q = −μp sgn(s)` where `s ≠ 0`, `|q| ≤ μp` where `s = 0`. The solution (Carter 1926; Johnson
//! §8.2) is, with σ = sgn(Q), `c/a = √(1 − |Q|/(μP))`, `d = a − c`:
//!
//! ```text
//!   stick a − 2c < x < a :  q = σ μ p0 [ √(1 − x²/a²) − (c/a) √(1 − (x − d)²/c²) ],  s = 0
//!   slip −a < x < a − 2c :  q = σ μ p(x),   s = −σ (μ/R) √((x − d)² − c²)
//!   creepage            :  ξ = −σ (μa/R) (1 − √(1 − |Q|/(μP)))
//! ```
//!
//! i.e. `|ξ| = (μa/R)(1 − √(1 − |Q|/(μP)))`, saturating (full slip) at `|ξ| ≥ μa/R`.
//! **Sign relation:** ξ and Q have opposite signs. `Q > 0` (force on the cylinder along the rolling
//! direction: driving) ⇔ `ξ < 0` (ΩR > V, the wheel spins faster than free rolling); braking
//! `Q < 0` ⇔ `ξ > 0`. The convention is consistent: in the slip zone `s` has the sign −σ, opposite
//! to `q`, as Coulomb requires. Placing the stick zone at the trailing edge instead gives `s` of the
//! same sign as `q` there (inadmissible) — so the leading-edge stick zone is forced by this
//! convention (tests `carter_*`).

use super::cattaneo::cattaneo_c_over_a;
use super::hertz::Hertz2D;
use super::special::semi;

/// Carter stick-zone ratio `c/a = √(1 − |Q|/(μP))` (stick zone `a − 2c < x < a`).
pub fn carter_c_over_a(q_over_mu_p: f64) -> f64 {
    cattaneo_c_over_a(q_over_mu_p)
}

/// Carter stick-zone ratio from the creepage: `c/a = 1 − |ξ|R/(μa)` (0 at and beyond full slip, `|ξ| ≥ μa/R`).
/// `r` is the (effective) radius.
pub fn carter_c_over_a_of_creepage(h: &Hertz2D, mu: f64, r: f64, xi: f64) -> f64 {
    (1.0 - xi.abs() * r / (mu * h.a)).max(0.0)
}

/// Carter stick zone `(c, d)` for the stick-zone ratio `c_over_a`, rolling towards `+x`: half-width `c = (c/a) a`,
/// centred at `d = a − c` (touching the leading edge `x = a`).
pub fn carter_stick_zone(h: &Hertz2D, c_over_a: f64) -> (f64, f64) {
    let c = h.a * c_over_a;
    (c, h.a - c)
}

/// Carter traction on the cylinder, rolling towards `+x`, total tangential force `Q` on the
/// cylinder (|Q| ≥ μP gives full slip `sgn(Q) μ p`). See module docs §4. Rolling towards `−x`, the traction at `x`
/// is this one at `−x` (the problem mirrored, with the same force).
pub fn carter_traction(h: &Hertz2D, mu: f64, q_force: f64, x: f64) -> f64 {
    let (c, d) = carter_stick_zone(h, carter_c_over_a(q_force / (mu * h.load)));
    q_force.signum() * mu * h.p0 / h.a * (semi(x, h.a) - semi(x - d, c))
}

/// Carter creepage `ξ = (V − ΩR)/V` for the force `Q` on the cylinder (|Q| ≤ μP):
/// `ξ = −sgn(Q) (μa/R)(1 − √(1 − |Q|/(μP)))`. `r` is the (effective) radius.
pub fn carter_creepage(h: &Hertz2D, mu: f64, r: f64, q_force: f64) -> f64 {
    let k = carter_c_over_a(q_force / (mu * h.load));
    -q_force.signum() * mu * h.a / r * (1.0 - k)
}

/// Inverse creepage–force law: `Q = −sgn(ξ) μP [1 − (c/a)²]` with `c/a = 1 − |ξ|R/(μa)`
/// ([`carter_c_over_a_of_creepage`]), saturating at `Q = −sgn(ξ) μP` for `|ξ| ≥ μa/R` (full slip).
pub fn carter_force(h: &Hertz2D, mu: f64, r: f64, xi: f64) -> f64 {
    if xi == 0.0 {
        return 0.0;
    }
    let k = carter_c_over_a_of_creepage(h, mu, r, xi);
    -xi.signum() * mu * h.load * (1.0 - k * k)
}

/// Carter slip `s(x) = ξ − ∂u_x/∂x` (slip velocity of the cylinder surface relative to the flat,
/// divided by the rolling speed) for |x| ≤ a: 0 in the stick zone, `−sgn(Q)(μ/R)√((x − d)² − c²)`
/// in the slip zone. NaN outside the contact.
pub fn carter_slip(h: &Hertz2D, mu: f64, r: f64, q_force: f64, x: f64) -> f64 {
    if x.abs() > h.a {
        return f64::NAN;
    }
    let (c, d) = carter_stick_zone(h, carter_c_over_a(q_force / (mu * h.load)));
    if x >= h.a - 2.0 * c {
        0.0
    } else {
        let y = x - d;
        -q_force.signum() * mu / r * ((y - c) * (y + c)).max(0.0).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::contact_modulus;
    use crate::theory::test_support::*;
    use std::f64::consts::PI;

    #[test]
    fn carter_resultant_and_creepage_law() {
        // Expected: ∫q = Q by quadrature; |ξ| = (μa/R)(1 − √(1 − |Q|/μP)) with sign opposite to Q
        // (module docs §4); inverse law round trip; saturation at |ξ| ≥ μa/R.
        let e = 1.0;
        let r = 1.0;
        let h = Hertz2D::from_load(1.0, r, e);
        let mu = 0.3;
        let mp = mu * h.load;
        for ratio in [-0.9, -0.4, 0.4, 0.9] {
            let qf = ratio * mp;
            let c = h.a * carter_c_over_a(ratio);
            let total = quad(&|x| carter_traction(&h, mu, qf, x), &[-h.a, h.a - 2.0 * c, h.a], 1e-13, 0.0);
            assert!(close(total, qf, 1e-11 * mp));
            let xi = carter_creepage(&h, mu, r, qf);
            assert!(xi * qf < 0.0);
            assert!(close(xi.abs(), mu * h.a / r * (1.0 - (1.0 - ratio.abs()).sqrt()), 1e-15));
            assert!(close(carter_force(&h, mu, r, xi), qf, 1e-13));
        }
        assert!(close(carter_force(&h, mu, r, 2.0 * mu * h.a / r), -mp, 1e-15));
        // c/a from the creepage inverts the creepage of a force (the closed form c/a = √(1 − |Q|/(μP))).
        for ratio in [-0.9, 0.0, 0.4, 1.0] {
            let xi = carter_creepage(&h, mu, r, ratio * mp);
            assert!(close(carter_c_over_a_of_creepage(&h, mu, r, xi), carter_c_over_a(ratio), 1e-14));
        }
        assert_eq!(carter_c_over_a_of_creepage(&h, mu, r, -3.0 * mu * h.a / r), 0.0);
        assert!(close(carter_force(&h, mu, r, -mu * h.a / r), mp, 1e-15));
    }

    /// Numerical slip `s = ξ + (2/(πE*)) PV∫ q/(x − t) dt` for a given traction.
    fn slip_numeric(q: &dyn Fn(f64) -> f64, xi: f64, e_star: f64, a: f64, kinks: &[f64], x: f64) -> f64 {
        xi + 2.0 / (PI * e_star) * hilbert(q, x, a, kinks)
    }

    #[test]
    fn carter_slip_from_hilbert_transform() {
        // Expected: s = 0 in the stick zone (to 1e-8 μa/R; achieved ~1e-13), s opposite to q in the
        // slip zone and equal to the closed form carter_slip. ∂u_x/∂x from the numerical Hilbert
        // transform of the Carter tractions, E* of the cylinder on a rigid flat.
        let (young, nu) = (210e9, 0.3);
        let e = contact_modulus(young, nu, f64::INFINITY, 0.0);
        let r = 0.46;
        let h = Hertz2D::from_load(1.0e5, r, e);
        let mu = 0.35;
        let mp = mu * h.load;
        let scale = mu * h.a / r;
        for ratio in [-0.95, -0.5, 0.2, 0.5, 0.95] {
            let qf = ratio * mp;
            let c = h.a * carter_c_over_a(ratio);
            let xi = carter_creepage(&h, mu, r, qf);
            let q = |t: f64| carter_traction(&h, mu, qf, t);
            let kinks = [h.a - 2.0 * c];
            let mut worst_stick: f64 = 0.0;
            for i in 0..50 {
                let x = -h.a + (i as f64 + 0.5) * 2.0 * h.a / 50.0;
                let s = slip_numeric(&q, xi, e, h.a, &kinks, x);
                if x > h.a - 2.0 * c {
                    worst_stick = worst_stick.max(s.abs() / scale);
                } else {
                    assert!(s * q(x) < 0.0, "slip must oppose friction at x={x}");
                    let sc = carter_slip(&h, mu, r, qf, x);
                    assert!(close(s, sc, 1e-9 * scale), "x={x}: {s} vs {sc}");
                }
            }
            eprintln!("Carter Q/μP={ratio}: max|s|/(μa/R) in stick = {worst_stick:.2e}");
            assert!(worst_stick < 1e-8, "ratio {ratio}: max |s|/(μa/R) in stick = {worst_stick:e}");
        }
    }

    #[test]
    fn carter_trailing_edge_stick_is_inadmissible() {
        // Expected: mirroring Carter's solution (stick zone at the trailing edge) and choosing ξ to
        // make s = 0 there gives, in the slip zone, s with the *same* sign as q — violating Coulomb.
        // This shows the leading-edge stick zone is forced by the convention s = ξ − ∂u_x/∂x.
        let e = 1.0;
        let h = Hertz2D::from_load(1.0, 1.0, e);
        let mu = 0.3;
        let qf = 0.5 * mu * h.load;
        let c = h.a * carter_c_over_a(0.5);
        let d = h.a - c;
        let q = |t: f64| mu * h.p0 / h.a * (semi(t, h.a) - semi(t + d, c));
        let kinks = [-h.a + 2.0 * c];
        let xs = -h.a + c; // centre of the mirrored stick zone
        let xi = -2.0 / (PI * e) * hilbert(&q, xs, h.a, &kinks);
        for frac in [0.05, 0.3, 0.6, 0.95] {
            let x = -h.a + 2.0 * c + frac * (2.0 * h.a - 2.0 * c);
            let s = slip_numeric(&q, xi, e, h.a, &kinks, x);
            assert!(s * q(x) > 0.0 && qf > 0.0, "expected inadmissible slip at x={x}");
        }
    }
}
