//! The figures of a half-space (3D) result document (`rollbem plot RESULT.json` on a `run --json` of a scene with
//! `[wheel] model = "half_space"`), for its last step that has tractions:
//!
//! - `STEM.pn.svg`, `STEM.pt.svg`: maps of the pressure p and of the shear's magnitude |p_t| = |(q_x, q_y)| on the
//!   (MY, MX) grid (a [`ContourMap`] over the element centres: x across, y down the page, as the grid's rows are
//!   listed), with the largest value marked; `STEM.state.svg`: the element states (bands 0–1 exterior, 1–2 slip,
//!   2–3 stick);
//! - `STEM.section_x.svg`, `STEM.section_y.svg`: sections along x and along y through the element row and column
//!   nearest the origin (the profile's lowest point): p, the shear components, and μp (the friction bound) dashed,
//!   with Hertz's `p₀ √(1 − x²/a_x² − y²/a_y²)` on the same line where the document has Hertz's ellipse for that
//!   step's load and the normal problem is not coupled.
//!
//! `pt` and `state` are drawn only for a frictional scene.

use super::{Chart, ContourMap, Field, PlotError, Series, Style};
use crate::results::space::{GridInfo, SpaceReport, SpaceStepResult};
use crate::scene::SpaceStatus;
use std::path::{Path, PathBuf};

/// Draw the figures of the module docs into `out`, named after the scene; the files written.
///
/// # Errors
/// [`crate::Error::Output`] when no step has tractions, a figure cannot be drawn or a file cannot be written.
pub fn plot_space(r: &SpaceReport, out: &Path) -> crate::Result<Vec<PathBuf>> {
    let failed = |what: String, e: PlotError| crate::Error::Output { what, message: e.to_string() };
    let Some(step) = r.steps.iter().rev().find(|s| s.load > 0.0 && s.status != SpaceStatus::NotConverged) else {
        return Err(crate::Error::Output {
            what: format!("the figures of {}", r.scene.name),
            message: "no step has a contact (every step is without load or did not converge)".into(),
        });
    };
    let stem = &r.scene.name;
    let unit = |i: usize| -> String {
        r.scene.units.as_deref().and_then(|u| u.split(',').nth(i)).map(|s| s.trim().to_string()).unwrap_or_default()
    };
    let (lu, su) = (unit(1), unit(2));
    let tag = format!("step {}.{} ({})", step.step, step.substep, step.status);
    let e = &step.elements;
    let pt: Vec<f64> = e.qx.iter().zip(&e.qy).map(|(x, y)| x.hypot(*y)).collect();
    // Each state mid-band, so that the map's unit bands 0–1, 1–2, 2–3 hold one state each; slip between exterior and
    // stick, where it is on the grid (the bands interpolate between element centres: an exterior–stick order would
    // draw a false stick rim around every contact).
    let states: Vec<f64> = e.state.iter().map(|&s| [0.5, 2.5, 1.5][usize::from(s).min(2)]).collect();
    let mut maps = vec![("pn", "pressure p", e.pressure.clone(), su.clone())];
    if r.scene.contact.friction > 0.0 {
        maps.push(("pt", "shear |p_t|", pt, su.clone()));
        maps.push(("state", "state: 0–1 exterior, 1–2 slip, 2–3 stick", states, String::new()));
    }
    let mut files = Vec::new();
    for (name, label, values, vu) in maps {
        let file = out.join(format!("{stem}.{name}.svg"));
        let mut map = ContourMap::new(format!("{stem}, {tag}: {label}"), field(&r.grid, values))
            .x_axis("x", lu.clone())
            .depth_axis("y (down the page)", lu.clone())
            .value_axis(label, vu)
            .size(900, 700);
        map = if name == "state" { map.bands(3) } else { map.bands(12).mark_max() };
        let aspect = (r.grid.dy * r.grid.my as f64) / (r.grid.dx * r.grid.mx as f64);
        if (0.2..=5.0).contains(&aspect) {
            map = map.equal_aspect();
        }
        map.write(&file).map_err(|e| failed(file.display().to_string(), e))?;
        files.push(file);
    }
    for along_x in [true, false] {
        let file = out.join(format!("{stem}.section_{}.svg", if along_x { "x" } else { "y" }));
        section(r, step, along_x, (&lu, &su), &tag).write(&file).map_err(|e| failed(file.display().to_string(), e))?;
        files.push(file);
    }
    Ok(files)
}

/// The element values as a field over the element centres (a grid of one element along a side is widened to two
/// equal columns or rows, the least a map can draw).
fn field(g: &GridInfo, values: Vec<f64>) -> Field {
    let (x_last, y_last) = g.centre(g.mx - 1, g.my - 1);
    let (mut nx, mut ny, mut v) = (g.mx, g.my, values);
    let mut xr = (g.x0, x_last);
    let mut yr = (g.y0, y_last);
    if nx == 1 {
        v = v.iter().flat_map(|&a| [a, a]).collect();
        nx = 2;
        xr = (g.x0 - 0.5 * g.dx, g.x0 + 0.5 * g.dx);
    }
    if ny == 1 {
        v = [v.clone(), v].concat();
        ny = 2;
        yr = (g.y0 - 0.5 * g.dy, g.y0 + 0.5 * g.dy);
    }
    Field::new(nx, ny, v, xr, yr)
}

/// The index of the grid line nearest 0 (x0 + i·d closest to 0, clamped).
fn nearest_zero(first: f64, d: f64, n: usize) -> usize {
    ((-first / d).round().max(0.0) as usize).min(n - 1)
}

/// A section along x (through the row nearest y = 0) or along y (through the column nearest x = 0).
fn section(r: &SpaceReport, s: &SpaceStepResult, along_x: bool, (lu, su): (&str, &str), tag: &str) -> Chart {
    let g = &r.grid;
    let (ix0, iy0) = (nearest_zero(g.x0, g.dx, g.mx), nearest_zero(g.y0, g.dy, g.my));
    let idx: Vec<(usize, usize)> =
        if along_x { (0..g.mx).map(|ix| (ix, iy0)).collect() } else { (0..g.my).map(|iy| (ix0, iy)).collect() };
    let (x_fixed, y_fixed) = g.centre(ix0, iy0);
    let coord = |ix: usize, iy: usize| if along_x { g.centre(ix, iy).0 } else { g.centre(ix, iy).1 };
    let pick =
        |v: &[f64]| -> Vec<(f64, f64)> { idx.iter().map(|&(ix, iy)| (coord(ix, iy), v[ix + g.mx * iy])).collect() };
    let e = &s.elements;
    let (axis, other, at) = if along_x { ("x", "y", y_fixed) } else { ("y", "x", x_fixed) };
    let mut chart =
        Chart::new(format!("{}, {tag}: section along {axis} at {other} = {at:.4e}", r.scene.name), axis, "traction")
            .x_unit(lu)
            .y_unit(su)
            .size(900, 560)
            .add(Series::new("p", pick(&e.pressure), Style::LineMarkers));
    let mu = r.scene.contact.friction;
    if mu > 0.0 {
        chart = chart.add(Series::new("q_x", pick(&e.qx), Style::LineMarkers)).add(Series::new(
            "q_y",
            pick(&e.qy),
            Style::LineMarkers,
        ));
        let bound: Vec<f64> = e.pressure.iter().map(|p| mu * p).collect();
        chart = chart.add(Series::new("μp (friction bound)", pick(&bound), Style::Dashed));
    }
    if let Some(h) = r.references.hertz.filter(|h| (h.load - s.load).abs() <= 1e-9 * s.load && !r.kernels.coupled) {
        let (lo, hi) = if along_x {
            (g.x0 - 0.5 * g.dx, g.x0 + (g.mx as f64 - 0.5) * g.dx)
        } else {
            (g.y0 - 0.5 * g.dy, g.y0 + (g.my as f64 - 0.5) * g.dy)
        };
        let curve: Vec<(f64, f64)> = (0..=400)
            .map(|k| {
                let t = lo + (hi - lo) * k as f64 / 400.0;
                let (x, y) = if along_x { (t, y_fixed) } else { (x_fixed, t) };
                (t, h.p0 * (1.0 - (x / h.a_x).powi(2) - (y / h.a_y).powi(2)).max(0.0).sqrt())
            })
            .collect();
        chart = chart.add(Series::new("Hertz p (theory)", curve, Style::Dashed));
    }
    chart
}
