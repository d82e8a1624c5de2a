//! Cattaneo–Mindlin, β = 0 ([`cattaneo_traction`])
//!
//! Tangential force `Q` (|Q| < μP) applied after `P`, on the body, in `+x` for `Q > 0`:
//!
//! ```text
//!   q(x) = sgn(Q) μ p0 [ √(1 − x²/a²) − (c/a) √(1 − x²/c²) ]   |x| < c     (stick)
//!   q(x) = sgn(Q) μ p(x)                                         c < |x| < a (slip)
//!   c/a  = √(1 − |Q|/(μP))
//! ```
//!
//! Source: Cattaneo (1938), Mindlin (1949); 2D form in Johnson (1985) §7.2. Both semi-ellipses
//! have a constant Hilbert transform difference on |x| < c, so the stick zone displaces rigidly
//! (verified numerically with the log kernel in the tests).

use super::hertz::Hertz2D;
use super::special::semi;

/// Cattaneo–Mindlin stick-zone ratio `c/a = √(1 − |Q|/(μP))` (0 at and beyond gross sliding).
pub fn cattaneo_c_over_a(q_over_mu_p: f64) -> f64 {
    (1.0 - q_over_mu_p.abs()).max(0.0).sqrt()
}

/// Cattaneo–Mindlin traction `q(x)` on the body for a tangential force `q_force = Q` applied after
/// the normal load (β = 0). Has the sign of `Q`; |Q| ≥ μP gives gross sliding `q = sgn(Q) μ p`.
pub fn cattaneo_traction(h: &Hertz2D, mu: f64, q_force: f64, x: f64) -> f64 {
    let c = h.a * cattaneo_c_over_a(q_force / (mu * h.load));
    q_force.signum() * mu * h.p0 / h.a * (semi(x, h.a) - semi(x, c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;
    use std::f64::consts::PI;

    #[test]
    fn cattaneo_resultant_bounds_and_rigid_stick_zone() {
        // Expected: ∫q = Q, |q| ≤ μp, and — independently, via the log kernel — the stick zone
        // displaces rigidly (slip u(x) − u(0) = 0 for |x| < c) while the slip zone slips against q.
        let (e_star, mu) = (1.0, 0.3);
        let h = Hertz2D::from_load(1.0, 1.0, e_star);
        let mp = mu * h.load;
        for ratio in [0.3, 0.8, -0.5] {
            let qf = ratio * mp;
            let c = h.a * cattaneo_c_over_a(ratio);
            let q = |t: f64| cattaneo_traction(&h, mu, qf, t);
            let total = quad(&q, &[-h.a, -c, c, h.a], 1e-13, 0.0);
            assert!(close(total, qf, 1e-11 * mp), "∫q = {total} vs Q = {qf}");
            let u = |x: f64| -2.0 / (PI * e_star) * log_potential(&q, x, 1.0, h.a, &[-c, c]);
            let u0 = u(0.0);
            for i in 0..40 {
                let x = -h.a + (i as f64 + 0.5) * 2.0 * h.a / 40.0;
                let qx = q(x);
                assert!(qx.abs() <= mu * h.pressure(x) * (1.0 + 1e-12));
                let s = u(x) - u0;
                if x.abs() < c {
                    assert!(s.abs() < 1e-12, "stick slip {s} at x={x}");
                } else {
                    assert!(close(qx, qf.signum() * mu * h.pressure(x), 1e-14));
                    assert!(s * qx < 0.0, "slip must oppose friction, x={x}");
                }
            }
        }
    }
}
