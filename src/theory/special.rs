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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;

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
