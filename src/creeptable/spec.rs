//! A creep-table spec (TOML) and its cases.
//!
//! ```toml
//! kind = "creep_table"          # what makes `rollbem sweep` read the file as a creep table
//! name = "fastsim-usetab"
//! description = "..."           # optional
//! engine = "fastsim"            # a registered engine (creeptable::BUILT_IN)
//! [options]                     # optional: the engine's own settings
//! flexibility = "weighted"
//! [contact]                     # optional; each default 1 (the normalised table does not depend on them)
//! shear_modulus = 1.0           # G
//! friction = 1.0                # μ (> 0: it normalises)
//! normal_force = 1.0            # N
//! size = 1.0                    # c = √(ab)
//! [grid]                        # optional; default 100 × 100 (FASTSIM's default)
//! mx = 100
//! my = 100
//! [axes]                        # each a non-empty, strictly increasing list of finite numbers
//! nu = [0.28]
//! a_over_b = [0.5, 1.0, 2.0]    # in [0.1, 10] (Kalker's Table E.3, which normalises)
//! xi = [0.0, 0.25, 0.5, 1.0]    # normalised creepages ξ', η', φ' (module docs of creeptable)
//! eta = [0.0, 0.5]
//! phi = [-1.0, 0.0, 1.0]
//! ```

use super::{engine_entry, CreepCase, CreepEngine, Forces, Load, Resolution};
use crate::error::{Error, Result};
use crate::fastsim::Creepages;
use crate::theory::kalker;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The largest table run without `--allow-large` (cases), as for sweeps.
pub const MAX_CASES: usize = 100_000;

/// The largest table at all (cases): the plan and the merge keep a few bytes per case.
const HARD_MAX_CASES: usize = 100_000_000;

/// The axes of a table, each strictly increasing (module docs of `creeptable`).
#[derive(Debug, Clone, PartialEq)]
pub struct Axes {
    /// Poisson ratios ν (slowest).
    pub nu: Vec<f64>,
    /// Ellipses a/b.
    pub a_over_b: Vec<f64>,
    /// Normalised longitudinal creepages ξ'.
    pub xi: Vec<f64>,
    /// Normalised lateral creepages η'.
    pub eta: Vec<f64>,
    /// Normalised spins φ' (fastest).
    pub phi: Vec<f64>,
}

impl Axes {
    /// The axes' lengths (nν, n_ab, nξ, nη, nφ).
    pub fn shape(&self) -> [usize; 5] {
        [self.nu.len(), self.a_over_b.len(), self.xi.len(), self.eta.len(), self.phi.len()]
    }

    /// The number of cases (the product of the lengths, saturating).
    pub fn len(&self) -> usize {
        self.shape().iter().fold(1usize, |n, &k| n.saturating_mul(k))
    }

    /// Whether there is no case.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A case's indices on the axes (iν, i_ab, iξ, iη, iφ): φ' fastest, ν slowest.
    pub fn coords(&self, index: usize) -> [usize; 5] {
        let shape = self.shape();
        let mut out = [0; 5];
        let mut rest = index;
        for d in (0..5).rev() {
            out[d] = rest % shape[d].max(1);
            rest /= shape[d].max(1);
        }
        out
    }

    /// A case's values (ν, a/b, ξ', η', φ').
    pub fn values(&self, index: usize) -> [f64; 5] {
        let [i, j, k, l, m] = self.coords(index);
        [self.nu[i], self.a_over_b[j], self.xi[k], self.eta[l], self.phi[m]]
    }

    fn named(&self) -> [(&'static str, &Vec<f64>); 5] {
        [("nu", &self.nu), ("a_over_b", &self.a_over_b), ("xi", &self.xi), ("eta", &self.eta), ("phi", &self.phi)]
    }
}

/// Kalker's scaling of one ellipse (module docs of `creeptable`): physical creepages from normalised ones and
/// normalised forces from physical ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Normalisation {
    /// C11, C22, C23 at the ellipse's a/b and ν (Table E.3).
    pub coefficients: [f64; 3],
    /// μN (force).
    pub mu_n: f64,
    /// G (force/length²).
    pub shear_modulus: f64,
    /// c = √(ab) (length).
    pub size: f64,
}

impl Normalisation {
    /// The scaling for an ellipse a/b at ν with G, μN and c. Errors: a/b or ν outside Table E.3.
    pub fn new(
        a_over_b: f64,
        nu: f64,
        shear_modulus: f64,
        mu_n: f64,
        size: f64,
    ) -> std::result::Result<Normalisation, crate::error::ArgumentError> {
        let k = kalker::creep_coefficients(a_over_b, 1.0, nu)?;
        Ok(Normalisation { coefficients: [k.c11, k.c22, k.c23], mu_n, shear_modulus, size })
    }

    /// ξ = −ξ' 3μN/(G c² C11), η = −η' 3μN/(G c² C22), φ = −φ' μN/(G c³ C23).
    pub fn creepages(&self, xi_n: f64, eta_n: f64, phi_n: f64) -> Creepages {
        let (g, c, [c11, c22, c23]) = (self.shear_modulus, self.size, self.coefficients);
        // `+ 0.0` turns the −0 of a zero creepage into 0.
        Creepages {
            xi: -xi_n * 3.0 * self.mu_n / (g * c * c * c11) + 0.0,
            eta: -eta_n * 3.0 * self.mu_n / (g * c * c * c22) + 0.0,
            phi: -phi_n * self.mu_n / (g * c * c * c * c23) + 0.0,
        }
    }

    /// (Fx/(μN), Fy/(μN), Mz/(μN c)).
    pub fn forces(&self, f: &Forces) -> (f64, f64, Option<f64>) {
        (f.fx / self.mu_n, f.fy / self.mu_n, f.mz.map(|m| m / (self.mu_n * self.size)))
    }
}

/// A creep-table spec (module docs), validated.
#[derive(Debug, Clone, PartialEq)]
pub struct TableSpec {
    /// Short identifier.
    pub name: String,
    /// What the table is for.
    pub description: String,
    /// The engine's registered name.
    pub engine: String,
    /// The engine's `[options]` (checked by the engine's `build`).
    pub options: Table,
    /// G (force/length²).
    pub shear_modulus: f64,
    /// μ (> 0).
    pub friction: f64,
    /// N (force).
    pub normal_force: f64,
    /// c = √(ab) (length).
    pub size: f64,
    /// The grid resolution every case gets.
    pub resolution: Resolution,
    /// The axes.
    pub axes: Axes,
}

fn invalid(path: &Path, field: &str, message: impl Into<String>) -> Error {
    Error::Invalid { path: path.to_path_buf(), field: field.to_string(), message: message.into() }
}

/// Whether a TOML document is a creep-table spec (`kind = "creep_table"`).
pub(super) fn is_table_document(doc: &Table) -> bool {
    doc.get("kind").and_then(Value::as_str) == Some("creep_table")
}

fn number(v: &Value) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

/// A sub-table's keys: each of `allowed` read as a number > 0 (`positive`) or an integer ≥ 1, defaults kept.
fn sub_table<'a>(doc: &'a Table, name: &str, allowed: &[&str], path: &Path) -> Result<Option<&'a Table>> {
    let Some(v) = doc.get(name) else { return Ok(None) };
    let t = v.as_table().ok_or_else(|| invalid(path, name, "must be a table"))?;
    if let Some(k) = t.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(invalid(path, &format!("{name}.{k}"), format!("unknown key (allowed: {})", allowed.join(", "))));
    }
    Ok(Some(t))
}

fn read_axis(axes: &Table, key: &str, path: &Path) -> Result<Vec<f64>> {
    let field = format!("axes.{key}");
    let v = axes.get(key).ok_or_else(|| invalid(path, &field, "missing: a list of numbers"))?;
    let arr = v.as_array().ok_or_else(|| invalid(path, &field, "must be a list of numbers"))?;
    if arr.is_empty() {
        return Err(invalid(path, &field, "must not be empty"));
    }
    let mut out = Vec::with_capacity(arr.len());
    for (i, x) in arr.iter().enumerate() {
        let x =
            number(x).ok_or_else(|| invalid(path, &format!("{field}[{i}]"), format!("must be a number, is {x}")))?;
        if !x.is_finite() {
            return Err(invalid(path, &format!("{field}[{i}]"), format!("must be finite, is {x}")));
        }
        if let Some(&last) = out.last() {
            if x <= last {
                let msg = format!("the list must be strictly increasing: {x} follows {last}");
                return Err(invalid(path, &format!("{field}[{i}]"), msg));
            }
        }
        out.push(x);
    }
    Ok(out)
}

impl TableSpec {
    /// Reads and validates a spec file. Errors: the file cannot be read (exit 2), malformed TOML, a missing,
    /// unknown or invalid key (named), an unknown engine or option.
    pub fn from_file(path: &Path) -> Result<TableSpec> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        TableSpec::from_toml(&text, path)
    }

    /// Parses and validates a spec's text (`path` names it in errors).
    pub fn from_toml(text: &str, path: &Path) -> Result<TableSpec> {
        let doc: Table =
            toml::from_str(text).map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string() })?;
        const TOP: [&str; 9] =
            ["kind", "name", "description", "engine", "options", "contact", "grid", "axes", "analysis"];
        if let Some(k) = doc.keys().find(|k| !TOP.contains(&k.as_str())) {
            return Err(invalid(path, k, format!("unknown key of a creep-table spec (allowed: {})", TOP.join(", "))));
        }
        if !is_table_document(&doc) {
            return Err(invalid(path, "kind", "must be \"creep_table\""));
        }
        let string = |key: &str, required: bool| -> Result<String> {
            match doc.get(key) {
                Some(Value::String(s)) => Ok(s.clone()),
                Some(v) => Err(invalid(path, key, format!("must be a string, is {v}"))),
                None if required => Err(invalid(path, key, "missing")),
                None => Ok(String::new()),
            }
        };
        let name = string("name", true)?;
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c)) {
            return Err(invalid(path, "name", format!("must be letters, digits, -, _ or . (not empty), is {name:?}")));
        }
        let description = string("description", false)?;
        let engine = string("engine", true)?;
        let Some(entry) = engine_entry(&engine) else {
            let names: Vec<&str> = super::BUILT_IN.iter().map(|e| e.name).collect();
            return Err(invalid(
                path,
                "engine",
                format!("unknown engine {engine:?} (registered: {})", names.join(", ")),
            ));
        };
        let options = match doc.get("options") {
            None => Table::new(),
            Some(Value::Table(t)) => t.clone(),
            Some(_) => return Err(invalid(path, "options", "must be a table")),
        };
        (entry.build)(&options).map_err(|(k, m)| invalid(path, &format!("options.{k}"), m))?;
        if let Some(v) = doc.get("analysis") {
            if v.as_str() != Some("table") {
                return Err(invalid(path, "analysis", "a creep table's analysis is \"table\" (or leave it out)"));
            }
        }
        let mut spec = TableSpec {
            name,
            description,
            engine,
            options,
            shear_modulus: 1.0,
            friction: 1.0,
            normal_force: 1.0,
            size: 1.0,
            resolution: Resolution { mx: 100, my: 100 },
            axes: Axes { nu: vec![], a_over_b: vec![], xi: vec![], eta: vec![], phi: vec![] },
        };
        spec.read_contact_and_grid(&doc, path)?;
        spec.read_axes(&doc, path)?;
        Ok(spec)
    }

    fn read_contact_and_grid(&mut self, doc: &Table, path: &Path) -> Result<()> {
        let keys = ["shear_modulus", "friction", "normal_force", "size"];
        if let Some(t) = sub_table(doc, "contact", &keys, path)? {
            for (k, v) in t {
                let x = number(v).filter(|x| x.is_finite() && *x > 0.0);
                let x =
                    x.ok_or_else(|| invalid(path, &format!("contact.{k}"), format!("must be finite and > 0, is {v}")))?;
                match k.as_str() {
                    "shear_modulus" => self.shear_modulus = x,
                    "friction" => self.friction = x,
                    "normal_force" => self.normal_force = x,
                    _ => self.size = x,
                }
            }
        }
        if let Some(t) = sub_table(doc, "grid", &["mx", "my"], path)? {
            for (k, v) in t {
                let n = v.as_integer().filter(|&n| (1..=100_000).contains(&n));
                let n = n.ok_or_else(|| {
                    invalid(path, &format!("grid.{k}"), format!("must be a whole number in [1, 100000], is {v}"))
                })? as usize;
                if k == "mx" {
                    self.resolution.mx = n;
                } else {
                    self.resolution.my = n;
                }
            }
        }
        let elements = self.resolution.mx.saturating_mul(self.resolution.my);
        if elements > crate::fastsim::MAX_ELEMENTS {
            let msg = format!("mx × my = {elements} elements, at most {}", crate::fastsim::MAX_ELEMENTS);
            return Err(invalid(path, "grid.mx", msg));
        }
        Ok(())
    }

    fn read_axes(&mut self, doc: &Table, path: &Path) -> Result<()> {
        let keys = ["nu", "a_over_b", "xi", "eta", "phi"];
        let axes = sub_table(doc, "axes", &keys, path)?.ok_or_else(|| invalid(path, "axes", "missing"))?;
        self.axes = Axes {
            nu: read_axis(axes, "nu", path)?,
            a_over_b: read_axis(axes, "a_over_b", path)?,
            xi: read_axis(axes, "xi", path)?,
            eta: read_axis(axes, "eta", path)?,
            phi: read_axis(axes, "phi", path)?,
        };
        for (i, &nu) in self.axes.nu.iter().enumerate() {
            if !(0.0..=0.5).contains(&nu) {
                return Err(invalid(
                    path,
                    &format!("axes.nu[{i}]"),
                    format!("must be in [0, 0.5] (Table E.3), is {nu}"),
                ));
            }
        }
        for (i, &r) in self.axes.a_over_b.iter().enumerate() {
            if !(0.1..=10.0).contains(&r) {
                let msg = format!("must be in [0.1, 10] (Table E.3, which normalises the creepages), is {r}");
                return Err(invalid(path, &format!("axes.a_over_b[{i}]"), msg));
            }
        }
        let n = self.axes.len();
        if n > HARD_MAX_CASES {
            return Err(invalid(path, "axes", format!("{n} cases, at most {HARD_MAX_CASES}")));
        }
        Ok(())
    }

    /// The number of cases.
    pub fn len(&self) -> usize {
        self.axes.len()
    }

    /// Whether the table has no case (never, once validated).
    pub fn is_empty(&self) -> bool {
        self.axes.is_empty()
    }

    /// The engine the spec names, built with its options.
    pub fn engine(&self, path: &Path) -> Result<Box<dyn CreepEngine>> {
        let entry = engine_entry(&self.engine).ok_or_else(|| invalid(path, "engine", "unknown engine"))?;
        (entry.build)(&self.options).map_err(|(k, m)| invalid(path, &format!("options.{k}"), m))
    }

    /// The normalisation of the ellipse (iν, i_ab).
    pub fn normalisation(&self, inu: usize, iab: usize) -> Result<Normalisation> {
        let (nu, r) = (self.axes.nu[inu], self.axes.a_over_b[iab]);
        Normalisation::new(r, nu, self.shear_modulus, self.friction * self.normal_force, self.size)
            .map_err(|e| invalid(&PathBuf::from("<spec>"), "axes", e.to_string()))
    }

    /// Case `index` in physical units, with its normalisation.
    pub fn case(&self, index: usize) -> Result<(CreepCase, Normalisation)> {
        let [inu, iab, ..] = self.axes.coords(index);
        let [nu, r, xi, eta, phi] = self.axes.values(index);
        let norm = self.normalisation(inu, iab)?;
        let case = CreepCase::from_shape(
            r,
            self.size,
            nu,
            self.shear_modulus,
            self.friction,
            Load::NormalForce(self.normal_force),
            norm.creepages(xi, eta, phi),
            self.resolution,
        );
        Ok((case, norm))
    }

    /// A digest of what case `index`'s answer depends on (engine name and settings, contact, grid, coordinates), as
    /// 16 hex digits.
    pub fn case_digest(&self, index: usize, engine_settings: &str) -> String {
        let mut d = Fnv::new();
        d.eat(format!("{}|{}|", self.engine, engine_settings).as_bytes());
        for x in [self.shear_modulus, self.friction, self.normal_force, self.size] {
            d.eat(&x.to_bits().to_le_bytes());
        }
        d.eat(&(self.resolution.mx as u64).to_le_bytes());
        d.eat(&(self.resolution.my as u64).to_le_bytes());
        for x in self.axes.values(index) {
            d.eat(&x.to_bits().to_le_bytes());
        }
        format!("{:016x}", d.0)
    }

    /// A digest of the whole table (everything [`TableSpec::case_digest`] covers, for every case, and the spec's
    /// name), as 16 hex digits: a journal records it, and a resume after a change is refused.
    pub fn digest(&self, engine_settings: &str) -> String {
        let mut d = Fnv::new();
        d.eat(format!("{}|{}|{}|", self.name, self.engine, engine_settings).as_bytes());
        for x in [self.shear_modulus, self.friction, self.normal_force, self.size] {
            d.eat(&x.to_bits().to_le_bytes());
        }
        d.eat(&(self.resolution.mx as u64).to_le_bytes());
        d.eat(&(self.resolution.my as u64).to_le_bytes());
        for (name, axis) in self.axes.named() {
            d.eat(name.as_bytes());
            for x in axis {
                d.eat(&x.to_bits().to_le_bytes());
            }
        }
        format!("{:016x}", d.0)
    }
}

/// FNV-1a, 64 bits (stable across runs and platforms).
struct Fnv(u64);

impl Fnv {
    fn new() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }

    fn eat(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}
