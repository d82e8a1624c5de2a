//! One row of a sweep CSV, typed: one solver run of one case (or the row that says why a case could not run).
//!
//! The CSV is written and read through this type only: [`SweepRow::record`] writes a row against a header
//! ([`header`]), [`SweepRow::from_record`] reads one back, both through the one column table below, so the column
//! names, their order and their formats live in one place. Numbers are written in Rust's shortest round-trip
//! scientific notation (`1.25e-3`), so a row read back is the row written, bit for bit.
//!
//! Columns, in order: `case`; the swept keys (one per key of the spec, empty where a case's grid does not set it);
//! `scene, scene_digest, element, contact_elements, contact_nodes, solver, formulation, status, problem_size`; the
//! registry's work counters ([`crate::solvers::work_columns`]); the figures of the run (resultants, fits, the errors
//! against the references that apply, [`crate::references::Metrics`]), the pair and the rigid motion, the two-body
//! figures ([`super::two_body`]); `message`.
//! Those are the **results**: the same cases give the same cells whichever run wrote them (serial, sharded and
//! merged, resumed; with `warm_start` the work counters and the last bits of Lemke's answers aside). Last come the
//! **provenance** columns, [`PROVENANCE_COLUMNS`]: how this run went (the timings, `timing_runs`, and `setup`:
//! whether the case's model was built for it or reused from the case before it in the same run), which differ from
//! run to run. Two runs of the same cases compare equal on every column before the first provenance column. A cell
//! is empty where a value does not apply.
//!
//! A CSV of an older rollbem (without `scene_digest`, columns in another order) still reads: columns are found by
//! name.

use super::Kind;
use crate::error::{Error, Result};
use crate::references::Metrics;
use crate::scene::{BodyModel, ElementKind, SpaceStatus};
use crate::solvers::Work;
use crate::status::Status;
use std::path::Path;

/// The status cell of a row: a run's status, or `error` for a case that could not run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum RowStatus {
    /// The run's status.
    Run(Status),
    /// A 3D (half-space) case's status: the first (sub)step's that is not `solved`, else `solved`.
    Space(SpaceStatus),
    /// The case could not be built or run (the message says why).
    Error,
}

impl RowStatus {
    /// The name written in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            RowStatus::Run(s) => s.name(),
            RowStatus::Space(s) => s.name(),
            RowStatus::Error => "error",
        }
    }

    /// Whether the run solved.
    pub fn solved(self) -> bool {
        matches!(self, RowStatus::Run(Status::Solved) | RowStatus::Space(SpaceStatus::Solved))
    }
}

/// One row of a sweep CSV (see the module docs). Lengths, loads and stresses are in the scene's units; times in
/// seconds.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SweepRow {
    /// The case's position in the sweep's enumeration, from 0.
    pub case: usize,
    /// The kind of the case's scene: which columns the row has ([`header_of`]).
    pub kind: Kind,
    /// The swept keys this case's grid sets, with their values as written in the spec (strings bare).
    pub params: Vec<(String, String)>,
    /// The scene's name.
    pub scene: String,
    /// The digest of the case's resolved scene (`super::identity::scene_digest`): equal in two rows only
    /// if they were computed for the same scene. `None` in a CSV of a rollbem that did not write it.
    pub scene_digest: Option<u64>,
    /// Element family.
    pub element: Option<ElementKind>,
    /// Contact elements.
    pub contact_elements: Option<usize>,
    /// Contact nodes.
    pub contact_nodes: Option<usize>,
    /// The solver's name.
    pub solver: String,
    /// The formulation's name (`frictionless`, `displacement`, `loading`).
    pub formulation: Option<String>,
    /// The run's status, or `error`.
    pub status: RowStatus,
    /// Complementarity (or QP) unknowns.
    pub problem_size: Option<usize>,
    /// Work counters by name.
    pub work: Work,
    /// Largest solver-independent residual.
    pub residual: Option<f64>,
    /// Resultant P.
    pub normal_load: Option<f64>,
    /// Resultant Q.
    pub tangential_load: Option<f64>,
    /// Fitted contact half-width a.
    pub half_width_fit: Option<f64>,
    /// Fitted peak pressure p0.
    pub peak_pressure_fit: Option<f64>,
    /// Errors against the references that apply.
    pub metrics: Metrics,
    /// The wheel's model.
    pub model: Option<BodyModel>,
    /// The width of the strip of half-spaces (`[mesh] strip_width`, CONTACT's 2D model); empty in plane strain.
    pub strip_width: Option<f64>,
    /// Wheel radius R.
    pub radius: Option<f64>,
    /// Contact modulus E* of the pair.
    pub contact_modulus: Option<f64>,
    /// Coulomb's μ.
    pub friction: Option<f64>,
    /// Hertz's a at the run's P.
    pub hertz_a: Option<f64>,
    /// Hertz's p0 at the run's P.
    pub hertz_p0: Option<f64>,
    /// The support's tangential shift (null when indeterminate).
    pub shift: Option<f64>,
    /// The support's approach.
    pub approach: Option<f64>,
    /// Left edge of the stick zone.
    pub stick_left: Option<f64>,
    /// Right edge of the stick zone.
    pub stick_right: Option<f64>,
    /// Creepage ξ (prescribed or computed).
    pub creepage: Option<f64>,
    /// Assembly time (the model's build).
    pub t_assembly: Option<f64>,
    /// Condensation time (the model's build).
    pub t_condensation: Option<f64>,
    /// Formulation time.
    pub t_formulation: Option<f64>,
    /// Solve time.
    pub t_solve: Option<f64>,
    /// Total time (the cost of the answer from scratch).
    pub t_total: Option<f64>,
    /// Fastest repeat's total.
    pub t_total_min: Option<f64>,
    /// Slowest repeat's total.
    pub t_total_max: Option<f64>,
    /// Timed repeats.
    pub timing_runs: Option<usize>,
    /// Whether the model (assembly, condensation) was built for this case or reused from another case of the same
    /// bodies and mesh (its times are then the model's one build, not spent again).
    pub setup: Option<crate::results::Setup>,
    /// The solver's explanation, or why the case could not run.
    pub message: String,
    /// The figures of a 3D case that the 2D columns do not hold (all empty in a 2D row).
    pub space: SpaceFigures,
    /// The figures of two finite bodies, and the nodal peak pressure and R* of every 2D row (all empty in a 3D row).
    pub bodies: super::two_body::TwoBodyFigures,
    /// Figures a reader derives from the rows, by name (not written to the CSV; e.g. the report's errors against a
    /// mesh's limit). [`SweepRow::number`] finds them as it finds the columns.
    pub derived: std::collections::BTreeMap<String, f64>,
}

/// The figures of a 3D (half-space) case beyond the columns it shares with the 2D rows, at the end of its last
/// (sub)step unless said otherwise. Lengths, forces and stresses in the scene's units; the errors relative (the
/// stick radius's in elements, in `metrics.cm_c_err_elements`).
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct SpaceFigures {
    /// Elements along x (MX).
    pub mx: Option<usize>,
    /// Elements along y (MY).
    pub my: Option<usize>,
    /// Element side along x (DX).
    pub dx: Option<f64>,
    /// Element side along y (DY).
    pub dy: Option<f64>,
    /// Elements across Hertz's minor axis at the run's load, `2 min(a_x/DX, a_y/DY)` (a quadratic profile).
    pub elements_across: Option<f64>,
    /// (Sub)steps solved (the path's length).
    pub steps: Option<usize>,
    /// Normal solver iterations, summed over the steps.
    pub iterations_normal: Option<usize>,
    /// Tangential solver iterations, summed over the steps.
    pub iterations_tangential: Option<usize>,
    /// Normal–tangential alternations, summed over the steps.
    pub outer_iterations: Option<usize>,
    /// Tangential force on body 1 along x.
    pub force_x: Option<f64>,
    /// Tangential force on body 1 along y.
    pub force_y: Option<f64>,
    /// Elements in contact.
    pub contact_count: Option<usize>,
    /// Elements sticking.
    pub stick_count: Option<usize>,
    /// Elements slipping.
    pub slip_count: Option<usize>,
    /// The largest element pressure.
    pub peak_pressure: Option<f64>,
    /// Semi-axis along x of the least-squares ellipse fit `p² = p₀²(1 − x²/a_x² − y²/a_y²)`.
    pub a_x_fit: Option<f64>,
    /// Semi-axis along y of the fit.
    pub a_y_fit: Option<f64>,
    /// Error of `a_x_fit` against Hertz's a_x.
    pub hertz_a_x_err: Option<f64>,
    /// Error of `a_y_fit` against Hertz's a_y.
    pub hertz_a_y_err: Option<f64>,
    /// Error of the approach against Hertz's.
    pub hertz_approach_err: Option<f64>,
    /// Cattaneo–Mindlin: error of the shift for a prescribed force (or of the force for a prescribed shift).
    pub cm_transfer_err: Option<f64>,
    /// The profile's curvature A (h = A x² + B y²).
    pub curvature_a: Option<f64>,
    /// The profile's curvature B.
    pub curvature_b: Option<f64>,
    /// Hertz's a_x at the run's load.
    pub hertz_a_x: Option<f64>,
    /// Hertz's a_y at the run's load.
    pub hertz_a_y: Option<f64>,
    /// Hertz's approach at the run's load.
    pub hertz_approach: Option<f64>,
    /// The shift of body 1 relative to body 2 along x.
    pub shift_x: Option<f64>,
    /// The shift along y.
    pub shift_y: Option<f64>,
}

impl SweepRow {
    /// An empty row of a case and solver with a status (every figure empty).
    pub fn new(case: usize, solver: &str, status: RowStatus) -> SweepRow {
        SweepRow {
            case,
            kind: Kind::Plane,
            params: Vec::new(),
            scene: String::new(),
            scene_digest: None,
            element: None,
            contact_elements: None,
            contact_nodes: None,
            solver: solver.to_string(),
            formulation: None,
            status,
            problem_size: None,
            work: Work::default(),
            residual: None,
            normal_load: None,
            tangential_load: None,
            half_width_fit: None,
            peak_pressure_fit: None,
            metrics: Metrics::default(),
            model: None,
            strip_width: None,
            radius: None,
            contact_modulus: None,
            friction: None,
            hertz_a: None,
            hertz_p0: None,
            shift: None,
            approach: None,
            stick_left: None,
            stick_right: None,
            creepage: None,
            t_assembly: None,
            t_condensation: None,
            t_formulation: None,
            t_solve: None,
            t_total: None,
            t_total_min: None,
            t_total_max: None,
            timing_runs: None,
            setup: None,
            message: String::new(),
            space: SpaceFigures::default(),
            bodies: Default::default(),
            derived: Default::default(),
        }
    }

    /// Set a known column from its CSV cell; `Ok(false)` when `name` is not a known column (a swept key, a work
    /// counter or a derived figure).
    pub fn set(&mut self, name: &str, cell: &str) -> std::result::Result<bool, String> {
        match columns(self.kind).find(|c| c.name == name) {
            Some(c) => (c.set)(self, cell).map(|_| true),
            None => Ok(false),
        }
    }

    /// The value of a swept key in this row (`None` where its grid does not set it).
    pub fn param(&self, key: &str) -> Option<&str> {
        self.params.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    /// The cell of a column or swept key as written in the CSV ("" when empty or unknown).
    pub fn cell(&self, name: &str) -> String {
        if let Some(v) = self.param(name) {
            return v.to_string();
        }
        if let Some(c) = columns(self.kind).find(|c| c.name == name) {
            return (c.get)(self).text();
        }
        if let Some(v) = self.derived.get(name) {
            return format!("{v:e}");
        }
        self.work.get(name).map(|v| v.to_string()).unwrap_or_default()
    }

    /// The value of a numeric column by name (a figure, an error, a time, a count), if it has one and it is finite.
    pub fn number(&self, name: &str) -> Option<f64> {
        let v = match columns(self.kind).find(|c| c.name == name) {
            Some(c) => match (c.get)(self) {
                Cell::Num(v) => v,
                Cell::Int(v) => v.map(|v| v as f64),
                Cell::Text(_) => None,
            },
            None => self.derived.get(name).copied().or_else(|| self.work.get(name).map(|v| v as f64)),
        };
        v.filter(|v| v.is_finite())
    }

    /// The row's cells against a header written by [`header_of`] for the row's kind with the same swept keys.
    pub fn record(&self, keys: &[String]) -> Vec<String> {
        let mut out = vec![self.case.to_string()];
        out.extend(keys.iter().map(|k| self.param(k).unwrap_or_default().to_string()));
        for c in columns(self.kind) {
            if c.name == WORK_AFTER {
                out.push((c.get)(self).text());
                out.extend(crate::solvers::work_columns().iter().map(|w| self.cell(w)));
            } else {
                out.push((c.get)(self).text());
            }
        }
        out
    }

    /// Read a row from a record of a CSV with header `header` (file `path` and line for messages).
    pub fn from_record(header: &Header, record: &csv::StringRecord, path: &Path, line: usize) -> Result<SweepRow> {
        let bad = |col: &str, why: String| Error::Parse {
            path: path.to_path_buf(),
            message: format!("line {line}, column `{col}`: {why}"),
        };
        let get = |i: usize| record.get(i).unwrap_or("");
        let case = get(0).parse().map_err(|_| bad("case", format!("`{}` is not a case number", get(0))))?;
        let mut row = SweepRow::new(case, "", RowStatus::Error);
        row.kind = header.kind;
        row.params = header
            .keys
            .iter()
            .enumerate()
            .filter(|(k, _)| !get(1 + k).is_empty())
            .map(|(k, key)| (key.clone(), get(1 + k).to_string()))
            .collect();
        for (c, i) in columns(header.kind).zip(&header.columns) {
            if let Some(i) = *i {
                (c.set)(&mut row, get(i)).map_err(|why| bad(c.name, why))?;
            }
        }
        let mut work = Vec::new();
        for (name, i) in &header.work {
            if !get(*i).is_empty() {
                let v = get(*i).parse().map_err(|_| bad(name, format!("`{}` is not a count", get(*i))))?;
                work.push((name.clone(), v));
            }
        }
        row.work = Work(work);
        Ok(row)
    }

    /// Read every row of a sweep CSV.
    pub fn read_csv(path: &Path) -> Result<(Header, Vec<SweepRow>)> {
        let perr = |e: csv::Error| Error::Parse { path: path.to_path_buf(), message: e.to_string() };
        let mut rd = csv::Reader::from_path(path).map_err(|e| match e.into_kind() {
            csv::ErrorKind::Io(source) => Error::Io { path: path.to_path_buf(), source },
            other => Error::Parse { path: path.to_path_buf(), message: format!("{other:?}") },
        })?;
        let names: Vec<String> = rd.headers().map_err(perr)?.iter().map(str::to_string).collect();
        let header = Header::parse(&names, path)?;
        let mut rows = Vec::new();
        for (k, rec) in rd.records().enumerate() {
            rows.push(SweepRow::from_record(&header, &rec.map_err(perr)?, path, k + 2)?);
        }
        Ok((header, rows))
    }
}

/// A row's timing columns; `spread` is (fastest, slowest, repeats) of the total time when the case was timed
/// repeatedly.
pub(super) fn set_timing(row: &mut SweepRow, t: &crate::results::Timing, spread: Option<(f64, f64, usize)>) {
    row.t_assembly = Some(t.assembly);
    row.t_condensation = Some(t.condensation);
    row.t_formulation = Some(t.formulation);
    row.t_solve = Some(t.solve);
    row.t_total = Some(t.total);
    let (lo, hi, k) = spread.unwrap_or((t.total, t.total, 1));
    row.t_total_min = Some(lo);
    row.t_total_max = Some(hi);
    row.timing_runs = Some(k);
    row.setup = Some(t.setup);
}

/// Where the columns of a sweep CSV are: the swept keys, the known columns (in the order of the module docs) and the work
/// counters.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Header {
    /// The kind of the sweep's scenes (a 3D CSV has the column `mx`).
    pub kind: Kind,
    /// The swept keys, in CSV order.
    pub keys: Vec<String>,
    /// Index of each known column (`None`: an [`OPTIONAL`] one this CSV lacks).
    columns: Vec<Option<usize>>,
    /// Work counters and their indices.
    work: Vec<(String, usize)>,
    /// The header as read.
    pub names: Vec<String>,
}

impl Header {
    /// Whether the CSV has a column of this name.
    pub fn has(&self, name: &str) -> bool {
        self.names.iter().any(|n| n == name)
    }

    /// Locate the columns of a header written by [`header`]; an error names what is missing.
    pub fn parse(names: &[String], path: &Path) -> Result<Header> {
        let bad = |message: String| Error::Parse { path: path.to_path_buf(), message };
        if names.first().map(String::as_str) != Some("case") {
            return Err(bad("not a sweep CSV: the first column is not `case`".into()));
        }
        let first = names
            .iter()
            .position(|n| n == COLUMNS[0].name)
            .ok_or_else(|| bad(format!("not a sweep CSV of this version: no `{}` column", COLUMNS[0].name)))?;
        let kind = if names[first..].iter().any(|n| n == SPACE_MARK) { Kind::Space } else { Kind::Plane };
        let mut found = Vec::with_capacity(COLUMNS.len());
        for c in columns(kind) {
            let i = names.iter().position(|n| n == c.name);
            if i.is_none() && !OPTIONAL.contains(&c.name) {
                return Err(bad(format!("not a sweep CSV of this version: no `{}` column (rerun the sweep)", c.name)));
            }
            found.push(i);
        }
        let work = match kind {
            Kind::Plane => {
                let work_at = names.iter().position(|n| n == WORK_AFTER).map_or(first, |i| i + 1);
                let work_end = names.iter().position(|n| n == "residual").unwrap_or(work_at);
                (work_at..work_end).map(|i| (names[i].clone(), i)).collect()
            }
            Kind::Space => Vec::new(),
        };
        Ok(Header { kind, keys: names[1..first].to_vec(), columns: found, work, names: names.to_vec() })
    }
}

/// The full CSV header of a sweep of 2D scenes for a spec's swept keys ([`header_of`]).
pub fn header(keys: &[String]) -> Vec<String> {
    header_of(keys, Kind::Plane)
}

/// The full CSV header of a sweep of `kind` for a spec's swept keys: `case`, the keys, then the kind's columns (the
/// module docs; a 3D sweep's in [`space_columns`]).
pub fn header_of(keys: &[String], kind: Kind) -> Vec<String> {
    let mut h = vec!["case".to_string()];
    h.extend(keys.iter().cloned());
    for c in columns(kind) {
        h.push(c.name.to_string());
        if c.name == WORK_AFTER {
            h.extend(crate::solvers::work_columns().iter().map(|s| s.to_string()));
        }
    }
    h
}

/// The provenance columns of a sweep CSV, its last ones (after `message`): how the run that wrote a row went —
/// wall-clock times, the number of timed repeats, and whether the case's model was built for it or reused (which
/// depends on the cases run before it: a shard or a resumed run builds where a serial one reuses). They differ
/// from run to run; every column before them is a result (module docs). Mask them, or drop them, to compare two
/// runs.
pub const PROVENANCE_COLUMNS: &[&str] = &[
    "t_assembly",
    "t_condensation",
    "t_formulation",
    "t_solve",
    "t_total",
    "t_total_min",
    "t_total_max",
    "timing_runs",
    "setup",
];

/// The column whose presence marks a 3D sweep's CSV.
const SPACE_MARK: &str = "mx";

/// Which kinds of sweep have a column.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kinds {
    /// 2D only.
    P,
    /// 3D only.
    S,
    /// Both.
    B,
}

impl Kinds {
    fn has(self, kind: Kind) -> bool {
        matches!((self, kind), (Kinds::B, _) | (Kinds::P, Kind::Plane) | (Kinds::S, Kind::Space))
    }
}

/// The known columns of a kind of sweep, in CSV order.
fn columns(kind: Kind) -> impl Iterator<Item = &'static Column> {
    COLUMNS.iter().filter(move |c| c.kinds.has(kind))
}

/// The columns of a 3D sweep's CSV after the swept keys, in order (for documentation and tests).
pub fn space_columns() -> Vec<&'static str> {
    columns(Kind::Space).map(|c| c.name).collect()
}

/// Columns a CSV of an older rollbem may lack (read as empty).
const OPTIONAL: &[&str] = &[
    "scene_digest",
    "peak_pressure",
    "contact_radius",
    "counter_body",
    "counter_radius",
    "contact_half_angle",
    "pin_bore_half_angle",
    "pin_bore_p0",
    "pin_bore_half_angle_err",
    "pin_bore_p0_err",
];

/// A cell's value before formatting.
enum Cell {
    Num(Option<f64>),
    Int(Option<u64>),
    Text(String),
}

impl Cell {
    fn text(self) -> String {
        match self {
            // `+ 0.0` writes −0 as 0.
            Cell::Num(v) => v.map(|v| format!("{:e}", v + 0.0)).unwrap_or_default(),
            Cell::Int(v) => v.map(|v| v.to_string()).unwrap_or_default(),
            Cell::Text(s) => s,
        }
    }
}

/// One known column: its name, how it is written and how it is read back.
struct Column {
    name: &'static str,
    kinds: Kinds,
    get: fn(&SweepRow) -> Cell,
    set: fn(&mut SweepRow, &str) -> std::result::Result<(), String>,
}

/// The work counters' columns come right after this one.
const WORK_AFTER: &str = "problem_size";

fn num(s: &str) -> std::result::Result<Option<f64>, String> {
    if s.is_empty() {
        return Ok(None);
    }
    s.parse().map(Some).map_err(|_| format!("`{s}` is not a number"))
}

fn int(s: &str) -> std::result::Result<Option<usize>, String> {
    if s.is_empty() {
        return Ok(None);
    }
    s.parse().map(Some).map_err(|_| format!("`{s}` is not a count"))
}

/// A name cell read back into its enum (serde's snake_case names).
fn named<T: serde::de::DeserializeOwned>(s: &str) -> std::result::Result<Option<T>, String> {
    if s.is_empty() {
        return Ok(None);
    }
    serde_json::from_value(serde_json::Value::String(s.to_string())).map(Some).map_err(|_| format!("`{s}` unknown"))
}

macro_rules! num_col {
    ($kinds:ident, $name:literal, $($f:ident).+) => {
        Column {
            name: $name,
            kinds: Kinds::$kinds,
            get: |r| Cell::Num(r.$($f).+),
            set: |r, s| { r.$($f).+ = num(s)?; Ok(()) },
        }
    };
}

macro_rules! int_col {
    ($kinds:ident, $name:literal, $($f:ident).+) => {
        Column {
            name: $name,
            kinds: Kinds::$kinds,
            get: |r| Cell::Int(r.$($f).+.map(|v| v as u64)),
            set: |r, s| { r.$($f).+ = int(s)?; Ok(()) },
        }
    };
}

/// The known columns, in CSV order (the swept keys before them, the work counters after `problem_size`).
static COLUMNS: &[Column] = &[
    Column {
        name: "scene",
        kinds: Kinds::B,
        get: |r| Cell::Text(r.scene.clone()),
        set: |r, s| {
            r.scene = s.into();
            Ok(())
        },
    },
    Column {
        name: "scene_digest",
        kinds: Kinds::B,
        get: |r| Cell::Text(r.scene_digest.map(super::identity::show_digest).unwrap_or_default()),
        set: |r, s| {
            r.scene_digest = match s {
                "" => None,
                s => Some(super::identity::parse_digest(s).ok_or(format!("`{s}` is not a scene digest"))?),
            };
            Ok(())
        },
    },
    int_col!(S, "mx", space.mx),
    int_col!(S, "my", space.my),
    num_col!(S, "dx", space.dx),
    num_col!(S, "dy", space.dy),
    num_col!(S, "elements_across", space.elements_across),
    Column {
        name: "element",
        kinds: Kinds::P,
        get: |r| Cell::Text(r.element.map(|e| e.name().to_string()).unwrap_or_default()),
        set: |r, s| {
            r.element = named(s)?;
            Ok(())
        },
    },
    int_col!(P, "contact_elements", contact_elements),
    int_col!(P, "contact_nodes", contact_nodes),
    Column {
        name: "solver",
        kinds: Kinds::B,
        get: |r| Cell::Text(r.solver.clone()),
        set: |r, s| {
            r.solver = s.into();
            Ok(())
        },
    },
    Column {
        name: "formulation",
        kinds: Kinds::P,
        get: |r| Cell::Text(r.formulation.clone().unwrap_or_default()),
        set: |r, s| {
            r.formulation = (!s.is_empty()).then(|| s.to_string());
            Ok(())
        },
    },
    Column {
        name: "status",
        kinds: Kinds::B,
        get: |r| Cell::Text(r.status.name().to_string()),
        set: |r, s| {
            r.status = match s {
                "error" => RowStatus::Error,
                _ if r.kind == Kind::Space => RowStatus::Space(named(s)?.ok_or("empty status")?),
                _ => RowStatus::Run(named(s)?.ok_or("empty status")?),
            };
            Ok(())
        },
    },
    int_col!(P, "problem_size", problem_size),
    int_col!(S, "steps", space.steps),
    int_col!(S, "iterations_normal", space.iterations_normal),
    int_col!(S, "iterations_tangential", space.iterations_tangential),
    int_col!(S, "outer_iterations", space.outer_iterations),
    num_col!(B, "residual", residual),
    num_col!(B, "normal_load", normal_load),
    num_col!(P, "tangential_load", tangential_load),
    num_col!(S, "force_x", space.force_x),
    num_col!(S, "force_y", space.force_y),
    int_col!(S, "contact_count", space.contact_count),
    int_col!(S, "stick_count", space.stick_count),
    int_col!(S, "slip_count", space.slip_count),
    num_col!(S, "peak_pressure", space.peak_pressure),
    num_col!(P, "half_width_fit", half_width_fit),
    num_col!(B, "peak_pressure_fit", peak_pressure_fit),
    num_col!(P, "peak_pressure", bodies.peak_pressure),
    num_col!(S, "a_x_fit", space.a_x_fit),
    num_col!(S, "a_y_fit", space.a_y_fit),
    num_col!(S, "hertz_a_x_err", space.hertz_a_x_err),
    num_col!(S, "hertz_a_y_err", space.hertz_a_y_err),
    num_col!(P, "hertz_a_err", metrics.hertz_a_err),
    num_col!(B, "hertz_p0_err", metrics.hertz_p0_err),
    num_col!(S, "hertz_approach_err", space.hertz_approach_err),
    num_col!(P, "hertz_l2_err", metrics.hertz_l2_err),
    num_col!(B, "cm_c_over_a", metrics.cm_c_over_a),
    num_col!(B, "cm_c_over_a_exact", metrics.cm_c_over_a_exact),
    num_col!(B, "cm_c_err_elements", metrics.cm_c_err_elements),
    num_col!(P, "cm_centre_elements", metrics.cm_centre_elements),
    num_col!(P, "cm_shear_err", metrics.cm_shear_err),
    num_col!(S, "cm_transfer_err", space.cm_transfer_err),
    num_col!(P, "cm_shear_l2_err", metrics.cm_shear_l2_err),
    Column {
        name: "model",
        kinds: Kinds::P,
        get: |r| Cell::Text(r.model.map(|m| m.name().to_string()).unwrap_or_default()),
        set: |r, s| {
            r.model = named(s)?;
            Ok(())
        },
    },
    num_col!(P, "strip_width", strip_width),
    num_col!(P, "radius", radius),
    num_col!(P, "contact_radius", bodies.contact_radius),
    Column {
        name: "counter_body",
        kinds: Kinds::P,
        get: |r| Cell::Text(r.bodies.counter_body.clone().unwrap_or_default()),
        set: |r, s| {
            r.bodies.counter_body = (!s.is_empty()).then(|| s.to_string());
            Ok(())
        },
    },
    num_col!(P, "counter_radius", bodies.counter_radius),
    num_col!(S, "curvature_a", space.curvature_a),
    num_col!(S, "curvature_b", space.curvature_b),
    num_col!(B, "contact_modulus", contact_modulus),
    num_col!(B, "friction", friction),
    num_col!(S, "hertz_a_x", space.hertz_a_x),
    num_col!(S, "hertz_a_y", space.hertz_a_y),
    num_col!(P, "hertz_a", hertz_a),
    num_col!(B, "hertz_p0", hertz_p0),
    num_col!(S, "hertz_approach", space.hertz_approach),
    num_col!(P, "shift", shift),
    num_col!(S, "shift_x", space.shift_x),
    num_col!(S, "shift_y", space.shift_y),
    num_col!(B, "approach", approach),
    num_col!(P, "stick_left", stick_left),
    num_col!(P, "stick_right", stick_right),
    num_col!(P, "creepage", creepage),
    num_col!(P, "carter_q_over_mup", metrics.carter_q_over_mup),
    num_col!(P, "carter_q_over_mup_exact", metrics.carter_q_over_mup_exact),
    num_col!(P, "carter_c_over_a", metrics.carter_c_over_a),
    num_col!(P, "carter_c_over_a_exact", metrics.carter_c_over_a_exact),
    num_col!(P, "carter_c_err_elements", metrics.carter_c_err_elements),
    num_col!(P, "carter_shear_rms", metrics.carter_shear_rms),
    num_col!(P, "contact_half_angle", bodies.contact_half_angle),
    num_col!(P, "pin_bore_half_angle", bodies.pin_bore_half_angle),
    num_col!(P, "pin_bore_p0", bodies.pin_bore_p0),
    num_col!(P, "pin_bore_half_angle_err", bodies.pin_bore_half_angle_err),
    num_col!(P, "pin_bore_p0_err", bodies.pin_bore_p0_err),
    Column {
        name: "message",
        kinds: Kinds::B,
        get: |r| Cell::Text(r.message.clone()),
        set: |r, s| {
            r.message = s.into();
            Ok(())
        },
    },
    num_col!(B, "t_assembly", t_assembly),
    num_col!(P, "t_condensation", t_condensation),
    num_col!(P, "t_formulation", t_formulation),
    num_col!(B, "t_solve", t_solve),
    num_col!(B, "t_total", t_total),
    num_col!(B, "t_total_min", t_total_min),
    num_col!(B, "t_total_max", t_total_max),
    int_col!(B, "timing_runs", timing_runs),
    Column {
        name: "setup",
        kinds: Kinds::B,
        get: |r| {
            Cell::Text(
                r.setup
                    .map(|s| if s == crate::results::Setup::Built { "built" } else { "reused" }.to_string())
                    .unwrap_or_default(),
            )
        },
        set: |r, s| {
            r.setup = named(s)?;
            Ok(())
        },
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_reads_back_as_written() {
        let mut r = SweepRow::new(7, "lemke", RowStatus::Run(Status::Solved));
        r.params = vec![("mesh.contact_elements".into(), "40".into())];
        r.scene = "x".into();
        r.element = Some(ElementKind::Quadratic);
        r.model = Some(BodyModel::HalfPlane);
        r.residual = Some(1.0 / 3.0);
        r.metrics.hertz_a_err = Some(-0.0);
        r.t_total = Some(2.5e-7);
        r.timing_runs = Some(5);
        r.work = Work::of(&[("pivots", 12)]);
        r.message = "a, \"quoted\" message".into();
        let keys = vec!["mesh.contact_elements".to_string(), "solvers.use".to_string()];
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(header(&keys)).unwrap();
        w.write_record(r.record(&keys)).unwrap();
        let text = String::from_utf8(w.into_inner().unwrap()).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("s.csv");
        std::fs::write(&p, text).unwrap();
        let (h, rows) = SweepRow::read_csv(&p).unwrap();
        assert_eq!(h.keys, keys);
        let mut expected = r.clone();
        // −0 is written as 0.
        expected.metrics.hertz_a_err = Some(0.0);
        assert_eq!(rows, vec![expected]);
        assert_eq!(rows[0].number("residual").map(f64::to_bits), Some((1.0f64 / 3.0).to_bits()));
        assert_eq!(rows[0].cell("pivots"), "12");
    }
}
