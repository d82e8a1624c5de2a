//! The clarabel interior-point solver on the frictionless QP, as a contact solver: the symmetrised QP with the
//! normal load as an equality constraint, then the active-set polish with the nonsymmetric flexibility
//! ([`super::clarabel_qp`]). It applies to the frictionless problem without a prescribed moment.

use super::clarabel_qp::{solve_frictionless_cancellable, QpSettings, QpStatus};
use super::{settings_of, Entry, Facts, Figures, Outcome, Solver, SolverId, Start, Termination, Work};
use crate::formulation::{ContactProblem, DofKind};

/// clarabel on the frictionless QP.
pub struct Clarabel {
    /// Its settings.
    pub settings: QpSettings,
}

/// clarabel's identity.
pub const ID: SolverId = SolverId::new("clarabel");

/// Why clarabel does not apply to a frictional problem.
const FRICTIONAL: &str = "it solves the frictionless QP; with friction use normtang_qp (NORM-TANG with clarabel QPs)";

/// Why clarabel does not apply to a prescribed moment.
const MOMENT: &str = "the frictionless QP takes at most the normal load; this scene prescribes a moment";

/// A rough cost of an interior-point QP on m unknowns (seconds, bytes): a dense factorisation per iteration.
pub(crate) fn cost(m: f64) -> (f64, f64) {
    (2e-9 * m * m * m, 24.0 * m * m)
}

/// Registry entry.
pub const ENTRY: Entry = Entry::new::<QpSettings>(
    "clarabel",
    "interior-point QP (symmetric part of K) + active-set polish with the nonsymmetric K; frictionless, no \
     moment load",
    true,
    &["iterations"],
    |_, s| Box::new(Clarabel { settings: settings_of::<QpSettings>(s).cloned().unwrap_or_default() }),
    cost,
);
impl Solver for Clarabel {
    fn id(&self) -> SolverId {
        ID
    }

    fn admits(&self, f: &Facts) -> Result<(), String> {
        if f.friction {
            Err(FRICTIONAL.into())
        } else if f.moment_load {
            Err(MOMENT.into())
        } else {
            Ok(())
        }
    }

    fn solve_from(&self, p: &ContactProblem, start: Start) -> Outcome {
        let Some(np) = p.normal.as_ref().filter(|_| self.applies(p).is_ok()) else {
            let why = self.applies(p).err().unwrap_or_else(|| "no normal problem".into());
            return Outcome::failed(
                Termination::NumericalError,
                format!("clarabel does not apply: {why}"),
                Work::default(),
            );
        };
        let n = p.n();
        let kcol: Vec<f64> = (0..n * n).map(|idx| np.k[(idx % n, idx / n)]).collect();
        let ones = vec![1.0; n];
        let normal_load = p.dofs.iter().find(|d| d.kind == DofKind::Approach).and_then(|d| d.drive.load());
        let load = normal_load.map(|l| (ones.as_slice(), l));
        let out = solve_frictionless_cancellable(&kcol, n, &np.q0, load, &self.settings, &start.cancel);
        let mut rigid = p.given();
        if let (Some(d), Some(k)) = (out.approach, p.dofs.iter().position(|d| d.kind == DofKind::Approach)) {
            rigid[k] = d;
        }
        let w = &p.flex.weights;
        let pmax = out.f.iter().zip(w).fold(0.0_f64, |a, (f, w)| a.max(f / w));
        let polish_change =
            out.f.iter().zip(&out.f_unpolished).zip(w).fold(0.0_f64, |a, ((f, g), w)| a.max((f - g).abs() / w))
                / pmax.max(f64::MIN_POSITIVE);
        let status = Termination::from(&out.status);
        let msg = match &out.status {
            QpStatus::NumericalError(m) => m.clone(),
            s => format!("{s}"),
        };
        let message = format!("{msg}; active-set polish {}", if out.polished { "accepted" } else { "not accepted" });
        Outcome {
            solution: Some(crate::formulation::Solution { f: out.f, h: None, rigid, tangential_known: true }),
            status,
            message,
            work: Work::one("iterations", out.iterations as u64),
            figures: Figures::one("polish_change", polish_change),
            state: None,
        }
    }
}
