//! Lemke's complementary pivoting algorithm (seed §5; Cottle, Pang & Stone, *The Linear Complementarity Problem*,
//! §4.4; Murty 1988 ch. 2) for `w = M z + q`, with the covering vector e = (1, …, 1), or warm-started from a
//! guessed basis ([`solve_warm`]).
//!
//! Implementation notes:
//! - **Scaling.** Rows and columns are equilibrated (Ruiz) before pivoting: `M' = D_r M D_c`, `q' = D_r q`,
//!   `z = D_c z'`, `w = D_r⁻¹ w'`. Positive diagonal scalings preserve complementarity, and they bring the
//!   unknowns to order one whatever the units of the physical problem. M' is not stored: the engines read
//!   `dr_i M_ij dc_j` where they gather entries.
//! - **Revised form, product form.** Both engines keep the inverse of a *base* basis B₀ and an eta file (one pivot
//!   column per pivot since then), `B⁻¹ = E_t ⋯ E_1 B₀⁻¹`: a pivot column costs one application of B₀⁻¹ and t eta
//!   steps, and nothing of size m² or k² is written per pivot. The block engine factorises B₀ through its z-part
//!   (LU of the k × k block C) and refactorises every `max(refactor_every, k/4)` pivots (`block`); the dense
//!   engine keeps B₀⁻¹ explicitly and absorbs the eta file into it every `refactor_every` pivots with one rank-t
//!   product, recomputing it from scratch only when a drift check fails ([`dense`]). The final basic solution is
//!   obtained by a fresh LU solve with one step of iterative refinement, so the complementarity of the answer is
//!   exact (every nonbasic variable is zero) and its residual is at round-off level.
//! - **Anti-cycling.** Ties in the minimum-ratio test are broken by the lexicographic rule: among the tied rows
//!   choose the one whose row of `B⁻¹` (of `B⁻¹ B_init` for a warm start from B_init), divided by the pivot column
//!   entry, is lexicographically smallest. Rows of `B⁻¹` are linearly independent, so no tie survives and no basis
//!   repeats: the algorithm is finite on degenerate problems. When z₀ is among the tied rows it leaves at once
//!   (termination). The rows are formed only as far as the comparison needs: `e_iᵀ E_t ⋯ E_1` is sparse, and its
//!   product with B₀⁻¹ is read off it wherever B₀⁻¹ maps the starting basis' column to a unit vector.
//! - **Outcome.** `Solved` (z₀ left the basis), `RayTermination` (no blocking row: for a copositive-plus M this
//!   proves the LCP infeasible), `NotConverged` (pivot limit).
//! - **Engines.** [`solve`] is the block-revised engine (`block`); the dense reference engine is
//!   [`dense`]. Both pivot on the same scaled problem (`prepare`) and follow the same path, and each computes its
//!   final solution exactly as its previous version did, so their answers are those of the previous versions to
//!   the bit (the recorded key figures of `tests/regression.rs` include round-off-level quantities).
//!
//! **Speed (rework of 2026-11).** Measured on the peer benchmark's LCPs (`benches/peer/README.md`: the coupled
//! Cattaneo scene with 200, 400, 800, 880 contact elements), `rollbem lcp solve FILE --json` `solve_time_s`,
//! median of 3, previous and new binaries interleaved on the project's shared 2-core machine (load average
//! 1.6–2.3); pivots unchanged (264, 527, 1051, 1157) and z identical to the bit:
//!
//! | unknowns | pivots | block before (s) | block after (s) | dense before (s) | dense after (s) |
//! |---:|---:|---:|---:|---:|---:|
//! | 604 | 264 | 0.039 | 0.018 | 0.218 | 0.044 |
//! | 1204 | 527 | 0.211 | 0.079 | 1.85 | 0.232 |
//! | 2404 | 1051 | 2.25 | 0.718 | 22.7 | 3.53 |
//! | 2644 | 1157 | 2.82 | 0.906 | 30.9 | 6.01 |
//!
//! Siconos' `lcp_lexicolemke` (the peer driver, same files, same pivots, right after): 11.9 s at 2404 and 16.7 s
//! at 2644 unknowns, with the dense engine at 3.96 s and 4.91 s in the same run. (At load 5–7 the previous
//! engines took 3.7 s and 5.4 s (block), 33 s and 51 s (dense) at 2404 and 2644.)
//!
//! Where the time went, and what changed:
//! - *Block engine* (profile at m = 2644 before: 33 % the pass over all m rows of the k basic columns of M, 14 %
//!   the row `M_{i,Z} C⁻¹`, 14 % the column `C⁻¹ c_R`, 11 % the rank-one update of C⁻¹ — four memory-bound passes
//!   per pivot). Now one triangular solve pair with the LU of C₀ (k²) and one product with a contiguous copy of
//!   M_{W,Z} ((m − k) k) per pivot. Then the lexicographic rule (146 ties at m = 2644, each computing some 335
//!   columns of B⁻¹: 0.45 s) became the largest cost: rows are now formed sparsely as above (0.03 s). Then the
//!   preparation: equilibration was scalar (`f64::max` does not vectorise) and the scaled copy of M cost 56 MB
//!   of page faults; 0.23 s → 0.07 s.
//! - *Dense engine* (before: an O(m³) re-inversion of the whole basis every 100 pivots, 11 of them at m = 2644,
//!   plus two passes over the m × m inverse per pivot). Now one pass per pivot (the product B₀⁻¹ a, read only;
//!   none at all for a w entering), a rank-100 update every 100 pivots (a matrix product at full speed), and no
//!   re-inversion unless the residual of the basic solution or a probe of the inverse says it drifted (never on
//!   these LCPs: residuals 1e-15 to 2e-14, probe errors 5e-12 to 1e-9 against the limit 1e-8).
//!
//! **Warm start** ([`solve_warm`]): from the complementary basis of a guessed support, with covering vector
//! `d = B_g e` (Lemke with covering vector e on the principal pivotal transform of the LCP for that basis). On the
//! same LCPs: the solution's own support solves with no pivot; a guess off by 1–10 indices takes 2–13 pivots
//! (against 1157 cold at m = 2644); the previous load step's support (the coupled Cattaneo scene, Q raised by
//! 0.1 μP) takes 5–28 pivots against 132–148 cold. Covering only the infeasible rows (d̄ = their indicator)
//! was tried and dropped: on these non-copositive-plus LCPs it ended on secondary rays for guesses off by 3–30
//! indices where d̄ = e solved. A bad guess still solves, but it can cost more than a cold start (all z's guessed
//! basic at m = 2644: 1478 pivots, 6 s, with larger k throughout).
//!
//! As a contact solver ([`Lemke`]) it solves every problem's LCP and interprets its end: on the frictional LCP a
//! ray is retried with the other slack-sign patterns of the load-driven DOFs (the same solution set, another
//! path), and a ray is reported `infeasible` only when a bound proves it ([`classify_ray`]).

mod block;
pub mod dense;

use super::{
    settings_of, Entry, Figures, LcpOutcome, LcpSolver, Outcome, Solver, SolverId, SolverState, Start, Termination,
    Validate, Work,
};
use crate::cancel::Cancel;
use crate::formulation::{lcp::frictional_lcp, ContactProblem, Dof, Lcp, ProblemKind};
use faer::Mat;

/// Settings of Lemke's algorithm.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LemkeSettings {
    /// Maximum number of pivots, as a multiple of the problem size m (plus 100). Default 50.
    pub max_pivots_per_unknown: usize,
    /// Pivot-column entries ≤ `pivot_tolerance · ‖column‖∞` cannot block (default 1e-11).
    pub pivot_tolerance: f64,
    /// Ratios within `tie_tolerance` (relative) of the minimum count as tied (default 1e-9).
    pub tie_tolerance: f64,
    /// Refresh the basis factorisation every this many pivots (default 100): the block engine refactorises its
    /// base every `max(refactor_every, k/4)` pivots (k basic z's), the dense engine absorbs its eta file into the
    /// explicit inverse (and checks it for drift) every `refactor_every` pivots.
    pub refactor_every: usize,
    /// On a load path, start each step from the previous step's basis (the support of its z, [`solve_warm`]) when
    /// its LCP has the same size; the block engine only (default true). The cold start otherwise, and whenever the
    /// warm start fails (the message says so).
    pub warm_start: bool,
}

impl Default for LemkeSettings {
    fn default() -> Self {
        LemkeSettings {
            max_pivots_per_unknown: 50,
            pivot_tolerance: 1e-11,
            tie_tolerance: 1e-9,
            refactor_every: 100,
            warm_start: true,
        }
    }
}

impl Validate for LemkeSettings {
    fn validate(&self) -> Result<(), (&'static str, String)> {
        crate::solvers::check_tolerance("pivot_tolerance", self.pivot_tolerance)?;
        crate::solvers::check_tolerance("tie_tolerance", self.tie_tolerance)?;
        crate::solvers::check_count("max_pivots_per_unknown", self.max_pivots_per_unknown)?;
        crate::solvers::check_count("refactor_every", self.refactor_every)
    }
}

/// Result of Lemke's algorithm.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct LemkeOutcome {
    /// z (unscaled); on ray termination the last basic point's z (not a solution).
    pub z: Vec<f64>,
    /// w = M z + q (unscaled), recomputed from z.
    pub w: Vec<f64>,
    /// How the engine ended.
    pub status: Termination,
    /// Number of pivots, including the initial z₀ pivot.
    pub pivots: usize,
    /// Human-readable detail (which variable ended it, etc.).
    pub message: String,
}

/// z0 counts as zero below this fraction of its initial value (both engines).
pub(crate) const Z0_NEGLIGIBLE: f64 = 1e-13;

/// Ruiz equilibration (8 sweeps): returns (D_r, D_c) with max |D_r M D_c| ≈ 1 in every nonzero row and column.
/// Both Lemke engines pivot on `D_r M D_c`; with covering vector e this is Lemke on M with covering vector D_r⁻¹e.
pub fn equilibrate(m: &Mat<f64>) -> (Vec<f64>, Vec<f64>) {
    let n = m.nrows();
    let mut dr = vec![1.0; n];
    let mut dc = vec![1.0; n];
    for _ in 0..8 {
        let mut rmax = vec![0.0_f64; n];
        let mut cmax = vec![0.0_f64; n];
        for (j, cm) in cmax.iter_mut().enumerate() {
            *cm = scan_column(column(m, j), &dr, dc[j], &mut rmax);
        }
        for i in 0..n {
            if rmax[i] > 0.0 {
                dr[i] /= rmax[i].sqrt();
            }
            if cmax[i] > 0.0 {
                dc[i] /= cmax[i].sqrt();
            }
        }
    }
    (dr, dc)
}

/// One column of a Ruiz sweep: `rmax_i ← max(rmax_i, |dr_i m_i dcj|)`, returns `max_i |dr_i m_i dcj|`. Written with
/// comparisons in eight independent lanes so that it vectorises (`f64::max` does not, for its NaN rule); with
/// finite data the result is the same to the bit.
fn scan_column(col: &[f64], dr: &[f64], dcj: f64, rmax: &mut [f64]) -> f64 {
    let mut lanes = [0.0_f64; 8];
    let split = col.len() - col.len() % 8;
    let (rc, rt) = rmax.split_at_mut(split);
    for ((r8, d8), m8) in rc.chunks_exact_mut(8).zip(dr.chunks_exact(8)).zip(col.chunks_exact(8)) {
        for l in 0..8 {
            let v = (d8[l] * m8[l] * dcj).abs();
            if v > r8[l] {
                r8[l] = v;
            }
            if v > lanes[l] {
                lanes[l] = v;
            }
        }
    }
    let mut cm = lanes.iter().fold(0.0_f64, |a, &v| if v > a { v } else { a });
    for ((r, &dri), &mij) in rt.iter_mut().zip(&dr[split..]).zip(&col[split..]) {
        let v = (dri * mij * dcj).abs();
        if v > *r {
            *r = v;
        }
        if v > cm {
            cm = v;
        }
    }
    cm
}

/// Column j of a faer matrix as a slice (an owned `Mat` stores its columns contiguously).
pub(crate) fn column(m: &Mat<f64>, j: usize) -> &[f64] {
    m.col(j).try_as_col_major().expect("faer stores the columns of a Mat contiguously").as_slice()
}

/// The scaled problem both engines pivot on, and the way back to the user's variables. The scaled matrix
/// `M' = D_r M D_c` is not stored: engines read its entries as `dr[i] * M[i, j] * dc[j]` ([`Scaled::entry`],
/// [`Scaled::scaled_column`]) when they gather them, which saves a copy of M (and its page faults: at m = 2644
/// building the copy took about a tenth of the whole solve).
pub(crate) struct Scaled<'a> {
    pub(crate) lcp: &'a Lcp,
    pub(crate) q: Vec<f64>,
    pub(crate) dr: Vec<f64>,
    pub(crate) dc: Vec<f64>,
    pub(crate) qscale: f64,
}

impl Scaled<'_> {
    /// Entry (i, j) of the scaled matrix M'.
    #[inline]
    pub(crate) fn entry(&self, i: usize, j: usize) -> f64 {
        self.dr[i] * self.lcp.m[(i, j)] * self.dc[j]
    }

    /// Column j of the scaled matrix M', times `factor`, written to `out`.
    pub(crate) fn scaled_column(&self, j: usize, factor: f64, out: &mut [f64]) {
        let dcj = self.dc[j];
        for ((o, &dri), &mij) in out.iter_mut().zip(&self.dr).zip(column(&self.lcp.m, j)) {
            *o = factor * (dri * mij * dcj);
        }
    }

    /// Unscale z, recompute w = M z + q from the original data, and wrap up.
    pub(crate) fn finish(&self, z_s: Vec<f64>, status: Termination, pivots: usize, message: String) -> LemkeOutcome {
        let z: Vec<f64> = z_s.iter().zip(&self.dc).map(|(z, d)| z * d).collect();
        let w = self.lcp.w_of_sized(&z);
        LemkeOutcome { z, w, status, pivots, message }
    }
}

/// Validate and equilibrate; `Err` carries the outcome when there is nothing to pivot (bad data, or q ≥ 0).
pub(crate) fn prepare(lcp: &Lcp) -> Result<Scaled<'_>, LemkeOutcome> {
    let n = lcp.size();
    let fail = |msg: String| LemkeOutcome {
        z: vec![0.0; n],
        w: lcp.q.clone(),
        status: Termination::NumericalError,
        pivots: 0,
        message: msg,
    };
    if lcp.m.nrows() != n || lcp.m.ncols() != n {
        return Err(fail(format!("M is {}×{} but q has {} entries", lcp.m.nrows(), lcp.m.ncols(), n)));
    }
    if !lcp.q.iter().all(|v| v.is_finite()) || !lcp.m.col_iter().all(|c| c.iter().all(|v| v.is_finite())) {
        return Err(fail("M or q has a non-finite entry (NaN or infinity)".into()));
    }
    let (dr, dc) = equilibrate(&lcp.m);
    let q: Vec<f64> = (0..n).map(|i| dr[i] * lcp.q[i]).collect();
    let qscale = q.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let sc = Scaled { lcp, q, dr, dc, qscale };
    if sc.q.iter().all(|&v| v >= 0.0) {
        return Err(sc.finish(vec![0.0; n], Termination::Solved, 0, "q ≥ 0: z = 0 is the solution".into()));
    }
    Ok(sc)
}

/// Solve `w = M z + q ⊥ z ≥ 0` by Lemke's method: the block-revised engine (`block`), which works
/// on the k × k block of the basis that involves z-columns only.
pub fn solve(lcp: &Lcp, settings: &LemkeSettings) -> LemkeOutcome {
    solve_cancellable(lcp, settings, &Cancel::never())
}

/// [`solve`], stopping (`not_converged`, "cancelled") at the first pivot after `cancel` is raised.
pub fn solve_cancellable(lcp: &Lcp, settings: &LemkeSettings, cancel: &Cancel) -> LemkeOutcome {
    match prepare(lcp) {
        Ok(sc) => block::run(&sc, settings, cancel),
        Err(out) => out,
    }
}

/// Solve `w = M z + q ⊥ z ≥ 0` by Lemke's method warm-started from a guessed complementary basis (block-revised
/// engine): `guess[i]` is true when z_i is expected to be basic (positive) in the solution, e.g. the support of
/// the previous load step's solution or of a cheap iterative solve.
///
/// The guessed basis (z_i basic for the guessed i, w_i for the others) is factorised once and its basic solution
/// x̄ computed. If x̄ ≥ 0 it is the solution (0 pivots). Otherwise z₀ enters with the covering vector d = B d̄,
/// d̄ the indicator of the infeasible rows of x̄, so that z₀ only has to repair those rows (`block`). If the
/// guessed basis is numerically singular, or the warm-started path does not end with z₀ leaving the basis (a ray
/// or the pivot limit), the LCP is solved by the cold start ([`solve`]) and the message says so; the pivots of
/// the abandoned attempt are included in the count.
pub fn solve_warm(lcp: &Lcp, settings: &LemkeSettings, guess: &[bool]) -> LemkeOutcome {
    solve_warm_cancellable(lcp, settings, guess, &Cancel::never())
}

/// [`solve_warm`], stopping at the first pivot after `cancel` is raised.
pub fn solve_warm_cancellable(lcp: &Lcp, settings: &LemkeSettings, guess: &[bool], cancel: &Cancel) -> LemkeOutcome {
    let sc = match prepare(lcp) {
        Ok(sc) => sc,
        Err(out) => return out,
    };
    match block::run_warm(&sc, settings, guess, cancel) {
        Ok(out) => out,
        Err(failure) => {
            let out = block::run(&sc, settings, cancel);
            LemkeOutcome {
                pivots: out.pivots + failure.pivots,
                message: format!(
                    "{} (warm start abandoned after {} pivots: {}; solved from the cold start)",
                    out.message, failure.pivots, failure.reason
                ),
                ..out
            }
        }
    }
}

/// A Lemke engine: solve a bare LCP with the given settings, stopping when `cancel` is raised.
pub type Engine = fn(&Lcp, &LemkeSettings, &Cancel) -> LemkeOutcome;

/// Lemke's method as a contact solver: one engine ([`solve_cancellable`] or [`dense::solve_dense_cancellable`])
/// with the slack-sign retry and the ray interpretation of this module.
pub struct Lemke {
    /// Which registered engine this is.
    pub id: SolverId,
    /// Its settings.
    pub settings: LemkeSettings,
    /// The pivoting engine.
    pub engine: Engine,
}

/// The block-revised engine's identity.
pub const ID: SolverId = SolverId::new("lemke");

/// A rough cost of Lemke on m unknowns (seconds, bytes): O(m³) pivoting, the LCP's m × m matrix three times over.
pub(crate) fn cost(m: f64) -> (f64, f64) {
    (4e-10 * m * m * m, 24.0 * m * m)
}

/// Registry entry of the block-revised engine.
pub const ENTRY: Entry = Entry::new::<LemkeSettings>(
    "lemke",
    "Lemke's method, block-revised (only the z-part of the basis is factorised), lexicographic anti-cycling; \
     every scene",
    true,
    &["pivots"],
    |_, s| {
        let settings = settings_of::<LemkeSettings>(s).copied().unwrap_or_default();
        Box::new(Lemke { id: ID, settings, engine: solve_cancellable })
    },
    cost,
);

/// What Lemke keeps between runs on one layout ([`SolverState`]): the support of its last solution (which LCP
/// unknowns were positive), the guessed basis of its next warm start.
struct LemkeState {
    support: Vec<bool>,
}

impl LcpSolver for Lemke {
    fn solve_lcp(&self, lcp: &Lcp) -> LcpOutcome {
        let o = (self.engine)(lcp, &self.settings, &Cancel::never());
        LcpOutcome {
            z: o.z,
            w: o.w,
            termination: o.status,
            message: o.message,
            work: Work::one("pivots", o.pivots as u64),
        }
    }
}

impl Solver for Lemke {
    fn id(&self) -> SolverId {
        self.id
    }

    fn applies(&self, _problem: &ContactProblem) -> Result<(), String> {
        Ok(())
    }

    fn uses_lcp(&self) -> bool {
        true
    }

    fn lcp_solver(&self) -> Option<&dyn LcpSolver> {
        Some(self)
    }

    fn solve_from(&self, p: &ContactProblem, mut start: Start) -> Outcome {
        let Some(lcp) = p.lcp() else {
            let why = match &p.kind {
                ProblemKind::GrossSliding { message } => message.clone(),
                _ => "the problem has no LCP".to_string(),
            };
            return Outcome::failed(Termination::Infeasible, why, Work::one("pivots", 0));
        };
        let guess = start.take_state::<LemkeState>(self.id, p).map(|s| s.support);
        let attempt = Attempt { guess: guess.as_deref(), cancel: &start.cancel };
        let out = match p.kind {
            ProblemKind::Frictional => self.frictional_from(p, lcp, &attempt).1,
            ProblemKind::SlidingLimit { .. } => {
                let o = self.first_attempt(lcp, &attempt);
                let message = format!(
                    "sliding limit |Q| = μP: every contact node slips (q = μp sgn Q); the tangential shift is \
                     indeterminate (reported null); {}",
                    o.message
                );
                LemkeOutcome { message, ..o }
            }
            _ => self.first_attempt(lcp, &attempt),
        };
        let (status, message) = classify_ray(out.status, out.message, p);
        let support = out.z.iter().map(|&v| v > 0.0).collect();
        Outcome {
            solution: p.unpack(&out.z),
            state: (status == Termination::Solved).then(|| SolverState::new(self.id, p, LemkeState { support })),
            status,
            message,
            work: Work::one("pivots", out.pivots as u64),
            figures: Figures::default(),
        }
    }
}

/// What one attempt on an LCP starts from: a guessed basis (the previous run's support) and the cancellation token.
struct Attempt<'a> {
    guess: Option<&'a [bool]>,
    cancel: &'a Cancel,
}

impl Lemke {
    /// The first attempt on a problem's LCP: warm-started from the previous run's basis when it has the LCP's size
    /// and the settings allow it (block engine), else the engine's cold start.
    fn first_attempt(&self, lcp: &Lcp, a: &Attempt) -> LemkeOutcome {
        match a.guess.filter(|g| g.len() == lcp.size()) {
            Some(g) if self.settings.warm_start && self.id == ID => {
                solve_warm_cancellable(lcp, &self.settings, g, a.cancel)
            }
            _ => (self.engine)(lcp, &self.settings, a.cancel),
        }
    }

    /// Lemke on the frictional LCP with the default slack signs and, on a ray, with every other sign pattern of the
    /// load-driven DOFs (the same solution set; see [`crate::formulation::lcp`]). Returns the LCP that was solved
    /// (when a retry solved it) and the outcome, with the pivots of all attempts summed; `None` for a problem that
    /// is not frictional ([`ProblemKind::Frictional`]).
    pub fn frictional(&self, p: &ContactProblem) -> Option<(Option<Lcp>, LemkeOutcome)> {
        let lcp = p.lcp().filter(|_| p.kind == ProblemKind::Frictional)?;
        Some(self.frictional_from(p, lcp, &Attempt { guess: None, cancel: &Cancel::never() }))
    }

    /// [`Lemke::frictional`] on the problem's default LCP `lcp` from an attempt's start.
    fn frictional_from(&self, p: &ContactProblem, lcp: &Lcp, a: &Attempt) -> (Option<Lcp>, LemkeOutcome) {
        let mut out = self.first_attempt(lcp, a);
        let defaults: Vec<f64> = p.load_dofs().map(|d| d.default_sign()).collect();
        let loads = defaults.len();
        if out.status != Termination::RayTermination || loads == 0 {
            return (None, out);
        }
        let mut pivots = out.pivots;
        for pattern in 1..(1usize << loads) {
            if a.cancel.is_cancelled() {
                break;
            }
            let signs: Vec<f64> =
                defaults.iter().enumerate().map(|(b, s)| if pattern & (1 << b) != 0 { -s } else { *s }).collect();
            let Some(alt) = frictional_lcp(p, &signs).map(|f| f.lcp) else { break };
            let o = (self.engine)(&alt, &self.settings, a.cancel);
            pivots += o.pivots;
            if o.status == Termination::Solved {
                let msg = format!(
                    "{} (solved with flipped slack signs, attempt {} of {})",
                    o.message,
                    pattern + 1,
                    1 << loads
                );
                return (Some(alt), LemkeOutcome { pivots, message: msg, ..o });
            }
        }
        out.pivots = pivots;
        out.message = format!("{} ({} slack-sign patterns tried)", out.message, 1 << loads);
        (None, out)
    }

    /// The LCP this solver ends up solving for a problem (for `rollbem lcp export`): the default one, or the one
    /// with the slack signs of the attempt that succeeded. `None` beyond gross sliding (no static problem).
    pub fn solved_lcp(&self, p: &ContactProblem) -> Option<Lcp> {
        match self.frictional(p) {
            Some((Some(solved_by), _)) => Some(solved_by),
            _ => p.lcp().cloned(),
        }
    }
}

/// Interpret Lemke's secondary ray. A ray proves infeasibility only for a copositive-plus M, which the frictional
/// LCPs are not ([`crate::formulation::lcp`]); so `infeasible` is reported only when it is proven, with the bound
/// that is violated:
/// - |Q| > μP with both prescribed (Coulomb: |Σh| ≤ μΣf);
/// - a prescribed moment beyond `|M| ≤ P·max|x| + μP·max|y + R| + R·|Q|` (with |Q| ≤ μP when Q is not prescribed),
///   which every static solution obeys since M = Σ(x f − y h) and Σh = Q;
/// - a frictionless LCP (copositive-plus: the ray is the proof).
///
/// Otherwise the status stays `ray_termination` and the message says that feasibility is undecided.
pub fn classify_ray(status: Termination, message: String, p: &ContactProblem) -> (Termination, String) {
    if status != Termination::RayTermination {
        return (status, message);
    }
    let mu = p.law.friction;
    let r = p.flex.scales.radius();
    let l0 = p.flex.scales.length;
    let xmax = p.flex.x.iter().fold(0.0_f64, |m, v| m.max(v.abs())) * l0;
    let ymax = p.flex.y.iter().fold(0.0_f64, |m, v| m.max((v * l0 + r).abs()));
    let (normal, tangential, rotational) = (p.drive.normal, p.drive.tangential, p.drive.rotational);
    if let (Dof::Load(q), Dof::Load(pl)) = (tangential, normal) {
        if q.abs() > mu * pl {
            return (
                Termination::Infeasible,
                format!("infeasible: |Q| = {:.6e} exceeds μP = {:.6e} (Lemke: {message})", q.abs(), mu * pl),
            );
        }
    }
    if let (Dof::Load(m), Dof::Load(pl)) = (rotational, normal) {
        let qterm = match tangential {
            Dof::Load(q) => q.abs(),
            Dof::Displacement(_) => mu * pl,
        };
        let bound = pl * xmax + mu * pl * ymax + r * qterm;
        if m.abs() > bound {
            return (
                Termination::Infeasible,
                format!(
                    "infeasible: the moment |M| = {:.6e} exceeds what any static state can carry, \
                     P·max|x| + μP·max|y + R| + R·|Q| = {bound:.6e} (the pressure centre would have to leave the \
                     candidate zone, |x| ≤ {xmax:.4e}: overturning) (Lemke: {message})",
                    m.abs()
                ),
            );
        }
    }
    // The frictionless LCP is copositive-plus (K nearly SPD, skew rigid-motion coupling): its ray is a proof. The
    // frictional LCPs are not copositive-plus, and a displacement-driven contact always has a static solution, so
    // their ray is a solver failure, not a diagnosis.
    if mu == 0.0 {
        return (
            Termination::Infeasible,
            format!("infeasible: the LCP has no solution (Lemke's ray on a copositive-plus LCP: {message})"),
        );
    }
    (
        Termination::RayTermination,
        format!(
            "Lemke ended on a secondary ray with every choice of slack signs; the frictional LCP is not copositive-plus, \
             so this does not prove that no static solution exists ({message})"
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lcp(m: &[&[f64]], q: &[f64]) -> Lcp {
        let n = q.len();
        Lcp { m: Mat::from_fn(n, n, |i, j| m[i][j]), q: q.to_vec() }
    }

    #[test]
    fn solves_a_p_matrix_problem_known_by_hand() {
        // M = [[2,1],[1,2]], q = [-5,-6]: both positive, z = M⁻¹(−q) = (4/3, 7/3), w = 0 (solved by hand).
        let p = lcp(&[&[2.0, 1.0], &[1.0, 2.0]], &[-5.0, -6.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Termination::Solved);
        assert!((out.z[0] - 4.0 / 3.0).abs() < 1e-14 && (out.z[1] - 7.0 / 3.0).abs() < 1e-14);
    }

    #[test]
    fn detects_infeasibility_by_ray_termination() {
        // w1 = 0·z − 1 ≥ 0 is impossible whatever z (by inspection): Lemke must end on a secondary ray.
        let p = lcp(&[&[0.0, 0.0], &[0.0, 1.0]], &[-1.0, 1.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Termination::RayTermination);
    }

    #[test]
    fn degenerate_ties_terminate() {
        // Fully degenerate: every q equal, M with repeated columns (ties in every ratio test). The solution is
        // checked against the LCP conditions themselves.
        let p = lcp(&[&[1.0, 1.0, 1.0], &[1.0, 1.0, 1.0], &[1.0, 1.0, 2.0]], &[-1.0, -1.0, -1.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Termination::Solved, "{}", out.message);
        for i in 0..3 {
            assert!(out.w[i] >= -1e-14 && out.z[i] >= 0.0 && (out.w[i] * out.z[i]).abs() < 1e-14);
        }
    }
}
