//! The drive of the body's rigid degrees of freedom, turned once into the problem's rigid DOFs
//! ([`super::RigidDof`]): each a prescribed displacement or a prescribed resultant (then the rigid motion is an
//! unknown tied by an equilibrium row).

use super::slip::SlipOperator;
use crate::flexibility::{Flexibility, ModeKind};
use serde::{Deserialize, Serialize};

/// One rigid degree of freedom's drive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Dof {
    /// Prescribed rigid displacement (or rotation).
    Displacement(f64),
    /// Prescribed resultant (force or moment); the rigid motion is an unknown.
    Load(f64),
}

impl Dof {
    /// The prescribed load, if this DOF is load-driven.
    pub fn load(self) -> Option<f64> {
        match self {
            Dof::Load(l) => Some(l),
            Dof::Displacement(_) => None,
        }
    }
}

/// The drive of the three rigid degrees of freedom in the user's units (`DESIGN.md`): approach d_N or load P,
/// shift d_T or load Q, rotation φ or moment M.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Drive {
    /// Normal: approach d_N (length) or P = ∫p dx.
    pub normal: Dof,
    /// Tangential: shift d_T (length) or Q = ∫q dx.
    pub tangential: Dof,
    /// Rotational: φ (radians) or M about the wheel centre.
    pub rotational: Dof,
}

/// The contact law between the bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Coulomb friction coefficient μ ≥ 0 (0: frictionless, the normal problem only).
    pub friction: f64,
    /// Keep the normal–tangential cross flexibilities K_NT, K_TN (false drops them).
    pub coupling: bool,
}

/// What a degree of freedom of the contact problem is: a rigid mode of the body's support (or datum), or the
/// creepage of steady rolling, which takes the place of the shift as the tangential DOF there.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum DofKind {
    /// The tangential shift d_T (a rigid mode).
    Shift,
    /// The approach d_N (a rigid mode).
    Approach,
    /// The rotation φ (a rigid mode).
    Rotation,
    /// The creepage ξ of steady rolling: a uniform slip velocity (dimensionless), the tangential DOF of the steady
    /// problem (prescribed, or unknown with the tangential load prescribed).
    Creepage,
}

impl From<ModeKind> for DofKind {
    fn from(m: ModeKind) -> DofKind {
        match m {
            ModeKind::Shift => DofKind::Shift,
            ModeKind::Approach => DofKind::Approach,
            ModeKind::Rotation => DofKind::Rotation,
        }
    }
}

impl DofKind {
    /// Whether this is the problem's tangential DOF (conjugate to Q).
    pub fn is_tangential(self) -> bool {
        matches!(self, DofKind::Shift | DofKind::Creepage)
    }
}

/// One rigid degree of freedom of the contact problem, in dimensionless units ([`crate::flexibility`]).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct RigidDof {
    /// Which degree of freedom.
    pub kind: DofKind,
    /// Its drive, dimensionless (lengths / L0, forces / (E·L0), moments / (E·L0²)).
    pub drive: Dof,
    /// Its drive in the user's units.
    pub user: Dof,
    /// Gap change u_N of the contact nodes per unit of this DOF.
    pub gap: Vec<f64>,
    /// Slip change of the contact nodes per unit of this DOF, through the slip operator (`None` when the
    /// tangential problem is not built).
    pub slip: Option<Vec<f64>>,
    /// Equilibrium row on the normal nodal forces: its resultant is `row_nᵀ f + row_tᵀ h` (1 for P, 0 for Q, x for
    /// M).
    pub row_n: Vec<f64>,
    /// Equilibrium row on the tangential nodal forces (0 for P, 1 for Q, −y for M).
    pub row_t: Vec<f64>,
}

impl RigidDof {
    /// The default sign s of this DOF's slack rows in the loading LCPs (see [`super::lcp`]): chosen so that the
    /// DOF's gap response r ≈ s·row_n (the approach moves contact nodes by −1 in y: s = −1; the rotation by +x:
    /// s = +1; the shift, whose gap response is only the coupling: s = +1).
    pub fn default_sign(&self) -> f64 {
        match self.kind {
            DofKind::Approach => -1.0,
            DofKind::Shift | DofKind::Rotation | DofKind::Creepage => 1.0,
        }
    }

    /// Whether the DOF is load-driven (its rigid motion is an unknown).
    pub fn is_load(&self) -> bool {
        matches!(self.drive, Dof::Load(_))
    }
}

/// Turn the drive into the problem's rigid DOFs, in the order tangential, normal, rotational (the columns of the
/// loading LCPs follow it). A mode the source does not offer gets no DOF. With the steady-rolling slip operator the
/// tangential DOF is the creepage (slip response 1 at every node, no gap response: [`super::slip`]) and the
/// rotation is no DOF (the wheel turns continuously; its rate is in the creepage).
pub(crate) fn rigid_dofs(flex: &Flexibility, drive: &Drive, slip: &SlipOperator) -> Vec<RigidDof> {
    let sc = flex.scales;
    let n = flex.n();
    let scaled = |d: Dof, length: f64, load: f64| match d {
        Dof::Displacement(v) => Dof::Displacement(v / length),
        Dof::Load(v) => Dof::Load(v / load),
    };
    let steady = slip.is_steady();
    let mut out = Vec::with_capacity(3);
    if steady {
        out.push(RigidDof {
            kind: DofKind::Creepage,
            drive: scaled(drive.tangential, 1.0, sc.force()),
            user: drive.tangential,
            gap: vec![0.0; n],
            slip: flex.has_tangential().then(|| vec![1.0; n]),
            row_n: vec![0.0; n],
            row_t: vec![1.0; n],
        });
    }
    for (kind, user) in [
        (ModeKind::Shift, drive.tangential),
        (ModeKind::Approach, drive.normal),
        (ModeKind::Rotation, drive.rotational),
    ] {
        if steady && kind != ModeKind::Approach {
            continue;
        }
        let Some(mode) = flex.mode(kind) else { continue };
        let drive = match kind {
            ModeKind::Shift | ModeKind::Approach => scaled(user, sc.length, sc.force()),
            ModeKind::Rotation => scaled(user, 1.0, sc.moment()),
        };
        // The resultant conjugate to the mode (the flat's rows 0/1, 1/0, x/−y; turned with per-node frames).
        let (row_n, row_t) = flex.load_rows(kind);
        out.push(RigidDof {
            kind: kind.into(),
            drive,
            user,
            gap: mode.normal.clone(),
            slip: mode.tangential.as_ref().map(|t| slip.apply(t)),
            row_n,
            row_t,
        });
    }
    out
}
