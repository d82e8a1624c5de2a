//! Kelvin fundamental solution of 2D plane-strain elastostatics (seed eq. 13; Brebbia & Dominguez ch. 5).
//!
//! With `r = x − ξ` (field point `x` on the boundary minus source point `ξ`), `r,i = r_i / r` and
//! `∂r/∂n = r,k n_k` (`n` the outward unit normal at the field point):
//!
//! ```text
//! U*_lk = [−(3 − 4ν) ln r δ_lk + r,l r,k] / (8π G (1 − ν))
//! T*_lk = −{∂r/∂n [(1 − 2ν) δ_lk + 2 r,l r,k] − (1 − 2ν)(r,l n_k − r,k n_l)} / (4π (1 − ν) r)
//! ```
//!
//! `l` is the direction of the unit point load at the source (the row of H and G), `k` the component of the
//! boundary displacement or traction (the column). The boundary integral equation reads
//! `c_lk u_k(ξ) + ∫ T*_lk u_k ds = ∫ U*_lk t_k ds`.
//!
//! rollbem evaluates these kernels in dimensionless units (lengths divided by the reference length of
//! [`crate::source::bem_wheel::Model`], moduli divided by Young's modulus), so that `ln r` never depends on the user's unit
//! of length.

use crate::material::Material;

/// Material constants of the Kelvin kernels, dimensionless (Young's modulus scaled to 1 by the caller or not).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Kelvin {
    /// Poisson's ratio ν, 0 ≤ ν ≤ 0.5.
    pub nu: f64,
    /// Shear modulus G = E / (2(1 + ν)), in the caller's stress unit.
    pub shear_modulus: f64,
    /// Factor 1 / (8π G (1 − ν)) of U*.
    pub cu: f64,
    /// Factor 1 / (4π (1 − ν)) of T*.
    pub ct: f64,
    /// 3 − 4ν.
    pub a34: f64,
    /// 1 − 2ν.
    pub b12: f64,
}

impl Kelvin {
    /// Kernel constants for Young's modulus `e` and Poisson's ratio `nu` (plane strain).
    pub fn new(e: f64, nu: f64) -> Self {
        let g = Material::new(e, nu).shear_modulus();
        let pi = std::f64::consts::PI;
        Kelvin {
            nu,
            shear_modulus: g,
            cu: 1.0 / (8.0 * pi * g * (1.0 - nu)),
            ct: 1.0 / (4.0 * pi * (1.0 - nu)),
            a34: 3.0 - 4.0 * nu,
            b12: 1.0 - 2.0 * nu,
        }
    }

    /// Displacement kernel U*_lk at field point `x` for a source at `xi`: returns `[[U11, U12], [U21, U22]]`.
    #[inline]
    pub fn u(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        let rx = x[0] - xi[0];
        let ry = x[1] - xi[1];
        let r2 = rx * rx + ry * ry;
        let r = r2.sqrt();
        let (d0, d1) = (rx / r, ry / r);
        let lnr = -self.a34 * 0.5 * r2.ln();
        [[self.cu * (lnr + d0 * d0), self.cu * d0 * d1], [self.cu * d1 * d0, self.cu * (lnr + d1 * d1)]]
    }

    /// Traction kernel T*_lk at field point `x` with outward unit normal `n`, source at `xi`.
    #[inline]
    pub fn t(&self, x: [f64; 2], n: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        let rx = x[0] - xi[0];
        let ry = x[1] - xi[1];
        let r = (rx * rx + ry * ry).sqrt();
        let d = [rx / r, ry / r];
        let drdn = d[0] * n[0] + d[1] * n[1];
        let f = -self.ct / r;
        let mut out = [[0.0; 2]; 2];
        for (l, row) in out.iter_mut().enumerate() {
            for (k, v) in row.iter_mut().enumerate() {
                let delta = if l == k { 1.0 } else { 0.0 };
                *v = f * (drdn * (self.b12 * delta + 2.0 * d[l] * d[k]) - self.b12 * (d[l] * n[k] - d[k] * n[l]));
            }
        }
        out
    }
}
