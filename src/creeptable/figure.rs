//! Figures of a creep table's force surfaces (SVG through [`crate::plot`]): for one ellipse (ν, a/b), two families
//! of sections through the surfaces — Fx/(μN) against ξ' with one curve per η' (at the φ' nearest 0), and
//! Fy/(μN) against η' with one curve per φ' (at the ξ' nearest 0) — each with a reference table's curves dashed
//! beside them in the same colours when one is given (Kalker's linear theory, say), cut where it leaves 1.25 times
//! the engine's largest |F'| (the linear theory grows without bound).

use super::table::CreepTable;
use crate::error::{Error, Result};
use crate::plot::{Appearance, Chart, Series, Style};
use std::path::{Path, PathBuf};

/// At most this many curves per family (evenly picked from the axis).
const MAX_CURVES: usize = 6;

/// A reference curve cut where it leaves |y| ≤ `limit` (at the crossing, interpolated; a NaN breaks the line), so
/// that a linear theory growing without bound does not set the chart's scale.
fn clip(points: &[(f64, f64)], limit: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(points.len());
    for (i, &(x, y)) in points.iter().enumerate() {
        let inside = y.abs() <= limit;
        if let Some(&(x0, y0)) = i.checked_sub(1).and_then(|j| points.get(j)) {
            if inside != (y0.abs() <= limit) {
                let edge = if y.abs() > limit { limit.copysign(y) } else { limit.copysign(y0) };
                let t = (edge - y0) / (y - y0);
                out.push((x0 + t * (x - x0), edge));
                if !inside {
                    out.push((x, f64::NAN));
                }
            }
        }
        if inside {
            out.push((x, y));
        }
    }
    out
}

/// The index of the axis value nearest `x`.
fn nearest(axis: &[f64], x: f64) -> usize {
    (0..axis.len()).min_by(|&i, &j| (axis[i] - x).abs().total_cmp(&(axis[j] - x).abs())).unwrap_or(0)
}

/// Up to [`MAX_CURVES`] indices spread over `0..n`.
fn picks(n: usize) -> Vec<usize> {
    if n <= MAX_CURVES {
        return (0..n).collect();
    }
    let mut v: Vec<usize> = (0..MAX_CURVES).map(|k| k * (n - 1) / (MAX_CURVES - 1)).collect();
    v.dedup();
    v
}

/// One family: `component` (0 Fx', 1 Fy') along axis `along` (2 ξ', 3 η'), one curve per value of axis `per`
/// (3 η', 4 φ'), the remaining creepage axis at its value nearest 0.
fn family(
    t: &CreepTable,
    ellipse: [usize; 2],
    component: usize,
    along: usize,
    per: usize,
) -> Vec<(f64, Vec<(f64, f64)>)> {
    let axes = [&t.axes.nu, &t.axes.a_over_b, &t.axes.xi, &t.axes.eta, &t.axes.phi];
    let fixed = (2..5).find(|&d| d != along && d != per).unwrap_or(4);
    let at_zero = nearest(axes[fixed], 0.0);
    picks(axes[per].len())
        .into_iter()
        .map(|p| {
            let points = (0..axes[along].len())
                .filter_map(|i| {
                    let mut idx = [ellipse[0], ellipse[1], 0, 0, 0];
                    (idx[along], idx[per], idx[fixed]) = (i, p, at_zero);
                    t.at(idx).map(|f| (axes[along][i], f[component]))
                })
                .collect();
            (axes[per][p], points)
        })
        .collect()
}

/// The two charts of ellipse (iν, i_ab) of `table`, with `reference`'s curves dashed (same axes needed for them to
/// be drawn; a reference on other axes is drawn on its own values). Errors: an ellipse index outside the table.
pub fn creep_surface_svg(
    table: &CreepTable,
    reference: Option<(&str, &CreepTable)>,
    engine: &str,
    ellipse: [usize; 2],
) -> Result<[String; 2]> {
    let shape = table.axes.shape();
    if ellipse[0] >= shape[0] || ellipse[1] >= shape[1] {
        let message = format!("ellipse {ellipse:?} outside the table's {}×{}", shape[0], shape[1]);
        return Err(Error::Output { what: "creep-force figure".into(), message });
    }
    let (nu, ab) = (table.axes.nu[ellipse[0]], table.axes.a_over_b[ellipse[1]]);
    let specs = [
        (0, 2, 3, "Fx/(μN) against ξ'", "ξ' (normalised)", "Fx/(μN)", "η'", "φ'"),
        (1, 3, 4, "Fy/(μN) against η'", "η' (normalised)", "Fy/(μN)", "φ'", "ξ'"),
    ];
    let mut out = [String::new(), String::new()];
    for (slot, (comp, along, per, title, xl, yl, per_name, fixed_name)) in specs.into_iter().enumerate() {
        let title = format!("{title}: {engine}, a/b = {ab}, ν = {nu} ({fixed_name} nearest 0)");
        let mut chart = Chart::new(title, xl, yl).x_unit("1").y_unit("1").size(900, 560);
        let curves = family(table, ellipse, comp, along, per);
        let limit = 1.25 * curves.iter().flat_map(|(_, p)| p.iter().map(|q| q.1.abs())).fold(1.0, f64::max);
        for (i, (v, pts)) in curves.iter().enumerate() {
            let s = Series::new(format!("{engine}, {per_name} = {v}"), pts.clone(), Style::LineMarkers);
            chart = chart.add(s.with_appearance(Appearance::for_index(i)));
        }
        if let Some((name, r)) = reference {
            let (rn, ra) = (nearest(&r.axes.nu, nu), nearest(&r.axes.a_over_b, ab));
            let refs = family(r, [rn, ra], comp, along, per);
            let bits = |p: &[(f64, f64)]| p.iter().map(|q| (q.0.to_bits(), q.1.to_bits())).collect::<Vec<_>>();
            if refs.len() > 1 && refs.windows(2).all(|w| bits(&w[0].1) == bits(&w[1].1)) {
                // One curve for the whole family (the linear theory's Fx' does not depend on η').
                let label = format!("{name} (every {per_name})");
                let s = Series::new(label, clip(&refs[0].1, limit), Style::Dashed);
                chart = chart.add(s.with_appearance(Appearance::for_index(curves.len())));
            } else {
                for (i, (v, pts)) in refs.iter().enumerate() {
                    let s = Series::new(format!("{name}, {per_name} = {v}"), clip(pts, limit), Style::Dashed);
                    chart = chart.add(s.with_appearance(Appearance::for_index(i)));
                }
            }
        }
        out[slot] =
            chart.to_svg().map_err(|e| Error::Output { what: "creep-force figure".into(), message: e.to_string() })?;
    }
    Ok(out)
}

/// Writes the two charts of every ellipse of `table` into `dir` as `STEM-nu{iν}-ab{i_ab}-fx.svg` and `...-fy.svg`
/// (at most 12 ellipses, evenly picked), returning the files. Errors: a file that cannot be written (exit 3).
pub fn write_figure(
    table: &CreepTable,
    reference: Option<(&str, &CreepTable)>,
    engine: &str,
    dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>> {
    let [nn, na, ..] = table.axes.shape();
    std::fs::create_dir_all(dir).map_err(|source| Error::Write { path: dir.to_path_buf(), source })?;
    let mut files = Vec::new();
    let ellipses: Vec<[usize; 2]> = (0..nn).flat_map(|i| (0..na).map(move |j| [i, j])).collect();
    let step = ellipses.len().div_ceil(12).max(1);
    for e in ellipses.into_iter().step_by(step) {
        let svgs = creep_surface_svg(table, reference, engine, e)?;
        for (svg, which) in svgs.iter().zip(["fx", "fy"]) {
            let path = dir.join(format!("{stem}-nu{}-ab{}-{which}.svg", e[0], e[1]));
            crate::io::write_output(&path, svg)?;
            files.push(path);
        }
    }
    Ok(files)
}

/// `rollbem plot TABLE.csv` for a creep table: [`write_figure`] into `dir` with the stem of the file, Kalker's
/// linear theory ([`CreepTable::linear`]) dashed beside an engine that is not the linear theory itself. Errors: the
/// file cannot be read or is not a complete table (exit 2), a figure cannot be written (exit 3).
pub fn plot_table(csv: &Path, dir: &Path) -> Result<Vec<PathBuf>> {
    let rows = super::TableRow::read_csv(csv)?;
    let table = CreepTable::from_rows(&rows).map_err(|message| Error::Parse { path: csv.to_path_buf(), message })?;
    let engine = rows.first().map_or("table", |r| r.engine.as_str());
    let linear = CreepTable::linear(&table.axes);
    let reference = (engine != "kalker_linear").then_some(("linear theory", &linear));
    let stem = csv.file_stem().map_or("creep-table".into(), |s| s.to_string_lossy().into_owned());
    write_figure(&table, reference, engine, dir, &stem)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::creeptable::Axes;

    #[test]
    fn clip_cuts_at_the_crossing_and_breaks_the_line() {
        // Expected: y = 2x leaves |y| ≤ 1.25 at x = 0.625 (computed by hand); the next point is a break (NaN).
        let c = clip(&[(0.0, 0.0), (1.0, 2.0), (2.0, 4.0)], 1.25);
        assert_eq!(&c[..2], &[(0.0, 0.0), (0.625, 1.25)]);
        assert!(c[2].1.is_nan() && c.len() == 3);
        // Coming back inside: the crossing, then the inside point.
        let c = clip(&[(0.0, 2.0), (1.0, 0.0)], 1.0);
        assert_eq!(c, vec![(0.5, 1.0), (1.0, 0.0)]);
    }

    #[test]
    fn the_figure_draws_each_family_and_the_linear_theory_once() {
        // Expected: the engine's curves per η' (and per φ'), the linear theory's Fx' once (it does not depend on η'),
        // the same SVG for the same table, and an ellipse outside the table refused.
        let axes =
            Axes { nu: vec![0.25], a_over_b: vec![1.0], xi: vec![0.0, 0.5, 1.0], eta: vec![0.0, 0.5], phi: vec![0.0] };
        let linear = CreepTable::linear(&axes);
        let mut table = linear.clone();
        table.forces.iter_mut().for_each(|f| *f = f.clamp(-1.0, 1.0));
        let [fx, fy] = creep_surface_svg(&table, Some(("linear theory", &linear)), "clamped", [0, 0]).unwrap();
        assert!(fx.contains("clamped, η&apos; = 0.5") || fx.contains("clamped, η' = 0.5"), "{fx}");
        assert!(fx.contains("linear theory (every η"));
        assert!(fy.contains("clamped, φ"));
        assert_eq!(
            creep_surface_svg(&table, None, "clamped", [0, 0]).unwrap()[0],
            creep_surface_svg(&table, None, "clamped", [0, 0]).unwrap()[0]
        );
        assert!(creep_surface_svg(&table, None, "x", [1, 0]).is_err());
    }
}
