//! The slip operator: how the tangential kinematics of a formulation turns the tangential surface displacement
//! u_T (of the wheel relative to the counter-body, rigid motion included) into the slip s that Coulomb's law acts
//! on:
//!
//! ```text
//!   s = D u_T + c
//! ```
//!
//! with a matrix D (the identity when `None`) and an offset c (zero when `None`). Coulomb's law per contact node:
//! stick ⇔ s = 0 and |h| ≤ μf; slip ⇔ h = −μf·sgn(s) (friction on the wheel opposes the slip).
//!
//! - **Static** (the seed's problem, §4): s = u_T, the tangential displacement relative to the flat (it includes
//!   the rigid shift δ_T through the shift mode's response): D = I, c = 0.
//!
//! The LCP builder ([`super::lcp`]), NORM-TANG ([`crate::solvers::normtang`]) and the solver-independent residuals
//! ([`crate::post`]) all take the slip from here, so a new kinematics (steady rolling s = ξ + D u_T, a load step
//! s = Δu_T) is a new operator, not a new builder.

use faer::Mat;

/// Which kinematics the operator describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlipKind {
    /// s = u_T: static contact (seed §4).
    Static,
}

/// The slip operator s = D u_T + c (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SlipOperator {
    /// Which kinematics.
    pub kind: SlipKind,
    /// D (n × n); `None` is the identity.
    pub d: Option<Mat<f64>>,
    /// c (length n); `None` is zero.
    pub offset: Option<Vec<f64>>,
}

impl SlipOperator {
    /// The static slip s = u_T.
    pub fn static_slip() -> SlipOperator {
        SlipOperator { kind: SlipKind::Static, d: None, offset: None }
    }

    /// D v (a copy of v when D is the identity).
    pub fn apply(&self, v: &[f64]) -> Vec<f64> {
        match &self.d {
            None => v.to_vec(),
            Some(d) => (0..v.len()).map(|i| (0..v.len()).map(|j| d[(i, j)] * v[j]).sum()).collect(),
        }
    }

    /// D M for a matrix M with n rows (a copy when D is the identity).
    pub fn apply_mat(&self, m: &Mat<f64>) -> Mat<f64> {
        match &self.d {
            None => m.clone(),
            Some(d) => d * m,
        }
    }

    /// The slip s = D u_T + c of a tangential displacement u_T.
    pub fn slip(&self, u_t: &[f64]) -> Vec<f64> {
        let mut s = self.apply(u_t);
        if let Some(c) = &self.offset {
            for (si, ci) in s.iter_mut().zip(c) {
                *si += ci;
            }
        }
        s
    }
}
