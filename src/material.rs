//! Elastic materials in plane strain, and the two figures of a pair of bodies that contact theory uses: the
//! contact modulus E* and Dundurs' β. Each formula lives here and nowhere else.
//!
//! ## References
//! Johnson, *Contact Mechanics* (1985), §4.2 (E*) and §5.4 (β); Dundurs (1969).

use serde::{Deserialize, Serialize};

/// An isotropic linear elastic material: Young's modulus E (stress unit) and Poisson's ratio ν (0 ≤ ν ≤ 0.5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Young's modulus E (stress unit).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
}

impl Material {
    /// Shear modulus G = E / (2(1 + ν)).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// The plane-strain modulus E / (1 − ν²): the contact modulus of this body on a rigid flat.
    pub fn plane_strain_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }
}

/// The plane-strain contact modulus of a pair, E* with 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂; `other = None` is a
/// rigid counter-body (its term vanishes).
pub fn contact_modulus(body: &Material, other: Option<&Material>) -> f64 {
    let compliance = |m: &Material| (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
    1.0 / (compliance(body) + other.map_or(0.0, compliance))
}

/// Dundurs' β of a pair (body 1 against body 2; `other = None` is rigid, G₂ → ∞):
/// β = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)]. β = 0 decouples the normal and tangential
/// problems of two half-planes; its sign is that of body 1 being the more compressible one.
pub fn dundurs_beta(body: &Material, other: Option<&Material>) -> f64 {
    let parts = |m: &Material| {
        let g = m.shear_modulus();
        ((1.0 - 2.0 * m.poisson_ratio) / g, (1.0 - m.poisson_ratio) / g)
    };
    let (a1, b1) = parts(body);
    let (a2, b2) = other.map_or((0.0, 0.0), parts);
    (a1 - a2) / (2.0 * (b1 + b2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_values() {
        let m = |e, nu| Material { youngs_modulus: e, poisson_ratio: nu };
        // On a rigid flat β = (1 − 2ν)/(2(1 − ν)): ν = 0.1 → 0.8/1.8 = 0.4444…, ν = 0.5 → 0 (REFERENCES.md).
        assert!((dundurs_beta(&m(94500.0, 0.1), None) - 0.8 / 1.8).abs() < 1e-15);
        assert_eq!(dundurs_beta(&m(1.0, 0.5), None), 0.0);
        // Identical bodies: β = 0, E* = E / (2(1 − ν²)).
        let steel = m(210000.0, 0.3);
        assert_eq!(dundurs_beta(&steel, Some(&steel)), 0.0);
        assert!((contact_modulus(&steel, Some(&steel)) - 210000.0 / (2.0 * 0.91)).abs() < 1e-9);
        assert!((contact_modulus(&steel, None) - 210000.0 / 0.91).abs() < 1e-9);
        // Swapping the bodies flips β's sign.
        let soft = m(1000.0, 0.45);
        assert!((dundurs_beta(&steel, Some(&soft)) + dundurs_beta(&soft, Some(&steel))).abs() < 1e-15);
    }
}
