//! Hertz line contact ([`Hertz2D`])
//!
//! `a² = 4PR/(πE*)`, `p0 = 2P/(πa) = aE*/(2R)`, `p(x) = p0 √(1 − x²/a²)`.

use super::special::semi;
use std::f64::consts::PI;

/// 2D Hertz line contact, described by its half-width `a` and peak pressure `p0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hertz2D {
    /// Contact half-width.
    pub a: f64,
    /// Peak pressure.
    pub p0: f64,
}

impl Hertz2D {
    /// From half-width and peak pressure directly.
    pub fn new(a: f64, p0: f64) -> Self {
        Self { a, p0 }
    }
    /// From load per unit length `P`, effective radius `R` and contact modulus `E*`:
    /// `a² = 4PR/(πE*)`, `p0 = 2P/(πa)`.
    pub fn from_load(p: f64, r: f64, e_star: f64) -> Self {
        let a = (4.0 * p * r / (PI * e_star)).sqrt();
        Self { a, p0: 2.0 * p / (PI * a) }
    }
    /// Normal load per unit length `P = π a p0 / 2`.
    pub fn load(&self) -> f64 {
        0.5 * PI * self.a * self.p0
    }
    /// Effective radius consistent with `E*`: `R = a E*/(2 p0)`.
    pub fn radius(&self, e_star: f64) -> f64 {
        self.a * e_star / (2.0 * self.p0)
    }
    /// Hertz pressure `p(x) = p0 √(1 − x²/a²)` (0 outside the contact).
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * semi(x, self.a) / self.a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;

    #[test]
    fn hertz_relations() {
        // Expected: definitions a² = 4PR/(πE*), p0 = 2P/(πa); ∫p dx = P by quadrature.
        let (p, r, e) = (1234.0, 0.05, 2.1e11 / (1.0 - 0.09));
        let h = Hertz2D::from_load(p, r, e);
        assert!(close(h.a * h.a, 4.0 * p * r / (PI * e), 1e-15 * h.a * h.a));
        assert!(close(h.load(), p, 1e-12 * p));
        assert!(close(h.radius(e), r, 1e-12 * r));
        let total = quad(&|x| h.pressure(x), &[-h.a, h.a], 1e-13, 0.0);
        assert!(close(total, p, 1e-12 * p), "∫p = {total}");
    }
}
