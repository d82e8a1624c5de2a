//! A valid scene run through the model API with its work bounded, and the checks on what comes back: shared by the
//! `scene` fuzz target and `tests/fuzz_corpus.rs` (which includes this file), so that a corpus input replayed by
//! `cargo test` is run exactly as the fuzzer ran it.
//!
//! A scene whose mesh has more than [`MAX_RUN_ELEMENTS`] elements (contact + other), or whose load path has more
//! than [`MAX_SUBSTEPS`] substeps, is not run (it is only parsed and validated). A scene that is run has its
//! iteration budgets capped (every solver: Lemke 20 pivots per unknown, active set 50 iterations, PGS 2000 sweeps
//! and 50 outer iterations, NORM-TANG/QP 50 outer iterations, clarabel 100 iterations) and a `[stresses]` grid cut
//! to at most 4 × 4 points, through [`Scene::edit`], so it is validated again. Then [`Model::build`], and on `Ok`
//! [`Model::solve`] and [`Model::lcp`]: each returns `Ok` or an `Err` with a message, never panics, and a report's
//! runs are consistent: a `solved` run has finite residuals, resultants and nodal values; an unsolved one has no
//! residuals, no resultants and a message.

use rollbem::pipeline::{Model, Warm};
use rollbem::scene::{Body, Scene};
use rollbem::status::Status;

/// Largest mesh run (contact + other elements of the wheel's outer boundary): one execution stays within
/// milliseconds.
pub const MAX_RUN_ELEMENTS: usize = 24;

/// Largest number of substeps of a load path run (each is one solve per solver).
pub const MAX_SUBSTEPS: usize = 16;

/// Largest `[stresses]` grid side run (the grid is cut to this many points along x and along depth).
pub const MAX_STRESS_SIDE: usize = 4;

/// What happened to a valid scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ran {
    /// Its mesh or load path is beyond the bounds: not run.
    TooLarge,
    /// Capping its budgets made it invalid (an `Err` with a message): not run.
    CapRefused,
    /// [`Model::build`] returned an `Err` with a message.
    BuildRefused,
    /// [`Model::solve`] returned an `Err` with a message.
    SolveRefused,
    /// Solved: a report with this many runs, of which `solved` ended `solved`.
    Reported {
        /// Runs in the report.
        runs: usize,
        /// Runs with status `solved`.
        solved: usize,
    },
}

/// The elements of a scene's mesh: the contact zone's plus, for the BEM wheel, the rest of the outer boundary's (a
/// hub circle's, in proportion to its circumference, are not counted).
pub fn elements(scene: &Scene) -> usize {
    let other = match scene.body() {
        Body::Bem { other_elements, .. } => *other_elements,
        Body::HalfPlane { .. } => 0,
        // A body model added later: counted as too large to run until this bound knows it.
        _ => usize::MAX,
    };
    scene.zone().elements.saturating_add(other)
}

/// The scene with its iteration budgets and stress grid capped, or `None` when it is too large to run (`Some(Err)`
/// when the capped scene does not validate).
pub fn bounded(scene: &Scene) -> Option<rollbem::Result<Scene>> {
    let substeps = scene.steps().iter().fold(0usize, |n, s| n.saturating_add(s.substeps));
    if elements(scene) > MAX_RUN_ELEMENTS || substeps > MAX_SUBSTEPS {
        return None;
    }
    // Every solver's settings as parsed, defaults filled in; a count as written there (or its cap when absent).
    let tables = scene.solvers().settings.tables();
    let value = |solver: &str, key: &str, max: i64| {
        let mut v = tables.get(solver);
        for k in key.split('.') {
            v = v.and_then(|t| t.get(k));
        }
        v.and_then(toml::Value::as_integer).unwrap_or(max).min(max)
    };
    Some(scene.edit(|d| {
        let t = &mut d.solvers;
        t.set("lemke", "max_pivots_per_unknown", value("lemke", "max_pivots_per_unknown", 20));
        t.set("lemke_dense", "max_pivots_per_unknown", value("lemke_dense", "max_pivots_per_unknown", 20));
        t.set("active_set", "max_iterations", value("active_set", "max_iterations", 50));
        t.set("pgs", "max_sweeps", value("pgs", "max_sweeps", 2000));
        t.set("pgs", "max_outer", value("pgs", "max_outer", 50));
        t.set("normtang_qp", "max_outer", value("normtang_qp", "max_outer", 50));
        t.set("normtang_qp", "qp.max_iter", value("normtang_qp", "qp.max_iter", 100));
        t.set("clarabel", "max_iter", value("clarabel", "max_iter", 100));
        if let Some(st) = d.stresses.as_mut() {
            st.points = st.points.map(|p| p.min(MAX_STRESS_SIDE));
        }
    }))
}

/// An error must say what is wrong.
fn has_message(e: &rollbem::Error) -> bool {
    !e.to_string().trim().is_empty()
}

/// Run a valid scene through the model API within the bounds and check what comes back (panics on a violation,
/// as the fuzzer needs).
pub fn run(scene: &Scene) -> Ran {
    let scene = match bounded(scene) {
        None => return Ran::TooLarge,
        Some(Err(e)) => {
            assert!(has_message(&e), "capping: an error without a message");
            return Ran::CapRefused;
        }
        Some(Ok(s)) => s,
    };
    let model = match Model::build(&scene) {
        Ok(m) => m,
        Err(e) => {
            assert!(has_message(&e), "Model::build: an error without a message");
            return Ran::BuildRefused;
        }
    };
    if let Err(e) = model.lcp(&scene) {
        assert!(has_message(&e), "Model::lcp: an error without a message");
    }
    // Warm starts across two models (issue 31): a `Warm` written by another model's solve must be cleared, never
    // trusted, and this model's must then serve the other model the same way; neither may panic.
    let mut warm = Warm::default();
    let other = other_model();
    if let Some((m, s)) = other {
        let _ = m.solve_warm(s, &mut warm);
    }
    let report = match model.solve_warm(&scene, &mut warm) {
        Ok(r) => r,
        Err(e) => {
            assert!(has_message(&e), "Model::solve: an error without a message");
            return Ran::SolveRefused;
        }
    };
    if let Some((m, s)) = other {
        let back = m.solve_warm(s, &mut warm).expect("the fixed scene solves after a foreign warm start");
        assert!(back.runs.iter().all(|r| r.status == Status::Solved), "the fixed scene after a foreign Warm");
    }
    // And on this model again, from its own solutions (a second drive of a creep curve).
    if let Err(e) = model.solve_warm(&scene, &mut warm) {
        assert!(has_message(&e), "Model::solve_warm: an error without a message");
    }
    assert!(!report.runs.is_empty(), "a report without runs");
    let mut solved = 0;
    for run in &report.runs {
        if run.status == Status::Solved {
            solved += 1;
            let res = run.residuals.unwrap_or_else(|| panic!("{}: solved without residuals", run.solver));
            let parts = res.parts();
            assert!(parts.iter().all(|v| v.is_finite()), "{}: solved with residuals {res:?}", run.solver);
            let rs = run.resultants.unwrap_or_else(|| panic!("{}: solved without resultants", run.solver));
            assert!(
                rs.normal.is_finite() && rs.tangential.is_finite() && rs.moment.is_finite(),
                "{}: solved with resultants {rs:?}",
                run.solver
            );
            assert!(
                run.nodes.iter().all(|n| n.pressure.is_finite() && n.shear.is_finite() && n.gap.is_finite()),
                "{}: solved with non-finite nodal values",
                run.solver
            );
        } else {
            assert!(run.residuals.is_none(), "{} {}: residuals on an unsolved run", run.solver, run.status);
            assert!(run.resultants.is_none(), "{} {}: resultants on an unsolved run", run.solver, run.status);
            assert!(!run.explanation().trim().is_empty(), "{} {}: no message", run.solver, run.status);
        }
    }
    Ran::Reported { runs: report.runs.len(), solved }
}

/// A second model, built once per process from a fixed frictional half-plane scene (every solver that applies), for
/// the cross-model warm starts of [`run`]; `None` if it cannot be built (it always can: a test replays it).
fn other_model() -> Option<&'static (Model, Scene)> {
    static OTHER: std::sync::OnceLock<Option<(Model, Scene)>> = std::sync::OnceLock::new();
    OTHER
        .get_or_init(|| {
            let text = "name = \"other\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
                        model = \"half_plane\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\n\
                        contact_elements = 24\n[contact]\nfriction = 0.3\n[drive]\nnormal_load = 1000.0\n\
                        tangential_shift = -0.0004\n[solvers]\nuse = [\"all\", \"lemke_dense\"]\n";
            let scene = Scene::from_toml(text, std::path::Path::new("<other>")).ok()?;
            Some((Model::build(&scene).ok()?, scene))
        })
        .as_ref()
}
