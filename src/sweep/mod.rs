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
//! A key may index an array of tables the base scene has: `steps[1].tangential_load` is the second `[[steps]]`
//! entry's key (an index beyond the base scene's entries is bad input naming the key).
//!
//! **3D sweeps.** A base scene of the 3D kind (`[wheel] model = "half_space"`, [`SpaceScene`]) makes a 3D sweep:
//! its cases run through the same plan, journal, resume, shards and merge, the case runner (`run.rs`) dispatching
//! on each case's [`AnyScene`] and `space.rs` writing its rows, which have their own columns ([`row::header_of`],
//! [`Kind`]). Every case of a sweep is of one kind.
//!
//! A sweep can be cut into shards (`k/n`: the cases with `index % n == k − 1`) that run on different machines;
//! [`merge`] joins the shards' CSVs into the CSV the unsharded sweep writes (up to the [`PROVENANCE_COLUMNS`]).

mod identity;
mod journal;
mod plan;
pub mod row;
mod run;
mod space;
pub mod two_body;

pub use journal::MARKER;
pub use plan::{Counts, Estimate, Plan, SweepOptions};
pub use row::{RowStatus, SweepRow, PROVENANCE_COLUMNS};
pub use run::{
    error_rows_in, merge, merge_checked, run_sweep, sweep_rows, sweep_rows_with, sweep_table_with, Outcome,
    REPEAT_BELOW_S, TIMING_BATCH,
};

use crate::error::{Error, Result};
use crate::scene::{AnyScene, Scene, SpaceScene};
use std::collections::BTreeSet;
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
    /// What the sweep is (`analysis`; default `table`).
    pub analysis: Analysis,
    /// `warm_start = true`: each case starts from the previous case's solutions on the same model
    /// ([`crate::pipeline::Model::solve_warm`]), a creep curve's next creepage from the last one's node states and
    /// factorisation. The answers are certified by the same residuals either way, but the work columns (iterations,
    /// pivots, factorisations) and the last bits of Lemke's answers then depend on which case came before: a sharded
    /// or resumed warm sweep is not bit-identical to the uninterrupted one. Default false (every case cold: the rows
    /// do not depend on the order).
    pub warm_start: bool,
}

/// What a sweep is, as its spec says (`analysis = "..."`): what `rollbem report` makes of its rows. The report never
/// infers it from the rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Analysis {
    /// `accuracy`: errors against theory and against each mesh's limit, against cost (a mesh refinement:
    /// `mesh.contact_elements` must be swept).
    Accuracy,
    /// `finite_vs_half_plane`: the finite wheel against the half-plane at equal loads (`wheel.model` swept, or grids
    /// with their own base scenes of both models).
    FiniteVsHalfPlane,
    /// `creep_curve`: steady-rolling creep curves against Carter (`rolling.creepage` or `drive.tangential_load`
    /// swept).
    CreepCurve,
    /// `finite_bodies`: two finite bodies (a twin disc, a pin in a bore: [`crate::source::two_body`]) against the
    /// half-space answer and the pin-bore reference as the load or the clearance grows (`drive.normal_load` or
    /// `counter_body.radius` swept).
    FiniteBodies,
    /// `table` (default): the rows only.
    #[default]
    Table,
}

impl Analysis {
    /// The name in a spec.
    pub fn name(self) -> &'static str {
        match self {
            Analysis::Accuracy => "accuracy",
            Analysis::FiniteVsHalfPlane => "finite_vs_half_plane",
            Analysis::CreepCurve => "creep_curve",
            Analysis::FiniteBodies => "finite_bodies",
            Analysis::Table => "table",
        }
    }

    /// The analysis of a name; an unknown one is bad input naming `field` of `path`.
    pub fn from_name(name: &str, path: &Path) -> Result<Analysis> {
        let all = [
            Analysis::Accuracy,
            Analysis::FiniteVsHalfPlane,
            Analysis::CreepCurve,
            Analysis::FiniteBodies,
            Analysis::Table,
        ];
        all.into_iter().find(|x| x.name() == name).ok_or_else(|| {
            let names: Vec<&str> = all.iter().map(|x| x.name()).collect();
            invalid(path, "analysis", format!("unknown analysis `{name}` (expected one of: {})", names.join(", ")))
        })
    }

    /// The swept keys (one of which) the analysis needs, and why.
    fn needs(self) -> (&'static [&'static str], &'static str) {
        match self {
            Analysis::Accuracy => (&["mesh.contact_elements"], "a mesh refinement"),
            Analysis::FiniteVsHalfPlane => (&["wheel.model"], "both models of the wheel"),
            Analysis::CreepCurve => (&["rolling.creepage", "drive.tangential_load"], "the creepage or the creep force"),
            Analysis::FiniteBodies => (&["drive.normal_load", "counter_body.radius"], "the load or the clearance"),
            Analysis::Table => (&[], ""),
        }
    }
}

/// The dotted keys of a (possibly zipped, `a & b`) grid key.
fn zipped_keys(key: &str) -> Vec<&str> {
    key.split('&').map(str::trim).collect()
}

/// One variant of the base scene: a 2D [`Scene`] ([`Expansion::case`]), or a scene of either kind
/// (`Case<AnyScene>`, [`Expansion::any_case`]: what a sweep runs).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Case<S = Scene> {
    /// Position in the sweep's enumeration, from 0 (the `case` column of the CSV).
    pub index: usize,
    /// The swept keys of this case's grid with the values set, in sorted key order. Strings are given bare,
    /// other values in TOML syntax (e.g. `40`, `0.001`, `["lemke"]`).
    pub params: Vec<(String, String)>,
    /// The validated scene.
    pub scene: S,
}

/// The kind of a sweep's scenes, which decides its CSV's columns ([`row::header_of`]): every case of a sweep is of
/// one kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// 2D scenes (the BEM wheel, the half-plane): [`Scene`].
    #[default]
    Plane,
    /// 3D half-space scenes (`[wheel] model = "half_space"`): [`SpaceScene`].
    Space,
}

impl Kind {
    /// The kind of a scene.
    pub fn of(scene: &AnyScene) -> Kind {
        match scene {
            AnyScene::Plane(_) => Kind::Plane,
            AnyScene::Space(_) => Kind::Space,
        }
    }

    /// The kind in words (messages).
    pub fn describe(self) -> &'static str {
        match self {
            Kind::Plane => "2D scenes",
            Kind::Space => "3D half-space scenes",
        }
    }
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

/// Most cases a sweep spec may define, refused when the spec is read: a case's number must fit the 4 bytes a run's
/// plan keeps per case, and a grid this large would take days to validate, let alone run (a few keys of many values
/// multiply quickly: before this limit, 2^40 cases aborted the process and 2^64 overflowed the count).
pub const MAX_CASES: usize = 100_000_000;

/// Most cases a sweep runs without being told that its size is intended (`--allow-large`,
/// [`SweepOptions::allow_large`]): above it, a grid is refused before anything is validated or run, with its count
/// (`--dry-run` prints its estimate of time and memory). 10^5 cases of the smallest meshes take a few minutes on two
/// cores; of the reference meshes, hours.
pub const LARGE_SWEEP_CASES: usize = 100_000;

pub(crate) fn invalid(path: &Path, field: &str, message: impl Into<String>) -> Error {
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

/// No swept value may hold a line break: a sweep CSV has one line per row (its journal relies on it to find a cut
/// row, [`journal`]).
fn check_one_line(path: &Path, grid: &Table) -> Result<()> {
    fn breaks(v: &Value) -> bool {
        match v {
            Value::String(s) => s.contains(['\n', '\r']),
            Value::Array(a) => a.iter().any(breaks),
            Value::Table(t) => t.values().any(breaks),
            _ => false,
        }
    }
    match grid.iter().find(|(_, v)| breaks(v)) {
        Some((key, _)) => {
            Err(invalid(path, &format!("grid.{key}"), "a value with a line break: a sweep CSV row is one line"))
        }
        None => Ok(()),
    }
}

/// No swept key may be given twice, or set a table and a key inside it (`drive` and `drive.normal_load`): the CSV
/// would record both and the later one would silently override part of the earlier.
fn check_overlaps(path: &Path, grid: &Table) -> Result<()> {
    let keys: Vec<&str> = grid.keys().flat_map(|k| zipped_keys(k)).collect();
    for (i, a) in keys.iter().enumerate() {
        for b in &keys[i + 1..] {
            let (short, long) = if a.len() <= b.len() { (a, b) } else { (b, a) };
            if short == long {
                return Err(invalid(
                    path,
                    &format!("grid.{a}"),
                    "key given twice in the same grid (once in a zipped key)",
                ));
            }
            if long.starts_with(&format!("{short}.")) || long.starts_with(&format!("{short}[")) {
                return Err(invalid(
                    path,
                    &format!("grid.{long}"),
                    format!("overlaps `{short}`, which the same grid sets as a whole: give one or the other"),
                ));
            }
        }
    }
    Ok(())
}

/// A component of a dotted key: a name, with an index into an array of tables when it is written `name[i]`
/// (`steps[1].tangential_load`: the second `[[steps]]` entry's key).
fn component(part: &str) -> (&str, Option<usize>) {
    match part.strip_suffix(']').and_then(|p| p.split_once('[')) {
        Some((name, i)) => match i.trim().parse() {
            Ok(i) => (name.trim(), Some(i)),
            Err(_) => (part, None),
        },
        None => (part, None),
    }
}

/// Set the dotted `key` of a TOML document, creating missing intermediate tables. A component `name[i]` indexes an
/// array the base scene has (a load path's `[[steps]]`): it is not created.
fn set_dotted(doc: &mut Table, key: &str, value: Value) -> std::result::Result<(), String> {
    let parts: Vec<&str> = key.split('.').collect();
    let (last, inner) = parts.split_last().expect("split yields at least one part");
    let not_table = |i: usize, v: &Value| {
        format!("`{}` is a {} in the base scene, not a table: cannot set `{key}`", parts[..=i].join("."), v.type_str())
    };
    let mut t = doc;
    for (i, p) in inner.iter().enumerate() {
        let entry = match component(p) {
            (name, None) => t.entry(name.to_string()).or_insert_with(|| Value::Table(Table::new())),
            (name, Some(k)) => indexed(t, name, k, key)?,
        };
        t = match entry {
            Value::Table(t) => t,
            other => return Err(not_table(i, other)),
        };
    }
    match component(last) {
        (name, None) => {
            t.insert(name.to_string(), value);
        }
        (name, Some(k)) => *indexed(t, name, k, key)? = value,
    }
    Ok(())
}

/// Element `k` of the array `name` of a table (for [`set_dotted`]); an error says why there is none.
fn indexed<'a>(t: &'a mut Table, name: &str, k: usize, key: &str) -> std::result::Result<&'a mut Value, String> {
    match t.get_mut(name) {
        Some(Value::Array(a)) => {
            let n = a.len();
            a.get_mut(k).ok_or_else(|| {
                format!("`{name}` has {n} entries in the base scene (indices from 0): cannot set `{key}`")
            })
        }
        Some(other) => {
            Err(format!("`{name}` is a {} in the base scene, not an array: cannot set `{key}`", other.type_str()))
        }
        None => Err(format!("the base scene has no `{name}` to index: cannot set `{key}`")),
    }
}

/// The spec's run options: `timing_repeats`, `analysis`, `warm_start` (each with its default when absent).
fn run_options(doc: &Table, path: &Path) -> Result<(usize, Analysis, bool)> {
    let timing_repeats = match doc.get("timing_repeats") {
        None => 1,
        Some(Value::Integer(k)) if (1..=20).contains(k) => *k as usize,
        Some(other) => {
            return Err(invalid(path, "timing_repeats", format!("must be an integer from 1 to 20 (got {other})")))
        }
    };
    let analysis = match doc.get("analysis") {
        None => Analysis::Table,
        Some(Value::String(a)) => Analysis::from_name(a, path)?,
        Some(other) => return Err(invalid(path, "analysis", format!("must be a string (got {})", other.type_str()))),
    };
    let warm_start = match doc.get("warm_start") {
        None => false,
        Some(Value::Boolean(b)) => *b,
        Some(other) => {
            return Err(invalid(path, "warm_start", format!("must be true or false (got {})", other.type_str())))
        }
    };
    Ok((timing_repeats, analysis, warm_start))
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
            if !["name", "description", "base", "grid", "timing_repeats", "analysis", "warm_start"]
                .contains(&key.as_str())
            {
                return Err(invalid(
                    path,
                    key,
                    "unknown key in a sweep spec (expected `name`, `description`, `base`, `analysis`, \
                     `timing_repeats`, `warm_start` and `[[grid]]` tables)",
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
            check_overlaps(path, &flat)?;
            check_one_line(path, &flat)?;
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
                format!("{count} cases, more than a sweep spec may define ({MAX_CASES}): split it"),
            ));
        }
        let (timing_repeats, analysis, warm_start) = run_options(&doc, path)?;
        let spec = SweepSpec { name, description, base, grid, grid_base, timing_repeats, analysis, warm_start };
        spec.check_analysis(path)?;
        Ok(spec)
    }

    /// The analysis must be able to apply to the grid: the keys it needs are swept (a finite-vs-half-plane sweep may
    /// instead give its grids their own base scenes).
    fn check_analysis(&self, path: &Path) -> Result<()> {
        let (needed, what) = self.analysis.needs();
        let keys = self.keys();
        let own_bases = self.grid_base.iter().filter(|b| b.is_some()).count() >= 2;
        let ok = needed.is_empty()
            || needed.iter().any(|k| keys.iter().any(|x| x == k))
            || (self.analysis == Analysis::FiniteVsHalfPlane && own_bases);
        if ok {
            return Ok(());
        }
        Err(invalid(
            path,
            "analysis",
            format!(
                "`{}` needs {what}: sweep {} (the grid sweeps {})",
                self.analysis.name(),
                needed.iter().map(|k| format!("`{k}`")).collect::<Vec<_>>().join(" or "),
                if keys.is_empty() { "nothing".to_string() } else { keys.join(", ") }
            ),
        ))
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

    /// The spec's variants, built one at a time on demand ([`Expansion`]): the base scenes are read now, a case's
    /// scene when it is asked for. Errors name the spec file; a case's scene names its file as `label` (the spec's
    /// path, or its bare file name for CSV cells that must not depend on where a shard ran).
    pub fn expand(&self, spec_path: &Path, label: &Path) -> Result<Expansion> {
        Expansion::new(self, spec_path, label)
    }

    /// Every case of the sweep, in enumeration order, each scene built and validated (all in memory: for a small
    /// sweep, a test, a fuzz target; a sweep runs from [`SweepSpec::expand`] one case at a time). A variant that
    /// does not parse or validate is an error naming the spec file, the case's parameters and the offending field.
    pub fn cases(&self, spec_path: &Path) -> Result<Vec<Case>> {
        let e = self.expand(spec_path, spec_path)?;
        (0..e.len()).map(|i| e.case(i)).collect()
    }
}

/// One grid of an [`Expansion`]: its base scene's TOML, its keys with their values, and where its cases start.
#[derive(Debug, Clone)]
struct GridCases {
    /// The base scene as written in the spec.
    base_name: PathBuf,
    /// The base scene's path, resolved against the spec's folder (anchors a 3D scene's `gap_file`).
    base_path: PathBuf,
    /// The base scene's document.
    base: Table,
    /// The (possibly zipped) keys in sorted order, each with its values.
    entries: Vec<(String, Vec<Value>)>,
    /// The number of its first case.
    start: usize,
    /// Its number of cases.
    len: usize,
}

/// The variants of a sweep spec, built one at a time from their case numbers: what a sweep of any size holds in
/// memory is the base scenes and the grids' values, never the list of its cases ([`SweepSpec::expand`]).
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Expansion {
    grids: Vec<GridCases>,
    spec_path: PathBuf,
    label: PathBuf,
}

impl Expansion {
    fn new(spec: &SweepSpec, spec_path: &Path, label: &Path) -> Result<Expansion> {
        let mut grids = Vec::with_capacity(spec.grid.len());
        let mut start = 0;
        for (gi, g) in spec.grid.iter().enumerate() {
            let base_name = spec.grid_base(gi).to_path_buf();
            let own = spec.grid_base.get(gi).is_some_and(Option::is_some);
            let field = if own { format!("grid[{gi}].base") } else { "base".to_string() };
            let base_path = resolve(spec_path, &base_name);
            let base = read_base(spec_path, &base_path, &field)?;
            let entries: Vec<(String, Vec<Value>)> =
                g.iter().map(|(k, v)| (k.clone(), v.as_array().expect("grid values are arrays").clone())).collect();
            let len = entries.iter().map(|(_, a)| a.len()).product();
            grids.push(GridCases { base_name, base_path, base, entries, start, len });
            start += len;
        }
        Ok(Expansion { grids, spec_path: spec_path.to_path_buf(), label: label.to_path_buf() })
    }

    /// Number of cases.
    pub fn len(&self) -> usize {
        self.grids.last().map_or(0, |g| g.start + g.len)
    }

    /// Whether there is no case.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The grid of case `index` and the case's position in it; `None` beyond [`Expansion::len`].
    fn locate(&self, index: usize) -> Option<(&GridCases, usize)> {
        let g = self.grids.iter().find(|g| index < g.start + g.len)?;
        Some((g, index - g.start))
    }

    /// The swept keys of case `index` with their values (strings bare, other values in TOML syntax), in sorted key
    /// order: what its CSV rows carry. Cheap: no scene is built. `None` beyond [`Expansion::len`].
    pub fn params(&self, index: usize) -> Option<Vec<(String, String)>> {
        Some(self.values(index)?.into_iter().map(|(k, v)| (k, show(&v))).collect())
    }

    /// The swept keys of case `index` with their values: mixed-radix digits of its position in its grid, the last
    /// key varying fastest. `None` beyond [`Expansion::len`].
    fn values(&self, index: usize) -> Option<Vec<(String, Value)>> {
        let (g, m) = self.locate(index)?;
        let mut picks = vec![0; g.entries.len()];
        let mut rest = m;
        for (j, (_, a)) in g.entries.iter().enumerate().rev() {
            picks[j] = rest % a.len();
            rest /= a.len();
        }
        let mut out = Vec::with_capacity(g.entries.len());
        for ((key, a), &p) in g.entries.iter().zip(&picks) {
            let keys = zipped_keys(key);
            let values = match (&a[p], keys.len()) {
                (v, 1) => vec![v.clone()],
                (Value::Array(t), _) => t.clone(),
                _ => unreachable!("zipped grid values are checked to be tuples"),
            };
            out.extend(keys.iter().map(|k| k.to_string()).zip(values));
        }
        Some(out)
    }

    /// The identity of the sweep's cases as the spec and its base scenes are now (`resolved` left empty: it needs
    /// every case validated, `identity`).
    pub fn identity(&self, spec: &SweepSpec, shard: Option<Shard>) -> identity::Identity {
        let grids: Vec<identity::GridParts<'_>> =
            self.grids.iter().map(|g| (g.base_name.display().to_string(), &g.base, g.entries.as_slice())).collect();
        identity::Identity::new(spec, shard, &grids)
    }

    /// Whether `rows` (read from a sweep CSV) can be case `index`'s: the case is one of the spec's and every row
    /// carries its parameters (empty values are not written). `Err` says why not.
    pub fn check_rows(&self, index: usize, rows: &[SweepRow]) -> std::result::Result<(), String> {
        let Some(mut want) = self.params(index) else {
            return Err(format!("the spec has {} cases", self.len()));
        };
        want.retain(|(_, v)| !v.is_empty());
        match rows.iter().find(|r| r.params != want) {
            None => Ok(()),
            Some(r) => {
                let show = |p: &[(String, String)]| p.iter().map(|(k, v)| format!("{k} = {v}")).collect::<Vec<_>>();
                Err(format!(
                    "its row has parameters [{}], the spec's case has [{}]",
                    show(&r.params).join(", "),
                    show(&want).join(", ")
                ))
            }
        }
    }

    /// Case `index` of a sweep of 2D scenes: its parameters and its scene, parsed and validated. An error names the
    /// spec file, the case's parameters and the offending field (a 3D case is refused naming `wheel.model`: read it
    /// with [`Expansion::any_case`]); an index beyond [`Expansion::len`] is an error naming `case`.
    pub fn case(&self, index: usize) -> Result<Case> {
        self.built(index, false).map(|c| match c.scene {
            AnyScene::Plane(scene) => Case { index: c.index, params: c.params, scene },
            AnyScene::Space(_) => unreachable!("a 2D case is built as a 2D scene"),
        })
    }

    /// Case `index` of either kind (a 3D case when its document says `[wheel] model = "half_space"`): what a sweep
    /// runs. Errors as [`Expansion::case`]'s.
    pub fn any_case(&self, index: usize) -> Result<Case<AnyScene>> {
        self.built(index, true)
    }

    /// The kind of case `index` (from its document, without validating it); `None` beyond [`Expansion::len`] or
    /// when a swept key cannot be set (building the case says why).
    pub fn kind(&self, index: usize) -> Option<Kind> {
        let (doc, _, set_err) = self.document(index)?;
        set_err.is_none().then(|| if crate::scene::space::is_space_table(&doc) { Kind::Space } else { Kind::Plane })
    }

    fn built(&self, index: usize, any: bool) -> Result<Case<AnyScene>> {
        // A variant's error names the spec by `label` in the case's words; the spec's error names its file.
        let readdress = |e: Error| match e {
            Error::Invalid { field, message, .. } => invalid(&self.spec_path, &field, message),
            Error::Parse { message, .. } => Error::Parse { path: self.spec_path.clone(), message },
            other => other,
        };
        self.build(index, any).map_err(readdress)
    }

    /// Case `index`'s document (the base scene with the swept values set), its parameters, and the first key that
    /// could not be set with why.
    #[allow(clippy::type_complexity)]
    fn document(&self, index: usize) -> Option<(Table, Vec<(String, String)>, Option<(String, String)>)> {
        let (g, _) = self.locate(index)?;
        let values = self.values(index)?;
        let mut doc = g.base.clone();
        let mut params = Vec::with_capacity(values.len());
        let mut set_err = None;
        for (k, v) in values {
            params.push((k.clone(), show(&v)));
            if let Err(e) = set_dotted(&mut doc, &k, v) {
                set_err.get_or_insert((k, e));
            }
        }
        Some((doc, params, set_err))
    }

    fn build(&self, index: usize, any: bool) -> Result<Case<AnyScene>> {
        let (Some((g, _)), Some((doc, params, set_err))) = (self.locate(index), self.document(index)) else {
            return Err(invalid(&self.label, "case", format!("case {index}: the sweep has {} cases", self.len())));
        };
        let what = describe(index, &params);
        if let Some((key, e)) = set_err {
            return Err(invalid(&self.label, &key, format!("{what}: {e}")));
        }
        let scene = if any && crate::scene::space::is_space_table(&doc) {
            AnyScene::Space(build_space_scene(&doc, &self.label, g, &what)?)
        } else {
            // The case's messages name the spec and the case, wherever the scene came from.
            let origin = PathBuf::from(format!("{} [case {index}]", self.label.display()));
            AnyScene::Plane(build_scene(&doc, &self.label, &g.base_name, &what)?.relabel(origin))
        };
        Ok(Case { index, params, scene })
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
    // The document deserialised straight from the table (no text in between: a fifth of a small case's time); a
    // document that does not deserialise goes the way of the text below, for the parser's message.
    if let Ok(document) = toml::Value::Table(doc.clone()).try_into::<crate::scene::document::SceneDocument>() {
        return Scene::from_document(document, base).map_err(|e| readdress_scene(e, spec_label, base, what));
    }
    let text = toml::to_string(doc).map_err(|e| invalid(spec_label, "base", format!("{what}: {e}")))?;
    Scene::from_toml(&text, base).map_err(|e| readdress_scene(e, spec_label, base, what))
}

/// Parse a 3D variant's document as a half-space scene (through its text, so that a 2D key or an unknown one is
/// named as a scene file's would be); a relative `gap_file` is read beside the base scene. Errors as
/// [`build_scene`]'s.
fn build_space_scene(doc: &Table, spec_label: &Path, g: &GridCases, what: &str) -> Result<SpaceScene> {
    let text = toml::to_string(doc).map_err(|e| invalid(spec_label, "base", format!("{what}: {e}")))?;
    SpaceScene::from_toml(&text, &g.base_path).map_err(|e| readdress_scene(e, spec_label, &g.base_name, what))
}

/// A variant's error re-addressed to the spec (see [`build_scene`]).
fn readdress_scene(e: Error, spec_label: &Path, base: &Path, what: &str) -> Error {
    match e {
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
    }
}
