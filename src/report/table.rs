//! Sweep CSVs as rows of named cells, and the sweep facts every section needs: what was varied, how to label a
//! series, the scene's units.

use std::collections::BTreeSet;

/// One row of a sweep CSV, typed ([`crate::sweep::SweepRow`]: read by the type that wrote it).
pub use crate::sweep::SweepRow as Row;

/// A finite number in a column of a row (a figure, an error, a time, a derived figure).
pub fn num(r: &Row, k: &str) -> Option<f64> {
    r.number(k)
}

/// A cell as text ("" when empty): a column, a swept key or a derived figure.
pub fn cell(r: &Row, k: &str) -> String {
    r.cell(k)
}

/// Units as the scene declares them (`units = "N, mm, MPa"`: force, length, stress), for axis and table labels.
#[derive(Debug, Clone)]
pub struct Units {
    /// Force unit (empty when the scene declares none).
    pub force: String,
    /// Length unit.
    pub length: String,
    /// Stress unit.
    pub stress: String,
}

impl Default for Units {
    fn default() -> Units {
        Units { force: "F".into(), length: "L".into(), stress: "F/L²".into() }
    }
}

impl Units {
    /// Parse a scene's `units` label; `None` or a label without three parts gives the dimensions of a consistent
    /// set (`F`, `L`, `F/L²`), which is what the numbers are in when the scene does not say.
    pub fn parse(label: Option<&str>) -> Units {
        let parts: Vec<String> = label.unwrap_or("").split(',').map(|s| s.trim().to_string()).collect();
        match parts.as_slice() {
            [f, l, s] if !f.is_empty() && !l.is_empty() && !s.is_empty() => {
                Units { force: f.clone(), length: l.clone(), stress: s.clone() }
            }
            _ => Units::default(),
        }
    }

    /// Force per unit thickness: `N/mm` (the 2D load unit).
    pub fn line_load(&self) -> String {
        format!("{}/{}", self.force, self.length)
    }
}

/// The facts of a sweep the report needs beside its rows.
pub struct Sweep {
    /// The spec's `name`.
    pub name: String,
    /// The spec's `description`.
    pub description: String,
    /// File stem used for the CSV and figures.
    pub stem: String,
    /// The swept keys (CSV parameter columns).
    pub keys: Vec<String>,
    /// The rows.
    pub rows: Vec<Row>,
}

/// The mesh-refinement key: a series runs along it, it never labels a series.
pub const REFINEMENT_KEY: &str = "mesh.contact_elements";

impl Sweep {
    /// The keys that take more than one value over `rows` (other than the refinement key), i.e. what tells two
    /// series apart, with `solvers.use` replaced by the `solver` column and the element kind always shown when it
    /// varies.
    pub fn varied(&self, rows: &[&Row]) -> Vec<String> {
        let mut out = Vec::new();
        let mut columns: Vec<String> = vec!["element".into(), "solver".into(), "model".into()];
        // A grid key that sets one of those columns (`mesh.element`, `solvers.use`) would label it twice.
        columns.extend(
            self.keys
                .iter()
                .filter(|k| *k != REFINEMENT_KEY && *k != "solvers.use" && *k != "mesh.element" && *k != "wheel.model")
                .cloned(),
        );
        for k in columns {
            let values: BTreeSet<String> = rows.iter().map(|r| cell(r, &k)).collect();
            if values.len() > 1 || (k == "solver" && !values.is_empty()) {
                out.push(k);
            }
        }
        out
    }

    /// The series label of a row: every varied key's value (short key names), e.g. `constant · lemke · friction 0.3`.
    pub fn label(&self, r: &Row, varied: &[String]) -> String {
        varied
            .iter()
            .filter(|k| !cell(r, k).is_empty())
            .map(|k| match k.as_str() {
                "element" | "solver" | "model" => cell(r, k),
                k if k.ends_with(".tolerance") => format!("τ {}", short_number(&cell(r, k))),
                _ => format!("{} {}", k.rsplit('.').next().unwrap_or(k), short_number(&cell(r, k))),
            })
            .collect::<Vec<_>>()
            .join(" · ")
    }
}

/// `1e-8` for `0.00000001`, the number as written otherwise.
fn short_number(s: &str) -> String {
    match s.parse::<f64>() {
        Ok(v) if v != 0.0 && (v.abs() < 1e-3 || v.abs() >= 1e5) => format!("{v:.0e}"),
        _ => s.to_string(),
    }
}

/// Least-squares slope of ln y against ln x over all points with y > 0, and its standard error: an observed order of
/// convergence (error ∝ n^(−order)) is minus the slope. `None` below three points.
pub fn log_slope(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let p: Vec<(f64, f64)> =
        points.iter().filter(|(x, y)| *x > 0.0 && *y > 0.0).map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = p.len();
    if n < 3 {
        return None;
    }
    let nf = n as f64;
    let (mx, my) = (p.iter().map(|q| q.0).sum::<f64>() / nf, p.iter().map(|q| q.1).sum::<f64>() / nf);
    let sxx: f64 = p.iter().map(|q| (q.0 - mx).powi(2)).sum();
    let sxy: f64 = p.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let resid: f64 = p.iter().map(|q| (q.1 - my - slope * (q.0 - mx)).powi(2)).sum();
    let se = (resid / (nf - 2.0) / sxx).sqrt();
    Some((slope, se))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_slope_recovers_a_power_law_and_its_spread() {
        let pts: Vec<(f64, f64)> = [10.0, 20.0, 40.0, 80.0].iter().map(|&n: &f64| (n, 3.0 * n.powf(-1.5))).collect();
        let (s, se) = log_slope(&pts).unwrap();
        assert!((s + 1.5).abs() < 1e-12 && se < 1e-12);
        let noisy = [(10.0, 1.0), (20.0, 0.3), (40.0, 0.2), (80.0, 0.04)];
        let (_, se) = log_slope(&noisy).unwrap();
        assert!(se > 0.1);
        assert!(log_slope(&noisy[..2]).is_none());
    }

    #[test]
    fn units_parse() {
        let u = Units::parse(Some("N, mm, MPa"));
        assert_eq!((u.force.as_str(), u.length.as_str(), u.stress.as_str()), ("N", "mm", "MPa"));
        assert_eq!(u.line_load(), "N/mm");
        assert_eq!(Units::parse(None).length, "L");
    }
}
