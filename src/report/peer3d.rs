//! The figure of the CONTACT 3D peer pages: CPU time against the potential contact's elements for both programs on
//! CONTACT's performance series (`norm_problm_1p … 8p`, `tang_problm_1s … 8s`, and the steady-rolling
//! `tang_problm_1c … 8c`, `1f`, `2f`), read from the tables `benches/peer/contact3d.sh` wrote (`peer-contact3d.md`
//! and `peer-contact3d-rolling.md`, declared inputs of the report). Every point is a cell of
//! that table: NPOT, CONTACT's best CPU (the smaller of its runs with glibc's defaults and with the malloc tunables)
//! and rollbem's CPU; a time printed as 0.00 (below the table's resolution) has no place on a log axis and is left
//! out, as the caption says.

use crate::plot::{Chart, Series, Style};

/// Where the figure goes, relative to the report folder.
pub(super) const FIGURE: &str = "figures/peer-contact3d-time.svg";

/// One input of the series: which problem (`"norm"`, `"tang"` the shift, `"steady"` steady rolling with the
/// creepages prescribed, `"steady_force"` with the forces), NPOT, CONTACT's best CPU and rollbem's CPU (s).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Row {
    pub problem: &'static str,
    pub input: String,
    pub npot: f64,
    pub contact: f64,
    pub rollbem: f64,
}

/// The rows of the performance series in the peer table (columns found by their headers; rows whose cells do not
/// parse are skipped).
pub(super) fn rows(table: &str) -> Vec<Row> {
    let cells = super::html::cells;
    let mut lines = table.lines().filter(|l| l.trim_start().starts_with('|'));
    let Some(header) = lines.next().map(cells) else { return Vec::new() };
    let col = |name: &str| header.iter().position(|h| h == name);
    let (Some(npot), Some(cpu), Some(tuned), Some(ours)) =
        (col("NPOT"), col("CPU user+sys [s]"), col("with malloc tunables: CPU user+sys [s]"), col("rollbem CPU [s]"))
    else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for row in lines.map(cells) {
        let Some(name) = row.first() else { continue };
        let problem = match (name.strip_prefix("norm_problm_"), name.strip_prefix("tang_problm_")) {
            (Some(_), _) => "norm",
            (_, Some(level)) if level.ends_with('s') => "tang",
            (_, Some(level)) if level.ends_with('c') => "steady",
            (_, Some(level)) if level.ends_with('f') => "steady_force",
            _ => continue,
        };
        let num = |k: usize| row.get(k).and_then(|c| c.parse::<f64>().ok());
        if let (Some(n), Some(a), Some(b), Some(r)) = (num(npot), num(cpu), num(tuned), num(ours)) {
            out.push(Row { problem, input: name.clone(), npot: n, contact: a.min(b), rollbem: r });
        }
    }
    out
}

/// The chart: one line per program and problem, log–log.
pub(super) fn figure(rows: &[Row]) -> Chart {
    let mut chart = Chart::new(
        "CONTACT's performance series: CPU against elements",
        "potential contact elements NPOT",
        "CPU user + sys",
    )
    .log_x()
    .log_y()
    .y_unit("s");
    let problems = [
        ("norm", "normal problem"),
        ("tang", "shift"),
        ("steady", "steady rolling, creepages"),
        ("steady_force", "steady rolling, forces"),
    ];
    for (problem, what) in problems {
        for (program, pick) in [("CONTACT (MKL)", 0), ("rollbem", 1)] {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.problem == problem)
                .map(|r| (r.npot, if pick == 0 { r.contact } else { r.rollbem }))
                .filter(|p| p.1 > 0.0)
                .collect();
            if !points.is_empty() {
                chart = chart.add(Series::new(format!("{program}, {what}"), points, Style::LineMarkers));
            }
        }
    }
    chart
}

/// The page's figure paragraph for `rows` (links relative to the report folder).
pub(super) fn caption(rows: &[Row]) -> String {
    let dropped: Vec<&str> =
        rows.iter().filter(|r| r.contact <= 0.0 || r.rollbem <= 0.0).map(|r| r.input.as_str()).collect();
    let mut md = format!(
        "\n## CPU against elements\n\n![CPU against elements]({FIGURE})\n\nFrom the CONTACT 3D peer tables \
         (`peer-contact3d.md`, `peer-contact3d-rolling.md`, those present): NPOT, CONTACT's best CPU (the smaller of \
         its two runs) and rollbem's, {} inputs.",
        rows.len()
    );
    if !dropped.is_empty() {
        md.push_str(&format!(" Left out of the log axes (a time printed as 0.00): {}.", dropped.join(", ")));
    }
    md.push('\n');
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The columns are found by their headers, CONTACT's best is the smaller of its two runs, other inputs are
    /// skipped, and a 0.00 is left off the chart and named in the caption (the values are the table's, by hand).
    #[test]
    fn rows_come_from_the_table_cells() {
        let table = "| input | NPOT | CPU user+sys [s] | with malloc tunables: CPU user+sys [s] | rollbem CPU [s] |\n\
                     |---|---:|---:|---:|---:|\n\
                     | cattaneo | 361 | 0.00 | 0.00 | – |\n\
                     | norm_problm_1p | 5751 | 0.01 | 0.02 | 0.00 |\n\
                     | norm_problm_2p | 23309 | 0.09 | 0.08 | 0.03 |\n\
                     | tang_problm_8s | 372025 | 62.03 | 28.48 | 8.82 |\n\
                     | tang_problm_4c | 92701 | 22.79 | 21.13 | 1.90 |\n\
                     | tang_problm_2f | 23309 | 39.3 | 38.0 | 0.5 |\n";
        let r = rows(table);
        assert_eq!(r.len(), 5);
        assert_eq!((r[3].problem, r[4].problem), ("steady", "steady_force"));
        assert_eq!((r[1].npot, r[1].contact, r[1].rollbem), (23309.0, 0.08, 0.03));
        assert_eq!((r[2].problem, r[2].contact), ("tang", 28.48));
        let svg = figure(&r).to_svg().unwrap();
        assert!(svg.contains("rollbem, shift") && svg.contains("CONTACT (MKL), normal problem"));
        assert!(
            svg.contains("rollbem, steady rolling, creepages") && svg.contains("CONTACT (MKL), steady rolling, forces")
        );
        assert!(caption(&r).contains("Left out of the log axes (a time printed as 0.00): norm_problm_1p."));
        assert!(rows("no table").is_empty());
    }
}
