//! The pipeline: a [`Model`] is built once from a valid scene — the mesh, the BEM assembly and its condensation to
//! the contact flexibility (or the half-plane's influence coefficients) — and solved for as many drives as the
//! caller has: a creep curve, a family of loads, a load path, every case of a sweep that shares bodies and mesh.
//!
//! Its files are its stages: [`stages`] (what every solve shares: the problem, the solvers, a timed solve, the
//! verdict, the document), `single` (one step from rest) and `path` (a load path with memory). A solve returns
//! the result document ([`crate::results::Report`]); a problem without a solution is a status in it, never an
//! error, and no entry point panics on a validated scene.
//!
//! ```
//! use rollbem::pipeline::Model;
//! use rollbem::scene::Scene;
//! use rollbem::status::Status;
//! let scene = Scene::from_toml(
//!     r#"
//! name = "carter"
//! [wheel]
//! radius = 500.0
//! youngs_modulus = 209920.0
//! poisson_ratio = 0.28
//! model = "half_plane"
//! [counter_body]
//! kind = "half_plane"
//! youngs_modulus = 209920.0
//! poisson_ratio = 0.28
//! [mesh]
//! element = "constant"
//! contact_half_width = 1.5
//! contact_elements = 60
//! [contact]
//! friction = 0.3
//! [drive]
//! normal_load = 178.9
//! [rolling]
//! mode = "steady"
//! creepage = -1e-4
//! direction = 1
//! [solvers]
//! use = ["active_set"]
//! "#,
//!     std::path::Path::new("carter.toml"),
//! )
//! .unwrap();
//! // Build once, solve a creep curve on the same flexibility.
//! let model = Model::build(&scene).unwrap();
//! let mut forces = Vec::new();
//! for xi in [-1e-4, -2e-4, -4e-4] {
//!     let report = model.solve(&scene.with_creepage(xi).unwrap()).unwrap();
//!     let run = &report.runs[0];
//!     assert_eq!(run.status, Status::Solved);
//!     forces.push(run.resultants.unwrap().tangential);
//! }
//! // The creep force grows with the creepage (Carter), and the flexibility was built once.
//! assert!(forces[0] < forces[1] && forces[1] < forces[2]);
//! assert_eq!(model.solves(), 3);
//! ```

mod path;
mod single;
pub mod space;
mod space_checks;
pub mod stages;
mod veldep;

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::formulation::Lcp;
use crate::results::{Report, Setup};
use crate::scene::{Loading, Scene};
use crate::source::{self, Blocks, Built, SourceTiming};
use std::sync::atomic::{AtomicUsize, Ordering};

pub use space::{run_space_scene, SpaceModel};
pub use space_checks::fit_ellipse;

/// A scene's flexibility, built once and solved for many drives (see the module docs).
#[derive(Debug)]
pub struct Model {
    /// The scene it was built for.
    scene: Scene,
    /// The flexibility (and, for a BEM wheel with `[stresses]`, its boundary response).
    built: Built,
    /// Which blocks were built.
    blocks: Blocks,
    /// Number of solves so far.
    solves: AtomicUsize,
}

impl Model {
    /// Build the flexibility of a scene: the mesh, the BEM system and its condensation (a BEM wheel) or the
    /// half-plane's influence coefficients, plus an elastic counter-body's; only the blocks the scene needs.
    ///
    /// # Errors
    /// [`Error::Numerical`] when the BEM system is singular or not finite (a degenerate mesh or support).
    pub fn build(scene: &Scene) -> Result<Model> {
        scene.runnable()?;
        veldep::applies(scene)?;
        let blocks = stages::blocks_for(scene);
        let built = source::build(scene, blocks)?;
        Ok(Model { scene: scene.clone(), built, blocks, solves: AtomicUsize::new(0) })
    }

    /// The scene the model was built for.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The built flexibility.
    pub fn built(&self) -> &Built {
        &self.built
    }

    /// The contact law the model simulates for `scene`: the scene's, without coupling where the pair's cross
    /// flexibilities vanish ([`stages::simulated_law`]); what a caller posing its own `ContactProblem` on
    /// [`Model::built`] must use.
    pub fn law(&self, scene: &Scene) -> crate::formulation::ContactLaw {
        stages::simulated_law(scene)
    }

    /// The time the build took, per stage (seconds).
    pub fn timing(&self) -> SourceTiming {
        self.built.timing
    }

    /// How many solves the model has done.
    pub fn solves(&self) -> usize {
        self.solves.load(Ordering::Relaxed)
    }

    /// Whether `scene` can be solved on this model: the same bodies, mesh and candidate zone (and counter-body), the
    /// tangential blocks when it needs them, the boundary response when it asks for a BEM wheel's stresses. `Err`
    /// names the part of the scene that differs.
    pub fn accepts(&self, scene: &Scene) -> Result<()> {
        scene.runnable()?;
        let m = &self.scene;
        let differs = |field: &str, what: &str| Error::Invalid {
            path: scene.origin().to_path_buf(),
            field: field.into(),
            message: format!(
                "{what} differs from the scene the model was built for ({}): build a model for this scene",
                m.name()
            ),
        };
        if let Some((field, what)) = source_difference(m, scene) {
            return Err(differs(field, what));
        }
        let needed = stages::blocks_for(scene);
        if needed > Blocks::Normal && self.blocks == Blocks::Normal {
            return Err(differs("contact.friction", "friction or rolling (the model holds the normal problem only)"));
        }
        if needed == Blocks::All && self.blocks < Blocks::All {
            return Err(differs("contact.coupling", "normal–tangential coupling (the model was built without it)"));
        }
        if scene.stresses().is_some()
            && crate::mesh::MeshSpec::of_scene(scene).is_some()
            && self.built.boundary.is_none()
        {
            return Err(differs("stresses", "asking for the BEM wheel's stresses"));
        }
        Ok(())
    }

    /// Whether two scenes have the same flexibility source (bodies, mesh, zone, counter-body): one model, built from
    /// the one that [`Model::needs`] more, solves both.
    pub fn shares_source(a: &Scene, b: &Scene) -> bool {
        source_difference(a, b).is_none()
    }

    /// What a scene needs of a model beyond its source, ordered: (the tangential blocks, the BEM wheel's boundary
    /// response for stresses). A model built from the scene that needs the most accepts every scene sharing its
    /// source.
    pub fn needs(scene: &Scene) -> (Blocks, bool) {
        (stages::blocks_for(scene), scene.stresses().is_some())
    }

    /// Solve a scene on this model: its one-step drive or its load path, with its friction, rolling, solvers and
    /// checks. The scene must share the model's bodies and mesh ([`Model::accepts`]).
    ///
    /// The runs' timings carry the model's build time (assembly, condensation) as the cost of their answer, marked
    /// [`Setup::Built`] on the model's first solve and [`Setup::Reused`] after it.
    pub fn solve(&self, scene: &Scene) -> Result<Report> {
        self.solve_warm(scene, &mut Warm::default())
    }

    /// [`Model::solve`] from the solutions of a neighbouring drive, and leave this solve's solutions in `warm` for
    /// the next one: the creep curve's next creepage, the family's next load. Each solver that can starts from what
    /// its own previous run left (the active-set method from its node states and factorisations, Lemke from its
    /// basis, NORM-TANG from its forces); a solver with nothing in `warm` starts cold. The answer does not depend on
    /// the start (each run is certified by the same residuals); the work does. `warm` belongs to one model: a `Warm`
    /// written by another model is cleared before the solve, never trusted. A load path starts every solver from its
    /// previous substep anyway and neither reads nor writes `warm`.
    pub fn solve_warm(&self, scene: &Scene, warm: &mut Warm) -> Result<Report> {
        self.solve_with(scene, warm, &Cancel::never())
    }

    /// [`Model::solve_warm`], stopped by `cancel`: a load path before its next substep, every solver at its next
    /// iteration.
    ///
    /// # Errors
    /// As [`Model::solve`], and [`Error::Cancelled`] when `cancel` was raised before the solve finished (nothing is
    /// returned of it; `warm` keeps what the runs before the cancellation left).
    pub fn solve_with(&self, scene: &Scene, warm: &mut Warm, cancel: &Cancel) -> Result<Report> {
        self.accepts(scene)?;
        cancel.check()?;
        warm.adopt(self.built.flex.id.get());
        let setup = match self.solves.fetch_add(1, Ordering::Relaxed) {
            0 => Setup::Built,
            _ => Setup::Reused,
        };
        match scene.loading() {
            Loading::Drive(drive) => single::solve(scene, *drive, &self.built, setup, warm, cancel),
            Loading::Path(steps) => path::solve(scene, steps, &self.built, setup, cancel),
        }
    }

    /// The size guard of a list of `count` drives solved on this model at once (e.g. Python's `Model.solve_all`,
    /// which keeps every report): refused, before anything is solved, when the reports would need more than
    /// [`crate::scene::MAX_PATH_RESULT_BYTES`] (count × solvers × contact nodes ×
    /// [`crate::scene::PATH_BYTES_PER_NODE`], the estimate of a load path's substeps).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `drives` with the estimate.
    pub fn check_result_count(&self, count: usize) -> Result<()> {
        let set = self.scene.solvers();
        let solvers = if set.all { crate::solvers::registry().len() } else { set.named.len().max(1) };
        let bytes =
            count as u128 * solvers as u128 * self.built.flex.n() as u128 * crate::scene::PATH_BYTES_PER_NODE as u128;
        if bytes > u128::from(crate::scene::MAX_PATH_RESULT_BYTES) {
            return Err(Error::Invalid {
                path: self.scene.origin().to_path_buf(),
                field: "drives".into(),
                message: format!(
                    "{count} drives would keep about {:.1} GiB of reports ({count} × {solvers} solver(s) × {} contact \
                     nodes); at most {:.0} GiB at once: solve them in batches",
                    bytes as f64 / (1u64 << 30) as f64,
                    self.built.flex.n(),
                    crate::scene::MAX_PATH_RESULT_BYTES as f64 / (1u64 << 30) as f64
                ),
            });
        }
        Ok(())
    }

    /// Solve many scenes sharing the model's bodies and mesh, in order (a creep curve, a family of loads), each
    /// from the previous one's solutions ([`Model::solve_warm`]).
    pub fn solve_all<'a>(&self, scenes: impl IntoIterator<Item = &'a Scene>) -> Result<Vec<Report>> {
        let mut warm = Warm::default();
        scenes.into_iter().map(|s| self.solve_warm(s, &mut warm)).collect()
    }

    /// The LCP that Lemke solves for a one-step scene (`rollbem lcp export`); a load path, or a load beyond gross
    /// sliding, has none (an error saying why).
    pub fn lcp(&self, scene: &Scene) -> Result<Lcp> {
        self.accepts(scene)?;
        match scene.loading() {
            Loading::Drive(drive) => single::lcp(scene, *drive, &self.built),
            Loading::Path(_) => Err(Error::Unsupported {
                path: scene.origin().to_path_buf(),
                message: "steps: a load path is a sequence of LCPs, one per substep; export a one-step scene".into(),
            }),
        }
    }
}

/// What a solve leaves for the next solve on the same model, per solver: its certified solution (dimensionless, in
/// the model's unknowns) and its own state ([`crate::solvers::SolverState`]: Lemke's basis, the active-set method's
/// factorisations), see [`Model::solve_warm`]. It records the model it belongs to (the identity of the model's
/// flexibility): a solve on another model clears it first. Each solver's state is handed back only to that solver
/// on a problem of the same layout; a solution only when it has the problem's shape.
#[derive(Debug, Default)]
pub struct Warm {
    model: Option<u64>,
    entries: Vec<WarmEntry>,
}

/// One solver's part of a [`Warm`].
#[derive(Debug)]
struct WarmEntry {
    solver: crate::solvers::SolverId,
    solution: Option<crate::formulation::Solution>,
    state: Option<crate::solvers::SolverState>,
}

impl Warm {
    /// The solution the solver's last run left, if any.
    pub fn get(&self, solver: crate::solvers::SolverId) -> Option<&crate::formulation::Solution> {
        self.entries.iter().find(|e| e.solver == solver).and_then(|e| e.solution.as_ref())
    }

    /// Whether it holds anything for `solver` (a solution or a state).
    pub fn holds(&self, solver: crate::solvers::SolverId) -> bool {
        self.entries.iter().any(|e| e.solver == solver && (e.solution.is_some() || e.state.is_some()))
    }

    /// The identity of the model it belongs to (`None` before its first solve).
    pub fn model(&self) -> Option<u64> {
        self.model
    }

    /// Belong to the model whose flexibility has identity `model`: a `Warm` of another model is cleared (not
    /// trusted). Returns whether it was cleared.
    pub fn adopt(&mut self, model: u64) -> bool {
        let other = self.model.is_some_and(|m| m != model);
        if other {
            self.entries.clear();
        }
        self.model = Some(model);
        other
    }

    /// The start of `solver`'s next run: its solution (cloned) and its state (taken: a run consumes it), with the
    /// caller's cancellation token.
    pub fn start(&mut self, solver: crate::solvers::SolverId, cancel: &Cancel) -> crate::solvers::Start {
        let entry = self.entries.iter_mut().find(|e| e.solver == solver);
        crate::solvers::Start {
            solution: entry.as_ref().and_then(|e| e.solution.clone()),
            state: entry.and_then(|e| e.state.take()),
            cancel: cancel.clone(),
        }
    }

    /// Keep a solver's run (replacing its previous one): its solution when certified, and its state; a run without
    /// a certified solution clears the solution, so that a failed case does not start the next from a stale one.
    pub fn set(
        &mut self,
        solver: crate::solvers::SolverId,
        solution: Option<crate::formulation::Solution>,
        state: Option<crate::solvers::SolverState>,
    ) {
        self.entries.retain(|e| e.solver != solver);
        if solution.is_some() || state.is_some() {
            self.entries.push(WarmEntry { solver, solution, state });
        }
    }

    /// Forget every solution and state.
    pub fn clear(&mut self) {
        self.entries.clear();
    }
}

/// The first part of the flexibility source in which two scenes differ: (key, what), or `None`.
fn source_difference(a: &Scene, b: &Scene) -> Option<(&'static str, &'static str)> {
    if a.wheel() != b.wheel() {
        Some(("wheel", "the wheel's radius or material"))
    } else if a.strip_width() != b.strip_width() {
        Some(("mesh.strip_width", "the strip of half-spaces (or plane strain)"))
    } else if a.body() != b.body() {
        Some(("wheel.model", "the wheel's model, support or mesh"))
    } else if a.zone() != b.zone() {
        Some(("mesh", "the candidate contact zone or its elements"))
    } else if a.counter_body() != b.counter_body() {
        Some(("counter_body", "the counter-body"))
    } else if a.viscoelastic_memories() != b.viscoelastic_memories() {
        Some(("rolling.velocity", "the viscoelastic bodies' relaxation distance (rolling speed or direction)"))
    } else {
        None
    }
}

/// Build a scene's model and solve the scene once (what `rollbem run` does for each scene).
pub fn run_scene(scene: &Scene) -> Result<Report> {
    Model::build(scene)?.solve(scene)
}
