//! Contact solvers behind one small trait ([`Solver`]), chosen by name in one registry ([`registry`]): the only
//! place solver names are listed. Scenes (`[solvers] use`, `[solvers.NAME]` settings tables), `--solver`,
//! `rollbem lcp solve`, sweeps and reports all read it.
//!
//! A solver consumes a [`ContactProblem`] (plain data) and a [`Start`] (a nearby solution, its own state from its
//! previous run on the same flexibility and problem layout, and a cancellation token), and returns one [`Outcome`]:
//! the solution in the problem's one solution shape, a [`Termination`], a message, its work as named counters, its
//! own figures as named values, and the state it leaves for its next run. Non-convergence, ray termination and
//! infeasibility are terminations, never panics; a bad setting is an input error ([`SettingsError`]) raised when the
//! scene is read, before anything runs. Each back end's own status maps to [`Termination`] in one place (its file).
//!
//! **Adding a solver** is one file and one registry line: the file holds its settings (serde, [`Validate`]), its
//! [`Solver`] impl, its state type if it keeps one, and an [`Entry`] (`Entry::new::<Settings>(...)`); the line adds
//! the entry to [`BUILT_IN`]. A program that uses rollbem as a library can also plug in a solver of its own at run
//! time ([`register`]); `tests/solver_plugin.rs` does that with a solver written in `tests/` and runs it through the
//! model, the sweep and the command line.
//!
//! **State between solves** ([`SolverState`]): a solver may leave what it wants to start its next run from (Lemke
//! its basis, the active-set method its factorisations, NORM-TANG its forces), typed by the solver and stamped with
//! the flexibility ([`crate::flexibility::FlexId`]) and the problem's layout ([`Layout`]); it is handed back only to
//! the same solver on a problem of the same layout on the same flexibility, so a state from another model or
//! another drive layout is dropped, never trusted. The caller owns it ([`crate::pipeline::Warm`]): nothing is
//! cached in the flexibility, and concurrent solves on one model share nothing mutable.

pub mod active_set;
pub(crate) mod clarabel;
pub(crate) mod clarabel_box;
pub mod clarabel_qp;
pub mod lemke;
pub mod normtang;

pub use crate::formulation::Lcp;
pub use crate::status::{Status, Termination};

use crate::cancel::Cancel;
use crate::formulation::{ContactProblem, DofKind, Solution};
use crate::tolerances as tol;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::any::Any;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The solvers built into rollbem, in the order runs are reported.
pub static BUILT_IN: &[&Entry] = &[
    &lemke::ENTRY,
    &active_set::ENTRY,
    &clarabel::ENTRY,
    &normtang::PGS_ENTRY,
    &normtang::NORMTANG_QP_ENTRY,
    &lemke::dense::ENTRY,
];

/// Solvers registered at run time ([`register`]), after the built-in ones.
static REGISTERED: std::sync::RwLock<Vec<&'static Entry>> = std::sync::RwLock::new(Vec::new());

/// Every solver: the built-in ones ([`BUILT_IN`]), then those registered at run time ([`register`]), in the order
/// runs are reported.
pub fn registry() -> Vec<&'static Entry> {
    let extra = REGISTERED.read().unwrap_or_else(std::sync::PoisonError::into_inner);
    BUILT_IN.iter().copied().chain(extra.iter().copied()).collect()
}

/// Plug a solver of one's own into this process's registry: scenes can then name it in `[solvers] use` and
/// `[solvers.NAME]`, and the model, sweeps, reports and (for a program that runs [`crate::cli`]) the command line run
/// it like a built-in one. `Err` when its name is taken or is not a valid scene key (lowercase letters, digits, `_`).
pub fn register(entry: &'static Entry) -> Result<(), String> {
    let name = entry.id.name();
    let valid = !name.is_empty()
        && name != "all"
        && name != "use"
        && name.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    if !valid {
        return Err(format!("solver name `{name}`: lowercase letters, digits and `_`, not `all` or `use`"));
    }
    let mut extra = REGISTERED.write().unwrap_or_else(std::sync::PoisonError::into_inner);
    if BUILT_IN.iter().chain(extra.iter()).any(|e| e.id.name() == name) {
        return Err(format!("a solver named `{name}` is registered already"));
    }
    extra.push(entry);
    Ok(())
}

/// A solver's identity: its registry name, as written in scene files (`[solvers] use`), on the command line and in
/// results. Ordered as the registry reports runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SolverId(&'static str);

impl SolverId {
    /// The identity of a solver named `name` (for its [`Entry`]; use [`SolverId::from_name`] to look one up).
    pub const fn new(name: &'static str) -> SolverId {
        SolverId(name)
    }

    /// Its registry entry, if it is registered.
    pub fn entry(self) -> Option<&'static Entry> {
        registry().into_iter().find(|e| e.id == self)
    }

    /// Its name.
    pub fn name(self) -> &'static str {
        self.0
    }

    /// The registered solver of a name, if there is one.
    pub fn from_name(name: &str) -> Option<SolverId> {
        registry().into_iter().find(|e| e.id.0 == name).map(|e| e.id)
    }

    /// Its place among the built-in solvers (every other identity after them, by name): fixed for the process's
    /// life, so an ordered map of identities stays ordered whatever is registered later.
    fn rank(self) -> usize {
        BUILT_IN.iter().position(|e| e.id == self).unwrap_or(usize::MAX)
    }

    /// Build the solver with the given settings (validated settings of every registered solver; a solver with no
    /// table there gets its defaults). `None` for an unregistered identity.
    pub fn build(self, settings: &SolverSettings) -> Option<Box<dyn Solver>> {
        let entry = self.entry()?;
        Some(match settings.get(self) {
            Some(s) => (entry.build)(self, s),
            None => (entry.build)(self, (entry.defaults)().as_ref()),
        })
    }
}

impl PartialOrd for SolverId {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for SolverId {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.rank().cmp(&other.rank()).then_with(|| self.0.cmp(other.0))
    }
}

impl std::fmt::Display for SolverId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}

impl PartialEq<str> for SolverId {
    fn eq(&self, other: &str) -> bool {
        self.name() == other
    }
}

impl PartialEq<&str> for SolverId {
    fn eq(&self, other: &&str) -> bool {
        self.name() == *other
    }
}

impl Serialize for SolverId {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.0)
    }
}

impl<'de> Deserialize<'de> for SolverId {
    /// A solver's name: a registered one, or any other (a result document written by a program with a solver of its
    /// own plugged in is read by one without it; its runs keep their solver's name). A scene validates the names it
    /// gives against the registry (`solvers.use`, `checks.solver_status`).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<SolverId, D::Error> {
        let name = String::deserialize(d)?;
        Ok(SolverId::from_name(&name).unwrap_or_else(|| SolverId::interned(&name)))
    }
}

impl SolverId {
    /// The identity of a name that is not registered (read from a document): each distinct name is kept once for
    /// the process's life, so that identities stay `Copy` and `'static`.
    fn interned(name: &str) -> SolverId {
        static NAMES: std::sync::Mutex<Vec<&'static str>> = std::sync::Mutex::new(Vec::new());
        let mut names = NAMES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        match names.iter().find(|n| **n == name) {
            Some(n) => SolverId(n),
            None => {
                let leaked: &'static str = Box::leak(name.to_string().into_boxed_str());
                names.push(leaked);
                SolverId(leaked)
            }
        }
    }
}

/// Builds a solver from its identity and its own (validated) settings, as the registry hands them out (the
/// identity lets one builder serve several entries, e.g. solvers registered at run time by name).
pub type Builder = fn(SolverId, &dyn Settings) -> Box<dyn Solver>;

/// Parses and validates a solver's settings table (its name for the messages; `None`: the defaults).
pub type Parser = fn(&str, Option<&toml::Value>) -> Result<Arc<dyn Settings>, SettingsError>;

/// One registered solver: everything the rest of rollbem knows of it.
pub struct Entry {
    /// Its identity (its name).
    pub id: SolverId,
    /// One line: what it is and what it applies to.
    pub summary: &'static str,
    /// Whether `use = ["all"]` runs it (a slower reference engine is run by name only).
    pub in_all: bool,
    /// The work counters it reports, in display order (the sweep CSV's work columns are their union).
    pub counters: &'static [&'static str],
    /// Parse and validate its settings table (`None`: the defaults); errors name `solvers.NAME.KEY`.
    pub parse: Parser,
    /// Its default settings.
    pub defaults: fn() -> Arc<dyn Settings>,
    /// Build the solver from its settings.
    pub build: Builder,
    /// Its rough cost on m complementarity unknowns: (seconds, bytes), for a sweep's estimate
    /// ([`crate::sweep`]'s plan; a rough model, meant to tell minutes from days).
    pub cost: fn(f64) -> (f64, f64),
}

impl Entry {
    /// An entry whose settings are `T` (parsed from the `[solvers.NAME]` table with serde, validated by
    /// [`Validate`], defaults by `Default`); `build` receives them typed.
    pub const fn new<T>(
        name: &'static str,
        summary: &'static str,
        in_all: bool,
        counters: &'static [&'static str],
        build: Builder,
        cost: fn(f64) -> (f64, f64),
    ) -> Entry
    where
        T: SettingsType,
    {
        Entry {
            id: SolverId::new(name),
            summary,
            in_all,
            counters,
            parse: |name, raw| parse_settings::<T>(name, raw).map(|t| Arc::new(t) as Arc<dyn Settings>),
            defaults: || Arc::new(T::default()),
            build,
            cost,
        }
    }

    /// Its name.
    pub fn name(&self) -> &'static str {
        self.id.name()
    }
}

/// What a settings type must be: a serde table with defaults and range checks.
pub trait SettingsType:
    Serialize + DeserializeOwned + Default + Clone + PartialEq + std::fmt::Debug + Validate + Send + Sync + 'static
{
}

impl<T> SettingsType for T where
    T: Serialize + DeserializeOwned + Default + Clone + PartialEq + std::fmt::Debug + Validate + Send + Sync + 'static
{
}

/// One solver's settings, typed by its solver and seen by the rest of rollbem only through this trait.
pub trait Settings: std::fmt::Debug + Send + Sync + Any {
    /// The settings as a TOML table, every default filled in (the scene as parsed).
    fn table(&self) -> toml::Value;
    /// The relative tolerance an iterative solver stops at (`None` for a direct one).
    fn tolerance(&self) -> Option<f64>;
    /// Equality with another solver's settings (false for another type).
    fn same(&self, other: &dyn Settings) -> bool;
    /// As `Any`, for [`settings_of`].
    fn as_any(&self) -> &dyn Any;
}

impl<T: SettingsType> Settings for T {
    fn table(&self) -> toml::Value {
        settings_value(self)
    }

    fn tolerance(&self) -> Option<f64> {
        Validate::tolerance(self)
    }

    fn same(&self, other: &dyn Settings) -> bool {
        other.as_any().downcast_ref::<T>() == Some(self)
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// A solver's own settings, typed (in its [`Entry::build`]): the registry hands every solver the type its entry
/// parsed, so this is `Some` there; `None` for another type.
pub fn settings_of<T: 'static>(s: &dyn Settings) -> Option<&T> {
    s.as_any().downcast_ref::<T>()
}

/// The settings of every solver a scene names (`[solvers.NAME]` tables), typed by their solvers, validated when
/// a scene is read ([`SolverSettings::from_tables`]) — no solver is built for that — so that a bad value is an
/// input error naming its key before anything runs. A solver without a table has its defaults.
#[derive(Debug, Clone, Default)]
pub struct SolverSettings(BTreeMap<SolverId, Arc<dyn Settings>>);

impl PartialEq for SolverSettings {
    fn eq(&self, other: &Self) -> bool {
        self.0.len() == other.0.len() && self.0.iter().zip(&other.0).all(|((a, x), (b, y))| a == b && x.same(&**y))
    }
}

impl SolverSettings {
    /// Parse and validate the settings tables of a scene (`[solvers.NAME]`, keyed by solver name; absent tables take
    /// the defaults). An unknown table or key, or a value out of range, is an error naming `solvers.NAME.KEY`.
    pub fn from_tables(tables: &BTreeMap<String, toml::Value>) -> Result<SolverSettings, SettingsError> {
        let mut out = BTreeMap::new();
        for (k, v) in tables {
            let Some(entry) = SolverId::from_name(k).and_then(SolverId::entry) else {
                return Err(SettingsError {
                    field: format!("solvers.{k}"),
                    message: format!("unknown solver settings table (solvers are: {})", names()),
                    unknown: true,
                });
            };
            out.insert(entry.id, (entry.parse)(entry.name(), Some(v))?);
        }
        Ok(SolverSettings(out))
    }

    /// The settings of one solver, if the scene gave a table for it (else the solver takes its defaults).
    pub fn get(&self, id: SolverId) -> Option<&dyn Settings> {
        self.0.get(&id).map(|s| &**s)
    }

    /// The settings as tables keyed by solver name, every default filled in (the scene as parsed): every built-in
    /// solver's, and a solver registered at run time only when the scene gave its table (a scene that does not name
    /// a plug-in writes no trace of it, and stays readable where it is not registered).
    pub fn tables(&self) -> BTreeMap<String, toml::Value> {
        registry()
            .into_iter()
            .filter(|e| BUILT_IN.iter().any(|b| b.id == e.id) || self.0.contains_key(&e.id))
            .map(|e| {
                let table = match self.get(e.id) {
                    Some(s) => s.table(),
                    None => (e.defaults)().table(),
                };
                (e.name().to_string(), table)
            })
            .collect()
    }

    /// The relative tolerance an iterative solver stops at with these settings (`None` for a direct one or an
    /// unregistered identity).
    pub fn tolerance(&self, id: SolverId) -> Option<f64> {
        match self.get(id) {
            Some(s) => s.tolerance(),
            None => id.entry().and_then(|e| (e.defaults)().tolerance()),
        }
    }
}

/// The layout of a problem's unknowns, with the identity of the flexibility it is posed on: what a solver's state
/// must match to be reused ([`SolverState`]). Two problems of one layout have the same number of contact nodes,
/// the same kind (frictionless, frictional, at the sliding limit), and the same rigid degrees of freedom, each
/// prescribed or unknown alike; the LCPs they pose then have the same size and block structure.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    flexibility: u64,
    nodes: usize,
    kind: u8,
    dofs: Vec<(DofKind, bool)>,
}

impl Layout {
    /// The layout of a problem.
    pub fn of(p: &ContactProblem) -> Layout {
        use crate::formulation::ProblemKind as K;
        let kind = match p.kind {
            K::Frictionless => 0,
            K::Frictional => 1,
            K::SlidingLimit { .. } => 2,
            K::GrossSliding { .. } => 3,
        };
        let dofs = p.dofs.iter().map(|d| (d.kind, p.is_unknown(d))).collect();
        Layout { flexibility: p.flex.id.get(), nodes: p.n(), kind, dofs }
    }
}

/// A solver's own state after a run, for its next run: typed by the solver (its own type `T`, opaque to the rest of
/// rollbem), stamped with the solver and the problem's [`Layout`] (the flexibility's identity included). It is handed
/// back ([`Start::take_state`]) only to the same solver on a problem of the same layout.
pub struct SolverState {
    solver: SolverId,
    layout: Layout,
    data: Box<dyn Any + Send + Sync>,
}

impl SolverState {
    /// Keep `data` as `solver`'s state after a run on `problem`.
    pub fn new<T: Send + Sync + 'static>(solver: SolverId, problem: &ContactProblem, data: T) -> SolverState {
        SolverState { solver, layout: Layout::of(problem), data: Box::new(data) }
    }

    /// Which solver left it.
    pub fn solver(&self) -> SolverId {
        self.solver
    }

    /// Whether it was left by `solver` on a problem of `problem`'s layout (same flexibility, same unknowns).
    pub fn fits(&self, solver: SolverId, problem: &ContactProblem) -> bool {
        self.solver == solver && self.layout == Layout::of(problem)
    }
}

impl std::fmt::Debug for SolverState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "SolverState({} on {:?})", self.solver, self.layout)
    }
}

/// What a solve starts from: a nearby solution (the previous drive's or substep's, in the problem's unknowns), the
/// solver's own state from its previous run, and the caller's cancellation token. [`Start::cold`] has none of
/// them. A solver must not trust either blindly: [`Start::solution_for`] and [`Start::take_state`] hand them out
/// only when they fit the problem.
#[derive(Debug, Default)]
pub struct Start {
    /// A nearby solution (see [`Start::solution_for`]).
    pub solution: Option<Solution>,
    /// The solver's own state from its previous run (see [`Start::take_state`]).
    pub state: Option<SolverState>,
    /// The caller's cancellation token: a solver checks it at each iteration and returns promptly when it is
    /// raised, with a termination other than `solved` (the pipeline then returns `Error::Cancelled` rather than a
    /// run).
    pub cancel: Cancel,
}

impl Start {
    /// No start: the solver's cold start, not cancellable.
    pub fn cold() -> Start {
        Start::default()
    }

    /// A cold start with a cancellation token.
    pub fn cancellable(cancel: Cancel) -> Start {
        Start { cancel, ..Start::default() }
    }

    /// The nearby solution, if it has the problem's shape: f of n nodes, h of n nodes or none, one value per rigid
    /// DOF, every value finite. A solution of another shape is ignored (a cold start), never indexed.
    pub fn solution_for(&self, p: &ContactProblem) -> Option<&Solution> {
        self.solution
            .as_ref()
            .filter(|w| w.fits(p) && w.f.iter().chain(w.h.iter().flatten()).chain(&w.rigid).all(|v| v.is_finite()))
    }

    /// Take the solver's own state, typed, if it was left by `solver` on a problem of `p`'s layout and is a `T`;
    /// otherwise drop it (`None`: a cold start).
    pub fn take_state<T: 'static>(&mut self, solver: SolverId, p: &ContactProblem) -> Option<T> {
        let state = self.state.take().filter(|s| s.fits(solver, p))?;
        state.data.downcast::<T>().ok().map(|b| *b)
    }
}

/// The facts about a contact problem that decide whether a solver can take it ([`Solver::admits`]). Each is visible
/// in the scene that poses the problem, so that a scene naming a solver that cannot take it is refused when it is
/// read, by the rule the run applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Facts {
    /// Coulomb friction, μ > 0.
    pub friction: bool,
    /// The drive prescribes a moment (the rotation is load-driven); of a scene: at some step of its load path.
    pub moment_load: bool,
    /// Steady rolling: the tangential operator is the steady-rolling one (its tangential DOF the creepage).
    pub steady_rolling: bool,
    /// Both loads prescribed with |Q| = μP: the sliding limit ([`crate::formulation::ProblemKind::SlidingLimit`]);
    /// of a scene: its one-step drive (a load path's substeps are known only as it is walked).
    pub sliding_limit: bool,
}

impl Facts {
    /// The facts of a problem.
    pub fn of(p: &ContactProblem) -> Facts {
        Facts {
            friction: p.law.friction > 0.0,
            moment_load: matches!(p.drive.rotational, crate::formulation::Dof::Load(_)),
            steady_rolling: p.slip.is_steady(),
            sliding_limit: matches!(p.kind, crate::formulation::ProblemKind::SlidingLimit { .. }),
        }
    }
}

/// A contact solver (see the module docs).
pub trait Solver: Send + Sync {
    /// Its identity.
    fn id(&self) -> SolverId;

    /// Its registry name.
    fn name(&self) -> &'static str {
        self.id().name()
    }

    /// Whether it can take a problem of these facts ([`Facts`]: each visible in the scene that poses the problem);
    /// `Err` says why not. The one rule of the solver's scene-level limits: a scene that names the solver is refused
    /// by it when it is read (`solvers.use`), and a problem by it through [`Solver::applies`]. Default: every problem.
    fn admits(&self, _facts: &Facts) -> Result<(), String> {
        Ok(())
    }

    /// Whether it applies to a problem; `Err` says why not. Default: [`Solver::admits`] of the problem's
    /// [`Facts`].
    fn applies(&self, problem: &ContactProblem) -> Result<(), String> {
        self.admits(&Facts::of(problem))
    }

    /// Solve from a start (a nearby solution, its own state, a cancellation token). Called only when
    /// [`Solver::applies`] is `Ok` and the problem has a static solution to look for.
    fn solve_from(&self, problem: &ContactProblem, start: Start) -> Outcome;

    /// Solve from the cold start ([`Start::cold`]).
    fn solve(&self, problem: &ContactProblem) -> Outcome {
        self.solve_from(problem, Start::cold())
    }

    /// The relative tolerance it stops at, for an iterative solver (`None` for a direct one).
    fn tolerance(&self) -> Option<f64> {
        None
    }

    /// Whether the solver solves the problem's LCP ([`ContactProblem::lcp`]): the harness then builds it before the
    /// solve and counts its time as formulation time, as for a solver on the physical unknowns it is not built.
    fn uses_lcp(&self) -> bool {
        false
    }

    /// The solver as a solver of bare LCPs (`rollbem lcp solve`), if it is one.
    fn lcp_solver(&self) -> Option<&dyn LcpSolver> {
        None
    }
}

/// A solver of bare LCPs `w = M z + q ≥ 0, z ≥ 0, wᵀz = 0` (`rollbem lcp solve`, LCP files).
pub trait LcpSolver {
    /// Solve the LCP.
    fn solve_lcp(&self, lcp: &Lcp) -> LcpOutcome;
}

/// What a solver of bare LCPs returns.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct LcpOutcome {
    /// z; when not solved, the solver's last iterate (not a solution).
    pub z: Vec<f64>,
    /// w = M z + q, recomputed from z.
    pub w: Vec<f64>,
    /// How the solver ended.
    pub termination: Termination,
    /// Detail (which variable ended it, etc.).
    pub message: String,
    /// Work counters.
    pub work: Work,
}

impl LcpOutcome {
    /// What a solver of bare LCPs returns: its z (the last iterate when not solved), w = M z + q, how it ended, a
    /// message and its work counters.
    pub fn new(z: Vec<f64>, w: Vec<f64>, termination: Termination, message: String, work: Work) -> LcpOutcome {
        LcpOutcome { z, w, termination, message, work }
    }
}

/// (check bound, refusal bound) on a run's largest solver-independent residual: direct solvers are held to
/// round-off, an iterative solver stopped at τ to [`tol::ITERATIVE_RESIDUAL_FACTOR`] τ.
pub fn residual_bounds(solver: &dyn Solver) -> (f64, f64) {
    let f = tol::ITERATIVE_RESIDUAL_FACTOR * solver.tolerance().unwrap_or(0.0);
    (tol::RESIDUAL_DIRECT.max(f), tol::RESIDUAL_REFUSE.max(f))
}

/// Named work counters of a run (pivots, sweeps, iterations, outer iterations, ...), in the solver's order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Work(pub Vec<(String, u64)>);

impl Work {
    /// One counter.
    pub fn one(name: &str, value: u64) -> Work {
        Work(vec![(name.to_string(), value)])
    }

    /// Counters from (name, value) pairs, in that order.
    pub fn of(counters: &[(&str, u64)]) -> Work {
        Work(counters.iter().map(|(k, v)| (k.to_string(), *v)).collect())
    }

    /// The value of a counter.
    pub fn get(&self, name: &str) -> Option<u64> {
        self.0.iter().find(|(k, _)| *k == name).map(|(_, v)| *v)
    }

    /// Short text, e.g. `28 piv`, `120 sw/4`, `11 it`.
    pub fn short(&self) -> String {
        fn abbrev(k: &str) -> &str {
            match k {
                "pivots" => "piv",
                "sweeps" => "sw",
                "iterations" => "it",
                other => other,
            }
        }
        match self.0.as_slice() {
            [] => String::new(),
            [(k, v)] => format!("{v} {}", abbrev(k)),
            [(k, v), rest @ ..] => {
                let tail: Vec<String> = rest.iter().map(|(_, v)| v.to_string()).collect();
                format!("{v} {}/{}", abbrev(k), tail.join("/"))
            }
        }
    }

    /// Long text, e.g. `28 pivots`, `120 sweeps, 4 outer`.
    pub fn long(&self) -> String {
        if self.0.is_empty() {
            return "–".into();
        }
        self.0.iter().map(|(k, v)| format!("{v} {k}")).collect::<Vec<_>>().join(", ")
    }
}

impl<'de> Deserialize<'de> for Work {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Work, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = Work;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a map of work counters")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut m: A) -> Result<Work, A::Error> {
                let mut out = Vec::new();
                while let Some((k, v)) = m.next_entry::<String, u64>()? {
                    out.push((k, v));
                }
                Ok(Work(out))
            }
        }
        d.deserialize_map(V)
    }
}

impl Serialize for Work {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

/// A solver's own figures of a run, named (e.g. clarabel's `polish_change`), in the solver's order: what the
/// harness reports beside the work counters without knowing what they mean.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Figures(pub BTreeMap<String, f64>);

impl Figures {
    /// One figure.
    pub fn one(name: &str, value: f64) -> Figures {
        Figures(BTreeMap::from([(name.to_string(), value)]))
    }

    /// The value of a figure.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.get(name).copied()
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// What a solver run produced.
#[derive(Debug)]
#[non_exhaustive]
pub struct Outcome {
    /// The solution in the problem's unknowns (`None` when nothing was computed).
    pub solution: Option<Solution>,
    /// How the solver ended (the harness may still refuse a `solved` claim on the independent residuals).
    pub status: Termination,
    /// Detail.
    pub message: String,
    /// Work counters.
    pub work: Work,
    /// The solver's own figures of the run (none for most).
    pub figures: Figures,
    /// What the solver leaves for its next run on a problem of the same layout ([`SolverState`]).
    pub state: Option<SolverState>,
}

impl Outcome {
    /// A solver's outcome: its solution in the problem's unknowns (`None` when nothing was computed), how it ended,
    /// a message and its work counters; no figures and no state (add them with [`Outcome::with_figures`] and
    /// [`Outcome::with_state`]).
    pub fn new(solution: Option<Solution>, status: Termination, message: String, work: Work) -> Outcome {
        Outcome { solution, status, message, work, figures: Figures::default(), state: None }
    }

    /// A solver's claimed solution (the harness still certifies it by its own residuals), with its message and work,
    /// no figures and no state.
    pub fn solved(solution: Solution, message: String, work: Work) -> Outcome {
        Outcome::new(Some(solution), Termination::Solved, message, work)
    }

    /// An outcome with no solution (a failure, or a cancelled run), no figures and no state.
    pub fn failed(status: Termination, message: String, work: Work) -> Outcome {
        Outcome::new(None, status, message, work)
    }

    /// The same outcome with the solver's own figures of the run.
    pub fn with_figures(self, figures: Figures) -> Outcome {
        Outcome { figures, ..self }
    }

    /// The same outcome with the state the solver leaves for its next run ([`SolverState`]).
    pub fn with_state(self, state: SolverState) -> Outcome {
        Outcome { state: Some(state), ..self }
    }
}

/// A solver setting out of range or unknown: an input error naming the dotted key.
#[derive(Debug, Clone, PartialEq)]
pub struct SettingsError {
    /// Dotted key, e.g. `solvers.pgs.relaxation`.
    pub field: String,
    /// What is wrong and what is expected.
    pub message: String,
    /// True when a name or key is not known at all (a schema error, like an unknown key in the scene file), false
    /// when a known value is out of range.
    pub unknown: bool,
}

impl SettingsError {
    /// The scene error this is, for a scene file at `path`: an unknown name or key is a parse (schema) error, a
    /// value out of range an invalid value; both name the key.
    pub fn into_error(self, path: &std::path::Path) -> crate::error::Error {
        if self.unknown {
            crate::error::Error::Parse {
                path: path.to_path_buf(),
                message: format!("{}: {}", self.field, self.message),
            }
        } else {
            crate::error::Error::Invalid { path: path.to_path_buf(), field: self.field, message: self.message }
        }
    }
}

/// Settings that check their own ranges.
pub trait Validate {
    /// `Err((key, message))` for the first value out of range (the key relative to the settings table).
    fn validate(&self) -> Result<(), (&'static str, String)>;

    /// The relative tolerance an iterative solver with these settings stops at (`None`, the default: a direct one).
    fn tolerance(&self) -> Option<f64> {
        None
    }
}

/// Parse and validate a solver's settings table (`None`: the defaults). Errors name `solvers.NAME.KEY`.
pub fn parse_settings<T>(name: &str, raw: Option<&toml::Value>) -> Result<T, SettingsError>
where
    T: DeserializeOwned + Default + Validate,
{
    let settings: T = match raw {
        None => T::default(),
        Some(v) => T::deserialize(v.clone()).map_err(|e| SettingsError {
            field: format!("solvers.{name}"),
            message: e.to_string(),
            unknown: true,
        })?,
    };
    settings.validate().map_err(|(key, message)| SettingsError {
        field: format!("solvers.{name}.{key}"),
        message,
        unknown: false,
    })?;
    Ok(settings)
}

/// A settings struct as a TOML table (for the scene as parsed, with defaults filled in); a settings type that does
/// not serialise to a table (a type of a plugged-in solver) gives an empty table.
pub fn settings_value<T: Serialize>(t: &T) -> toml::Value {
    toml::Value::try_from(t).unwrap_or_else(|_| toml::Value::Table(Default::default()))
}

/// The registry entry of a name.
pub fn entry(name: &str) -> Option<&'static Entry> {
    registry().into_iter().find(|e| e.name() == name)
}

/// The union of the registry's work counters, in registry order (the work columns of a sweep CSV).
pub fn work_columns() -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for c in registry().into_iter().flat_map(|e| e.counters) {
        if !out.contains(c) {
            out.push(c);
        }
    }
    out
}

/// Every registered name, comma-separated (for error messages and help).
pub fn names() -> String {
    registry().into_iter().map(|e| e.name()).collect::<Vec<_>>().join(", ")
}

/// The solver of a name with the default settings; an unknown name is an error listing the valid ones.
pub fn build(name: &str) -> Result<Box<dyn Solver>, SettingsError> {
    match SolverId::from_name(name).and_then(|id| id.build(&SolverSettings::default())) {
        Some(solver) => Ok(solver),
        None => Err(SettingsError {
            unknown: true,
            field: "solvers.use".into(),
            message: format!("unknown solver `{name}` (expected one of: all, {})", names()),
        }),
    }
}

/// Range checks shared by settings: a tolerance in (0, 1).
pub fn check_tolerance(key: &'static str, v: f64) -> Result<(), (&'static str, String)> {
    if !v.is_finite() || v <= 0.0 || v >= 1.0 {
        return Err((key, format!("must lie in (0, 1) (got {v})")));
    }
    Ok(())
}

/// Range checks shared by settings: a count ≥ 1.
pub fn check_count(key: &'static str, v: usize) -> Result<(), (&'static str, String)> {
    if v == 0 {
        return Err((key, "must be at least 1".into()));
    }
    Ok(())
}
