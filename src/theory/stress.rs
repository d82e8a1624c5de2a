//! The in-plane stress state of the closed forms ([`Stress2D`]): tension positive, components `(xx, yy, xy)`;
//! for half-plane fields the second axis is the depth `z` (so `yy` = σ_zz, `xy` = τ_xz).

use std::ops::Add;

/// In-plane Cartesian stress components, tension positive. For half-plane fields the second axis is
/// the depth `z`: `yy` = σ_zz, `xy` = τ_xz. For the disk it is `y`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stress2D {
    /// σ_xx.
    pub xx: f64,
    /// σ_yy (σ_zz for half-plane fields).
    pub yy: f64,
    /// τ_xy (τ_xz for half-plane fields).
    pub xy: f64,
}

impl Add for Stress2D {
    type Output = Stress2D;
    fn add(self, o: Stress2D) -> Stress2D {
        Stress2D { xx: self.xx + o.xx, yy: self.yy + o.yy, xy: self.xy + o.xy }
    }
}

impl Stress2D {
    /// Multiply all components by `k`.
    pub fn scale(self, k: f64) -> Stress2D {
        Stress2D { xx: k * self.xx, yy: k * self.yy, xy: k * self.xy }
    }
    /// In-plane principal shear `τ1 = √(((σ_xx − σ_yy)/2)² + τ_xy²)`.
    pub fn principal_shear(&self) -> f64 {
        (0.5 * (self.xx - self.yy)).hypot(self.xy)
    }
    /// In-plane principal stresses `(σ1, σ2)`, σ1 ≥ σ2.
    pub fn principal(&self) -> (f64, f64) {
        let m = 0.5 * (self.xx + self.yy);
        let t = self.principal_shear();
        (m + t, m - t)
    }
    /// Von Mises equivalent stress in plane strain, out-of-plane stress `σ_33 = ν(σ_xx + σ_yy)`:
    /// `√(½[(σxx − σyy)² + (σyy − σ33)² + (σ33 − σxx)²] + 3τxy²)`.
    pub fn von_mises_plane_strain(&self, nu: f64) -> f64 {
        let s3 = nu * (self.xx + self.yy);
        let (a, b, c) = (self.xx - self.yy, self.yy - s3, s3 - self.xx);
        (0.5 * (a * a + b * b + c * c) + 3.0 * self.xy * self.xy).sqrt()
    }
}
