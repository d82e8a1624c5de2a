//! A report section for a creep table (Markdown): what the table holds, its statuses, and per ellipse the figures a
//! reader checks first — the largest |F|/(μN) (at most 1 up to the grid's Σ pn dA/N: Coulomb's bound), the slope
//! Fx'/ξ' at the smallest ξ' > 0 alone against the linear theory's 3, and Fx' at ξ' alone against Kalker's
//! saturation. `rollbem report` does not call it yet (the lead wires it in); it is a pure function of the table.

use super::table::{CreepTable, STATUS_CODES};
use std::fmt::Write as _;

/// Fx' at (ellipse, ξ index) with η' and φ' at their values nearest 0, and those values.
fn xi_alone(t: &CreepTable, inu: usize, iab: usize, ixi: usize) -> Option<f64> {
    let near0 = |axis: &[f64]| (0..axis.len()).min_by(|&i, &j| axis[i].abs().total_cmp(&axis[j].abs()));
    let (ie, ip) = (near0(&t.axes.eta)?, near0(&t.axes.phi)?);
    (t.axes.eta[ie] == 0.0 && t.axes.phi[ip] == 0.0).then(|| t.at([inu, iab, ixi, ie, ip]).map(|f| f[0]))?
}

/// The Markdown section for `table` computed by `engine`, with `figures` as (caption, relative link) pairs.
pub fn markdown_section(table: &CreepTable, engine: &str, figures: &[(String, String)]) -> String {
    let mut md = String::new();
    let s = table.axes.shape();
    let _ = writeln!(md, "## Creep-force table: {engine}\n");
    let _ = writeln!(
        md,
        "{} cases: ν × a/b × ξ' × η' × φ' = {} × {} × {} × {} × {} (normalised creepages and forces as Kalker's \
         USETAB: Fx' = Fx/(μN), linear theory Fx' = 3ξ', Fy' = 3η' + φ'; README \"Creep-force tables\").\n",
        table.status.len(),
        s[0],
        s[1],
        s[2],
        s[3],
        s[4]
    );
    let counts: Vec<String> = STATUS_CODES
        .iter()
        .map(|(name, code)| format!("{} {name}", table.status.iter().filter(|&&c| c == *code).count()))
        .collect();
    let _ = writeln!(md, "Statuses: {}.\n", counts.join(", "));
    let _ =
        writeln!(md, "| ν | a/b | max \\|F\\|/(μN) | Fx'/ξ' at the smallest ξ' (linear: 3) | Fx' at the largest ξ' |");
    let _ = writeln!(md, "|---:|---:|---:|---:|---:|");
    for inu in 0..s[0] {
        for iab in 0..s[1] {
            let mut max = f64::NAN;
            for ixi in 0..s[2] {
                for ie in 0..s[3] {
                    for ip in 0..s[4] {
                        if let Some(f) = table.at([inu, iab, ixi, ie, ip]) {
                            max = max.max(f[0].hypot(f[1]));
                        }
                    }
                }
            }
            let first = (0..s[2]).find(|&i| table.axes.xi[i] > 0.0);
            let slope = first.and_then(|i| xi_alone(table, inu, iab, i).map(|f| f / table.axes.xi[i]));
            let last = xi_alone(table, inu, iab, s[2].saturating_sub(1));
            let show = |x: Option<f64>| x.map_or("—".to_string(), |v| format!("{v:.4}"));
            let (nu, ab) = (table.axes.nu[inu], table.axes.a_over_b[iab]);
            let _ = writeln!(md, "| {nu} | {ab} | {} | {} | {} |", show(Some(max)), show(slope), show(last));
        }
    }
    md.push('\n');
    for (caption, link) in figures {
        let _ = writeln!(md, "![{caption}]({link})\n");
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::creeptable::Axes;

    #[test]
    fn the_section_of_the_linear_theory_shows_its_slope_and_no_bound() {
        // Expected: for the linear theory itself, Fx'/ξ' = 3 exactly (its definition), the largest |F'| is
        // |(3·2, 3·1 + 0)| = √45 = 6.7082 at ξ' = 2, η' = 1, and Fx' at ξ' = 2 alone is 6.
        let axes =
            Axes { nu: vec![0.25], a_over_b: vec![1.0], xi: vec![0.0, 0.1, 2.0], eta: vec![0.0, 1.0], phi: vec![0.0] };
        let md = markdown_section(&CreepTable::linear(&axes), "kalker_linear", &[("Fx".into(), "f.svg".into())]);
        assert!(md.contains("| 0.25 | 1 | 6.7082 | 3.0000 | 6.0000 |"), "{md}");
        assert!(md.contains("6 cases") && md.contains("6 solved, 0 gross_sliding"));
        assert!(md.contains("![Fx](f.svg)"));
    }
}
