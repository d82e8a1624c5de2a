//! Sweep sections about physics rather than cost: what the finite body changes against the half-plane (rows of both
//! models at the same loads), and creep curves against Carter (steady rolling over a range of creepages).

use super::table::{log_slope, num, Row, Sweep};
use super::Figs;
use crate::error::Result;
use crate::plot::{Chart, Series, Style};
use crate::scene::BodyModel;
use crate::theory::{self, Hertz2D};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// (P, Q, μ) as text.
type LoadKey = (String, String, String);

/// The key of a load case: (P, Q, μ) to nine significant digits (the resultants of two models at the same load
/// differ in the last bits).
fn load_key(r: &Row) -> LoadKey {
    let k = |c: &str| num(r, c).map(|v| format!("{v:.9e}")).unwrap_or_default();
    (k("normal_load"), k("tangential_load"), k("friction"))
}

/// Relative difference (finite − half-plane)/|half-plane|.
fn rel(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) if b != 0.0 => Some((a - b) / b.abs()),
        _ => None,
    }
}

/// What the finite body changes: pair the finite wheel's and the half-plane's rows at the same (P, Q, μ); table and
/// plot of the relative differences against a/R with their fitted slopes.
pub fn finite_vs_half_plane(sw: &Sweep, md: &mut String, figs: &mut Figs) -> Result<()> {
    let solved: Vec<&Row> = sw.rows.iter().filter(|r| r.status.solved()).collect();
    let mut pairs: BTreeMap<LoadKey, (Option<&Row>, Option<&Row>)> = BTreeMap::new();
    for r in &solved {
        let e = pairs.entry(load_key(r)).or_default();
        match r.model.map_or("", |m| m.name()) {
            "bem" => e.0 = Some(r),
            _ => e.1 = Some(r),
        }
    }
    let half = |r: &Row| Some(0.5 * (num(r, "stick_right")? - num(r, "stick_left")?));
    // (friction, a/R, Δa, Δp0, Δc, Δshift)
    let mut data: Vec<(f64, f64, [Option<f64>; 4])> = Vec::new();
    for (f, h) in pairs.values().filter_map(|(f, h)| Some(((*f)?, (*h)?))) {
        let (Some(a), Some(radius)) = (h.hertz_a, h.radius) else { continue };
        let a_over_r = a / radius;
        let d = [
            rel(f.half_width_fit, h.half_width_fit),
            rel(f.peak_pressure_fit, h.peak_pressure_fit),
            rel(half(f), half(h)),
            rel(num(f, "shift"), num(h, "shift")),
        ];
        data.push((f.friction.unwrap_or(0.0), a_over_r, d));
    }
    if data.is_empty() {
        writeln!(
            md,
            "No load was solved on both models (rows are paired by their resultant P, Q and μ), so there is nothing \
             to compare.\n"
        )
        .unwrap();
        return Ok(());
    }
    data.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let unpaired = pairs.values().filter(|(f, h)| f.is_none() || h.is_none()).count();
    writeln!(
        md,
        "Each load is solved on the finite wheel and on the half-plane; the table gives the finite wheel's relative \
         difference from the half-plane, (finite − half-plane)/half-plane, at the Hertz a/R of the load{}.\n",
        if unpaired > 0 {
            format!(" ({unpaired} loads lack one of the two models and are left out)")
        } else {
            String::new()
        }
    )
    .unwrap();
    writeln!(md, "| μ | a/R | Δa | Δp0 | Δ stick half-width | Δ rigid shift |\n|---|---|---|---|---|---|").unwrap();
    let f = |v: Option<f64>| v.map(|v| format!("{v:+.2e}")).unwrap_or_else(|| "–".into());
    for (mu, ar, d) in &data {
        writeln!(md, "| {mu} | {ar:.4} | {} | {} | {} | {} |", f(d[0]), f(d[1]), f(d[2]), f(d[3])).unwrap();
    }
    let names = ["Δa", "Δp0", "Δ stick half-width", "Δ rigid shift"];
    writeln!(
        md,
        "\nFitted slopes of |difference| against a/R (least squares in log–log over every load, ± standard error):\n"
    )
    .unwrap();
    writeln!(md, "| μ | quantity | loads | slope |\n|---|---|---|---|").unwrap();
    let mut chart = Chart::new(format!("{}: finite wheel against half-plane", sw.name), "a/R", "|relative difference|")
        .x_unit("1")
        .y_unit("1")
        .log_x()
        .log_y();
    let frictions: BTreeSet<String> = data.iter().map(|d| format!("{}", d.0)).collect();
    for mu in &frictions {
        for (q, name) in names.iter().enumerate() {
            let pts: Vec<(f64, f64)> = data
                .iter()
                .filter(|d| format!("{}", d.0) == *mu)
                .filter_map(|d| Some((d.1, d.2[q]?.abs())))
                .filter(|p| p.1 > 0.0)
                .collect();
            if pts.is_empty() {
                continue;
            }
            let slope = log_slope(&pts).map(|(s, se)| format!("{s:.2} ± {se:.2}")).unwrap_or_else(|| "–".into());
            writeln!(md, "| {mu} | {name} | {} | {slope} |", pts.len()).unwrap();
            chart = chart.add(Series::new(format!("{name}, μ = {mu}"), pts, Style::LineMarkers));
        }
    }
    let file = figs.save(
        &chart,
        &format!("{}-differences.svg", sw.stem),
        format!("{}: finite wheel against half-plane", sw.name),
    )?;
    writeln!(
        md,
        "\n![finite wheel against half-plane]({file})\n\nThe rigid shift is measured at different points — the finite \
         wheel's hub, the half-plane's datum at depth D — so its difference is a difference of reference points as much \
         as of bodies; a, p0 and the stick zone are local and comparable. The stick edges are read from the nodes' \
         states, so a stick-zone difference smaller than one element over the stick half-width is mesh resolution.\n"
    )
    .unwrap();
    Ok(())
}

/// Free-rolling creepages ξR/(μa) within this of zero are zero: the interpolation between swept creepages of the
/// reference sweeps (steps of 0.1 μa/R) resolves a crossing to about 1e-3 on a curve through the origin.
const FREE_ROLLING_ZERO: f64 = 1e-3;

/// What a creep curve's departure from Carter's is: Carter's is the steady-rolling answer for a half-plane with
/// β = 0, so on the half-plane model it is a check; on the finite wheel a model comparison (the body is not a
/// half-space); and a curve that does not pass through the origin (free rolling at ξ ≠ 0: normal–tangential
/// coupling, β ≠ 0) is outside Carter's model whatever the body.
fn carter_domain(model: Option<BodyModel>, strip: bool, free: Option<f64>) -> &'static str {
    let coupled = free.is_some_and(|f| f.abs() > FREE_ROLLING_ZERO);
    match (model, coupled) {
        _ if strip => "model comparison: a strip of half-spaces (`mesh.strip_width`), not plane strain",
        (_, true) => "model comparison: coupled (free rolling at ξ ≠ 0; Carter assumes β = 0)",
        (Some(BodyModel::HalfPlane), false) => "check (Carter's model)",
        (Some(BodyModel::Bem), false) => "model comparison: finite wheel",
        (None, false) => "model not recorded",
    }
}

/// Creep curves: Q/(μP) against ξR/(μa) per series, with Carter's curve; the largest departure from Carter and
/// the free-rolling creepage (where Q changes sign) per series.
pub fn creep_curves(sw: &Sweep, md: &mut String, figs: &mut Figs) -> Result<()> {
    let solved: Vec<&Row> = sw.rows.iter().filter(|r| r.status.solved()).collect();
    // The creepage is the curve's abscissa, not a series.
    let varied: Vec<String> = sw.varied(&solved).into_iter().filter(|k| !k.ends_with("creepage")).collect();
    let mut groups: BTreeMap<String, Vec<(f64, f64)>> = BTreeMap::new();
    let mut models: BTreeMap<String, (Option<BodyModel>, bool)> = BTreeMap::new();
    for r in &solved {
        let (Some(xi), Some(q), Some(p), Some(mu), Some(a), Some(rad)) =
            // R* of the pair (a twin disc's R₁R₂/(R₁ + R₂)), the wheel's R in a CSV without the column.
            (r.creepage, r.tangential_load, r.normal_load, r.friction, r.hertz_a, r.bodies.contact_radius.or(r.radius))
        else {
            continue;
        };
        groups.entry(sw.label(r, &varied)).or_default().push((xi * rad / (mu * a), q / (mu * p)));
        models.insert(sw.label(r, &varied), (r.model, r.strip_width.is_some()));
    }
    let mut chart = Chart::new(format!("{}: creep curves", sw.name), "ξR/(μa)", "Q/(μP)").x_unit("1").y_unit("1");
    let carter = |s: f64| theory::carter_force(&Hertz2D::new(1.0, 2.0 / std::f64::consts::PI), 1.0, 1.0, s);
    let xs: Vec<f64> = (0..=300).map(|i| -1.6 + 3.2 * i as f64 / 300.0).collect();
    chart = chart.add(Series::new("Carter (2D, β = 0)", xs.iter().map(|&s| (s, carter(s))).collect(), Style::Dashed));
    writeln!(
        md,
        "Q/(μP) against the normalised creepage ξR/(μa) (a: Hertz at the run's load). Carter's curve is the 2D \
         half-plane answer with β = 0; the free-rolling creepage is where Q changes sign (linear interpolation \
         between the swept creepages). A departure from it is a check on the half-plane model and a model \
         comparison elsewhere (last column).\n"
    )
    .unwrap();
    writeln!(
        md,
        "| series | creepages | max \\|Q/(μP) − Carter\\| | free-rolling ξR/(μa) | against Carter |\n|---|---|---|---|---|"
    )
    .unwrap();
    for (label, mut pts) in groups {
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let dev = pts.iter().map(|(s, q)| (q - carter(*s)).abs()).fold(0.0, f64::max);
        let free = pts.windows(2).find_map(|w| {
            let ((s0, q0), (s1, q1)) = (w[0], w[1]);
            if q0 == 0.0 {
                Some(s0)
            } else if q0 * q1 < 0.0 {
                Some(s0 + (s1 - s0) * q0 / (q0 - q1))
            } else {
                None
            }
        });
        let (model, strip) = models.get(&label).copied().unwrap_or((None, false));
        let domain = carter_domain(model, strip, free);
        let free = free.map(|v| format!("{v:+.4}")).unwrap_or_else(|| "not crossed".into());
        writeln!(md, "| {label} | {} | {dev:.2e} | {free} | {domain} |", pts.len()).unwrap();
        chart = chart.add(Series::new(label, pts, Style::Markers));
    }
    let file = figs.save(&chart, &format!("{}-creep-curves.svg", sw.stem), format!("{}: creep curves", sw.name))?;
    writeln!(md, "\n![creep curves]({file})\n").unwrap();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn carter_is_a_check_only_in_its_own_model() {
        // Expected: Carter's domain (half-plane, β = 0, so a curve through the origin) — REFERENCES.md.
        assert_eq!(carter_domain(Some(BodyModel::HalfPlane), false, Some(0.0)), "check (Carter's model)");
        assert!(carter_domain(Some(BodyModel::Bem), false, Some(0.0)).starts_with("model comparison: finite wheel"));
        assert!(carter_domain(Some(BodyModel::Bem), false, Some(-0.58)).contains("coupled"));
        assert!(carter_domain(Some(BodyModel::HalfPlane), false, Some(0.2)).contains("coupled"));
        assert_eq!(carter_domain(Some(BodyModel::HalfPlane), false, None), "check (Carter's model)");
        // A strip of half-spaces is not Carter's plane strain (src/halfplane.rs, "Strip of half-spaces").
        assert!(carter_domain(Some(BodyModel::HalfPlane), true, Some(0.0)).contains("strip"));
    }

    /// A twin disc's creep curve is normalised by the pair's R* (`contact_radius`), not the wheel's R: rows that
    /// lie exactly on Carter's curve with R* = R/2 (theory::carter_force) show a zero departure. With the wheel's R
    /// the abscissa doubles and the departure is of order 0.5 (the old code).
    #[test]
    fn a_twin_disc_creep_curve_is_normalised_by_the_pairs_radius() {
        let (r, r_star, mu, p) = (40.0, 20.0, 0.3, 724.982920059183);
        let h = Hertz2D::from_load(p, r_star, 115_384.615_384_615_4);
        let rows = [0.1, 0.3, 0.6, 0.9]
            .iter()
            .enumerate()
            .map(|(k, frac)| {
                let xi = frac * mu * h.a / r_star;
                let mut row = Row::new(k, "active_set", crate::sweep::RowStatus::Run(crate::status::Status::Solved));
                row.creepage = Some(xi);
                row.normal_load = Some(p);
                row.tangential_load = Some(theory::carter_force(&h, mu, r_star, xi));
                row.friction = Some(mu);
                row.hertz_a = Some(h.a);
                row.radius = Some(r);
                row.bodies.contact_radius = Some(r_star);
                row
            })
            .collect();
        let sw = Sweep {
            name: "t".into(),
            description: String::new(),
            stem: "t".into(),
            keys: vec!["rolling.creepage".into()],
            rows,
        };
        let tmp = tempfile::tempdir().unwrap();
        let mut md = String::new();
        creep_curves(&sw, &mut md, &mut Figs::new(tmp.path(), "")).unwrap();
        assert!(md.contains("| active_set | 4 | 0.00e0 |"), "{md}");
    }
}
