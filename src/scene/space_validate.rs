//! Validation of a half-space scene ([`super::space`]): every value range-checked, naming its dotted key; the grid,
//! the profile (curvatures, a gap file or inline gaps) and the path's substeps typed for [`crate::halfspace::Path`].

use super::space::{
    HalfSpaceSettingsTable, SpaceCounterTable, SpaceDocument, SpaceDriveTable, SpaceScene, SpaceStep,
    MAX_HALF_SPACE_ELEMENTS, SPACE_BYTES_PER_ELEMENT,
};
use super::{safe_name, MAX_PATH_RESULT_BYTES, MAX_PATH_SUBSTEPS};
use crate::error::{Error, Result};
use crate::halfspace::normal::Drive as NormalDrive;
use crate::halfspace::tangential::TangentialDrive;
use crate::halfspace::{ContactGrid, HalfSpace, Profile, Step};
use std::path::Path;

/// Errors naming the file and the key.
struct Bad<'a>(&'a Path);

impl Bad<'_> {
    fn at(&self, field: &str, message: String) -> Error {
        Error::Invalid { path: self.0.to_path_buf(), field: field.into(), message }
    }

    fn positive(&self, field: &str, v: f64) -> Result<()> {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(self.at(field, format!("must be a finite number > 0 (got {v})")))
        }
    }

    fn poisson(&self, field: &str, nu: f64) -> Result<()> {
        if (0.0..=0.5).contains(&nu) {
            Ok(())
        } else {
            Err(self.at(field, format!("must lie in [0, 0.5] (got {nu})")))
        }
    }

    fn finite(&self, field: &str, v: f64) -> Result<()> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(self.at(field, format!("must be a finite number (got {v})")))
        }
    }

    fn unit_interval(&self, field: &str, v: Option<f64>) -> Result<()> {
        match v {
            Some(v) if !(v > 0.0 && v < 1.0) => Err(self.at(field, format!("must lie in (0, 1) (got {v})"))),
            _ => Ok(()),
        }
    }

    fn at_least_one(&self, field: &str, v: Option<usize>) -> Result<()> {
        match v {
            Some(0) => Err(self.at(field, "must be at least 1".into())),
            _ => Ok(()),
        }
    }
}

impl SpaceScene {
    /// Validate a document (`path` as in [`SpaceScene::from_toml`]).
    ///
    /// # Errors
    /// As [`SpaceScene::from_toml`].
    pub fn from_document(document: SpaceDocument, path: &Path) -> Result<SpaceScene> {
        validate(document, path)
    }
}

/// Validate a half-space document and build the typed scene.
fn validate(document: SpaceDocument, path: &Path) -> Result<SpaceScene> {
    let bad = Bad(path);
    if let Err(why) = safe_name(&document.name) {
        return Err(bad.at("name", why));
    }
    let w = &document.wheel;
    bad.positive("wheel.youngs_modulus", w.youngs_modulus)?;
    bad.poisson("wheel.poisson_ratio", w.poisson_ratio)?;
    let body = HalfSpace::new(w.youngs_modulus, w.poisson_ratio).map_err(|e| bad.at("wheel", e.to_string()))?;
    let counter = match document.counter_body {
        SpaceCounterTable::Rigid => HalfSpace::new(f64::INFINITY, 0.0),
        SpaceCounterTable::HalfSpace { youngs_modulus, poisson_ratio } => {
            bad.positive("counter_body.youngs_modulus", youngs_modulus)?;
            bad.poisson("counter_body.poisson_ratio", poisson_ratio)?;
            HalfSpace::new(youngs_modulus, poisson_ratio)
        }
    }
    .map_err(|e| bad.at("counter_body", e.to_string()))?;
    let grid = grid(&bad, &document)?;
    let profile = profile(&bad, &document, &grid, path)?;
    let mu = document.contact.friction;
    if !(mu.is_finite() && mu >= 0.0) {
        return Err(bad.at("contact.friction", format!("must be a finite number ≥ 0 (got {mu})")));
    }
    let steps = steps(&bad, &document, grid.len())?;
    solvers(&bad, &document)?;
    if let Some(c) = &document.checks {
        for (field, v) in [("checks.hertz", c.hertz), ("checks.cattaneo", c.cattaneo), ("checks.residual", c.residual)]
        {
            if let Some(v) = v {
                bad.positive(field, v)?;
            }
        }
    }
    let settings = document.solvers.half_space.settings();
    Ok(SpaceScene::assemble(path.to_path_buf(), document, (body, counter), grid, profile, steps, settings))
}

/// `[mesh]`: counts, extents, the size guard.
fn grid(bad: &Bad, d: &SpaceDocument) -> Result<ContactGrid> {
    let m = &d.mesh;
    for (field, n) in [("mesh.mx", m.mx), ("mesh.my", m.my)] {
        if n == 0 {
            return Err(bad.at(field, "must be at least 1".into()));
        }
    }
    if m.mx.saturating_mul(m.my) > MAX_HALF_SPACE_ELEMENTS {
        return Err(bad.at(
            "mesh.mx",
            format!(
                "{} × {} = {} elements: rollbem allows at most {MAX_HALF_SPACE_ELEMENTS} (2048 × 2048) on the \
                 half-space grid (its FFT kernels hold about 400 bytes per element)",
                m.mx,
                m.my,
                m.mx.saturating_mul(m.my)
            ),
        ));
    }
    for (field, [lo, hi], n) in [("mesh.contact_x", m.contact_x, m.mx), ("mesh.contact_y", m.contact_y, m.my)] {
        bad.finite(field, lo)?;
        bad.finite(field, hi)?;
        let h = (hi - lo) / n as f64;
        if !(hi > lo && h.is_normal() && h > f64::EPSILON * lo.abs().max(hi.abs())) {
            return Err(bad.at(
                field,
                format!(
                    "must be [min, max] with min < max and elements resolvable in double precision (got [{lo}, {hi}])"
                ),
            ));
        }
    }
    let [x_lo, x_hi] = m.contact_x;
    let [y_lo, y_hi] = m.contact_y;
    ContactGrid::covering(m.mx, m.my, x_lo, x_hi, y_lo, y_hi).map_err(|e| bad.at("mesh", e.to_string()))
}

/// `[profile]`: exactly one of curvatures, gap_file, gap.
fn profile(bad: &Bad, d: &SpaceDocument, grid: &ContactGrid, path: &Path) -> Result<Profile> {
    let p = &d.profile;
    let given = [p.curvatures.is_some(), p.gap_file.is_some(), p.gap.is_some()].iter().filter(|&&g| g).count();
    if given != 1 {
        return Err(
            bad.at("profile", format!("give exactly one of `curvatures = [A, B]`, `gap_file` or `gap` (got {given})"))
        );
    }
    if let Some([a, b]) = p.curvatures {
        bad.positive("profile.curvatures", a)?;
        bad.positive("profile.curvatures", b)?;
        return Ok(Profile::Quadratic { a, b });
    }
    let rows = match (&p.gap_file, &p.gap) {
        (Some(file), _) => {
            let full = path.parent().map(|dir| dir.join(file)).unwrap_or_else(|| file.clone());
            let text = std::fs::read_to_string(&full)
                .map_err(|e| bad.at("profile.gap_file", format!("cannot read {}: {e}", full.display())))?;
            gap_rows(&text).map_err(|why| bad.at("profile.gap_file", format!("{}: {why}", full.display())))?
        }
        (None, Some(rows)) => rows.clone(),
        (None, None) => unreachable!("one form is given"),
    };
    let key = if p.gap_file.is_some() { "profile.gap_file" } else { "profile.gap" };
    if rows.len() != grid.my() || rows.iter().any(|r| r.len() != grid.mx()) {
        let widths: Vec<usize> = rows.iter().map(Vec::len).collect();
        let shown = if widths.len() > 6 { format!("{:?}…", &widths[..6]) } else { format!("{widths:?}") };
        return Err(bad.at(
            key,
            format!(
                "must hold MY = {} rows of MX = {} gaps (got {} rows of {shown})",
                grid.my(),
                grid.mx(),
                rows.len()
            ),
        ));
    }
    if let Some((iy, ix)) =
        rows.iter().enumerate().find_map(|(iy, r)| r.iter().position(|v| !v.is_finite()).map(|ix| (iy, ix)))
    {
        return Err(bad.at(key, format!("the gap of element (ix {ix}, iy {iy}) is not a finite number")));
    }
    Ok(Profile::Gap(rows.concat()))
}

/// The rows of a gap CSV (commas or white space between values; `#` comment lines and blank lines skipped).
fn gap_rows(text: &str) -> std::result::Result<Vec<Vec<f64>>, String> {
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let row: std::result::Result<Vec<f64>, String> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .map(|s| s.parse::<f64>().map_err(|_| format!("line {}: `{s}` is not a number", n + 1)))
            .collect();
        rows.push(row?);
    }
    Ok(rows)
}

/// `[solvers]`: `use` and the settings' ranges.
fn solvers(bad: &Bad, d: &SpaceDocument) -> Result<()> {
    let s = &d.solvers;
    if s.use_.is_empty() {
        return Err(bad.at("solvers.use", "must name at least one solver (\"all\" or \"half_space\")".into()));
    }
    if let Some(other) = s.use_.iter().find(|n| *n != "all" && *n != "half_space") {
        let why = if crate::solvers::SolverId::from_name(other).is_some() {
            format!("`{other}` is a solver of the 2D scenes and does not apply to a half-space scene")
        } else {
            format!("unknown solver `{other}`")
        };
        return Err(bad.at("solvers.use", format!("{why}: a half-space scene runs \"half_space\" (or \"all\")")));
    }
    let t: &HalfSpaceSettingsTable = &s.half_space;
    bad.unit_interval("solvers.half_space.normal_tolerance", t.normal_tolerance)?;
    bad.unit_interval("solvers.half_space.tangential_tolerance", t.tangential_tolerance)?;
    bad.unit_interval("solvers.half_space.outer_tolerance", t.outer_tolerance)?;
    bad.unit_interval("solvers.half_space.residual", t.residual)?;
    bad.at_least_one("solvers.half_space.normal_max_iterations", t.normal_max_iterations)?;
    bad.at_least_one("solvers.half_space.tangential_max_iterations", t.tangential_max_iterations)?;
    bad.at_least_one("solvers.half_space.max_outer", t.max_outer)
}

/// The kind of the normal and tangential drives at the end of the previous step (for substeps and shifts).
#[derive(Clone, Copy, PartialEq)]
enum Last {
    /// The path's start: load and approach 0.
    Rest,
    Load(f64),
    Approach(f64),
}

/// `[drive]` or `[[steps]]`: every table's drives, the substeps expanded, the size guards.
fn steps(bad: &Bad, d: &SpaceDocument, elements: usize) -> Result<Vec<SpaceStep>> {
    let tables: Vec<(String, &SpaceDriveTable)> = if d.steps.is_empty() {
        if d.drive.substeps.is_some() {
            return Err(bad.at("drive.substeps", "substeps belong to `[[steps]]` (a load path)".into()));
        }
        vec![("drive".into(), &d.drive)]
    } else {
        if d.drive != SpaceDriveTable::default() {
            return Err(bad.at("steps", "give either `[drive]` or `[[steps]]`, not both".into()));
        }
        d.steps.iter().enumerate().map(|(k, s)| (format!("steps[{k}]"), s)).collect()
    };
    let mu = d.contact.friction;
    let mut out = Vec::new();
    let (mut normal, mut force, mut shift) = (Last::Rest, Some([0.0, 0.0]), Some([0.0, 0.0]));
    let mut total = 0u128;
    for (k, (prefix, t)) in tables.iter().enumerate() {
        let key = |k: &str| format!("{prefix}.{k}");
        check_table(bad, prefix, t, mu)?;
        let n = t.substeps.unwrap_or(1);
        if n == 0 {
            return Err(bad.at(&key("substeps"), "must be at least 1".into()));
        }
        total += n as u128;
        let bytes = total * elements as u128 * SPACE_BYTES_PER_ELEMENT as u128;
        if total > MAX_PATH_SUBSTEPS as u128 || bytes > MAX_PATH_RESULT_BYTES as u128 {
            return Err(bad.at(
                &key("substeps"),
                format!(
                    "the path has {total} substeps by this step on {elements} elements: its result would hold about \
                     {:.1} GiB; at most {MAX_PATH_SUBSTEPS} substeps and {} GiB",
                    bytes as f64 / (1u64 << 30) as f64,
                    MAX_PATH_RESULT_BYTES >> 30
                ),
            ));
        }
        let end = match SpaceScene::normal_drive(t) {
            Some(NormalDrive::Load(p)) => Last::Load(p),
            Some(NormalDrive::Approach(a)) => Last::Approach(a),
            _ => unreachable!("checked"),
        };
        let interpolate_normal = |i: usize| match (normal, end) {
            (Last::Rest, Last::Load(b)) => NormalDrive::Load(b * i as f64 / n as f64),
            (Last::Rest, Last::Approach(b)) => NormalDrive::Approach(b * i as f64 / n as f64),
            (Last::Load(a), Last::Load(b)) => NormalDrive::Load(a + (b - a) * i as f64 / n as f64),
            (Last::Approach(a), Last::Approach(b)) => NormalDrive::Approach(a + (b - a) * i as f64 / n as f64),
            (_, Last::Load(b)) => NormalDrive::Load(b),
            (_, Last::Approach(b)) => NormalDrive::Approach(b),
            (_, Last::Rest) => unreachable!("an end is a load or an approach"),
        };
        let same_kind = matches!(
            (normal, end),
            (Last::Rest, _) | (Last::Load(_), Last::Load(_)) | (Last::Approach(_), Last::Approach(_))
        );
        if n > 1 && !same_kind {
            return Err(bad.at(
                &key("substeps"),
                "substeps interpolate from the previous step's end value of the same quantity, and the previous step \
                 prescribes the other normal drive (load or approach): give this step 1 substep"
                    .into(),
            ));
        }
        let tangential = SpaceScene::tangential_total(t);
        let drives: Vec<TangentialDrive> = if mu == 0.0 {
            vec![TangentialDrive::Shift(0.0, 0.0); n]
        } else {
            tangential_substeps(bad, prefix, t, tangential, (force, shift), n)?
        };
        for (i, tang) in drives.into_iter().enumerate() {
            out.push(SpaceStep {
                step: k,
                substep: i + 1,
                substeps: n,
                drive: Step::new(interpolate_normal(i + 1), tang),
            });
        }
        normal = end;
        (force, shift) = match tangential {
            TangentialDrive::Force(x, y) => (Some([x, y]), None),
            TangentialDrive::Shift(x, y) => (None, Some([x, y])),
        };
    }
    Ok(out)
}

/// The substeps' tangential drives: a force interpolated from the previous step's end force, or the shift's
/// increments from the previous step's end shift. A drive whose start is an outcome (a shift after a force-driven
/// step; a force interpolated after a shift-driven one) is refused, naming the key.
fn tangential_substeps(
    bad: &Bad,
    prefix: &str,
    t: &SpaceDriveTable,
    end: TangentialDrive,
    (force, shift): (Option<[f64; 2]>, Option<[f64; 2]>),
    n: usize,
) -> Result<Vec<TangentialDrive>> {
    let f = |i: usize| i as f64 / n as f64;
    match (end, force, shift) {
        (TangentialDrive::Force(x, y), Some([x0, y0]), _) => {
            Ok((1..=n).map(|i| TangentialDrive::Force(x0 + (x - x0) * f(i), y0 + (y - y0) * f(i))).collect())
        }
        (TangentialDrive::Force(x, y), None, _) if n == 1 => Ok(vec![TangentialDrive::Force(x, y)]),
        (TangentialDrive::Force(..), None, _) => Err(bad.at(
            &format!("{prefix}.substeps"),
            "the tangential force at the start of this step is the outcome of the shift-driven step before it, so \
             substeps cannot interpolate it: give this step 1 substep, or split it"
                .into(),
        )),
        (TangentialDrive::Shift(x, y), _, Some([x0, y0])) => {
            let (dx, dy) = ((x - x0) / n as f64, (y - y0) / n as f64);
            Ok(vec![TangentialDrive::Shift(dx, dy); n])
        }
        (TangentialDrive::Shift(..), _, None) => {
            let (key, what) = if t.tangential_shift.is_some() {
                (format!("{prefix}.tangential_shift"), "this step's shift")
            } else {
                (prefix.to_string(), "this step's shift (absent: [0, 0])")
            };
            Err(bad.at(
                &key,
                format!(
                    "{what} is counted from the path's start, and the shift at the end of the force-driven step \
                     before it is an outcome, not known when the scene is read: prescribe `tangential_load` in this \
                     step (e.g. [0.0, 0.0] to hold the force), or shifts in the steps before"
                ),
            ))
        }
    }
}

/// One drive table's keys: one normal drive, one tangential drive, finite values, a load > 0, no force without
/// friction.
fn check_table(bad: &Bad, prefix: &str, t: &SpaceDriveTable, mu: f64) -> Result<()> {
    let key = |k: &str| format!("{prefix}.{k}");
    match (t.normal_load, t.normal_approach) {
        (Some(_), Some(_)) => {
            return Err(
                bad.at(&key("normal_approach"), "give either `normal_approach` or `normal_load`, not both".into())
            )
        }
        (None, None) => return Err(bad.at(prefix, "give `normal_approach` or `normal_load`".into())),
        (Some(p), None) => bad.positive(&key("normal_load"), p)?,
        (None, Some(a)) => bad.finite(&key("normal_approach"), a)?,
    }
    if t.tangential_load.is_some() && t.tangential_shift.is_some() {
        return Err(
            bad.at(&key("tangential_shift"), "give either `tangential_shift` or `tangential_load`, not both".into())
        );
    }
    for (name, v) in [("tangential_load", t.tangential_load), ("tangential_shift", t.tangential_shift)] {
        if let Some([x, y]) = v {
            bad.finite(&key(name), x)?;
            bad.finite(&key(name), y)?;
        }
    }
    if let (0.0, Some([x, y])) = (mu, t.tangential_load) {
        if x != 0.0 || y != 0.0 {
            return Err(bad.at(
                &key("tangential_load"),
                format!(
                    "[{x}, {y}] on a frictionless contact (contact.friction = 0) has no static solution: use a \
                         zero tangential load or friction > 0"
                ),
            ));
        }
    }
    Ok(())
}
