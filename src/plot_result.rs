//! `rollbem plot RESULT.json [--out DIR]`: the figures of a result document written by `rollbem run --json`.
//!
//! Per solver run (`runs[]`, for a load path the runs at its end): the surface tractions p and q against x
//! (`STEM.SOLVER.tractions.svg`) with Hertz's pressure when the document carries it (`references.hertz`); the node
//! states against x (`STEM.SOLVER.states.svg`: separated / contact or slip / stick); the slip velocity against x
//! when the scene rolls (`STEM.SOLVER.slip_velocity.svg`); and, when the run has subsurface stresses ([`crate::stresses`]), one filled contour
//! map per quantity (`STEM.SOLVER.QUANTITY.svg`) with the maximum (largest |value|, as in the result document)
//! marked and captioned. STEM is the result file's name without `.json`; DIR defaults to the result file's folder.
//! A field written to a CSV file beside the document (large grids) is read from there.
//!
//! The axes carry the scene's units: its `[stresses]` `length_unit` and `stress_unit` when given, else the length
//! and stress of its `units` label ("N, mm, MPa": force, length, stress), else the words "length unit" and "stress
//! unit" (rollbem's units are the user's, consistent, and a scene need not name
//! them). Depth is drawn downward, x and depth to the same scale when the grid's aspect ratio is moderate.
//!
//! The document is read as plain JSON (`serde_json::Value`), so any result document with the keys of `DESIGN.md`
//! works, also one written by an earlier version. Every file is written atomically.

use crate::error::{Error, Result};
use crate::plot::{Chart, ContourMap, Field, Series, Style};
use crate::scene::StressQuantity;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// What `plot` wrote, and what it could not draw (and why).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Plotted {
    /// Files written.
    pub files: Vec<PathBuf>,
    /// Figures left out, with the reason (e.g. a run that did not solve has no tractions).
    pub skipped: Vec<String>,
}

/// The label of a quantity on a colour bar.
fn label(q: StressQuantity) -> &'static str {
    match q {
        StressQuantity::Sxx => "σ_xx",
        StressQuantity::Szz => "σ_zz",
        StressQuantity::Txz => "τ_xz",
        StressQuantity::Syy => "σ_yy = ν(σ_xx + σ_zz)",
        StressQuantity::PrincipalShear => "principal shear τ₁",
        StressQuantity::VonMises => "von Mises stress",
        StressQuantity::OrthogonalShear => "orthogonal shear τ_xz",
    }
}

/// `v` to four significant digits, in positional notation for magnitudes 1e-3 to 1e6 (scientific beyond).
fn sig4(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..6).contains(&e) {
        format!("{:.*}", (3 - e).max(0) as usize, v)
    } else {
        format!("{v:.3e}")
    }
}

/// A malformed document: an input error naming the file and the key.
fn bad(path: &Path, message: String) -> Error {
    Error::Parse { path: path.to_path_buf(), message }
}

fn plot_err(e: crate::plot::PlotError) -> Error {
    Error::Output { what: "a plot".into(), message: e.to_string() }
}

/// Draw the figures of the result document `json` into `out` (default: its folder); see the module docs.
pub fn plot_result(json: &Path, out: Option<&Path>) -> Result<Plotted> {
    let text = std::fs::read_to_string(json).map_err(|source| Error::Io { path: json.to_path_buf(), source })?;
    let doc: Value = serde_json::from_str(&text).map_err(|e| bad(json, format!("not JSON: {e}")))?;
    let runs = doc
        .get("runs")
        .and_then(Value::as_array)
        .ok_or_else(|| bad(json, "not a rollbem result document: no `runs` array".into()))?;
    let dir = json.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new(".")).to_path_buf();
    let out = out.map(Path::to_path_buf).unwrap_or_else(|| dir.clone());
    std::fs::create_dir_all(&out).map_err(|source| Error::Write { path: out.clone(), source })?;
    let stem = json.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "result".into());
    let name = doc.pointer("/scene/name").and_then(Value::as_str).unwrap_or(&stem).to_string();
    let unit = |key: &str, default: &str| {
        doc.pointer(&format!("/scene/stresses/{key}")).and_then(Value::as_str).unwrap_or(default).to_string()
    };
    // The scene's `units` label, "force, length, stress".
    let label_units: Vec<String> = doc
        .pointer("/scene/units")
        .and_then(Value::as_str)
        .map(|u| u.split(',').map(|p| p.trim().to_string()).collect())
        .unwrap_or_default();
    let from_label =
        |k: usize, default: &str| label_units.get(k).filter(|u| !u.is_empty()).cloned().unwrap_or(default.into());
    let (lu, su) =
        (unit("length_unit", &from_label(1, "length unit")), unit("stress_unit", &from_label(2, "stress unit")));
    // Hertz's pressure at the document's load, when the references carry it.
    let hertz = doc.pointer("/references/hertz").and_then(|h| {
        let hertz = crate::hertz::Hertz {
            half_width: h.get("half_width")?.as_f64()?,
            peak_pressure: h.get("peak_pressure")?.as_f64()?,
            load: h.get("load")?.as_f64()?,
        };
        (hertz.half_width > 0.0 && hertz.peak_pressure > 0.0).then_some(hertz)
    });
    let mut done = Plotted::default();
    for (k, run) in runs.iter().enumerate() {
        let solver = run.get("solver").and_then(Value::as_str).unwrap_or("run").to_string();
        let nodes = run.get("nodes").and_then(Value::as_array).map(Vec::as_slice).unwrap_or(&[]);
        let series = |key: &str| -> Vec<(f64, f64)> {
            nodes.iter().filter_map(|n| Some((n.get("x")?.as_f64()?, n.get(key)?.as_f64()?))).collect()
        };
        let (p, q) = (series("pressure"), series("shear"));
        // A run judged not an answer (contact at the zone's edge, kinematics out of range) keeps its nodes as
        // evidence: its titles say so.
        let status = run.get("status").and_then(Value::as_str).unwrap_or("unknown");
        let verdict = if status == "solved" { String::new() } else { format!(" ({status}: not an answer)") };
        if p.is_empty() {
            done.skipped.push(format!("{solver}: no tractions (status {})", run["status"]));
            continue;
        }
        let mut chart =
            Chart::new(format!("{name}, {solver}: surface tractions on the wheel{verdict}"), "x", "traction")
                .x_unit(lu.as_str())
                .y_unit(su.as_str())
                .add(Series::new("pressure p", p, Style::LineMarkers))
                .add(Series::new("shear q", q, Style::LineMarkers));
        if let Some(h) = hertz {
            let a = h.half_width;
            let curve = (0..=200).map(|i| -a + 2.0 * a * f64::from(i) / 200.0).map(|x| (x, h.pressure(x))).collect();
            chart = chart.add(Series::new("Hertz pressure", curve, Style::Dashed));
        }
        let file = out.join(format!("{stem}.{solver}.tractions.svg"));
        chart.write(&file).map_err(plot_err)?;
        done.files.push(file);
        // Node states on a categorical axis.
        let states: Vec<(f64, f64)> = nodes
            .iter()
            .filter_map(|n| {
                let y = match n.get("state")?.as_str()? {
                    "separated" => 0.0,
                    "slip" | "contact" => 1.0,
                    "stick" => 2.0,
                    _ => return None,
                };
                Some((n.get("x")?.as_f64()?, y))
            })
            .collect();
        if !states.is_empty() {
            let chart = Chart::new(format!("{name}, {solver}: node states{verdict}"), "x", "state")
                .x_unit(lu.as_str())
                .categories_y(&["separated", "contact / slip", "stick"])
                .add(Series::new(solver.as_str(), states, Style::Markers));
            let file = out.join(format!("{stem}.{solver}.states.svg"));
            chart.write(&file).map_err(plot_err)?;
            done.files.push(file);
        }
        let sv = series("slip_velocity");
        if !sv.is_empty() {
            let chart = Chart::new(format!("{name}, {solver}: slip velocity{verdict}"), "x", "slip velocity s")
                .x_unit(lu.as_str())
                .y_unit("1")
                .add(Series::new(solver.as_str(), sv, Style::LineMarkers));
            let file = out.join(format!("{stem}.{solver}.slip_velocity.svg"));
            chart.write(&file).map_err(plot_err)?;
            done.files.push(file);
        }
        let Some(st) = run.get("stresses").filter(|s| s.is_object()) else { continue };
        let at = format!("runs[{k}].stresses");
        let maps = StressMaps::read(json, &dir, st, &at)?;
        for (q, values) in &maps.values {
            let max = st.pointer(&format!("/maxima/{}", q.name())).filter(|m| m.is_object());
            let (Some(mx), Some(mz), Some(mv)) = (
                max.and_then(|m| m["x"].as_f64()),
                max.and_then(|m| m["depth"].as_f64()),
                max.and_then(|m| m["value"].as_f64()),
            ) else {
                done.skipped.push(format!("{solver}: {}: no point of the grid has a value", q.name()));
                continue;
            };
            let field = Field::new(maps.points[0], maps.points[1], values.clone(), maps.x, maps.depth);
            let caption = if matches!(q, StressQuantity::PrincipalShear | StressQuantity::VonMises) {
                format!("max {} = {} {su}", label(*q), sig4(mv))
            } else {
                format!("largest |{}|: {} {su}", label(*q), sig4(mv))
            };
            let mut map = ContourMap::new(format!("{name}, {solver}: {} in the wheel", label(*q)), field)
                .x_axis("x", lu.as_str())
                .depth_axis("depth", lu.as_str())
                .value_axis(label(*q), su.as_str())
                .bands(12)
                .size(960, 600)
                .marker(mx, mz, caption);
            let aspect = (maps.depth.1 - maps.depth.0) / (maps.x.1 - maps.x.0);
            if (0.2..=5.0).contains(&aspect) {
                map = map.equal_aspect();
            }
            let file = out.join(format!("{stem}.{solver}.{}.svg", q.name()));
            map.write(&file).map_err(plot_err)?;
            done.files.push(file);
        }
    }
    Ok(done)
}

/// A run's stress fields as the maps need them: the grid and, per quantity, the values (NaN where refused).
struct StressMaps {
    points: [usize; 2],
    x: (f64, f64),
    depth: (f64, f64),
    values: Vec<(StressQuantity, Vec<f64>)>,
}

impl StressMaps {
    /// Read `st` (`runs[k].stresses`, key path `at` for messages) of the document `json` (folder `dir`): the inline
    /// field, or the CSV file it names.
    fn read(json: &Path, dir: &Path, st: &Value, at: &str) -> Result<StressMaps> {
        let miss = |key: &str| bad(json, format!("{at}.{key}: missing or malformed"));
        let pair = |key: &str| -> Result<(f64, f64)> {
            let v = st.pointer(&format!("/grid/{key}")).and_then(Value::as_array).ok_or_else(|| miss(key))?;
            match (v.first().and_then(Value::as_f64), v.get(1).and_then(Value::as_f64)) {
                (Some(a), Some(b)) => Ok((a, b)),
                _ => Err(miss(&format!("grid.{key}"))),
            }
        };
        let (x, depth) = (pair("x")?, pair("depth")?);
        let pts = pair("points")?;
        let points = [pts.0 as usize, pts.1 as usize];
        let n = points[0].saturating_mul(points[1]);
        let quantities: Vec<StressQuantity> = st
            .get("quantities")
            .and_then(Value::as_array)
            .ok_or_else(|| miss("quantities"))?
            .iter()
            .filter_map(|q| q.as_str().and_then(StressQuantity::from_name))
            .collect();
        let values = match st.get("csv").and_then(Value::as_str) {
            Some(file) => read_csv(&dir.join(file), &quantities, n)?,
            None => quantities
                .iter()
                .map(|&q| {
                    let v = st
                        .pointer(&format!("/field/values/{}", q.name()))
                        .and_then(Value::as_array)
                        .filter(|v| v.len() == n)
                        .ok_or_else(|| miss(&format!("field.values.{}", q.name())))?;
                    Ok((q, v.iter().map(|v| v.as_f64().unwrap_or(f64::NAN)).collect()))
                })
                .collect::<Result<Vec<_>>>()?,
        };
        Ok(StressMaps { points, x, depth, values })
    }
}

/// The quantities' columns of a stress CSV ([`crate::stresses::StressField::csv`]); empty cells are NaN.
fn read_csv(path: &Path, quantities: &[StressQuantity], n: usize) -> Result<Vec<(StressQuantity, Vec<f64>)>> {
    let mut rd = csv::Reader::from_path(path)
        .map_err(|e| bad(path, format!("cannot read the stress field named by the result document: {e}")))?;
    let header = rd.headers().map_err(|e| bad(path, e.to_string()))?.clone();
    let mut cols = Vec::new();
    for &q in quantities {
        let c =
            header.iter().position(|h| h == q.name()).ok_or_else(|| bad(path, format!("no column `{}`", q.name())))?;
        cols.push((q, c, Vec::with_capacity(n)));
    }
    for (line, rec) in rd.records().enumerate() {
        let rec = rec.map_err(|e| bad(path, e.to_string()))?;
        for (q, c, v) in &mut cols {
            let cell = rec.get(*c).unwrap_or("");
            let value = if cell.is_empty() {
                f64::NAN
            } else {
                cell.parse::<f64>()
                    .map_err(|_| bad(path, format!("row {}: `{}` is not a number ({})", line + 2, cell, q.name())))?
            };
            v.push(value);
        }
    }
    cols.into_iter()
        .map(|(q, _, v)| {
            if v.len() == n {
                Ok((q, v))
            } else {
                Err(bad(path, format!("{} rows for a grid of {n} points", v.len())))
            }
        })
        .collect()
}
