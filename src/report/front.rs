//! The front page (`README.md` of the report): per problem family and target error the recommended method and its
//! time, one figure of every front, the verification scoreboard and what changed since the previous report. Every
//! number on it is a field of `recommendations.csv`, `fronts.csv`, the scenes' result documents (`runs/*.json`) or
//! the 3D section's table, rendered from the values the detail pages are written from ([`Summary`]): nothing is
//! computed a second way here.

use super::accuracy::{Summary, TARGETS};
use super::friction3d::Found;
use super::pages::Family;
use crate::plot::{Chart, Series, Style};
use crate::results::Report;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// The recommendations' CSV (one row per sweep, error measure, problem and target).
pub const RECOMMENDATIONS: &str = "recommendations.csv";
/// The fronts' CSV (one row per front entry).
pub const FRONTS: &str = "fronts.csv";
/// The front page's figure.
pub const FIGURE: &str = "figures/front-accuracy-vs-time.svg";

/// The header of [`RECOMMENDATIONS`].
const REC_HEADER: [&str; 11] = [
    "family",
    "sweep",
    "measure",
    "label",
    "problem",
    "target",
    "discretisation",
    "solver",
    "contact_elements",
    "error",
    "time_s",
];

/// An accuracy sweep's summaries with the family whose page holds them.
pub type Families = Vec<(Family, Summary)>;

fn csv_text(header: &[&str], rows: Vec<Vec<String>>) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).expect("in-memory CSV");
    for r in rows {
        w.write_record(&r).expect("in-memory CSV");
    }
    String::from_utf8(w.into_inner().expect("in-memory CSV")).expect("UTF-8 cells")
}

/// `recommendations.csv`: per summary and target, the chosen configuration (empty cells and `none` as the solver
/// when no entry reaches the target); errors and times at full precision.
pub fn recommendations_csv(all: &Families) -> String {
    let mut rows = Vec::new();
    for (fam, s) in all {
        for p in &s.picks {
            let head = vec![
                fam.slug().to_string(),
                s.sweep.clone(),
                s.measure.clone(),
                s.label.clone(),
                s.problem.clone(),
                format!("{:.0e}", p.target),
            ];
            let tail = match &p.chosen {
                Some(c) => vec![
                    c.discretisation.clone(),
                    c.solver.clone(),
                    c.elements.clone(),
                    format!("{:e}", c.error),
                    format!("{:e}", c.time),
                ],
                None => vec![String::new(), "none".into(), String::new(), String::new(), String::new()],
            };
            rows.push([head, tail].concat());
        }
    }
    csv_text(&REC_HEADER, rows)
}

/// `fronts.csv`: every front entry (sweep, measure, problem, error, time), fastest first within a front.
pub fn fronts_csv(all: &Families) -> String {
    let mut rows = Vec::new();
    for (_, s) in all {
        for (t, e) in &s.front {
            rows.push(vec![s.sweep.clone(), s.measure.clone(), s.problem.clone(), format!("{e:e}"), format!("{t:e}")]);
        }
    }
    csv_text(&["sweep", "measure", "problem", "error", "time_s"], rows)
}

/// The previous report's CSVs, read before this run writes anything (`None`: the file was not there).
pub struct Previous {
    recommendations: Option<Vec<Vec<String>>>,
    fronts: Option<Vec<Vec<String>>>,
}

fn read_rows(path: &Path) -> Option<Vec<Vec<String>>> {
    let mut r = csv::Reader::from_path(path).ok()?;
    let rows: Result<Vec<csv::StringRecord>, _> = r.records().collect();
    Some(rows.ok()?.iter().map(|x| x.iter().map(str::to_string).collect()).collect())
}

impl Previous {
    /// Read `out`'s CSVs as the previous run left them.
    pub fn read(out: &Path) -> Previous {
        Previous { recommendations: read_rows(&out.join(RECOMMENDATIONS)), fronts: read_rows(&out.join(FRONTS)) }
    }
}

/// A recommendation row's identity (sweep, measure, problem, target) and its choice (discretisation, elements,
/// solver, or `none`): what a change of recommendation changes. Times are left out (they differ between runs by
/// construction).
fn rec_key(r: &[String]) -> (String, String) {
    let problem = if r[4].is_empty() { String::new() } else { format!(" ({})", r[4]) };
    let choice = if r[7] == "none" {
        "none".to_string()
    } else {
        let mesh = [r[6].as_str(), r[8].as_str()].iter().filter(|x| !x.is_empty()).copied().collect::<Vec<_>>();
        format!("{} · {}", mesh.join(" "), r[7])
    };
    (format!("{} · {}{problem} at {}", r[1], r[3], r[5]), choice)
}

/// How many changed recommendations or fronts the front page lists by name (the rest are counted).
const LISTED: usize = 8;

fn parse(t: &str) -> Vec<Vec<String>> {
    csv::Reader::from_reader(t.as_bytes())
        .records()
        .filter_map(|r| r.ok().map(|x| x.iter().map(str::to_string).collect()))
        .collect()
}

/// Up to [`LISTED`] lines, then how many more.
fn listed(md: &mut String, lines: &[String]) {
    for l in lines.iter().take(LISTED) {
        writeln!(md, "- {l}").unwrap();
    }
    if lines.len() > LISTED {
        writeln!(md, "- and {} more", lines.len() - LISTED).unwrap();
    }
}

/// The "what changed" section: recommendations and front memberships (errors, not times) against the previous
/// report's CSVs; says so when there are none.
pub fn changes(prev: &Previous, recs: &str, fronts: &str) -> String {
    let mut md = String::from("## What changed since the last report\n\n");
    let Some(old) = &prev.recommendations else {
        md.push_str(
            "First report with a `recommendations.csv` in this folder (no earlier run wrote one here): nothing to \
             compare with.\n",
        );
        return md;
    };
    let old: BTreeMap<String, String> =
        old.iter().filter(|r| r.len() == REC_HEADER.len()).map(|r| rec_key(r)).collect();
    let new: BTreeMap<String, String> = parse(recs).iter().map(|r| rec_key(r)).collect();
    let moved: Vec<String> =
        new.iter().filter_map(|(k, v)| old.get(k).filter(|o| *o != v).map(|o| format!("{k}: {o} → {v}"))).collect();
    let same = new.iter().filter(|(k, v)| old.get(*k) == Some(*v)).count();
    let added = new.keys().filter(|k| !old.contains_key(*k)).count();
    let gone = old.keys().filter(|k| !new.contains_key(*k)).count();
    writeln!(
        md,
        "Recommendations (discretisation, elements and solver; times left out): {same} unchanged, {} changed, \
         {added} new, {gone} no longer computed.",
        moved.len()
    )
    .unwrap();
    listed(&mut md, &moved);
    if let Some(old_fronts) = &prev.fronts {
        let members = |rows: &[Vec<String>]| {
            let mut m: BTreeMap<String, Vec<String>> = BTreeMap::new();
            for r in rows.iter().filter(|r| r.len() == 5) {
                let problem = if r[2].is_empty() { String::new() } else { format!(" ({})", r[2]) };
                m.entry(format!("{} · {}{problem}", r[0], r[1])).or_default().push(r[3].clone());
            }
            m
        };
        let (a, b) = (members(old_fronts), members(&parse(fronts)));
        let differ: Vec<String> = b
            .iter()
            .filter_map(|(k, new)| a.get(k).filter(|old| *old != new).map(|old| format!("{k}: {}", moved_by(old, new))))
            .collect();
        let added = b.keys().filter(|k| !a.contains_key(*k)).count();
        let same = b.len() - differ.len() - added;
        writeln!(
            md,
            "\nPareto fronts (their entries' errors; times left out): {same} identical, {} moved, {added} new.",
            differ.len()
        )
        .unwrap();
        listed(&mut md, &differ);
    }
    md
}

/// How a front's entries moved: the largest relative change of an entry's error when the front kept its number of
/// entries (in order), else the counts.
fn moved_by(old: &[String], new: &[String]) -> String {
    if old.len() != new.len() {
        return format!("{} → {} entries", old.len(), new.len());
    }
    let num = |x: &String| x.parse::<f64>().ok();
    let change = old.iter().zip(new).try_fold(0.0_f64, |m, (a, b)| {
        let (a, b) = (num(a)?, num(b)?);
        Some(m.max((a - b).abs() / a.abs().max(f64::MIN_POSITIVE)))
    });
    match change {
        Some(c) => format!("the same {} entries, errors changed by at most {c:.1e} (relative)", new.len()),
        None => format!("{} entries, not all numbers", new.len()),
    }
}

/// One cell of the front page's table: `constant 50 · active_set: 8.40e-3 in 8.48e-5 s`.
fn cell(s: &Summary, target: f64) -> String {
    match s.picks.iter().find(|p| p.target == target).and_then(|p| p.chosen.as_ref()) {
        Some(c) => {
            let mesh = if c.elements.is_empty() {
                c.discretisation.clone()
            } else {
                format!("{} {}", c.discretisation, c.elements)
            };
            format!("{mesh} · {}: {:.2e} in {:.2e} s", c.solver, c.error, c.time)
        }
        None if s.measure.starts_with("disc_") => "not resolved".into(),
        None => "not reached".into(),
    }
}

/// The recommendation table: one row per (family, sweep, measure, problem), one column per target; then the 3D
/// Coulomb formulations by the same targets.
pub fn recommendation_table(all: &Families, found: &Found) -> String {
    let mut md = String::from("| family | sweep: error measure | ");
    md.push_str(&TARGETS.map(|t| format!("{t:.0e}")).join(" | "));
    md.push_str(" |\n|---|---|---|---|---|\n");
    for (fam, s) in all {
        let what = if s.problem.is_empty() { s.label.clone() } else { format!("{} ({})", s.label, s.problem) };
        let cells: Vec<String> = TARGETS.iter().map(|&t| cell(s, t)).collect();
        writeln!(md, "| [{}]({}) | {}: {what} | {} |", fam.short(), fam.page(), s.sweep, cells.join(" | ")).unwrap();
    }
    let cells: Vec<String> = found
        .picks
        .iter()
        .map(|(_, i)| match i.map(|i| &found.lines[i]) {
            Some((name, e, t)) => format!("{}: {e:.1e} in {t:.1e} s", name.split(" (").next().unwrap_or(name)),
            None => "not reached".into(),
        })
        .collect();
    writeln!(
        md,
        "| [{}]({}) | Coulomb's law, disc or pyramid: total-force error of μP | {} |",
        Family::Space3d.short(),
        Family::Space3d.page(),
        cells.join(" | ")
    )
    .unwrap();
    md
}

/// The figure: every front (relative error against total time, log–log) as a line, and the 3D Coulomb
/// formulations as markers.
pub fn figure(all: &Families, found: &Found) -> Chart {
    let mut chart = Chart::new("Accuracy against time: every Pareto front", "total time", "relative error")
        .x_unit("s")
        .y_unit("1")
        .log_x()
        .log_y()
        .size(1100, 700);
    for (_, s) in all.iter().filter(|(_, s)| !s.front.is_empty()) {
        let p = if s.problem.is_empty() { String::new() } else { format!(" ({})", s.problem) };
        // The measure's words (the recommendation table's), not its CSV column name.
        chart = chart.add(Series::new(format!("{}: {}{p}", s.sweep, s.label), s.front.clone(), Style::LineMarkers));
    }
    let pts: Vec<(f64, f64)> = found.lines.iter().filter(|l| l.1 > 0.0).map(|l| (l.2, l.1)).collect();
    if !pts.is_empty() {
        chart = chart.add(Series::new("3D Coulomb: force error, each formulation", pts, Style::Markers));
    }
    chart
}

/// Theory checks of the scenes' result documents, grouped: what a check's name says it compares with.
fn reference_of(name: &str) -> Option<&'static str> {
    if name.contains(" vs ") {
        Some("rollbem's solvers against each other")
    } else if name.contains("Hertz") {
        Some("Hertz")
    } else if name.contains("Cattaneo–Mindlin") {
        Some("Cattaneo–Mindlin")
    } else if name.contains("Carter") {
        Some("Carter")
    } else {
        None
    }
}

/// The scoreboard's row per reference: checks, passed, the worst agreement (largest error over tolerance, with
/// its error, tolerance, check and scene) — from every `figure` check of the reference scenes' documents.
pub fn scoreboard(reports: &BTreeMap<String, Report>) -> String {
    struct Worst {
        n: usize,
        passed: usize,
        ratio: f64,
        what: String,
    }
    let mut by: BTreeMap<&str, Worst> = BTreeMap::new();
    for (scene, r) in reports {
        for c in r.checks.iter().filter(|c| c.kind == crate::results::CheckKind::Figure) {
            let Some(reference) = reference_of(&c.name) else { continue };
            let w = by.entry(reference).or_insert(Worst { n: 0, passed: 0, ratio: -1.0, what: String::new() });
            w.n += 1;
            w.passed += usize::from(c.pass);
            let ratio = if c.tolerance > 0.0 { c.error / c.tolerance } else { 0.0 };
            if ratio > w.ratio {
                w.ratio = ratio;
                w.what = format!(
                    "{:.1e} (tolerance {:.1e}; {}, [{scene}](runs/{scene}.json))",
                    c.error,
                    c.tolerance,
                    c.name.replace('|', "\\|")
                );
            }
        }
    }
    let mut md = String::from(
        "| reference | checks | passed | worst agreement (error, its tolerance) | verdict |\n|---|---|---|---|---|\n",
    );
    for (reference, w) in &by {
        let verdict = if w.passed == w.n { "pass" } else { "FAIL" };
        writeln!(md, "| {reference} | {} | {} | {} | {verdict} |", w.n, w.passed, w.what).unwrap();
    }
    md
}

#[cfg(test)]
mod tests {
    use super::moved_by;

    /// A moved front says by how much (the values by hand: 1.0000001e-3 against 1e-3 is 1e-7 relative), or how its
    /// membership changed.
    #[test]
    fn a_moved_front_says_by_how_much() {
        let v = |x: &[&str]| x.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            moved_by(&v(&["1e-3", "2e-4"]), &v(&["1.0000001e-3", "2e-4"])),
            "the same 2 entries, errors changed by at most 1.0e-7 (relative)"
        );
        assert_eq!(moved_by(&v(&["1e-3", "2e-4"]), &v(&["1e-3", "2e-4", "3e-5"])), "2 → 3 entries");
    }
}
