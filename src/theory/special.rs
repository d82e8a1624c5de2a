//! Special functions and small helpers of the closed forms: the semi-ellipse `√(c² − x²)₊`, `γ ln γ`, and the
//! complete elliptic integral of the first kind by the arithmetic–geometric mean.

use std::f64::consts::FRAC_PI_2;

/// `√(c² − x²)` for |x| < c, else 0 (computed as (c − x)(c + x) for accuracy near the ends).
pub(super) fn semi(x: f64, c: f64) -> f64 {
    if x.abs() < c {
        ((c - x) * (c + x)).sqrt()
    } else {
        0.0
    }
}

/// `γ ln γ`, continuous at 0.
pub(super) fn xlogx(g: f64) -> f64 {
    if g > 0.0 {
        g * g.ln()
    } else {
        0.0
    }
}

/// Arithmetic–geometric mean.
pub(super) fn agm(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..64 {
        if (a - b).abs() <= 1e-16 * a.abs() {
            break;
        }
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
    }
    0.5 * (a + b)
}

/// Complete elliptic integral of the first kind K(k) (modulus k, not parameter m = k²).
pub fn elliptic_k(k: f64) -> f64 {
    let kp = ((1.0 - k) * (1.0 + k)).sqrt();
    FRAC_PI_2 / agm(1.0, kp)
}

/// Complete elliptic integral of the second kind E(k) (modulus k), by the arithmetic–geometric mean (Abramowitz &
/// Stegun 17.6.4): `E = K (1 − Σ_{n≥0} 2^{n−1} c_n²)` with `a₀ = 1, b₀ = k′, c₀ = k`, `c_{n+1} = (a_n − b_n)/2`.
pub fn elliptic_e(k: f64) -> f64 {
    let kp = ((1.0 - k) * (1.0 + k)).sqrt();
    if kp == 0.0 {
        return 1.0;
    }
    let (mut a, mut b) = (1.0_f64, kp);
    let mut sum = 0.5 * k * k;
    let mut power = 0.5;
    for _ in 0..64 {
        let c = 0.5 * (a - b);
        power *= 2.0;
        sum += power * c * c;
        // Convergence is quadratic; c stagnates at round-off, where the doubling weights would amplify it.
        if c.abs() <= 4.0 * f64::EPSILON * a {
            break;
        }
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
    }
    FRAC_PI_2 / a * (1.0 - sum)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;

    #[test]
    fn elliptic_e_values() {
        // E(0) = π/2, E(1) = 1, E(1/√2) = 1.350643881047675502520 (Abramowitz & Stegun table 17.5).
        assert!(close(elliptic_e(0.0), FRAC_PI_2, 1e-15));
        assert!(close(elliptic_e(1.0), 1.0, 1e-15));
        assert!(close(elliptic_e(0.5f64.sqrt()), 1.350_643_881_047_675_5, 1e-14));
        // Legendre's relation E K' + E' K − K K' = π/2 at k = 0.3 (k' = √0.91): an identity, not a table.
        let (k, kp) = (0.3_f64, 0.91_f64.sqrt());
        let lhs = elliptic_e(k) * elliptic_k(kp) + elliptic_e(kp) * elliptic_k(k) - elliptic_k(k) * elliptic_k(kp);
        assert!(close(lhs, FRAC_PI_2, 1e-14));
    }

    #[test]
    fn elliptic_k_values() {
        // Expected: K(0) = π/2; K(1/√2) = Γ(1/4)²/(4√π) = 1.854074677301372 (A&S 17.3);
        // and K(k) by direct quadrature of ∫dθ/√(1 − k²sin²θ).
        assert!(close(elliptic_k(0.0), FRAC_PI_2, 1e-15));
        assert!(close(elliptic_k(0.5f64.sqrt()), 1.854_074_677_301_372, 1e-14));
        for k in [0.1, 0.5, 0.9, 0.999] {
            let kq = quad(&|t: f64| 1.0 / (1.0 - (k * t.sin()).powi(2)).sqrt(), &[0.0, FRAC_PI_2], 1e-14, 0.0);
            assert!(close(elliptic_k(k), kq, 1e-13 * kq));
        }
    }
}
