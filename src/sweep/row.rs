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
//! against the references that apply, [`crate::references::Metrics`]), the pair and the rigid motion; `message`.
//! Those are the **results**: the same cases give the same cells whichever run wrote them (serial, sharded and
//! merged, resumed; with `warm_start` the work counters and the last bits of Lemke's answers aside). Last come the
//! **provenance** columns, [`PROVENANCE_COLUMNS`]: how this run went (the timings, `timing_runs`, and `setup`:
//! whether the case's model was built for it or reused from the case before it in the same run), which differ from
//! run to run. Two runs of the same cases compare equal on every column before the first provenance column. A cell
//! is empty where a value does not apply.
//!
//! A CSV of an older rollbem (without `scene_digest`, columns in another order) still reads: columns are found by
//! name.

use crate::error::{Error, Result};
use crate::references::Metrics;
use crate::scene::{BodyModel, ElementKind};
use crate::solvers::Work;
use crate::status::Status;
use std::path::Path;

/// The status cell of a row: a run's status, or `error` for a case that could not run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum RowStatus {
    /// The run's status.
    Run(Status),
    /// The case could not be built or run (the message says why).
    Error,
}

impl RowStatus {
    /// The name written in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            RowStatus::Run(s) => s.name(),
            RowStatus::Error => "error",
        }
    }

    /// Whether the run solved.
    pub fn solved(self) -> bool {
        self == RowStatus::Run(Status::Solved)
    }
}

/// One row of a sweep CSV (see the module docs). Lengths, loads and stresses are in the scene's units; times in
/// seconds.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SweepRow {
    /// The case's position in the sweep's enumeration, from 0.
    pub case: usize,
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
    /// Figures a reader derives from the rows, by name (not written to the CSV; e.g. the report's errors against a
    /// mesh's limit). [`SweepRow::number`] finds them as it finds the columns.
    pub derived: std::collections::BTreeMap<String, f64>,
}

impl SweepRow {
    /// An empty row of a case and solver with a status (every figure empty).
    pub fn new(case: usize, solver: &str, status: RowStatus) -> SweepRow {
        SweepRow {
            case,
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
            derived: Default::default(),
        }
    }

    /// Set a known column from its CSV cell; `Ok(false)` when `name` is not a known column (a swept key, a work
    /// counter or a derived figure).
    pub fn set(&mut self, name: &str, cell: &str) -> std::result::Result<bool, String> {
        match COLUMNS.iter().find(|c| c.name == name) {
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
        if let Some(c) = COLUMNS.iter().find(|c| c.name == name) {
            return (c.get)(self).text();
        }
        if let Some(v) = self.derived.get(name) {
            return format!("{v:e}");
        }
        self.work.get(name).map(|v| v.to_string()).unwrap_or_default()
    }

    /// The value of a numeric column by name (a figure, an error, a time, a count), if it has one and it is finite.
    pub fn number(&self, name: &str) -> Option<f64> {
        let v = match COLUMNS.iter().find(|c| c.name == name) {
            Some(c) => match (c.get)(self) {
                Cell::Num(v) => v,
                Cell::Int(v) => v.map(|v| v as f64),
                Cell::Text(_) => None,
            },
            None => self.derived.get(name).copied().or_else(|| self.work.get(name).map(|v| v as f64)),
        };
        v.filter(|v| v.is_finite())
    }

    /// The row's cells against a header written by [`header`] with the same swept keys.
    pub fn record(&self, keys: &[String]) -> Vec<String> {
        let mut out = vec![self.case.to_string()];
        out.extend(keys.iter().map(|k| self.param(k).unwrap_or_default().to_string()));
        for c in COLUMNS {
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
        row.params = header
            .keys
            .iter()
            .enumerate()
            .filter(|(k, _)| !get(1 + k).is_empty())
            .map(|(k, key)| (key.clone(), get(1 + k).to_string()))
            .collect();
        for (c, i) in COLUMNS.iter().zip(&header.columns) {
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

/// Where the columns of a sweep CSV are: the swept keys, the known columns (in the order of the module docs) and the work
/// counters.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Header {
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
        let mut columns = Vec::with_capacity(COLUMNS.len());
        for c in COLUMNS {
            let i = names.iter().position(|n| n == c.name);
            if i.is_none() && !OPTIONAL.contains(&c.name) {
                return Err(bad(format!("not a sweep CSV of this version: no `{}` column (rerun the sweep)", c.name)));
            }
            columns.push(i);
        }
        let work_at = names.iter().position(|n| n == WORK_AFTER).map_or(first, |i| i + 1);
        let work_end = names.iter().position(|n| n == "residual").unwrap_or(work_at);
        let work = (work_at..work_end).map(|i| (names[i].clone(), i)).collect();
        Ok(Header { keys: names[1..first].to_vec(), columns, work, names: names.to_vec() })
    }
}

/// The full CSV header for a spec's swept keys.
pub fn header(keys: &[String]) -> Vec<String> {
    let mut h = vec!["case".to_string()];
    h.extend(keys.iter().cloned());
    for c in COLUMNS {
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

/// Columns a CSV of an older rollbem may lack (read as empty).
const OPTIONAL: &[&str] = &["scene_digest"];

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
    ($name:literal, $($f:ident).+) => {
        Column { name: $name, get: |r| Cell::Num(r.$($f).+), set: |r, s| { r.$($f).+ = num(s)?; Ok(()) } }
    };
}

macro_rules! int_col {
    ($name:literal, $($f:ident).+) => {
        Column {
            name: $name,
            get: |r| Cell::Int(r.$($f).+.map(|v| v as u64)),
            set: |r, s| { r.$($f).+ = int(s)?; Ok(()) },
        }
    };
}

/// The known columns, in CSV order (the swept keys before them, the work counters after `problem_size`).
static COLUMNS: &[Column] = &[
    Column {
        name: "scene",
        get: |r| Cell::Text(r.scene.clone()),
        set: |r, s| {
            r.scene = s.into();
            Ok(())
        },
    },
    Column {
        name: "scene_digest",
        get: |r| Cell::Text(r.scene_digest.map(super::identity::show_digest).unwrap_or_default()),
        set: |r, s| {
            r.scene_digest = match s {
                "" => None,
                s => Some(super::identity::parse_digest(s).ok_or(format!("`{s}` is not a scene digest"))?),
            };
            Ok(())
        },
    },
    Column {
        name: "element",
        get: |r| Cell::Text(r.element.map(|e| e.name().to_string()).unwrap_or_default()),
        set: |r, s| {
            r.element = named(s)?;
            Ok(())
        },
    },
    int_col!("contact_elements", contact_elements),
    int_col!("contact_nodes", contact_nodes),
    Column {
        name: "solver",
        get: |r| Cell::Text(r.solver.clone()),
        set: |r, s| {
            r.solver = s.into();
            Ok(())
        },
    },
    Column {
        name: "formulation",
        get: |r| Cell::Text(r.formulation.clone().unwrap_or_default()),
        set: |r, s| {
            r.formulation = (!s.is_empty()).then(|| s.to_string());
            Ok(())
        },
    },
    Column {
        name: "status",
        get: |r| Cell::Text(r.status.name().to_string()),
        set: |r, s| {
            r.status = match s {
                "error" => RowStatus::Error,
                _ => RowStatus::Run(named(s)?.ok_or("empty status")?),
            };
            Ok(())
        },
    },
    int_col!("problem_size", problem_size),
    num_col!("residual", residual),
    num_col!("normal_load", normal_load),
    num_col!("tangential_load", tangential_load),
    num_col!("half_width_fit", half_width_fit),
    num_col!("peak_pressure_fit", peak_pressure_fit),
    num_col!("hertz_a_err", metrics.hertz_a_err),
    num_col!("hertz_p0_err", metrics.hertz_p0_err),
    num_col!("hertz_l2_err", metrics.hertz_l2_err),
    num_col!("cm_c_over_a", metrics.cm_c_over_a),
    num_col!("cm_c_over_a_exact", metrics.cm_c_over_a_exact),
    num_col!("cm_c_err_elements", metrics.cm_c_err_elements),
    num_col!("cm_centre_elements", metrics.cm_centre_elements),
    num_col!("cm_shear_err", metrics.cm_shear_err),
    num_col!("cm_shear_l2_err", metrics.cm_shear_l2_err),
    Column {
        name: "model",
        get: |r| Cell::Text(r.model.map(|m| m.name().to_string()).unwrap_or_default()),
        set: |r, s| {
            r.model = named(s)?;
            Ok(())
        },
    },
    num_col!("strip_width", strip_width),
    num_col!("radius", radius),
    num_col!("contact_modulus", contact_modulus),
    num_col!("friction", friction),
    num_col!("hertz_a", hertz_a),
    num_col!("hertz_p0", hertz_p0),
    num_col!("shift", shift),
    num_col!("approach", approach),
    num_col!("stick_left", stick_left),
    num_col!("stick_right", stick_right),
    num_col!("creepage", creepage),
    num_col!("carter_q_over_mup", metrics.carter_q_over_mup),
    num_col!("carter_q_over_mup_exact", metrics.carter_q_over_mup_exact),
    num_col!("carter_c_over_a", metrics.carter_c_over_a),
    num_col!("carter_c_over_a_exact", metrics.carter_c_over_a_exact),
    num_col!("carter_c_err_elements", metrics.carter_c_err_elements),
    num_col!("carter_shear_rms", metrics.carter_shear_rms),
    Column {
        name: "message",
        get: |r| Cell::Text(r.message.clone()),
        set: |r, s| {
            r.message = s.into();
            Ok(())
        },
    },
    num_col!("t_assembly", t_assembly),
    num_col!("t_condensation", t_condensation),
    num_col!("t_formulation", t_formulation),
    num_col!("t_solve", t_solve),
    num_col!("t_total", t_total),
    num_col!("t_total_min", t_total_min),
    num_col!("t_total_max", t_total_max),
    int_col!("timing_runs", timing_runs),
    Column {
        name: "setup",
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
