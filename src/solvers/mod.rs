//! Contact solvers behind one small trait ([`Solver`]), chosen by name in one registry ([`REGISTRY`]): the only
//! place solver names are listed. Scenes (`[solvers] use`, `[solvers.NAME]` settings tables), `--solver`,
//! `rollbem lcp solve`, sweeps and reports all read it.
//!
//! A solver consumes a [`ContactProblem`] (plain data) and returns one [`Outcome`]: the solution in the problem's
//! one solution shape, a [`Status`], a message and its work as named counters. Non-convergence, ray termination
//! and infeasibility are statuses, never panics; a bad setting is an input error ([`SettingsError`]) raised when the
//! solver is built, before anything runs. Each back end's own status maps to [`Status`] in one place (its file).
//!
//! Adding a solver: one file with its settings (serde, `validate`), its [`Solver`] impl and an [`Entry`], plus one
//! line in [`REGISTRY`].

pub mod active_set;
pub mod clarabel;
pub mod clarabel_box;
pub mod clarabel_qp;
pub mod lemke;
pub mod normtang;

pub use crate::formulation::Lcp;
pub use crate::status::{Status, Termination};

use crate::formulation::{ContactProblem, Solution};
use crate::tolerances as tol;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The registry: every solver rollbem has, in the order runs are reported (the order of [`SolverId`]).
pub static REGISTRY: &[Entry] = &[
    lemke::ENTRY,
    active_set::ENTRY,
    clarabel::ENTRY,
    normtang::PGS_ENTRY,
    normtang::NORMTANG_QP_ENTRY,
    lemke::dense::ENTRY,
];

/// A solver's identity, as written in scene files (`[solvers] use`), on the command line and in results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SolverId {
    /// Lemke's method, block-revised engine.
    Lemke,
    /// Primal–dual active set on the physical unknowns.
    ActiveSet,
    /// clarabel on the frictionless QP.
    Clarabel,
    /// NORM-TANG with projected Gauss–Seidel sweeps.
    Pgs,
    /// NORM-TANG with clarabel QPs.
    NormtangQp,
    /// Lemke's method, dense reference engine.
    LemkeDense,
}

impl SolverId {
    /// Every solver, in registry order.
    pub const ALL: [SolverId; 6] = [
        SolverId::Lemke,
        SolverId::ActiveSet,
        SolverId::Clarabel,
        SolverId::Pgs,
        SolverId::NormtangQp,
        SolverId::LemkeDense,
    ];

    /// Its registry entry.
    pub fn entry(self) -> &'static Entry {
        REGISTRY.iter().find(|e| e.id == self).expect("every SolverId has a registry entry")
    }

    /// Its name.
    pub fn name(self) -> &'static str {
        self.entry().name
    }

    /// The solver of a name, if there is one.
    pub fn from_name(name: &str) -> Option<SolverId> {
        REGISTRY.iter().find(|e| e.name == name).map(|e| e.id)
    }

    /// Build the solver with the given settings (validated settings cannot fail to build).
    pub fn build(self, settings: &SolverSettings) -> Box<dyn Solver> {
        (self.entry().build)(settings)
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

/// Builds a solver from the (validated) settings of every solver.
pub type Builder = fn(&SolverSettings) -> Box<dyn Solver>;

/// One registered solver.
pub struct Entry {
    /// Its identity.
    pub id: SolverId,
    /// Name in scene files, on the command line and in results.
    pub name: &'static str,
    /// One line: what it is and what it applies to.
    pub summary: &'static str,
    /// Whether `use = ["all"]` runs it (a slower reference engine is run by name only).
    pub in_all: bool,
    /// The work counters it reports, in display order (the sweep CSV's work columns are their union).
    pub counters: &'static [&'static str],
    /// Build the solver from its settings.
    pub build: Builder,
}

/// The settings of every solver (`[solvers.NAME]` tables), typed, with documented defaults. Built and validated
/// when a scene is read ([`SolverSettings::from_tables`]) — no solver is built for that — so that a bad value is an
/// input error naming its key before anything runs.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SolverSettings {
    /// `[solvers.lemke]`.
    pub lemke: lemke::LemkeSettings,
    /// `[solvers.active_set]`.
    pub active_set: active_set::ActiveSetSettings,
    /// `[solvers.clarabel]`.
    pub clarabel: clarabel_qp::QpSettings,
    /// `[solvers.pgs]`.
    pub pgs: normtang::PgsSettings,
    /// `[solvers.normtang_qp]`.
    pub normtang_qp: normtang::NormTangQpSettings,
    /// `[solvers.lemke_dense]`.
    pub lemke_dense: lemke::LemkeSettings,
}

impl SolverSettings {
    /// Parse and validate the settings tables of a scene (`[solvers.NAME]`, keyed by solver name; absent tables take
    /// the defaults). An unknown table or key, or a value out of range, is an error naming `solvers.NAME.KEY`.
    pub fn from_tables(tables: &BTreeMap<String, toml::Value>) -> Result<SolverSettings, SettingsError> {
        if let Some(k) = tables.keys().find(|k| SolverId::from_name(k).is_none()) {
            return Err(SettingsError {
                field: format!("solvers.{k}"),
                message: format!("unknown solver settings table (solvers are: {})", names()),
                unknown: true,
            });
        }
        let t = |id: SolverId| tables.get(id.name());
        Ok(SolverSettings {
            lemke: parse_settings("lemke", t(SolverId::Lemke))?,
            active_set: parse_settings("active_set", t(SolverId::ActiveSet))?,
            clarabel: parse_settings("clarabel", t(SolverId::Clarabel))?,
            pgs: parse_settings("pgs", t(SolverId::Pgs))?,
            normtang_qp: parse_settings("normtang_qp", t(SolverId::NormtangQp))?,
            lemke_dense: parse_settings("lemke_dense", t(SolverId::LemkeDense))?,
        })
    }

    /// The settings as tables keyed by solver name, every default filled in (the scene as parsed).
    pub fn tables(&self) -> BTreeMap<String, toml::Value> {
        let mut out = BTreeMap::new();
        let mut put = |id: SolverId, v: toml::Value| {
            out.insert(id.name().to_string(), v);
        };
        put(SolverId::Lemke, settings_value(&self.lemke));
        put(SolverId::ActiveSet, settings_value(&self.active_set));
        put(SolverId::Clarabel, settings_value(&self.clarabel));
        put(SolverId::Pgs, settings_value(&self.pgs));
        put(SolverId::NormtangQp, settings_value(&self.normtang_qp));
        put(SolverId::LemkeDense, settings_value(&self.lemke_dense));
        out
    }

    /// Check every solver's ranges (for settings built in code; [`SolverSettings::from_tables`] already did).
    pub fn validate(&self) -> Result<(), SettingsError> {
        SolverSettings::from_tables(&self.tables()).map(|_| ())
    }

    /// The relative tolerance an iterative solver stops at (`None` for a direct one).
    pub fn tolerance(&self, id: SolverId) -> Option<f64> {
        match id {
            SolverId::Pgs => Some(self.pgs.tolerance),
            SolverId::NormtangQp => Some(self.normtang_qp.tolerance),
            _ => None,
        }
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

    /// Solve. Called only when [`Solver::applies`] is `Ok` and the problem has a static solution to look for.
    fn solve(&self, problem: &ContactProblem) -> Outcome;

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

/// What a solver run produced.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The solution in the problem's unknowns (`None` when nothing was computed).
    pub solution: Option<Solution>,
    /// How the solver ended (the harness may still refuse a `solved` claim on the independent residuals).
    pub status: Termination,
    /// Detail.
    pub message: String,
    /// Work counters.
    pub work: Work,
    /// For clarabel: max |p − p_unpolished| / p_max, the effect of solving the symmetrised QP before the
    /// active-set polish with the nonsymmetric flexibility.
    pub polish_change: Option<f64>,
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

/// A settings struct as a TOML table (for the scene as parsed, with defaults filled in).
pub fn settings_value<T: Serialize>(t: &T) -> toml::Value {
    toml::Value::try_from(t).expect("solver settings serialise to a TOML table")
}

/// The registry entry of a name.
pub fn entry(name: &str) -> Option<&'static Entry> {
    REGISTRY.iter().find(|e| e.name == name)
}

/// The union of the registry's work counters, in registry order (the work columns of a sweep CSV).
pub fn work_columns() -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for c in REGISTRY.iter().flat_map(|e| e.counters) {
        if !out.contains(c) {
            out.push(c);
        }
    }
    out
}

/// Every registered name, comma-separated (for error messages and help).
pub fn names() -> String {
    REGISTRY.iter().map(|e| e.name).collect::<Vec<_>>().join(", ")
}

/// The solver of a name with the default settings; an unknown name is an error listing the valid ones.
pub fn build(name: &str) -> Result<Box<dyn Solver>, SettingsError> {
    match SolverId::from_name(name) {
        Some(id) => Ok(id.build(&SolverSettings::default())),
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
