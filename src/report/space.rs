//! The report's table of a 3D half-space sweep (a spec with `analysis = "table"` over `[wheel] model =
//! "half_space"` scenes): one row per case with the figures the 3D CSV holds, read by column name.

use super::table::Sweep;
use crate::sweep::Kind;
use std::fmt::Write as _;

/// The CSV columns shown, with their headings.
const COLUMNS: [(&str, &str); 10] = [
    ("elements_across", "elements across"),
    ("contact_count", "contact"),
    ("stick_count", "stick"),
    ("hertz_a_x_err", "a_x err"),
    ("hertz_a_y_err", "a_y err"),
    ("hertz_p0_err", "p0 err"),
    ("hertz_approach_err", "approach err"),
    ("cm_c_err_elements", "c err [elements]"),
    ("cm_transfer_err", "transfer err"),
    ("t_total", "time [s]"),
];

/// Append the table of a 3D sweep's rows to `md` (nothing for a sweep without 3D rows).
pub(super) fn table(sw: &Sweep, md: &mut String) {
    let rows: Vec<_> = sw.rows.iter().filter(|r| r.kind == Kind::Space).collect();
    if rows.is_empty() {
        return;
    }
    writeln!(
        md,
        "One row per case: the swept keys, the status, the grid's elements across Hertz's minor axis at the run's \
         load, the elements in contact and in stick at the last step, the relative errors against Hertz's ellipse \
         (semi-axes from the fit of p², peak pressure, approach) and, for a tangential load, against \
         Cattaneo–Mindlin (stick radius in elements; the shift for a prescribed force, or the force for a \
         prescribed shift), each empty where the run did \
         not compute it; the time is the case's from scratch.\n"
    )
    .unwrap();
    let keys = sw.keys.join(" | ");
    let heads: Vec<&str> = COLUMNS.iter().map(|c| c.1).collect();
    writeln!(md, "| {keys} | status | {} |", heads.join(" | ")).unwrap();
    writeln!(md, "|{}", "---|".repeat(sw.keys.len() + 1 + COLUMNS.len())).unwrap();
    for r in rows {
        let params: Vec<&str> =
            sw.keys.iter().map(|k| r.params.iter().find(|(n, _)| n == k).map_or("", |(_, v)| v.as_str())).collect();
        let cells: Vec<String> = COLUMNS
            .iter()
            .map(|(name, _)| match r.number(name) {
                Some(v) if name.ends_with("_count") => format!("{v:.0}"),
                Some(v) if *name == "elements_across" => format!("{v:.1}"),
                Some(v) => format!("{v:.2e}"),
                None => String::new(),
            })
            .collect();
        writeln!(md, "| {} | {} | {} |", params.join(" | "), r.status.name(), cells.join(" | ")).unwrap();
    }
    md.push('\n');
}
