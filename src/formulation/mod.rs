//! Contact formulations: the contact problem built once from (flexibility, drive, slip operator), plain data that
//! every solver consumes ([`ContactProblem`]), and the one solution shape every solver's unknowns unpack into
//! ([`Solution`]).
//!
//! **Unknowns are nodal forces**, `f_i = w_i p_i` (tributary length × pressure), not tractions. The matrix that
//! maps nodal forces to displacements, `K = F W⁻¹`, is symmetric up to the collocation error of the BEM
//! (Betti's reciprocity), so (i) the frictionless problem is the LCP of an almost symmetric positive definite
//! matrix and the symmetric part defines the QP solved by clarabel, and (ii) in the load-driven LCP the columns of
//! the rigid motion and the rows of equilibrium cancel in `zᵀMz`, which makes M copositive-plus: Lemke then either
//! solves the problem or proves it infeasible (Cottle–Pang–Stone, Thm. 4.4.13). This is how rollbem resolves the
//! seed's ambiguous equilibrium matrices G_N (eq. 39): with nodal forces they are the rows `1ᵀ` (P) and `xᵀ` (M).
//!
//! Which problem a scene poses ([`ProblemKind`]):
//! - **frictionless** (μ = 0): the normal problem only (seed eq. 38 without friction rows, or §4.2 with the normal
//!   load and moment);
//! - **frictional** (μ > 0): the seed's displacement (eq. 38), loading (eq. 49) or mixed LCP ([`lcp`]);
//! - **sliding limit** (P and Q prescribed, |Q| = μP): every contact node slips with h = σμf (σ = sgn Q), so the
//!   tangential forces are eliminated exactly and only the normal problem remains, with `K = K_NN + σμ K_NT` (the
//!   cross block only with coupling) and the moment row `x − σμ y`; Σh = σμP = Q holds by construction and the
//!   shift is indeterminate;
//! - **gross sliding** (|Q| > μP): no static solution; every solver reports `infeasible` with the friction limit.
//!
//! All quantities are dimensionless ([`crate::flexibility`]): lengths / L0, forces / (E·L0), moments / (E·L0²).

mod drive;
pub mod lcp;
pub mod slip;

pub use drive::{ContactLaw, Dof, DofKind, Drive, RigidDof};
pub use lcp::Lcp;
pub use slip::{SlipKind, SlipOperator};

use crate::flexibility::Flexibility;
use crate::tolerances::SLIDING_LIMIT_BAND;
use faer::Mat;
use serde::{Deserialize, Serialize};

/// Which problem a scene poses (see the module docs).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ProblemKind {
    /// μ = 0: the normal problem only.
    Frictionless,
    /// μ > 0: the frictional LCP (displacement, loading or mixed drive).
    Frictional,
    /// |Q| = μP with both prescribed: full slip h = σμf, normal problem only, shift indeterminate.
    SlidingLimit {
        /// σ = sgn Q.
        sigma: f64,
    },
    /// |Q| > μP with both prescribed: no static solution (the message names the friction limit).
    GrossSliding {
        /// What is violated, with the numbers.
        message: String,
    },
}

impl ProblemKind {
    /// The problem a drive poses under Coulomb's μ (see the module docs). It depends on ratios of the drive's loads
    /// only, so a scene's drive in its own units ([`crate::scene::Scene::loading`]) poses the problem its
    /// dimensionless drive does.
    pub fn of(mu: f64, drive: &Drive) -> Result<ProblemKind, DriveIssue> {
        if mu == 0.0 {
            if let Dof::Load(q) = drive.tangential {
                if q != 0.0 {
                    return Err(DriveIssue::TangentialLoadWithoutFriction(q));
                }
            }
            return Ok(ProblemKind::Frictionless);
        }
        Ok(match (drive.normal, drive.tangential) {
            (Dof::Load(p), Dof::Load(q)) if q.abs() > mu * p * (1.0 + SLIDING_LIMIT_BAND) => {
                ProblemKind::GrossSliding {
                    message: format!(
                        "gross sliding: the tangential load |Q| = {:.6e} exceeds the friction limit μP = {:.6e} \
                         (μ = {mu}, P = {p:.6e}); no static solution exists",
                        q.abs(),
                        mu * p
                    ),
                }
            }
            (Dof::Load(p), Dof::Load(q)) if q.abs() >= mu * p * (1.0 - SLIDING_LIMIT_BAND) => {
                ProblemKind::SlidingLimit { sigma: q.signum() }
            }
            _ => ProblemKind::Frictional,
        })
    }
}

/// The formulation's name in results: the seed's two approaches, or the frictionless problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum FormulationName {
    /// The normal problem of a frictionless scene.
    Frictionless,
    /// Every rigid DOF prescribed as a displacement (seed eq. 38).
    Displacement,
    /// At least one rigid DOF prescribed as a load (seed eq. 49, or mixed).
    Loading,
}

impl FormulationName {
    /// Name as written in results.
    pub fn name(self) -> &'static str {
        match self {
            FormulationName::Frictionless => "frictionless",
            FormulationName::Displacement => "displacement",
            FormulationName::Loading => "loading",
        }
    }
}

impl std::fmt::Display for FormulationName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}

/// Why a drive cannot be formulated on a flexibility ([`ContactProblem::new`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DriveIssue {
    /// A nonzero tangential load with no friction: no static solution (user's units).
    #[error("a tangential load {0} without friction: no static solution (gross sliding)")]
    TangentialLoadWithoutFriction(f64),
    /// The flexibility does not fit the problem (its fields are public: one built or edited by hand may not): blocks
    /// or node vectors of other sizes than its contact nodes, the tangential blocks (and, with coupling, the cross
    /// blocks) missing for a frictional problem, or a slip operator of another grid. The message says which.
    #[error("the flexibility does not fit the problem: {0}")]
    Flexibility(String),
}

/// The normal problem of a frictionless scene or of the sliding limit: `g = K f + Σ_m r_m ρ_m + q₀ ≥ 0 ⊥ f ≥ 0`
/// over the load-driven DOFs m.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct NormalProblem {
    /// K: gap change per unit nodal force (K_NN, or K_NN + σμ K_NT at the sliding limit).
    pub k: Mat<f64>,
    /// q₀ = g₀ + Σ r_m ρ_m over the displacement-driven DOFs.
    pub q0: Vec<f64>,
}

/// The contact problem, built once ([`ContactProblem::new`], which checks that its parts fit) and consumed by every
/// solver. Read-only outside the crate (its accessors): the LCP it builds on first use stays the LCP of its parts.
#[derive(Debug, Clone)]
pub struct ContactProblem<'a> {
    /// The flexibility it is built on.
    pub(crate) flex: &'a Flexibility,
    /// Friction and coupling.
    pub(crate) law: ContactLaw,
    /// The drive in the user's units.
    pub(crate) drive: Drive,
    /// Which problem.
    pub(crate) kind: ProblemKind,
    /// The rigid DOFs (tangential, normal, rotational; those the source offers).
    pub(crate) dofs: Vec<RigidDof>,
    /// The tangential kinematics.
    pub(crate) slip: SlipOperator,
    /// The normal problem (frictionless and sliding limit).
    pub(crate) normal: Option<NormalProblem>,
    /// The LCP with the default slack signs, built on first use ([`ContactProblem::lcp`]): a solver that works on the
    /// physical unknowns never pays for it (the frictional LCP costs several n³ and (3n)² memory). `None` beyond
    /// gross sliding.
    lcp_cache: std::sync::OnceLock<Option<LcpBuild>>,
}

/// Whether a flexibility, a contact law and a slip operator fit one problem of kind `kind` (see
/// [`ContactProblem::new`]); `Err` says what does not.
fn fits(flex: &Flexibility, law: &ContactLaw, kind: &ProblemKind, slip: &SlipOperator) -> Result<(), String> {
    let n = flex.n();
    let square = |name: &str, m: &Mat<f64>| {
        if (m.nrows(), m.ncols()) == (n, n) {
            Ok(())
        } else {
            Err(format!("{name} is {}×{}, not {n}×{n} ({n} contact nodes)", m.nrows(), m.ncols()))
        }
    };
    let vector =
        |name: &str, len: usize| if len == n { Ok(()) } else { Err(format!("{name} has {len} entries, not {n}")) };
    square("K_NN", &flex.k_nn)?;
    for (name, m) in [("K_NT", &flex.k_nt), ("K_TN", &flex.k_tn), ("K_TT", &flex.k_tt)] {
        if let Some(m) = m {
            square(name, m)?;
        }
    }
    vector("y", flex.y.len())?;
    vector("g0", flex.g0.len())?;
    vector("weights", flex.weights.len())?;
    for m in &flex.modes {
        vector("a rigid mode's normal response", m.normal.len())?;
        if let Some(t) = &m.tangential {
            vector("a rigid mode's tangential response", t.len())?;
        }
    }
    if *kind == ProblemKind::Frictional {
        if flex.k_tt.is_none() || flex.modes.iter().any(|m| m.tangential.is_none()) {
            return Err("friction needs the tangential blocks (build the flexibility with them)".into());
        }
        if law.coupling && (flex.k_nt.is_none() || flex.k_tn.is_none()) {
            return Err("coupling needs the cross blocks K_NT and K_TN (or `coupling = false`)".into());
        }
    }
    if let Some(d) = &slip.d {
        vector("the slip operator's diagonal", d.diag.len())?;
        vector("the slip operator's second diagonal", d.off.len())?;
        if d.off.iter().flatten().any(|&(j, _)| j >= n) {
            return Err(format!("the slip operator refers to a node beyond the {n} contact nodes"));
        }
    }
    if let Some(c) = &slip.offset {
        vector("the slip operator's offset", c.len())?;
    }
    Ok(())
}

/// The LCP of a problem, built once.
#[derive(Debug, Clone)]
struct LcpBuild {
    lcp: Lcp,
    /// The affine map of the tangential forces of the frictional LCP (see [`lcp::Frictional`]).
    tangential: Option<lcp::TangentialMap>,
    /// Seconds it took.
    seconds: f64,
}

/// A solver's answer in the problem's dimensionless unknowns: the one solution shape of every solver (a solver, a
/// plug-in's included, builds it; [`Solution::fits`] says whether it has a problem's shape).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Normal nodal forces f.
    pub f: Vec<f64>,
    /// Tangential nodal forces h (`None` when the tangential problem was not built).
    pub h: Option<Vec<f64>>,
    /// Value of each rigid DOF of the problem (same order as [`ContactProblem::dofs`]): the prescribed
    /// displacement, or the solved one.
    pub rigid: Vec<f64>,
    /// False when the tangential rigid motion is indeterminate (at the sliding limit).
    pub tangential_known: bool,
}

impl Solution {
    /// Whether it has the shape of a solution of `p`: f of n nodes, h of n nodes or none, one value per rigid DOF.
    pub fn fits(&self, p: &ContactProblem) -> bool {
        let n = p.n();
        self.f.len() == n && self.rigid.len() == p.dofs.len() && self.h.as_ref().is_none_or(|h| h.len() == n)
    }
}

impl<'a> ContactProblem<'a> {
    /// Build the problem a drive poses on a flexibility with the given slip operator. Refused
    /// ([`DriveIssue::Flexibility`]) when the parts do not fit: the flexibility's blocks and node vectors must have
    /// its n contact nodes, a frictional problem needs the tangential blocks and every rigid mode's tangential
    /// response (and with coupling K_NT and K_TN), and the slip operator must be of the same n nodes.
    pub fn new(
        flex: &'a Flexibility,
        law: ContactLaw,
        drive: Drive,
        slip: SlipOperator,
    ) -> Result<ContactProblem<'a>, DriveIssue> {
        let kind = ProblemKind::of(law.friction, &drive)?;
        fits(flex, &law, &kind, &slip).map_err(DriveIssue::Flexibility)?;
        let dofs = drive::rigid_dofs(flex, &drive, &slip);
        let mut p =
            ContactProblem { flex, law, drive, kind, dofs, slip, normal: None, lcp_cache: std::sync::OnceLock::new() };
        if p.normal_only() {
            p.normal = Some(lcp::normal_problem(&p));
        }
        Ok(p)
    }

    /// The flexibility it is built on.
    pub fn flex(&self) -> &'a Flexibility {
        self.flex
    }

    /// Friction and coupling.
    pub fn law(&self) -> ContactLaw {
        self.law
    }

    /// The drive in the user's units.
    pub fn drive(&self) -> Drive {
        self.drive
    }

    /// Which problem.
    pub fn kind(&self) -> &ProblemKind {
        &self.kind
    }

    /// The rigid DOFs (tangential, normal, rotational; those the source offers), in the order of
    /// [`Solution::rigid`].
    pub fn dofs(&self) -> &[RigidDof] {
        &self.dofs
    }

    /// The tangential kinematics.
    pub fn slip(&self) -> &SlipOperator {
        &self.slip
    }

    /// The normal problem (frictionless and sliding limit; `None` otherwise).
    pub fn normal(&self) -> Option<&NormalProblem> {
        self.normal.as_ref()
    }

    /// The LCP with the default slack signs (built on the first call); `None` beyond gross sliding (no static
    /// problem, no LCP).
    pub fn lcp(&self) -> Option<&Lcp> {
        self.lcp_build().map(|b| &b.lcp)
    }

    /// Seconds the LCP took to build, once built.
    pub fn lcp_build_time(&self) -> Option<f64> {
        self.lcp_cache.get().and_then(|b| b.as_ref()).map(|b| b.seconds)
    }

    /// The number of LCP unknowns (without building it): n + 2L for the normal problem, 3n + 2L frictional, 0
    /// beyond gross sliding.
    pub fn lcp_size(&self) -> usize {
        let l = 2 * self.load_dofs().count();
        match self.kind {
            ProblemKind::Frictionless | ProblemKind::SlidingLimit { .. } => self.n() + l,
            ProblemKind::Frictional => 3 * self.n() + l,
            ProblemKind::GrossSliding { .. } => 0,
        }
    }

    /// The LCP, built on the first call (`None` beyond gross sliding).
    fn lcp_build(&self) -> Option<&LcpBuild> {
        self.lcp_cache
            .get_or_init(|| {
                let t0 = std::time::Instant::now();
                let (lcp, tangential) = match self.kind {
                    // `normal` is set by `new` for these kinds.
                    ProblemKind::Frictionless | ProblemKind::SlidingLimit { .. } => {
                        (lcp::normal_lcp(self, self.normal.as_ref()?), None)
                    }
                    ProblemKind::Frictional => {
                        let signs: Vec<f64> = self.load_dofs().map(|d| d.default_sign()).collect();
                        let fr = lcp::frictional_lcp(self, &signs)?;
                        (fr.lcp, Some(fr.map))
                    }
                    ProblemKind::GrossSliding { .. } => return None,
                };
                Some(LcpBuild { lcp, tangential, seconds: t0.elapsed().as_secs_f64() })
            })
            .as_ref()
    }

    /// Number of contact nodes.
    pub fn n(&self) -> usize {
        self.flex.n()
    }

    /// The formulation's name.
    pub fn formulation(&self) -> FormulationName {
        match self.kind {
            ProblemKind::Frictionless => FormulationName::Frictionless,
            ProblemKind::Frictional if !self.dofs.iter().any(RigidDof::is_load) => FormulationName::Displacement,
            _ => FormulationName::Loading,
        }
    }

    /// σμ at the sliding limit (h = σμ f), 0 otherwise.
    pub fn limit_factor(&self) -> f64 {
        match self.kind {
            ProblemKind::SlidingLimit { sigma } => sigma * self.law.friction,
            _ => 0.0,
        }
    }

    /// The DOFs whose rigid motion is unknown, in LCP column order. The tangential DOF is not part of the normal
    /// problem (frictionless: it carries no load; sliding limit: its motion is indeterminate).
    pub fn load_dofs(&self) -> impl Iterator<Item = &RigidDof> + '_ {
        self.dofs.iter().filter(|d| self.is_unknown(d))
    }

    /// Whether a DOF's rigid motion is an unknown of the LCP (see [`ContactProblem::load_dofs`]).
    pub fn is_unknown(&self, d: &RigidDof) -> bool {
        d.is_load() && !(self.normal_only() && d.kind.is_tangential())
    }

    /// Whether only the normal problem is solved (frictionless, sliding limit).
    pub fn normal_only(&self) -> bool {
        matches!(self.kind, ProblemKind::Frictionless | ProblemKind::SlidingLimit { .. })
    }

    /// The prescribed value of each DOF (0 for load-driven ones).
    pub fn given(&self) -> Vec<f64> {
        self.dofs
            .iter()
            .map(|d| match d.drive {
                Dof::Displacement(v) => v,
                Dof::Load(_) => 0.0,
            })
            .collect()
    }

    /// Unpack an LCP solution z (of the default LCP or of one built with other slack signs: they share unknowns)
    /// into the one solution shape; `None` when z is not of the LCP's size ([`ContactProblem::lcp_size`]; there is
    /// none beyond gross sliding).
    pub fn unpack(&self, z: &[f64]) -> Option<Solution> {
        if matches!(self.kind, ProblemKind::GrossSliding { .. }) || z.len() != self.lcp_size() {
            return None;
        }
        let n = self.n();
        let mut rigid = self.given();
        let base = if self.kind == ProblemKind::Frictional { 3 * n } else { n };
        let mut load_values = Vec::new();
        for (k, d) in self.dofs.iter().enumerate() {
            if self.is_unknown(d) {
                let b = load_values.len();
                let r = z[base + 2 * b] - z[base + 2 * b + 1];
                rigid[k] = r;
                load_values.push(r);
            }
        }
        let f = z[..n].to_vec();
        let h = match &self.kind {
            ProblemKind::Frictional => {
                self.lcp_build()?.tangential.as_ref().map(|map| map.h(&z[..3 * n], &load_values))
            }
            ProblemKind::SlidingLimit { .. } => Some(f.iter().map(|v| self.limit_factor() * v).collect()),
            _ => None,
        };
        let tangential_known = !matches!(self.kind, ProblemKind::SlidingLimit { .. });
        Some(Solution { f, h, rigid, tangential_known })
    }

    /// The value of a DOF in a solution (0 when the problem has no DOF of that kind).
    pub fn rigid_value(&self, sol: &Solution, kind: impl Into<DofKind>) -> f64 {
        let kind = kind.into();
        self.dofs.iter().position(|d| d.kind == kind).map(|k| sol.rigid[k]).unwrap_or(0.0)
    }
}
