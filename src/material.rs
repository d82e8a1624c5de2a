//! Linear elastic materials and the elastic constants of a contact pair, in one place.
//!
//! A [`Material`] is isotropic and linear elastic, described by Young's modulus `E` (stress unit) and Poisson's
//! ratio `ν` (dimensionless). A rigid body is `E = f64::INFINITY` ([`Material::rigid`]): its compliances are 0.
//! Plane strain throughout (line contact, per unit thickness).
//!
//! ```text
//!   G   = E / (2(1 + ν))                                     shear modulus
//!   E'  = E / (1 − ν²)                                       plane-strain modulus
//!   1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂                       contact modulus of a pair
//!   β   = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)]   Dundurs' second parameter
//! ```
//!
//! **Sign convention of β.** Body 1 is the first argument (in rollbem the wheel), body 2 the second (the
//! counter-body): `β(1, 2) = −β(2, 1)`, `|β| ≤ 1/2`. β > 0 when body 1 is the more compliant in the `(1 − 2ν)/G`
//! sense, e.g. an elastic body on a rigid one: `β = (1 − 2ν)/(2(1 − ν))` (4/9 at ν = 0.1). β = 0 for identical
//! materials and for an incompressible body on a rigid one; then the normal and tangential problems of two
//! half-planes decouple.
//!
//! # References
//! K.L. Johnson, *Contact Mechanics*, CUP 1985, §4.2 (E*) and ch. 5 (dissimilar solids, β); J. Dundurs, "Discussion of edge-bonded
//! dissimilar orthogonal elastic wedges under normal and shear loading", J. Appl. Mech. 36 (1969) 650–652.

/// An isotropic linear elastic material (plane strain).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus E, in the caller's stress unit; `f64::INFINITY` for a rigid body.
    pub youngs_modulus: f64,
    /// Poisson's ratio ν, dimensionless (0 ≤ ν ≤ 1/2 for the formulas here to be physical).
    pub poisson_ratio: f64,
}

impl Material {
    /// A material of Young's modulus `youngs_modulus` (stress) and Poisson's ratio `poisson_ratio`.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Material {
        Material { youngs_modulus, poisson_ratio }
    }

    /// A rigid body: `E = ∞` (ν = 0, which no formula uses).
    pub fn rigid() -> Material {
        Material { youngs_modulus: f64::INFINITY, poisson_ratio: 0.0 }
    }

    /// Whether the body is rigid (`E` infinite).
    pub fn is_rigid(&self) -> bool {
        self.youngs_modulus.is_infinite()
    }

    /// Shear modulus `G = E / (2(1 + ν))` (stress; infinite for a rigid body).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Plane-strain modulus `E / (1 − ν²)` (stress): the contact modulus `E*` of this body on a rigid flat.
    pub fn plane_strain_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// Shear compliance `1/G = 2(1 + ν)/E` (1/stress; 0 for a rigid body).
    pub fn shear_compliance(&self) -> f64 {
        if self.is_rigid() {
            0.0
        } else {
            2.0 * (1.0 + self.poisson_ratio) / self.youngs_modulus
        }
    }

    /// Plane-strain compliance `(1 − ν²)/E` (1/stress; 0 for a rigid body).
    pub fn plane_strain_compliance(&self) -> f64 {
        if self.is_rigid() {
            0.0
        } else {
            (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
        }
    }
}

/// Plane-strain contact modulus of a pair, `E* = [(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂]⁻¹` (stress; Johnson 1985 §4.2).
/// Symmetric in its arguments; a rigid body contributes nothing (elastic body on a rigid flat: `E* = E/(1 − ν²)`).
/// Both rigid: infinite.
pub fn contact_modulus(a: &Material, b: &Material) -> f64 {
    1.0 / (a.plane_strain_compliance() + b.plane_strain_compliance())
}

/// Dundurs' second parameter β of a pair in plane strain, body 1 = `a` first (dimensionless; Dundurs 1969):
/// `β = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)]`, a rigid body having `1/G = 0`.
/// Antisymmetric: `β(a, b) = −β(b, a)`; elastic `a` on rigid `b`: `β = (1 − 2ν)/(2(1 − ν)) > 0`. At most one
/// body may be rigid (both rigid: NaN).
pub fn dundurs_beta(a: &Material, b: &Material) -> f64 {
    let (k1, k2) = (a.shear_compliance(), b.shear_compliance());
    let (nu1, nu2) = (a.poisson_ratio, b.poisson_ratio);
    ((1.0 - 2.0 * nu1) * k1 - (1.0 - 2.0 * nu2) * k2) / (2.0 * ((1.0 - nu1) * k1 + (1.0 - nu2) * k2))
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material { youngs_modulus: 210e9, poisson_ratio: 0.3 };

    /// Hand values: G = E/(2(1 + ν)) = 210e9/2.6; E/(1 − ν²) = 210e9/0.91; rigid compliances vanish.
    #[test]
    fn moduli_of_one_material() {
        assert!((STEEL.shear_modulus() - 210e9 / 2.6).abs() <= 1e-15 * 210e9);
        assert!((STEEL.plane_strain_modulus() - 210e9 / 0.91).abs() <= 1e-15 * 210e9 / 0.91);
        assert!((STEEL.shear_compliance() * STEEL.shear_modulus() - 1.0).abs() < 1e-15);
        assert!((STEEL.plane_strain_compliance() * STEEL.plane_strain_modulus() - 1.0).abs() < 1e-15);
        let rigid = Material::rigid();
        assert!(rigid.is_rigid() && !STEEL.is_rigid());
        assert_eq!(rigid.shear_compliance(), 0.0);
        assert_eq!(rigid.plane_strain_compliance(), 0.0);
    }

    /// E* of steel on steel is half the plane-strain modulus, E/(2(1 − ν²)); on a rigid flat it is E/(1 − ν²).
    #[test]
    fn contact_modulus_hand_values() {
        let e = 210e9;
        let half = e / (2.0 * (1.0 - 0.3 * 0.3));
        assert!((contact_modulus(&STEEL, &STEEL) - half).abs() <= 1e-15 * half);
        let on_rigid = contact_modulus(&STEEL, &Material::rigid());
        assert!((on_rigid - e / 0.91).abs() <= 1e-15 * on_rigid);
        assert_eq!(contact_modulus(&Material::rigid(), &STEEL), on_rigid);
        let al = Material::new(70e9, 0.33);
        assert_eq!(contact_modulus(&al, &STEEL), contact_modulus(&STEEL, &al));
    }

    /// β: ν = 0.1 on rigid gives (1 − 2ν)/(2(1 − ν)) = 0.8/1.8 = 4/9 = 0.444…; identical bodies and an
    /// incompressible body on a rigid one give 0; swapping the bodies flips the sign.
    #[test]
    fn dundurs_beta_hand_values() {
        let soft = Material::new(210e9, 0.1);
        assert!((dundurs_beta(&soft, &Material::rigid()) - 4.0 / 9.0).abs() < 1e-15);
        assert!((dundurs_beta(&Material::rigid(), &soft) + 4.0 / 9.0).abs() < 1e-15);
        assert_eq!(dundurs_beta(&STEEL, &STEEL), 0.0);
        assert_eq!(dundurs_beta(&Material::new(1.0, 0.5), &Material::rigid()), 0.0);
        let al = Material::new(70e9, 0.33);
        assert_eq!(dundurs_beta(&al, &STEEL), -dundurs_beta(&STEEL, &al));
        assert!(dundurs_beta(&al, &STEEL) > 0.0, "the more compliant body first gives β > 0");
        assert!(dundurs_beta(&Material::rigid(), &Material::rigid()).is_nan());
    }
}
