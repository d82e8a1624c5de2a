//! 2D Hertz theory of a frictionless line contact, elastic cylinder on a rigid flat (Johnson, *Contact
//! Mechanics*, 1985, §4.2; REFERENCES.md), per unit thickness, plane strain:
//!
//! ```text
//! E* = E / (1 − ν²),  a² = 4 P R / (π E*),  p0 = 2 P / (π a) = E* a / (2R),  p(x) = p0 √(1 − x²/a²)
//! ```
//!
//! Valid for a ≪ R. The approach is *not* a Hertz result in 2D (it depends on the support), so comparisons are
//! made at equal load.

use crate::material::Material;
use serde::{Deserialize, Serialize};

/// Hertz solution for one load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Hertz {
    /// Contact half-width a (length).
    pub half_width: f64,
    /// Peak pressure p0 (stress).
    pub peak_pressure: f64,
    /// Normal load P per unit thickness (force/length).
    pub load: f64,
}

impl Hertz {
    /// Hertz contact of a wheel of radius `r`, modulus `e`, Poisson's ratio `nu` under load `p` on a rigid flat.
    pub fn new(r: f64, e: f64, nu: f64, p: f64) -> Hertz {
        Hertz::with_modulus(r, Material::new(e, nu).plane_strain_modulus(), p)
    }

    /// Hertz contact of a cylinder of radius `r` on a flat with the pair's contact modulus `estar`
    /// (1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) under load `p`.
    pub fn with_modulus(r: f64, estar: f64, p: f64) -> Hertz {
        let a = (4.0 * p * r / (std::f64::consts::PI * estar)).sqrt();
        Hertz { half_width: a, peak_pressure: 2.0 * p / (std::f64::consts::PI * a), load: p }
    }

    /// Pressure at x.
    pub fn pressure(&self, x: f64) -> f64 {
        let s = 1.0 - (x / self.half_width).powi(2);
        if s > 0.0 {
            self.peak_pressure * s.sqrt()
        } else {
            0.0
        }
    }
}

/// Least-squares fit of `p² = p0² (1 − x²/a²)` to loaded nodes (x_i, p_i), as REFERENCES.md recommends (the last
/// loaded node only brackets a within ±h/2). Returns `(a, p0)`, or `None` with fewer than two loaded nodes or a
/// non-elliptic fit.
pub fn fit_ellipse(x: &[f64], p: &[f64]) -> Option<(f64, f64)> {
    // p² = A + B x² by linear least squares over nodes with p > 0.
    let pts: Vec<(f64, f64)> = x.iter().zip(p).filter(|(_, &p)| p > 0.0).map(|(&x, &p)| (x * x, p * p)).collect();
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
    let (mx, my) = (sx / n, sy / n);
    let (sxx, sxy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + (x - mx) * (x - mx), b + (x - mx) * (y - my)));
    if sxx <= 0.0 {
        return None;
    }
    let b = sxy / sxx;
    let a0 = my - b * mx;
    if a0 <= 0.0 || b >= 0.0 {
        return None;
    }
    Some(((-a0 / b).sqrt(), a0.sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_data_of_references_md() {
        // REFERENCES.md: R = 1, E = 94500, ν = 0.1: a/R = 0.05 ↔ P = 187.42, p0 = 2386.4.
        let h = Hertz::new(1.0, 94500.0, 0.1, 187.42);
        assert!((h.half_width - 0.05).abs() < 1e-5);
        assert!((h.peak_pressure - 2386.4).abs() < 0.5);
    }

    #[test]
    fn fit_recovers_an_exact_ellipse() {
        let h = Hertz::new(2.0, 1000.0, 0.3, 5.0);
        let xs: Vec<f64> = (0..15).map(|i| -0.9 * h.half_width + 0.13 * h.half_width * i as f64).collect();
        let ps: Vec<f64> = xs.iter().map(|&x| h.pressure(x)).collect();
        let (a, p0) = fit_ellipse(&xs, &ps).unwrap();
        assert!((a / h.half_width - 1.0).abs() < 1e-12 && (p0 / h.peak_pressure - 1.0).abs() < 1e-12);
    }
}
