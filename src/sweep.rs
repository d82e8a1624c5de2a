//! Sweeps: a grid of scene variants, run in parallel, one CSV row per (case, solver run) (`DESIGN.md`, "Scaling
//! out").
//!
//! A sweep spec is a TOML file:
//!
//! ```toml
//! name = "hertz-accuracy"
//! description = "..."
//! base = "../scenes/hertz-hub-fine.toml"     # relative to the spec file (or absolute)
//!
//! [[grid]]                                    # a union of cartesian products: one [[grid]] table each
//! "mesh.element" = ["constant"]
//! "mesh.contact_elements" = [20, 40, 80]
//! "solvers.use" = [["lemke"], ["clarabel"]]
//! ```
//!
//! Each key of a `[[grid]]` table is a dotted path into the base scene's TOML document and its value the array of
//! values to try (an unquoted dotted key, `mesh.element = [...]`, means the same as the quoted one). Cases are
//! numbered from 0: grids in file order, within a grid the cartesian product with the keys in sorted order and the
//! last key varying fastest. Every variant goes through [`Scene::from_toml`], so it is validated like a scene file.
//!
//! Two refinements for studies whose variants are not a plain product:
//! - **Zipped keys**: a key made of several dotted keys joined by `&` takes an array of tuples, one value per key,
//!   set together (`"drive.normal_load & mesh.contact_half_width" = [[1000.0, 2.0], [4000.0, 4.0]]`: the mesh grows
//!   with the load). The CSV has one column per key.
//! - **A grid's own base**: `base = "..."` inside a `[[grid]]` table (a string, not an array) replaces the spec's
//!   base scene for that grid, so one sweep can compare models whose scenes differ in more than the swept keys (a
//!   finite wheel with a hub beside a half-plane that refuses one).
//!
//! A sweep can be cut into shards (`k/n`: the cases with `index % n == k − 1`) that run on different machines;
//! [`merge`] joins the shards' CSVs into the CSV the unsharded sweep writes (up to the [`TIMING_COLUMNS`]).

use crate::error::{Error, Result};
use crate::io::write_atomic;
use crate::references::metrics;
use crate::results::SolverRun;
use crate::run::run_scene;
use crate::scene::Scene;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::collections::{BTreeSet, HashSet};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// A sweep specification, as read from its TOML file.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSpec {
    /// Short identifier of the sweep.
    pub name: String,
    /// What the sweep measures.
    pub description: String,
    /// The base scene file, as written in the spec (relative paths are relative to the spec file's folder).
    pub base: PathBuf,
    /// The grids: each maps a dotted scene key to the (non-empty) array of values to try. Nested tables in the
    /// file are flattened to dotted keys.
    pub grid: Vec<Table>,
    /// Per grid (same order as `grid`), its own base scene file when it names one (`base` inside `[[grid]]`); a
    /// missing entry means the spec's `base`.
    pub grid_base: Vec<Option<PathBuf>>,
    /// How many warm repeats time a case (`timing_repeats`, default 1: the case runs once and that run is timed;
    /// above 1 the cases run one at a time instead of in parallel, for timings free of contention): cases whose first run took less
    /// than [`REPEAT_BELOW_S`] are run `timing_repeats` more times, in rounds over all such cases, and their times are
    /// the median repeat's (the upper middle one for an even count; all stages from that repeat), with the fastest and slowest repeat in `t_total_min`, `t_total_max` (the first, cold run
    /// is not timed). Results (not
    /// times) are those of the first run; they do not change.
    pub timing_repeats: usize,
}

/// The dotted keys of a (possibly zipped, `a & b`) grid key.
fn zipped_keys(key: &str) -> Vec<&str> {
    key.split('&').map(str::trim).collect()
}

/// One variant of the base scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Position in the sweep's enumeration, from 0 (the `case` column of the CSV).
    pub index: usize,
    /// The swept keys of this case's grid with the values set, in sorted key order. Strings are given bare,
    /// other values in TOML syntax (e.g. `40`, `0.001`, `["lemke"]`).
    pub params: Vec<(String, String)>,
    /// The validated scene.
    pub scene: Scene,
}

/// One shard of a sweep: `k` of `n` (1-based), the cases with `index % n == k − 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which shard, 1 ≤ k ≤ n.
    pub k: usize,
    /// Number of shards, n ≥ 1.
    pub n: usize,
}

impl Shard {
    /// Whether the case numbered `index` belongs to this shard.
    pub fn contains(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// Parse `k/n`, e.g. `2/8`, with 1 ≤ k ≤ n.
    fn from_str(s: &str) -> std::result::Result<Shard, String> {
        let bad = |why: &str| format!("invalid shard `{s}`: {why} (expected k/n with 1 ≤ k ≤ n, e.g. 2/8)");
        let (k, n) = s.split_once('/').ok_or_else(|| bad("no `/`"))?;
        let k: usize = k.trim().parse().map_err(|_| bad("k is not a positive integer"))?;
        let n: usize = n.trim().parse().map_err(|_| bad("n is not a positive integer"))?;
        if n == 0 {
            return Err(bad("n must be at least 1"));
        }
        if k == 0 || k > n {
            return Err(bad("k must lie in 1..=n"));
        }
        Ok(Shard { k, n })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

/// The names of the timing columns of a sweep CSV: wall-clock times, which differ from run to run (exclude them
/// when comparing CSVs).
pub const TIMING_COLUMNS: &[&str] = &[
    "t_assembly",
    "t_condensation",
    "t_formulation",
    "t_solve",
    "t_total",
    "t_total_min",
    "t_total_max",
    "timing_runs",
];

/// A case is timed again (up to the spec's `timing_repeats`) only when its first run took less than this (seconds):
/// repeating small cases is cheap and is where the noise of a busy machine dominates.
pub const REPEAT_BELOW_S: f64 = 2.0;

/// Most cases a sweep spec may define: every case's scene is built before any runs ([`SweepSpec::cases`]), so a
/// larger grid (a few keys of many values multiply quickly) is refused when the spec is read rather than by an
/// allocation failure, or an overflow of the count, later.
pub const MAX_CASES: usize = 100_000;

/// The columns after the swept keys and before the work counters.
const RESULT_COLUMNS_HEAD: &[&str] =
    &["scene", "element", "contact_elements", "contact_nodes", "solver", "formulation", "status", "problem_size"];

/// The columns after the work counters ([`crate::solvers::work_columns`]), up to the timings.
const RESULT_COLUMNS_TAIL: &[&str] = &[
    "residual",
    "normal_load",
    "tangential_load",
    "half_width_fit",
    "peak_pressure_fit",
    "hertz_a_err",
    "hertz_p0_err",
    "hertz_l2_err",
    "cm_c_over_a",
    "cm_c_over_a_exact",
    "cm_c_err_elements",
    "cm_centre_elements",
    "cm_shear_err",
    "cm_shear_l2_err",
    "model",
    "radius",
    "contact_modulus",
    "friction",
    "hertz_a",
    "hertz_p0",
    "shift",
    "approach",
    "stick_left",
    "stick_right",
    "creepage",
    "carter_q_over_mup",
    "carter_q_over_mup_exact",
    "carter_c_over_a",
    "carter_c_over_a_exact",
    "carter_c_err_elements",
    "carter_shear_rms",
];

/// The columns after the swept keys, up to the timings: the head, the registry's work counters, the tail.
fn result_columns() -> Vec<&'static str> {
    let mut c = RESULT_COLUMNS_HEAD.to_vec();
    c.extend(crate::solvers::work_columns());
    c.extend(RESULT_COLUMNS_TAIL);
    c
}

/// The status written for a case that could not be built or run.
const ERROR_STATUS: &str = "error";

fn invalid(path: &Path, field: &str, message: impl Into<String>) -> Error {
    Error::Invalid { path: path.to_path_buf(), field: field.to_string(), message: message.into() }
}

/// A value as written in `Case::params` and the CSV: strings bare, everything else in TOML syntax.
fn show(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        v => v.to_string(),
    }
}

/// Flatten nested tables of a grid into dotted keys; every leaf must be a non-empty array.
fn flatten(path: &Path, prefix: &str, table: &Table, out: &mut Table) -> Result<()> {
    for (k, v) in table {
        let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
        if key.split('.').any(|s| s.trim().is_empty()) {
            return Err(invalid(path, &format!("grid.{key}"), "a dotted key with an empty component"));
        }
        match v {
            Value::Table(t) => flatten(path, &key, t, out)?,
            Value::Array(a) if a.is_empty() => {
                return Err(invalid(path, &format!("grid.{key}"), "empty array: give at least one value to try"))
            }
            Value::Array(_) => {
                if out.insert(key.clone(), v.clone()).is_some() {
                    return Err(invalid(path, &format!("grid.{key}"), "key given twice in the same grid"));
                }
            }
            other => {
                return Err(invalid(
                    path,
                    &format!("grid.{key}"),
                    format!(
                        "must be an array of the values to try, e.g. [{}] (got {} `{}`)",
                        other,
                        other.type_str(),
                        other
                    ),
                ))
            }
        }
    }
    Ok(())
}

/// A path in a spec, resolved against the spec file's folder.
fn resolve(spec_path: &Path, p: &Path) -> PathBuf {
    if p.is_absolute() {
        p.to_path_buf()
    } else {
        spec_path.parent().unwrap_or(Path::new("")).join(p)
    }
}

/// Read a base scene as a TOML table; errors name `field` (`base` or `grid[i].base`).
fn read_base(spec_path: &Path, base_path: &Path, field: &str) -> Result<Table> {
    let text = std::fs::read_to_string(base_path)
        .map_err(|e| invalid(spec_path, field, format!("cannot read the base scene {}: {e}", base_path.display())))?;
    toml::from_str(&text).map_err(|e| {
        invalid(spec_path, field, format!("the base scene {} is not valid TOML: {e}", base_path.display()))
    })
}

/// Zipped keys (`a & b`) take arrays of tuples with one value per key.
fn check_zipped(path: &Path, grid: &Table) -> Result<()> {
    for (key, v) in grid {
        let keys = zipped_keys(key);
        if keys.len() < 2 {
            continue;
        }
        if keys.iter().any(|k| k.is_empty()) {
            return Err(invalid(path, &format!("grid.{key}"), "a zipped key with an empty component"));
        }
        for t in v.as_array().expect("grid values are arrays") {
            match t {
                Value::Array(t) if t.len() == keys.len() => {}
                other => {
                    return Err(invalid(
                        path,
                        &format!("grid.{key}"),
                        format!("zipped keys take tuples of {} values (one per key), got `{other}`", keys.len()),
                    ))
                }
            }
        }
    }
    Ok(())
}

/// Set the dotted `key` of a TOML document, creating missing intermediate tables.
fn set_dotted(doc: &mut Table, key: &str, value: Value) -> std::result::Result<(), String> {
    let parts: Vec<&str> = key.split('.').collect();
    let (last, inner) = parts.split_last().expect("split yields at least one part");
    let mut t = doc;
    for (i, p) in inner.iter().enumerate() {
        let entry = t.entry(p.to_string()).or_insert_with(|| Value::Table(Table::new()));
        t = match entry {
            Value::Table(t) => t,
            other => {
                return Err(format!(
                    "`{}` is a {} in the base scene, not a table: cannot set `{key}`",
                    parts[..=i].join("."),
                    other.type_str()
                ))
            }
        };
    }
    t.insert(last.to_string(), value);
    Ok(())
}

/// A variant before validation: the case number, its parameters, the TOML document and the parsed scene.
struct Variant {
    index: usize,
    params: Vec<(String, String)>,
    doc: Table,
    scene: Result<Scene>,
}

impl SweepSpec {
    /// Read and check a sweep spec file. Unknown top-level keys, a missing or empty grid, and grid values that are
    /// not non-empty arrays are [`Error::Invalid`] naming the key.
    pub fn from_file(path: &Path) -> Result<SweepSpec> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        SweepSpec::from_toml(&text, path)
    }

    /// Parse and check the text of a sweep spec like [`SweepSpec::from_file`]; `path` names the file in errors and
    /// is not read (nor is the base scene).
    pub fn from_toml(text: &str, path: &Path) -> Result<SweepSpec> {
        let doc: Table = toml::from_str(text)
            .map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string().trim_end().to_string() })?;
        for key in doc.keys() {
            if !["name", "description", "base", "grid", "timing_repeats"].contains(&key.as_str()) {
                return Err(invalid(
                    path,
                    key,
                    "unknown key in a sweep spec (expected `name`, `description`, `base`, `timing_repeats` and \
                     `[[grid]]` tables)",
                ));
            }
        }
        let string = |key: &str, required: bool| -> Result<String> {
            match doc.get(key) {
                Some(Value::String(s)) => Ok(s.clone()),
                Some(other) => Err(invalid(path, key, format!("must be a string (got {})", other.type_str()))),
                None if required => Err(invalid(path, key, "missing")),
                None => Ok(String::new()),
            }
        };
        let name = string("name", true)?;
        if name.trim().is_empty() {
            return Err(invalid(path, "name", "must not be empty"));
        }
        let description = string("description", false)?;
        let base = PathBuf::from(string("base", true)?);
        let grids = match doc.get("grid") {
            Some(Value::Array(a)) if !a.is_empty() => a,
            Some(Value::Array(_)) | None => {
                return Err(invalid(path, "grid", "give at least one [[grid]] table of keys and values to try"))
            }
            Some(other) => {
                return Err(invalid(
                    path,
                    "grid",
                    format!("must be an array of tables ([[grid]]), got {}", other.type_str()),
                ))
            }
        };
        let mut grid = Vec::with_capacity(grids.len());
        let mut grid_base = Vec::with_capacity(grids.len());
        for (i, g) in grids.iter().enumerate() {
            let Value::Table(t) = g else {
                return Err(invalid(path, "grid", format!("grid {} is a {}, not a table", i + 1, g.type_str())));
            };
            let mut t = t.clone();
            grid_base.push(match t.remove("base") {
                Some(Value::String(b)) => Some(PathBuf::from(b)),
                Some(other) => {
                    return Err(invalid(
                        path,
                        &format!("grid[{i}].base"),
                        format!("must be the path of a base scene (a string), got {}", other.type_str()),
                    ))
                }
                None => None,
            });
            let t = &t;
            let mut flat = Table::new();
            flatten(path, "", t, &mut flat)?;
            if flat.is_empty() {
                return Err(invalid(path, "grid", format!("grid {} is empty: give at least one key to sweep", i + 1)));
            }
            check_zipped(path, &flat)?;
            grid.push(flat);
        }
        let cases = grid.iter().try_fold(0usize, |sum, g| {
            let product = g.values().try_fold(1usize, |p, v| p.checked_mul(v.as_array().map_or(1, Vec::len)));
            product.and_then(|c| sum.checked_add(c))
        });
        if cases.is_none_or(|c| c > MAX_CASES) {
            let count = cases.map_or(format!("more than {}", usize::MAX), |c| c.to_string());
            return Err(invalid(
                path,
                "grid",
                format!("{count} cases, more than a sweep may have ({MAX_CASES}): split it"),
            ));
        }
        let timing_repeats = match doc.get("timing_repeats") {
            None => 1,
            Some(Value::Integer(k)) if (1..=20).contains(k) => *k as usize,
            Some(other) => {
                return Err(invalid(path, "timing_repeats", format!("must be an integer from 1 to 20 (got {other})")))
            }
        };
        Ok(SweepSpec { name, description, base, grid, grid_base, timing_repeats })
    }

    /// The base scene file's path, resolved against the spec file's folder.
    pub fn base_path(&self, spec_path: &Path) -> PathBuf {
        resolve(spec_path, &self.base)
    }

    /// The base scene of grid `i` as written (its own `base`, else the spec's).
    pub fn grid_base(&self, i: usize) -> &Path {
        self.grid_base.get(i).and_then(|b| b.as_deref()).unwrap_or(&self.base)
    }

    /// Every swept key of every grid, sorted (the parameter columns of the CSV).
    pub fn keys(&self) -> Vec<String> {
        let keys: BTreeSet<&str> = self.grid.iter().flat_map(|g| g.keys()).flat_map(|k| zipped_keys(k)).collect();
        keys.into_iter().map(str::to_string).collect()
    }

    /// Number of cases: the sum over the grids of the products of their arrays' lengths.
    pub fn len(&self) -> usize {
        self.grid.iter().map(|g| g.values().map(|v| v.as_array().map_or(1, Vec::len)).product::<usize>()).sum()
    }

    /// Whether the sweep has no case (never, for a spec read by [`SweepSpec::from_file`]).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Build every variant; the scene of each is parsed and validated but errors are kept per variant. The
    /// variants' errors name `label` as their file (the spec's path, or its bare file name for CSV cells that must
    /// not depend on where a shard ran) and the base scene as written in the spec.
    fn variants(&self, spec_path: &Path, label: &Path) -> Result<Vec<Variant>> {
        let mut out = Vec::with_capacity(self.len());
        for (gi, g) in self.grid.iter().enumerate() {
            let base_name = self.grid_base(gi).to_path_buf();
            let own = self.grid_base.get(gi).is_some_and(Option::is_some);
            let field = if own { format!("grid[{gi}].base") } else { "base".to_string() };
            let base = read_base(spec_path, &resolve(spec_path, &base_name), &field)?;
            let entries: Vec<(&String, &Vec<Value>)> =
                g.iter().map(|(k, v)| (k, v.as_array().expect("grid values are arrays"))).collect();
            let total: usize = entries.iter().map(|(_, a)| a.len()).product();
            for m in 0..total {
                // Mixed-radix digits of m, the last key varying fastest.
                let mut rest = m;
                let mut picks = vec![0; entries.len()];
                for (j, (_, a)) in entries.iter().enumerate().rev() {
                    picks[j] = rest % a.len();
                    rest /= a.len();
                }
                let index = out.len();
                let mut doc = base.clone();
                let mut params = Vec::with_capacity(entries.len());
                let mut set_err = None;
                for ((key, a), &p) in entries.iter().zip(&picks) {
                    let keys = zipped_keys(key);
                    let values = match (&a[p], keys.len()) {
                        (v, 1) => vec![v.clone()],
                        (Value::Array(t), _) => t.clone(),
                        _ => unreachable!("zipped grid values are checked to be tuples"),
                    };
                    for (k, v) in keys.iter().zip(values) {
                        params.push((k.to_string(), show(&v)));
                        if let Err(e) = set_dotted(&mut doc, k, v) {
                            set_err.get_or_insert((k.to_string(), e));
                        }
                    }
                }
                let what = describe(index, &params);
                let scene = match set_err {
                    Some((key, e)) => Err(invalid(label, &key, format!("{what}: {e}"))),
                    None => build_scene(&doc, label, &base_name, &what),
                };
                out.push(Variant { index, params, doc, scene });
            }
        }
        Ok(out)
    }

    /// Every case of the sweep, in enumeration order. A variant that does not parse or validate is an error naming
    /// the spec file, the case's parameters and the offending field.
    pub fn cases(&self, spec_path: &Path) -> Result<Vec<Case>> {
        self.variants(spec_path, spec_path)?
            .into_iter()
            .map(|v| v.scene.map(|scene| Case { index: v.index, params: v.params, scene }))
            .collect()
    }
}

/// `case 3 (mesh.contact_elements = 40, solvers.use = ["lemke"])`.
fn describe(index: usize, params: &[(String, String)]) -> String {
    let p: Vec<String> = params.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    format!("case {index} ({})", p.join(", "))
}

/// Serialize a variant's document and parse it as a scene; errors are re-addressed to the spec (`spec_label`), name
/// the case (`what`) and the base scene as written in the spec (`base`).
fn build_scene(doc: &Table, spec_label: &Path, base: &Path, what: &str) -> Result<Scene> {
    let text = toml::to_string(doc).map_err(|e| invalid(spec_label, "base", format!("{what}: {e}")))?;
    Scene::from_toml(&text, base).map_err(|e| match e {
        Error::Invalid { field, message, .. } => {
            invalid(spec_label, &field, format!("{what}: in the variant of {}: {message}", base.display()))
        }
        Error::Parse { message, .. } => Error::Parse {
            path: spec_label.to_path_buf(),
            message: format!(
                "{what}: the variant of {} is not a valid scene: {}",
                base.display(),
                message.split_whitespace().collect::<Vec<_>>().join(" ")
            ),
        },
        other => other,
    })
}

/// The full CSV header for a spec's swept keys.
fn header(keys: &[String]) -> Vec<String> {
    let mut h = vec!["case".to_string()];
    h.extend(keys.iter().cloned());
    h.extend(result_columns().iter().map(|s| s.to_string()));
    h.extend(TIMING_COLUMNS.iter().map(|s| s.to_string()));
    h.push("message".into());
    h
}

fn float(v: Option<f64>) -> String {
    v.map(|v| format!("{v:e}")).unwrap_or_default()
}

fn int<T: ToString>(v: Option<T>) -> String {
    v.map(|v| v.to_string()).unwrap_or_default()
}

/// One CSV row (before the case-specific prefix): the solver name (for sorting) and the cells.
struct Row {
    case: usize,
    solver: String,
    cells: Vec<String>,
}

/// The swept-parameter cells of a case (empty where its grid does not set a key).
fn param_cells(keys: &[String], params: &[(String, String)]) -> Vec<String> {
    keys.iter().map(|k| params.iter().find(|(p, _)| p == k).map(|(_, v)| v.clone()).unwrap_or_default()).collect()
}

/// One result row; `spread` is (fastest, slowest, runs) of the total time when the case was timed repeatedly.
fn run_row(
    case: &Variant,
    keys: &[String],
    scene: &Scene,
    contact_nodes: usize,
    r: &SolverRun,
    spread: Option<(f64, f64, usize)>,
) -> Row {
    let m = metrics(scene, r);
    let c = r.contact.as_ref();
    let mut cells = vec![case.index.to_string()];
    cells.extend(param_cells(keys, &case.params));
    cells.extend([
        scene.name.clone(),
        scene.mesh.element.name().to_string(),
        scene.mesh.contact_elements.to_string(),
        contact_nodes.to_string(),
        r.solver.to_string(),
        r.formulation.to_string(),
        r.status.name().to_string(),
        r.problem_size.to_string(),
    ]);
    cells.extend(crate::solvers::work_columns().into_iter().map(|c| int(r.work.get(c))));
    cells.extend([
        float(r.residuals.map(|x| x.max())),
        float(r.resultants.map(|x| x.normal)),
        float(r.resultants.map(|x| x.tangential)),
        float(c.and_then(|c| c.fit_half_width)),
        float(c.and_then(|c| c.fit_peak_pressure)),
        float(m.hertz_a_err),
        float(m.hertz_p0_err),
        float(m.hertz_l2_err),
        float(m.cm_c_over_a),
        float(m.cm_c_over_a_exact),
        float(m.cm_c_err_elements),
        float(m.cm_centre_elements),
        float(m.cm_shear_err),
        float(m.cm_shear_l2_err),
        scene.wheel.model.name().to_string(),
    ]);
    let hertz = r.resultants.filter(|f| f.normal > 0.0).map(|f| crate::references::hertz_at(scene, f.normal));
    let edges = crate::references::stick_edges(r.answer_nodes()).filter(|_| scene.contact.friction > 0.0);
    cells.extend([
        float(Some(scene.wheel.radius)),
        float(Some(scene.contact_modulus())),
        float(Some(scene.contact.friction)),
        float(hertz.map(|h| h.half_width)),
        float(hertz.map(|h| h.peak_pressure)),
        float(r.rigid_body.and_then(|b| b.tangential)),
        float(r.rigid_body.map(|b| b.normal)),
        float(edges.map(|e| e.0)),
        float(edges.map(|e| e.1)),
        float(r.rolling.as_ref().and_then(|x| x.creepage)),
        float(m.carter_q_over_mup),
        float(m.carter_q_over_mup_exact),
        float(m.carter_c_over_a),
        float(m.carter_c_over_a_exact),
        float(m.carter_c_err_elements),
        float(m.carter_shear_rms),
    ]);
    let t = &r.timing_s;
    cells.extend([t.assembly, t.condensation, t.formulation, t.solve, t.total].map(|v| float(Some(v))));
    let (lo, hi, k) = spread.unwrap_or((t.total, t.total, 1));
    cells.extend([float(Some(lo)), float(Some(hi)), k.to_string()]);
    cells.push(r.message.clone());
    Row { case: case.index, solver: r.solver.to_string(), cells }
}

/// Rows for a case that could not be built or run: one per solver it names (read from the variant's document, so
/// this works for solver names this build does not know), status `error`, the message last.
fn error_rows(case: &Variant, keys: &[String], err: &Error) -> Vec<Row> {
    let get = |path: &[&str]| -> Option<&Value> {
        let mut v = case.doc.get(path[0])?;
        for p in &path[1..] {
            v = v.as_table()?.get(*p)?;
        }
        Some(v)
    };
    let text = |path: &[&str]| get(path).map(show).unwrap_or_default();
    let solvers: Vec<String> = match get(&["solvers", "use"]) {
        Some(Value::Array(a)) if !a.is_empty() => a.iter().map(show).collect(),
        Some(other) => vec![show(other)],
        None => vec!["all".into()],
    };
    // Sorted and deduplicated, as the rows of a case that ran.
    let solvers: BTreeSet<String> = solvers.into_iter().collect();
    let message = err.to_string().replace('\n', " ");
    solvers
        .into_iter()
        .map(|solver| {
            let mut cells = vec![case.index.to_string()];
            cells.extend(param_cells(keys, &case.params));
            let columns = result_columns();
            let mut rest = vec![String::new(); columns.len() + TIMING_COLUMNS.len()];
            let at = |name: &str| columns.iter().position(|c| *c == name).expect("a result column");
            rest[at("scene")] = text(&["name"]);
            rest[at("element")] = text(&["mesh", "element"]);
            rest[at("contact_elements")] = text(&["mesh", "contact_elements"]);
            rest[at("solver")] = solver.clone();
            rest[at("status")] = ERROR_STATUS.to_string();
            cells.extend(rest);
            cells.push(message.clone());
            Row { case: case.index, solver, cells }
        })
        .collect()
}

/// The first run of one case: its report, or the rows that say why it has none (`label` names the spec in error
/// messages).
fn first_run(case: &Variant, keys: &[String], label: &Path) -> std::result::Result<crate::results::Report, Vec<Row>> {
    let scene = match &case.scene {
        Ok(s) => s,
        Err(e) => return Err(error_rows(case, keys, e)),
    };
    let path = case_path(case, label);
    // A panic in one case (a bug) must not lose the others' rows.
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_scene(scene, &path)));
    match result {
        Ok(Ok(report)) => Ok(report),
        Ok(Err(e)) => Err(error_rows(case, keys, &e)),
        Err(panic) => {
            let what = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            let e = Error::Numerical { stage: "sweep", message: format!("panic: {what}") };
            Err(error_rows(case, keys, &e))
        }
    }
}

/// The path a case's messages name.
fn case_path(case: &Variant, label: &Path) -> PathBuf {
    PathBuf::from(format!("{} [case {}]", label.display(), case.index))
}

/// A case's rows from its report, with per run (fastest, slowest, repeats) of the total time where it was retimed.
fn case_rows(
    case: &Variant,
    keys: &[String],
    report: &crate::results::Report,
    spreads: &[Option<(f64, f64, usize)>],
) -> Vec<Row> {
    let scene = case.scene.as_ref().expect("a case that ran has a scene");
    report
        .runs
        .iter()
        .enumerate()
        .map(|(i, r)| run_row(case, keys, scene, report.mesh.contact_nodes, r, spreads.get(i).copied().flatten()))
        .collect()
}

/// Run one case once (no retiming).
fn run_case(case: &Variant, keys: &[String], label: &Path) -> Vec<Row> {
    match first_run(case, keys, label) {
        Ok(report) => case_rows(case, keys, &report, &[]),
        Err(rows) => rows,
    }
}

/// Run the cases one at a time, then time the fast ones (first run under [`REPEAT_BELOW_S`]) `repeats` more times
/// in rounds — every fast case once per round — and give each solver run the timing of its median repeat, with the
/// fastest and slowest. Results (not times) are the first run's.
///
/// The first run's times are left out: it runs cold (first touches of the allocator's pages, caches) and was
/// measured 2–50× slower than the repeats on small cases (e.g. 1.2 ms against 0.11 ms for lemke on 50 half-plane
/// elements). The repeats go in rounds rather than back to back so that a slow spell of the machine lands on one
/// repeat of many cases instead of on every repeat of the few cases running during it: back to back, all of one
/// sweep's active_set cases (a block of the grid) once came out 1.6× slower than in the next sweep while the lemke
/// cases before them did not, and a Pareto front changed with it.
fn run_cases_timed(cases: &[&Variant], keys: &[String], label: &Path, repeats: usize, bar: &ProgressBar) -> Vec<Row> {
    let mut firsts: Vec<std::result::Result<crate::results::Report, Vec<Row>>> = Vec::new();
    for case in cases {
        firsts.push(first_run(case, keys, label));
        bar.inc(1);
    }
    let fast =
        |r: &crate::results::Report| r.runs.iter().map(|x| x.timing_s.total).fold(0.0, f64::max) < REPEAT_BELOW_S;
    // Per case, per solver run: the timings of its repeats.
    let mut times: Vec<Vec<Vec<crate::results::Timing>>> =
        firsts.iter().map(|f| f.as_ref().map_or(Vec::new(), |r| vec![Vec::new(); r.runs.len()])).collect();
    let n_fast = firsts.iter().filter(|f| f.as_ref().is_ok_and(fast)).count();
    bar.inc_length((repeats * n_fast) as u64);
    for _ in 0..repeats {
        for ((case, first), t) in cases.iter().zip(&firsts).zip(times.iter_mut()) {
            let Ok(report) = first else { continue };
            if !fast(report) {
                continue;
            }
            let scene = case.scene.as_ref().expect("a case that ran has a scene");
            // A repeat that fails or panics (a bug) only loses that repeat's timing, never the sweep's rows.
            let again =
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_scene(scene, &case_path(case, label))));
            bar.inc(1);
            let Ok(Ok(again)) = again else { continue };
            for (ti, r) in t.iter_mut().zip(&again.runs) {
                ti.push(r.timing_s);
            }
        }
    }
    let mut rows = Vec::new();
    for ((case, first), t) in cases.iter().zip(firsts).zip(times) {
        match first {
            Err(r) => rows.extend(r),
            Ok(mut report) => {
                let spreads: Vec<Option<(f64, f64, usize)>> = report
                    .runs
                    .iter_mut()
                    .zip(t)
                    .map(|(r, mut t)| {
                        if t.is_empty() {
                            return None;
                        }
                        t.sort_by(|a, b| a.total.total_cmp(&b.total));
                        r.timing_s = t[t.len() / 2];
                        Some((t[0].total, t[t.len() - 1].total, t.len()))
                    })
                    .collect();
                rows.extend(case_rows(case, keys, &report, &spreads));
            }
        }
    }
    rows
}

fn sort_rows(rows: &mut [Row]) {
    rows.sort_by(|a, b| (a.case, &a.solver).cmp(&(b.case, &b.solver)));
}

fn write_csv(out_csv: &Path, header: &[String], rows: &[Vec<String>]) -> Result<()> {
    let werr = |e: csv::Error| Error::Write { path: out_csv.to_path_buf(), source: std::io::Error::other(e) };
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).map_err(werr)?;
    for r in rows {
        w.write_record(r).map_err(werr)?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Write { path: out_csv.to_path_buf(), source: e.into_error() })?;
    let text = String::from_utf8(bytes).expect("CSV of UTF-8 cells is UTF-8");
    write_atomic(out_csv, &text)
}

/// Run the cases of this shard (all cases without one) in parallel with rayon, with an indicatif progress bar
/// (hidden when `progress` is false or stderr is not a terminal), and write the CSV atomically: one row per
/// (case, solver run), sorted by case then solver name. Returns the number of rows written.
///
/// The spec and the base scene must read, and every variant of every grid (not only this shard's) must parse and
/// validate as a scene: an unknown key, a value of the wrong type or out of range, an unknown solver stops the sweep
/// before anything runs ([`Error::Parse`] or [`Error::Invalid`], naming the case and its keys). A valid variant
/// that cannot run (e.g. a named solver that does not apply to it, [`Error::Unsupported`]) gets rows with status
/// `error` and the message in the last column, `message` (which holds the solver's message for the runs that did
/// run); [`error_rows_in`] counts them for the caller.
///
/// Sets faer's global parallelism to sequential: the cases are the parallel unit.
pub fn run_sweep(spec_path: &Path, shard: Option<Shard>, out_csv: &Path, progress: bool) -> Result<usize> {
    let spec = SweepSpec::from_file(spec_path)?;
    // Per-case messages name the spec by its file name only: the CSV must not depend on where a shard ran.
    let label = PathBuf::from(spec_path.file_name().unwrap_or(spec_path.as_os_str()));
    let mut variants = spec.variants(spec_path, &label)?;
    // Every grid point is validated before anything runs (in every shard alike): a misspelt key, a value of the
    // wrong type or out of range, an unknown solver is the spec's error, not a row.
    if let Some(bad) = variants.iter().position(|v| v.scene.is_err()) {
        let e = variants.swap_remove(bad).scene.expect_err("a variant that failed");
        return Err(match e {
            Error::Invalid { field, message, .. } => invalid(spec_path, &field, message),
            Error::Parse { message, .. } => Error::Parse { path: spec_path.to_path_buf(), message },
            other => other,
        });
    }
    let mine: Vec<&Variant> = variants.iter().filter(|v| shard.is_none_or(|s| s.contains(v.index))).collect();
    let keys = spec.keys();

    faer::set_global_parallelism(faer::Par::Seq);
    // The cases run in parallel: their stage spinners would draw over each other and over the bar below.
    let _no_stages = crate::progress::suppress();
    let bar = if progress && std::io::stderr().is_terminal() {
        ProgressBar::with_draw_target(Some(mine.len() as u64), ProgressDrawTarget::stderr())
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template("{prefix} [{elapsed_precise}] {wide_bar} {pos}/{len} runs (eta {eta})")
            .expect("valid template"),
    );
    bar.set_prefix(match shard {
        Some(s) => format!("{} {s}", spec.name),
        None => spec.name.clone(),
    });
    let one = |v: &&Variant| {
        let rows = run_case(v, &keys, &label);
        bar.inc(1);
        rows
    };
    // A sweep that asks for repeated timings runs its cases one at a time, so that no case is timed while another
    // competes for the cores (on 2 cores, parallel cases moved timings by tens of percent between report runs and
    // reordered configurations on the Pareto front); other sweeps run their cases in parallel.
    let mut rows: Vec<Row> = if spec.timing_repeats > 1 {
        run_cases_timed(&mine, &keys, &label, spec.timing_repeats, &bar)
    } else {
        mine.par_iter().flat_map_iter(one).collect()
    };
    bar.finish_and_clear();
    sort_rows(&mut rows);
    let cells: Vec<Vec<String>> = rows.into_iter().map(|r| r.cells).collect();
    write_csv(out_csv, &header(&keys), &cells)?;
    Ok(cells.len())
}

/// The number of rows with status `error` in a sweep CSV written by [`run_sweep`] (0 when it cannot be read).
pub fn error_rows_in(csv_path: &Path) -> usize {
    let Ok(mut r) = csv::Reader::from_path(csv_path) else { return 0 };
    let Some(col) = r.headers().ok().and_then(|h| h.iter().position(|c| c == "status")) else { return 0 };
    r.records().filter_map(|x| x.ok()).filter(|x| x.get(col) == Some(ERROR_STATUS)).count()
}

/// Join shard CSVs (the same header required, else an error) into one CSV sorted by (case, solver) — identical to
/// the unsharded sweep's CSV except for the [`TIMING_COLUMNS`]. A (case, solver) pair present twice (the same
/// shard given twice) is an error. Returns the number of rows written.
pub fn merge(inputs: &[PathBuf], out_csv: &Path) -> Result<usize> {
    let Some(first) = inputs.first() else {
        return Err(invalid(out_csv, "inputs", "no shard CSV to merge"));
    };
    let mut header: Option<Vec<String>> = None;
    let mut rows: Vec<Row> = Vec::new();
    let mut seen = HashSet::new();
    for path in inputs {
        let perr = |e: csv::Error| Error::Parse { path: path.clone(), message: e.to_string() };
        let mut r = csv::Reader::from_path(path).map_err(|e| match e.into_kind() {
            csv::ErrorKind::Io(source) => Error::Io { path: path.clone(), source },
            other => Error::Parse { path: path.clone(), message: format!("{other:?}") },
        })?;
        let h: Vec<String> = r.headers().map_err(perr)?.iter().map(str::to_string).collect();
        let (case_col, solver_col) = match (h.first(), h.iter().position(|c| c == "solver")) {
            (Some(c), Some(s)) if c == "case" => (0, s),
            _ => return Err(invalid(path, "header", "not a sweep CSV: expected a `case` column first and `solver`")),
        };
        match &header {
            None => header = Some(h),
            Some(h0) if *h0 != h => {
                return Err(invalid(
                    path,
                    "header",
                    format!(
                        "its header differs from that of {}: the CSVs come from different sweeps (or \
                         versions)\n  {}\n  {}",
                        first.display(),
                        h0.join(","),
                        h.join(",")
                    ),
                ))
            }
            Some(_) => {}
        }
        for (line, rec) in r.records().enumerate() {
            let rec = rec.map_err(perr)?;
            let cells: Vec<String> = rec.iter().map(str::to_string).collect();
            let case: usize = cells[case_col].parse().map_err(|_| {
                invalid(path, "case", format!("row {}: case `{}` is not an integer", line + 1, cells[case_col]))
            })?;
            let solver = cells[solver_col].clone();
            if !seen.insert((case, solver.clone())) {
                return Err(invalid(
                    path,
                    "case",
                    format!("case {case}, solver {solver} appears twice: is a shard given twice?"),
                ));
            }
            rows.push(Row { case, solver, cells });
        }
    }
    sort_rows(&mut rows);
    let cells: Vec<Vec<String>> = rows.into_iter().map(|r| r.cells).collect();
    write_csv(out_csv, header.as_deref().unwrap_or_default(), &cells)?;
    Ok(cells.len())
}
