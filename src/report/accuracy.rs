//! Accuracy against cost, per sweep: the error of every configuration against its total time, the Pareto front, the
//! cheapest configuration reaching each accuracy (with the configurations tied with it in time), convergence under
//! refinement with least-squares orders, and — on the finite wheel — the split of the error against theory into
//! discretisation error (against the mesh-converged solution of the same model, extrapolated) and model error (that
//! converged solution against the half-space theory).

use super::table::{cell, log_slope, num, Row, Sweep, REFINEMENT_KEY};
use super::{plot_err, Figures};
use crate::error::Result;
use crate::plot::{Chart, Series, Style};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// Errors within this fraction of each other are equal for the front: a configuration is beaten on error only by one
/// at least this much more accurate (equal-error points that differ only by timing noise are not choices).
const PARETO_IMPROVEMENT: f64 = 0.02;

/// Relative timing noise assumed beyond the spread of a configuration's own repeated runs: its time interval
/// [fastest, slowest] is widened to [fastest/(1 + n), slowest·(1 + n)] before two configurations are compared, and
/// they are ordered in time only when the widened intervals do not overlap. Chosen by measurement: two consecutive
/// `report` runs on the project's 2-core machine gave identical Pareto fronts in 1 of 10 (error measure, sweep)
/// pairs with n = 0.25, 6 with 0.5 and 0.75, 9 with 1.0 (and 1.5); the recommendations per target were identical.
const TIMING_NOISE: f64 = 1.0;

/// The error measures a sweep may carry: CSV column and label.
const MEASURES: &[(&str, &str)] = &[
    ("hertz_l2_err", "L2 pressure error vs Hertz"),
    ("hertz_a_err", "half-width error vs Hertz"),
    ("hertz_p0_err", "peak-pressure error vs Hertz"),
    ("disc_a_err", "half-width error vs its mesh limit a∞"),
    ("disc_p0_err", "peak-pressure error vs its mesh limit p0∞"),
    ("cm_shear_l2_err", "L2 shear error vs Cattaneo–Mindlin (/‖μp‖)"),
    ("cm_shear_err", "max shear error vs C–M off ±a, ±c (/μp0)"),
];

/// Rows grouped into series by label, each in refinement order as (elements, row).
fn series<'a>(sw: &Sweep, rows: &[&'a Row]) -> BTreeMap<String, Vec<(f64, &'a Row)>> {
    let varied = sw.varied(rows);
    let mut g: BTreeMap<String, Vec<(f64, &Row)>> = BTreeMap::new();
    for r in rows {
        g.entry(sw.label(r, &varied)).or_default().push((num(r, "contact_elements").unwrap_or(0.0), r));
    }
    for v in g.values_mut() {
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    g
}

/// The accuracy sections of one sweep.
pub fn sections(sw: &mut Sweep, out: &Path, md: &mut String, figs: &mut Figures) -> Result<()> {
    let richardson = discretisation_errors(sw, md);
    let solved: Vec<&Row> = sw.rows.iter().filter(|r| cell(r, "status") == "solved").collect();
    let failed = sw.rows.len() - solved.len();
    if failed > 0 {
        writeln!(
            md,
            "{failed} of {} rows did not end `solved` and are left out of the plots and tables.\n",
            sw.rows.len()
        )
        .unwrap();
    }
    let present: Vec<(&str, &str)> =
        MEASURES.iter().copied().filter(|(k, _)| solved.iter().any(|r| num(r, k).is_some())).collect();
    for (err, label) in &present {
        front_and_cheapest(sw, &solved, err, label, out, md, figs)?;
    }
    if let Some(&(err, label)) = present.first() {
        convergence(sw, &solved, err, label, out, md, figs)?;
    }
    if richardson {
        if let Some(&(err, label)) = present.iter().find(|(k, _)| *k == "disc_a_err") {
            convergence(sw, &solved, err, label, out, md, figs)?;
        }
    }
    Ok(())
}

/// Accuracy against time for one error measure: plot, Pareto front, cheapest configuration per target with ties.
fn front_and_cheapest(
    sw: &Sweep,
    solved: &[&Row],
    err: &str,
    label: &str,
    out: &Path,
    md: &mut String,
    figs: &mut Figures,
) -> Result<()> {
    let mut chart = Chart::new(format!("{}: {label} against total time", sw.name), "total time", label)
        .x_unit("s")
        .y_unit("1")
        .log_x()
        .log_y();
    for (k, pts) in series(sw, solved) {
        let p: Vec<(f64, f64)> = pts.iter().filter_map(|(_, r)| Some((num(r, "t_total")?, num(r, err)?))).collect();
        if !p.is_empty() {
            chart = chart.add(Series::new(k, p, Style::LineMarkers));
        }
    }
    let file = format!("figures/{}-{err}-vs-time.svg", sw.stem);
    chart.write(&out.join(&file)).map_err(plot_err)?;
    figs.push((format!("{}: {label} against time", sw.name), file.clone()));
    writeln!(md, "#### {label}\n\n![{label} against time]({file})\n").unwrap();
    let varied = sw.varied(solved);
    let rows: Vec<&Row> =
        solved.iter().copied().filter(|r| num(r, err).is_some() && num(r, "t_total").is_some()).collect();
    let time = |r: &Row| {
        let t = num(r, "t_total").unwrap();
        let (lo, hi) = (num(r, "t_total_min").unwrap_or(t), num(r, "t_total_max").unwrap_or(t));
        (t, lo, hi, num(r, "timing_runs").unwrap_or(1.0) as usize)
    };
    // The widened time interval of a row, and "a is clearly faster than b".
    let widened = |r: &Row| {
        let (_, lo, hi, _) = time(r);
        (lo / (1.0 + TIMING_NOISE), hi * (1.0 + TIMING_NOISE))
    };
    let faster = |a: &Row, b: &Row| widened(a).1 < widened(b).0;
    let tied_in_time = |a: &Row, b: &Row| !faster(a, b) && !faster(b, a);
    // The front: every configuration that no other beats — clearly faster at no worse an error (within
    // PARETO_IMPROVEMENT), or tied in time and clearly more accurate. Membership does not depend on the order of
    // configurations whose times the noise cannot separate.
    let beats = |a: &Row, b: &Row| {
        let (ea, eb) = (num(a, err).unwrap(), num(b, err).unwrap());
        (faster(a, b) && ea <= eb * (1.0 + PARETO_IMPROVEMENT))
            || (tied_in_time(a, b) && ea < eb * (1.0 - PARETO_IMPROVEMENT))
    };
    let mut front: Vec<&Row> = rows.iter().copied().filter(|b| !rows.iter().any(|a| beats(a, b))).collect();
    if front.is_empty() {
        // `beats` is not transitive (tolerances), so with very wide timing spreads every row can be beaten by
        // another: fall back to plain dominance on the medians (faster and at least as accurate, one strictly).
        let t = |r: &Row| num(r, "t_total").unwrap();
        let e = |r: &Row| num(r, err).unwrap();
        front = rows
            .iter()
            .copied()
            .filter(|b| !rows.iter().any(|a| t(a) <= t(b) && e(a) <= e(b) && (t(a) < t(b) || e(a) < e(b))))
            .collect();
    }
    front.sort_by(|a, b| {
        num(a, "t_total")
            .unwrap()
            .total_cmp(&num(b, "t_total").unwrap())
            .then(sw.label(a, &varied).cmp(&sw.label(b, &varied)))
    });
    let show_time = |r: &Row| {
        let (t, lo, hi, k) = time(r);
        if k > 1 {
            format!("{t:.2e} ({lo:.2e}–{hi:.2e}, {k} runs)")
        } else {
            format!("{t:.2e} (1 run)")
        }
    };
    writeln!(
        md,
        "Pareto front: the configurations no other beats, where a configuration beats another if it is faster beyond \
         the timing noise at an error no more than {:.0} % larger, or tied in time and at least {:.0} % more accurate \
         (times: the median of repeated runs where the sweep asks for them, with the fastest and slowest; two \
         configurations are tied in time when their ranges, widened by a factor {} on each side for the machine's noise, \
         overlap):\n",
        100.0 * PARETO_IMPROVEMENT,
        100.0 * PARETO_IMPROVEMENT,
        1.0 + TIMING_NOISE
    )
    .unwrap();
    writeln!(md, "| configuration | contact elements | error | total time [s] |\n|---|---|---|---|").unwrap();
    for r in &front {
        let e = num(r, err).unwrap();
        writeln!(md, "| {} | {} | {e:.2e} | {} |", sw.label(r, &varied), cell(r, "contact_elements"), show_time(r))
            .unwrap();
    }
    writeln!(
        md,
        "\nCheapest configurations reaching each accuracy: the fastest, and every other configuration reaching it \
         that is tied with the fastest in time (the machine's noise cannot order them); the recommendation is the \
         tied configuration with the fewest elements, then the smallest error:\n"
    )
    .unwrap();
    writeln!(md, "| target | recommended | elements | error | total time [s] | tied with |\n|---|---|---|---|---|---|")
        .unwrap();
    let smallest = rows.iter().filter_map(|r| num(r, err)).fold(f64::INFINITY, f64::min);
    for target in [1e-2, 1e-3, 1e-4] {
        let reach: Vec<&Row> = rows.iter().copied().filter(|r| num(r, err).unwrap() <= target).collect();
        let Some(fastest) = reach.iter().copied().min_by(|a, b| time(a).0.total_cmp(&time(b).0)) else {
            writeln!(md, "| {target:.0e} | not reached by this sweep (smallest error {smallest:.2e}) | | | | |")
                .unwrap();
            continue;
        };
        let mut tied: Vec<&Row> = reach.iter().copied().filter(|r| tied_in_time(r, fastest)).collect();
        let elements = |r: &Row| num(r, "contact_elements").unwrap_or(f64::INFINITY);
        tied.sort_by(|a, b| {
            elements(a)
                .total_cmp(&elements(b))
                .then(num(a, err).unwrap().total_cmp(&num(b, err).unwrap()))
                .then(sw.label(a, &varied).cmp(&sw.label(b, &varied)))
        });
        let best = tied[0];
        let others: Vec<String> =
            tied[1..].iter().map(|r| format!("{} ({})", sw.label(r, &varied), cell(r, "contact_elements"))).collect();
        writeln!(
            md,
            "| {target:.0e} | {} | {} | {:.2e} | {} | {} |",
            sw.label(best, &varied),
            cell(best, "contact_elements"),
            num(best, err).unwrap(),
            show_time(best),
            if others.is_empty() { "–".into() } else { others.join(", ") }
        )
        .unwrap();
    }
    writeln!(md).unwrap();
    Ok(())
}

/// Error against the mesh per series, with the least-squares order over all meshes and its standard error.
fn convergence(
    sw: &Sweep,
    solved: &[&Row],
    err: &str,
    label: &str,
    out: &Path,
    md: &mut String,
    figs: &mut Figures,
) -> Result<()> {
    let mut chart = Chart::new(format!("{}: {label} against mesh", sw.name), "contact elements", label)
        .x_unit("1")
        .y_unit("1")
        .log_x()
        .log_y();
    writeln!(
        md,
        "Observed orders ({label}): error ∝ n^(−order), n the number of contact elements, least squares over every \
         mesh of the series, ± its standard error:\n"
    )
    .unwrap();
    writeln!(md, "| series | meshes | order | finest mesh | its error |\n|---|---|---|---|---|").unwrap();
    for (k, pts) in series(sw, solved) {
        let p: Vec<(f64, f64)> = pts.iter().filter_map(|(n, r)| Some((*n, num(r, err)?))).collect();
        if p.is_empty() {
            continue;
        }
        let order = log_slope(&p).map(|(s, se)| format!("{:.2} ± {:.2}", -s, se)).unwrap_or_else(|| "–".into());
        let last = p.last().unwrap();
        writeln!(md, "| {k} | {} | {order} | {} | {:.2e} |", p.len(), last.0, last.1).unwrap();
        chart = chart.add(Series::new(k, p, Style::LineMarkers));
    }
    let file = format!("figures/{}-{err}-vs-mesh.svg", sw.stem);
    chart.write(&out.join(&file)).map_err(plot_err)?;
    figs.push((format!("{}: {label} against mesh", sw.name), file.clone()));
    writeln!(md, "\n![{label} against mesh]({file})\n").unwrap();
    Ok(())
}

/// x(n) ≈ x∞ + C n^(−p): least squares in (x∞, C) for each p on a grid, the p of smallest residual. Returns (x∞, p).
fn extrapolate(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    if points.len() < 3 {
        return None;
    }
    let mut best: Option<(f64, f64, f64)> = None;
    for k in 0..=350 {
        let p = 0.5 + 0.01 * k as f64;
        let xs: Vec<f64> = points.iter().map(|(n, _)| n.powf(-p)).collect();
        let m = xs.len() as f64;
        let (mx, my) = (xs.iter().sum::<f64>() / m, points.iter().map(|q| q.1).sum::<f64>() / m);
        let sxx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
        let sxy: f64 = xs.iter().zip(points).map(|(x, q)| (x - mx) * (q.1 - my)).sum();
        if sxx <= 0.0 {
            continue;
        }
        let c = sxy / sxx;
        let x_inf = my - c * mx;
        let res: f64 = xs.iter().zip(points).map(|(x, q)| (q.1 - x_inf - c * x).powi(2)).sum();
        if best.is_none_or(|b| res < b.2) {
            best = Some((x_inf, p, res));
        }
    }
    best.map(|b| (b.0, b.1))
}

/// On the finite wheel: per series, the fitted a and p0 extrapolated to the converged mesh (with the spread of the
/// leave-one-out extrapolations as uncertainty); each row gets `disc_a_err`, `disc_p0_err` against its series'
/// limit; a table of the limits and their model error against Hertz goes into `md`. Returns whether it applied.
fn discretisation_errors(sw: &mut Sweep, md: &mut String) -> bool {
    let bem = sw.rows.iter().any(|r| cell(r, "model") == "bem" && num(r, "hertz_a_err").is_some());
    if !bem || !sw.keys.iter().any(|k| k == REFINEMENT_KEY) {
        return false;
    }
    let solved: Vec<usize> = (0..sw.rows.len()).filter(|&i| cell(&sw.rows[i], "status") == "solved").collect();
    let refs: Vec<&Row> = solved.iter().map(|&i| &sw.rows[i]).collect();
    let varied = sw.varied(&refs);
    let mut groups: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    for &i in &solved {
        groups.entry(sw.label(&sw.rows[i], &varied)).or_default().push(i);
    }
    writeln!(
        md,
        "Discretisation error and model error, separated. For each series the fitted half-width a and peak pressure p0 \
         are extrapolated to the converged mesh by a least-squares fit x(n) = x∞ + C n^(−p) over all its meshes; the \
         uncertainty is the largest change of x∞ when one mesh is left out (with three meshes, x∞'s distance to the \
         finest mesh's value). The discretisation error of a run is its distance to its series' x∞ (what a finer mesh \
         buys); x∞ against Hertz is the model error (what no mesh buys: the finite wheel is not a half-space) for the \
         direct solvers (lemke, lemke_dense, active_set, clarabel), exact on the discrete problem, and model plus \
         solver error for an iterative solver at a finite tolerance.\n"
    )
    .unwrap();
    writeln!(md, "| series | meshes | a∞ (± uncertainty) | x∞ vs Hertz, a | p0∞ (± uncertainty) | x∞ vs Hertz, p0 |\n|---|---|---|---|---|---|").unwrap();
    for (label, idx) in groups {
        let mut limits = Vec::new();
        for (col, hertz) in [("half_width_fit", "hertz_a"), ("peak_pressure_fit", "hertz_p0")] {
            let mut pts: Vec<(f64, f64, usize)> = idx
                .iter()
                .filter_map(|&i| Some((num(&sw.rows[i], "contact_elements")?, num(&sw.rows[i], col)?, i)))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            let xy: Vec<(f64, f64)> = pts.iter().map(|p| (p.0, p.1)).collect();
            let Some((x_inf, _)) = extrapolate(&xy) else {
                limits.push(None);
                continue;
            };
            let unc = if xy.len() >= 4 {
                (0..xy.len())
                    .filter_map(|k| {
                        let mut rest = xy.clone();
                        rest.remove(k);
                        extrapolate(&rest).map(|(x, _)| (x - x_inf).abs())
                    })
                    .fold(0.0, f64::max)
            } else {
                (x_inf - xy.last().unwrap().1).abs()
            };
            let theory = idx.iter().find_map(|&i| num(&sw.rows[i], hertz));
            let key = if col == "half_width_fit" { "disc_a_err" } else { "disc_p0_err" };
            for (_, x, i) in &pts {
                sw.rows[*i].insert(key.to_string(), format!("{:e}", (x - x_inf).abs() / x_inf.abs()));
            }
            limits.push(Some((x_inf, unc, theory.map(|t| (x_inf - t).abs() / t))));
        }
        let show = |l: &Option<(f64, f64, Option<f64>)>| match l {
            Some((x, u, m)) => (format!("{x:.6e} (± {u:.1e})"), m.map(|m| format!("{m:.2e}")).unwrap_or_default()),
            None => ("–".into(), "–".into()),
        };
        let (a, am) = show(&limits[0]);
        let (p, pm) = show(&limits[1]);
        writeln!(md, "| {label} | {} | {a} | {am} | {p} | {pm} |", idx.len()).unwrap();
    }
    writeln!(md).unwrap();
    true
}

#[cfg(test)]
mod tests {
    use super::extrapolate;

    #[test]
    fn extrapolation_recovers_the_limit_of_a_power_law() {
        let pts: Vec<(f64, f64)> =
            [15.0, 30.0, 60.0, 120.0, 240.0].iter().map(|&n: &f64| (n, 2.5 + 0.7 * n.powf(-1.3))).collect();
        let (x, p) = extrapolate(&pts).unwrap();
        assert!((x - 2.5).abs() < 1e-6, "{x}");
        assert!((p - 1.3).abs() < 0.011, "{p}");
    }
}
