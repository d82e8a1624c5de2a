//! Analytic reference solutions for a 2D (plane strain, line contact) contact-mechanics
//! verification harness.
//!
//! Everything is per unit thickness, `f64`, SI-agnostic (any consistent units). All functions are
//! pure. Every closed form below is checked in the `tests` module against an *independent*
//! numerical computation (quadrature of half-plane Green's functions, finite-difference equilibrium
//! checks, an incremental frictional contact solver); each test states where its expected value
//! comes from.
//!
//! # 0. Conventions
//!
//! * `x` tangential surface coordinate, `z` depth **into** the body (for the half-plane solutions).
//!   Stresses are **tension positive**. [`Stress2D`] holds in-plane Cartesian components
//!   `(xx, yy, xy)`; for half-plane fields the second axis is `z` (so `yy` = σ_zz, `xy` = τ_xz).
//! * Normal pressure `p(x) ≥ 0` is compressive. The tangential traction `q(x)` is the `x`-component
//!   of the traction that the counter-body exerts **on the body considered** (Cattaneo, M–D, Carter:
//!   the elastic body / the cylinder; Spence: body 1). On the surface of a half-plane `z ≥ 0`:
//!   σ_zz = −p and τ_xz = −q.
//! * Contact modulus (plane strain) `1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2` (elastic body on a rigid
//!   flat: `E* = E/(1 − ν²)`), see [`contact_modulus`]. `R` is the effective radius
//!   `1/R = 1/R1 + 1/R2`.
//! * Dundurs' β (plane strain), body 1 first (see [`dundurs_beta`]):
//!   `β = [(1 − 2ν1)/G1 − (1 − 2ν2)/G2] / [2((1 − ν1)/G1 + (1 − ν2)/G2)]`.
//!   β = 0 for identical materials and for an incompressible body on a rigid one.
//!
//! ## Half-plane surface compliance (Johnson 1985, ch. 2, line loading of a half-space)
//!
//! For a half-plane `z > 0` loaded by `p(x)`, `q(x)`, the surface displacement gradients are
//!
//! ```text
//!   ∂ū_x/∂x = −((1−2ν)(1+ν)/E) p(x) − (2(1−ν²)/(πE)) PV∫ q(t)/(x−t) dt
//!   ∂ū_z/∂x = −(2(1−ν²)/(πE)) PV∫ p(t)/(x−t) dt + ((1−2ν)(1+ν)/E) q(x)     (ū_z into the body)
//! ```
//!
//! so the tangential surface displacement is the logarithmic potential
//! `ū_x(x) = −(2(1−ν²)/(πE)) ∫ q(t) ln|x − t| dt + const`. The sign was checked against the
//! Flamant/McEwen stress field: at the surface σ_zz = −p and, for pure `q`,
//! σ_xx = −(2/π) PV∫ q/(x−t) dt, hence ε_xx = ((1−ν²)/E)(σ_xx − ν σ_zz/(1−ν)) reproduces the kernel
//! (test `surface_strain_from_mcewen_matches_compliance_kernel`). The x–x influence is invariant
//! under the reflection `z → −z`, so the same formula holds for a body occupying `z < 0` (the
//! cylinder above the flat). For two bodies, with `q` acting on body 1 and `−q` on body 2, the
//! relative tangential displacement `g = u_x1 − u_x2` satisfies
//!
//! ```text
//!   ∂g/∂x = −(2/(πE*)) [ π β p(x) + PV∫ q(t)/(x−t) dt ]                                  (0.1)
//! ```
//!
//! (body 1 above, body 2 below, both described in their own inward coordinates). With β = 0 the
//! pressure does not enter: normal and tangential problems decouple, and the tangential problem
//! only involves `E*`.
//!
//! # Files
//!
//! One file per theory: [`hertz`] (1. Hertz line contact), [`cattaneo`] (2. Cattaneo–Mindlin),
//! [`mindlin_deresiewicz`] (3. Mindlin–Deresiewicz), [`carter`] (4. Carter rolling), [`spence`] (5. Spence; [`spence3d`] its axisymmetric counterpart),
//! [`mcewen`] (6. McEwen subsurface stresses), [`disk`] (7. diametrally compressed disk), [`pin_bore`] (8. the pin in a bore, Persson); [`kalker`] (Kalker's creep coefficients of 3D
//! rolling, Table E.3); [`stress`] holds the
//! stress state they return and [`special`] the special functions. Every item is re-exported here, so
//! `rollbem::theory::X` names each of them.
//!
//! # Sources
//!
//! K.L. Johnson, *Contact Mechanics*, CUP 1985 (ch. 2, §4.2, §7.1–7.3, §8.2, and the treatment of
//! Spence's problem in ch. 5); D.A. Hills, D. Nowell, A. Sackfield, *Mechanics of Elastic Contacts*,
//! 1993; C. Cattaneo 1938; R.D. Mindlin 1949; R.D. Mindlin & H. Deresiewicz 1953; F.W. Carter 1926;
//! D.A. Spence, J. Elasticity 5 (1975) 297–319; E. McEwen, Phil. Mag. 40 (1949) 454–459;
//! S.P. Timoshenko & J.N. Goodier, *Theory of Elasticity*, 3rd ed. §41; G. Hondros, Aust. J. Appl.
//! Sci. 10 (1959) 243–268; J. Dundurs 1969; J.M. & P.B. Borwein, *Pi and the AGM* (singular moduli).
//! Section/equation numbers are quoted from memory of the standard texts; every formula here is
//! independently re-derived or numerically verified in the tests.

pub mod carter;
pub mod cattaneo;
pub mod disk;
pub mod hertz;
pub mod hertz3d;
pub mod kalker;
pub mod mcewen;
pub mod mindlin_deresiewicz;
pub mod pin_bore;
pub mod special;
pub mod spence;
pub mod spence3d;
pub mod spence_coupled;
pub mod stress;
#[cfg(test)]
mod test_support;

pub use carter::*;
pub use cattaneo::*;
pub use disk::*;
pub use hertz::*;
pub use hertz3d::*;
pub use kalker::*;
pub use mcewen::*;
pub use mindlin_deresiewicz::*;
pub use pin_bore::PinBore;
pub use special::*;
pub use spence::*;
pub use spence3d::*;
pub use spence_coupled::*;
pub use stress::*;

use crate::material::{self, Material};

/// Plane-strain contact modulus `E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹` ([`material::contact_modulus`]).
/// Pass `f64::INFINITY` for a rigid body (elastic body on a rigid flat: `E* = E/(1 − ν²)`).
pub fn contact_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    material::contact_modulus(&Material::new(e1, nu1), &Material::new(e2, nu2))
}

/// Dundurs' β for plane strain, body 1 first ([`material::dundurs_beta`]):
/// `β = [(1 − 2ν1)/G1 − (1 − 2ν2)/G2] / [2((1 − ν1)/G1 + (1 − ν2)/G2)]`, `G = E/(2(1 + ν))`.
/// `f64::INFINITY` marks a rigid body. Elastic body 1 on a rigid body 2: `β = (1 − 2ν)/(2(1 − ν)) > 0`.
pub fn dundurs_beta(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    material::dundurs_beta(&Material::new(e1, nu1), &Material::new(e2, nu2))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;
    use std::f64::consts::PI;

    #[test]
    fn material_parameters() {
        // Expected: Dundurs (1969) limits; E* = E/(1 − ν²) on a rigid flat.
        let (e, nu) = (200e9, 0.3);
        assert!(close(contact_modulus(e, nu, f64::INFINITY, 0.0), e / (1.0 - nu * nu), 1e-3));
        assert!(close(contact_modulus(e, nu, e, nu), 0.5 * e / (1.0 - nu * nu), 1e-3));
        assert!(dundurs_beta(e, nu, e, nu).abs() < 1e-15);
        let b = dundurs_beta(e, nu, f64::INFINITY, 0.0);
        assert!(close(b, (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)), 1e-15));
        assert!(dundurs_beta(e, 0.5, f64::INFINITY, 0.0).abs() < 1e-15);
        assert!(close(dundurs_beta(70e9, 0.33, e, nu), -dundurs_beta(e, nu, 70e9, 0.33), 1e-15));
    }

    /// Compliance sign (section 0): McEwen surface stress ↔ Hilbert-transform kernel.
    #[test]
    fn surface_strain_from_mcewen_matches_compliance_kernel() {
        // Expected: at the surface, for pure tangential q, σ_xx = −(2/π) PV∫ q/(x − t) dt (Flamant),
        // so ε_xx = ((1 − ν²)/E) σ_xx = −(2(1 − ν²)/(πE)) PV∫ q/(x − t) dt: the compliance kernel
        // used for M–D and Carter. Hilbert transform by independent quadrature.
        let h = Hertz2D::new(1.0, 1.0);
        let q0 = 0.7;
        let q = |t: f64| q0 * semi(t, h.a) / h.a;
        for x in [-0.9, -0.31, 0.05, 0.5, 0.97] {
            let hq = hilbert(&q, x, h.a, &[]);
            let s = mcewen_tangential(&h, q0, x, 0.0);
            assert!(close(s.xx, -2.0 / PI * hq, 1e-12), "x={x}: {} vs {}", s.xx, -2.0 / PI * hq);
        }
        for x in [-2.0, 1.3, 3.0] {
            let hq = quad(&|t| q(t) / (x - t), &[-h.a, h.a], 1e-13, 0.0);
            let s = mcewen_tangential(&h, q0, x, 0.0);
            assert!(close(s.xx, -2.0 / PI * hq, 1e-12));
        }
    }
}
