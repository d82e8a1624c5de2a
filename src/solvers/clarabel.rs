//! The clarabel interior-point solver on the frictionless QP, as a contact solver: the symmetrised QP with the
//! normal load as an equality constraint, then the active-set polish with the nonsymmetric flexibility
//! ([`super::clarabel_qp`]). It applies to the frictionless problem without a prescribed moment.

use super::clarabel_qp::{solve_frictionless, QpSettings, QpStatus};
use super::{Entry, Facts, Outcome, Solver, SolverId, SolverSettings, Termination, Work};
use crate::formulation::{ContactProblem, DofKind};

/// clarabel on the frictionless QP.
pub struct Clarabel {
    /// Its settings.
    pub settings: QpSettings,
}

/// Registry entry.
pub const ENTRY: Entry = Entry {
    id: SolverId::Clarabel,
    name: "clarabel",
    summary: "interior-point QP (symmetric part of K) + active-set polish with the nonsymmetric K; frictionless, no \
              moment load",
    in_all: true,
    counters: &["iterations"],
    build: |s: &SolverSettings| Box::new(Clarabel { settings: s.clarabel.clone() }),
};

impl Solver for Clarabel {
    fn id(&self) -> SolverId {
        SolverId::Clarabel
    }

    fn admits(&self, f: &Facts) -> Result<(), String> {
        if f.friction {
            Err("it solves the frictionless QP; with friction use normtang_qp (NORM-TANG with clarabel QPs)".into())
        } else if f.moment_load {
            Err("the frictionless QP takes at most the normal load; this scene prescribes a moment".into())
        } else {
            Ok(())
        }
    }

    fn solve(&self, p: &ContactProblem) -> Outcome {
        let np = p.normal.as_ref().expect("the frictionless problem");
        let n = p.n();
        let kcol: Vec<f64> = (0..n * n).map(|idx| np.k[(idx % n, idx / n)]).collect();
        let ones = vec![1.0; n];
        let normal_load = p.dofs.iter().find(|d| d.kind == DofKind::Approach).and_then(|d| d.drive.load());
        let load = normal_load.map(|l| (ones.as_slice(), l));
        let out = solve_frictionless(&kcol, n, &np.q0, load, &self.settings);
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
            solution: Some(crate::formulation::Solution {
                f: out.f,
                h: None,
                rigid,
                tangential_known: true,
                support: None,
            }),
            status,
            message,
            work: Work::one("iterations", out.iterations as u64),
            polish_change: Some(polish_change),
        }
    }
}
