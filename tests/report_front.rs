//! The report's front page (issue 35): at most about 1 500 words, every recommendation on it a row of
//! `recommendations.csv` and the same as its family page's, and a second run leaves only files it wrote.
//!
//! Checked on two reports: one generated here from a small reference folder (a half-plane Hertz sweep and a
//! finite-wheel Cattaneo–Mindlin sweep, seconds), and the committed `reports/` that `rollbem report` wrote from
//! `reference/` (the page a reader opens; regenerated with every change of the report).
//!
//! **How words are counted** ([`words`]): everything a reader reads counts, numbers in table cells included. Not
//! counted: link and image addresses (the `(target)` of `[text](target)`: the reader reads the text), table
//! separator lines (`|---|`), and Markdown markup characters (`|`, `#`, `*`, backticks), which are replaced by
//! spaces. The rest is split on whitespace; every token is a word (`8.40e-3`, `·` and `constant` alike).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The words a reader reads on a Markdown page (the module docs define the count).
fn words(md: &str) -> usize {
    let mut text = String::new();
    for line in md.lines() {
        let t = line.trim();
        if t.starts_with('|') && t.chars().all(|c| matches!(c, '|' | '-' | ':' | ' ')) {
            continue;
        }
        // Drop every link target: "](…)" up to its closing parenthesis.
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            text.push_str(&rest[..i]);
            text.push(' ');
            rest = &rest[i + 2..];
            rest = rest.find(')').map_or("", |j| &rest[j + 1..]);
        }
        text.push_str(rest);
        text.push('\n');
    }
    let text: String =
        text.chars().map(|c| if matches!(c, '|' | '#' | '*' | '`' | '[' | ']' | '!') { ' ' } else { c }).collect();
    text.split_whitespace().count()
}

#[test]
fn the_word_count_counts_what_a_reader_reads() {
    // Hand count: "See" "the" "table" "a" "b" "1.0e-3" "x" — the address and the separator line are not read.
    let md = "## See [the table](families/hertz.md)\n\n| a | b |\n|---|---|\n| 1.0e-3 | **x** |\n";
    assert_eq!(words(md), 7);
}

const SCENE: &str = r#"name = "pad-hertz"
[wheel]
radius = 460.0
youngs_modulus = 210000.0
poisson_ratio = 0.3
model = "half_plane"
[mesh]
element = "constant"
contact_half_width = 9.0
contact_elements = 40
[drive]
normal_load = 20000.0
[solvers]
use = ["lemke", "active_set"]
"#;

const HERTZ_SWEEP: &str = r#"name = "pad-mesh-study"
description = "pad mesh study, two direct solvers"
analysis = "accuracy"
base = "../scenes/pad.toml"
[[grid]]
"mesh.contact_elements" = [25, 50, 100, 200]
"solvers.use" = [["lemke"], ["active_set"]]
"#;

const CM_SWEEP: &str = r#"name = "cm-mesh"
description = "Cattaneo-Mindlin stick zone against the mesh"
analysis = "accuracy"
base = "../scenes/cattaneo-decoupled.toml"
[[grid]]
"mesh.contact_elements" = [15, 30, 60, 120, 240]
"solvers.use" = [["lemke"], ["active_set"]]
"#;

fn write(p: &Path, text: &str) {
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}

/// `rollbem report --reference REFS --out OUT`, which must succeed; returns its standard error.
fn report(refs: &Path, out: &Path) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(["report", "--reference"])
        .arg(refs)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    err
}

/// A small reference folder: the pad scene and the Cattaneo–Mindlin reference scene with their sweeps, and the 3D
/// Hertz ellipse with its convergence sweep.
fn small_refs(dir: &Path) -> PathBuf {
    let refs = dir.join("refs");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    write(&refs.join("scenes/pad.toml"), SCENE);
    let cm = std::fs::read_to_string(root.join("reference/scenes/cattaneo-decoupled.toml")).unwrap();
    write(&refs.join("scenes/cattaneo-decoupled.toml"), &cm);
    write(&refs.join("sweeps/hertz.toml"), HERTZ_SWEEP);
    write(&refs.join("sweeps/cm.toml"), CM_SWEEP);
    // A 3D sweep (4 grids, about a second): its fronts come from the same rule.
    let ellipse = std::fs::read_to_string(root.join("reference/scenes/half-space/hertz-ellipse.toml")).unwrap();
    write(&refs.join("scenes/half-space/hertz-ellipse.toml"), &ellipse);
    let sweep = std::fs::read_to_string(root.join("reference/sweeps/hertz3d-convergence.toml")).unwrap();
    write(&refs.join("sweeps/hertz3d-convergence.toml"), &sweep);
    refs
}

/// The committed report (`reports/` at the repository's root).
fn committed() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reports")
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The cells of a Markdown table row.
fn cells(row: &str) -> Vec<String> {
    let t = row.trim().trim_start_matches('|').trim_end_matches('|');
    t.split(" | ").map(|c| c.trim().to_string()).collect()
}

/// The front page's recommendation rows: (family page, "sweep: what", [cell per target]).
fn front_rows(front: &str) -> Vec<(String, String, Vec<String>)> {
    let start = front.find("| family | sweep: error measure | 1e-2 | 1e-3 | 1e-4 |").expect("the table");
    front[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let c = cells(l);
            let page = c[0].split("](").nth(1).unwrap().trim_end_matches(')').to_string();
            (page, c[1].clone(), c[2..].to_vec())
        })
        .collect()
}

/// `recommendations.csv` as maps of column to cell.
fn csv_rows(path: &Path) -> Vec<BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let head: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    r.records().map(|x| head.iter().cloned().zip(x.unwrap().iter().map(str::to_string)).collect()).collect()
}

/// The CSV row a front-page row and target come from: its sweep, and its label (with the problem in brackets
/// when the sweep poses several).
fn csv_row<'a>(rows: &'a [BTreeMap<String, String>], what: &str, target: &str) -> &'a BTreeMap<String, String> {
    rows.iter()
        .find(|r| {
            let label =
                if r["problem"].is_empty() { r["label"].clone() } else { format!("{} ({})", r["label"], r["problem"]) };
            format!("{}: {label}", r["sweep"]) == what && r["target"] == target
        })
        .unwrap_or_else(|| panic!("no recommendations.csv row for {what} at {target}"))
}

const TARGETS: [&str; 3] = ["1e-2", "1e-3", "1e-4"];

/// A mesh as the front page names it: the discretisation and its contact elements (3D grids have no element
/// count: their discretisation label names the grid).
fn mesh(discretisation: &str, elements: &str) -> String {
    if elements.is_empty() {
        discretisation.to_string()
    } else {
        format!("{discretisation} {elements}")
    }
}

/// Every recommendation cell of the front page is its CSV row: discretisation, elements, solver, and the error and
/// time to the digits shown; a cell without one says so and its row's solver is `none`.
fn check_traceable(out: &Path) -> usize {
    let front = read(&out.join("README.md"));
    let rows = csv_rows(&out.join("recommendations.csv"));
    let mut checked = 0;
    for (page, what, cells) in front_rows(&front).iter().filter(|r| !r.1.starts_with("Coulomb")) {
        assert!(page.starts_with("families/"), "{page}");
        for (cell, target) in cells.iter().zip(TARGETS) {
            let r = csv_row(&rows, what, target);
            if r["solver"] == "none" {
                assert!(cell == "not reached" || cell == "not resolved", "{what} {target}: {cell}");
                continue;
            }
            let num = |k: &str| r[k].parse::<f64>().unwrap();
            let expected = format!(
                "{} · {}: {:.2e} in {:.2e} s",
                mesh(&r["discretisation"], &r["contact_elements"]),
                r["solver"],
                num("error"),
                num("time_s")
            );
            assert_eq!(cell, &expected, "{what} at {target}");
            checked += 1;
        }
    }
    checked
}

/// The family page's recommendation for a sweep, measure label, problem and target: the cells of its
/// "Recommended" row (target, recommended, solver, elements, error, time, alternatives).
fn detail_row(page: &str, sweep: &str, what: &str, target: &str) -> Option<Vec<String>> {
    let at = page.find(&format!("### {sweep} ("))?;
    let section = &page[at..];
    let section = &section[..section[4..].find("\n### ").map_or(section.len(), |i| i + 4)];
    // `what` is "label" or "label (problem)": the measure's heading, then the problem's when there is one.
    let (measure, rest) = section
        .match_indices("#### ")
        .map(|(i, _)| {
            let line = section[i + 5..].lines().next().unwrap();
            (line, &section[i..])
        })
        .find(|(line, _)| what == *line || what.starts_with(&format!("{line} (")))?;
    let rest = if what == measure {
        rest
    } else {
        let problem = &what[measure.len() + 2..what.len() - 1];
        &rest[rest.find(&format!("##### {problem}\n"))?..]
    };
    let table = &rest[rest.find("Recommended (")?..];
    table.lines().filter(|l| l.starts_with("| 1e")).map(cells).find(|c| c[0].split(", ").any(|t| t == target))
}

/// Every front-page recommendation is the row its family page derives for the same sweep, measure, problem and
/// target; the 3D Coulomb row is the line of the 3D page's table it names.
fn check_same_as_detail(out: &Path) -> usize {
    let front = read(&out.join("README.md"));
    let mut checked = 0;
    for (page, what, cells) in front_rows(&front) {
        let detail = read(&out.join(&page));
        if what.starts_with("Coulomb") {
            for cell in cells.iter().filter(|c| *c != "not reached") {
                let (name, figures) = cell.split_once(": ").unwrap();
                let (err, time) = figures.trim_end_matches(" s").split_once(" in ").unwrap();
                let line = detail.lines().find(|l| l.starts_with(&format!("| {name} "))).expect(cell);
                let c = cells_of(line);
                assert_eq!((c[1].as_str(), c[3].as_str()), (err, time), "{cell} against {line}");
                checked += 1;
            }
            continue;
        }
        let (sweep, label) = what.split_once(": ").unwrap();
        for (cell, target) in cells.iter().zip(TARGETS) {
            let row = detail_row(&detail, sweep, label, target)
                .unwrap_or_else(|| panic!("{page} has no recommendation for {what} at {target}"));
            if cell == "not reached" || cell == "not resolved" {
                assert!(row[1].starts_with(&cell.to_string()), "{what} {target}: {cell} against {row:?}");
                continue;
            }
            let time = row[5].split(' ').next().unwrap();
            let expected = format!("{} · {}: {} in {} s", mesh(&row[1], &row[3]), row[2], row[4], time);
            assert_eq!(cell, &expected, "{what} at {target}");
            checked += 1;
        }
    }
    checked
}

fn cells_of(line: &str) -> Vec<String> {
    cells(line)
}

#[test]
fn a_small_report_front_page_is_traceable_and_agrees_with_its_pages() {
    let tmp = tempfile::tempdir().unwrap();
    let refs = small_refs(tmp.path());
    let out = tmp.path().join("out");
    report(&refs, &out);
    let front = read(&out.join("README.md"));
    assert!(check_traceable(&out) >= 3, "{front}");
    assert!(check_same_as_detail(&out) >= 3, "{front}");
    assert!(words(&front) <= 1500, "{} words", words(&front));
    assert!(front.contains("First report with a `recommendations.csv`"), "{front}");
    // A second run compares with the first's CSVs: every recommendation of the same inputs is there again (none
    // new, none gone), each unchanged or changed (single timings here: a solver tied in time may change), and the
    // counts add up to the CSV's rows; every front is there again.
    report(&refs, &out);
    let again = read(&out.join("README.md"));
    let line = again.lines().find(|l| l.starts_with("Recommendations (")).expect(&again);
    let counts: Vec<usize> =
        line.split(": ").nth(1).unwrap().split(", ").map(|c| c.split(' ').next().unwrap().parse().unwrap()).collect();
    let rows = csv_rows(&out.join("recommendations.csv")).len();
    assert_eq!((counts[0] + counts[1], counts[2], counts[3]), (rows, 0, 0), "{line}");
    let fronts = again.lines().find(|l| l.starts_with("Pareto fronts (")).expect(&again);
    assert!(fronts.ends_with(", 0 new."), "{fronts}");
}

#[test]
fn the_committed_front_page_is_short_traceable_and_agrees_with_its_pages() {
    let out = committed();
    let front = read(&out.join("README.md"));
    let n = words(&front);
    eprintln!("reports/README.md: {n} words");
    assert!(n <= 1500, "the front page has {n} words");
    for family in ["Hertz", "Cattaneo–Mindlin", "Carter", "load paths", "stresses", "3D half-space"] {
        assert!(front.contains(&format!("[{family}](families/")), "{family} is not on the front page");
    }
    assert!(check_traceable(&out) >= 10);
    assert!(check_same_as_detail(&out) >= 10);
}

/// Every relative link of every page under `out` resolves to a file or folder.
fn check_links(out: &Path) {
    let mut pages = vec![out.join("README.md"), out.join("methods.md"), out.join("solvers.md")];
    for d in ["families", "peers"] {
        if let Ok(rd) = std::fs::read_dir(out.join(d)) {
            pages.extend(rd.map(|e| e.unwrap().path()));
        }
    }
    for page in pages {
        let md = read(&page);
        for part in md.split("](").skip(1) {
            let target = part[..part.find(')').unwrap()].split('#').next().unwrap();
            if target.is_empty() || target.starts_with("http") {
                continue;
            }
            let p = page.parent().unwrap().join(target);
            assert!(p.exists(), "{}: link to {target} does not resolve", page.display());
        }
    }
    // The HTML site: one file per page, every href resolving, the figures inline.
    let mut html = Vec::new();
    let mut stack = vec![out.join("html")];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                html.push(p);
            }
        }
    }
    assert!(html.iter().any(|p| p.ends_with("html/index.html")), "{html:?}");
    for page in html {
        let text = read(&page);
        for part in text.split("href=\"").skip(1) {
            let target = part[..part.find('"').unwrap()].split('#').next().unwrap();
            if target.is_empty() || target.starts_with("http") {
                continue;
            }
            let p = page.parent().unwrap().join(target);
            assert!(p.exists(), "{}: link to {target} does not resolve", page.display());
        }
    }
    let index = read(&out.join("html/index.html"));
    assert!(index.contains("<figure><svg"), "the front page's figure is inline");
}

/// `rollbem report` run twice: files planted between the runs in the folders it owns are gone, a file the folder's
/// user put at its top is left and named, the peer tables (declared inputs) stay, a symbolic link to a folder
/// outside is removed as a link without touching what it points to, every remaining file is in the manifest or
/// a declared input, and every link of every page resolves.
#[cfg(unix)]
#[test]
fn a_second_run_leaves_only_what_it_wrote() {
    let tmp = tempfile::tempdir().unwrap();
    let refs = small_refs(tmp.path());
    let out = tmp.path().join("out");
    report(&refs, &out);
    let outside = tmp.path().join("outside");
    write(&outside.join("precious.svg"), "<svg/>");
    for stale in ["figures/old-sweep-hertz_l2_err-vs-time.svg", "sweeps/old-sweep.csv", "families/retired.md"] {
        write(&out.join(stale), "stale");
    }
    write(&out.join("notes.txt"), "mine");
    write(&out.join("peer-contact.md"), "| input | elements |\n|---|---:|\n| carter2d | 55 |\n");
    std::os::unix::fs::symlink(&outside, out.join("figures/elsewhere")).unwrap();
    let err = report(&refs, &out);
    for stale in ["figures/old-sweep-hertz_l2_err-vs-time.svg", "sweeps/old-sweep.csv", "families/retired.md"] {
        assert!(!out.join(stale).exists(), "{stale} survived");
    }
    assert!(std::fs::symlink_metadata(out.join("figures/elsewhere")).is_err(), "the link stays");
    assert!(outside.join("precious.svg").exists(), "a file outside the folder was touched");
    assert!(out.join("notes.txt").exists() && err.contains("notes.txt"), "{err}");
    assert!(out.join("peer-contact.md").exists());
    assert!(read(&out.join("peers/contact-2d.md")).contains("| carter2d | 55 |"));
    let manifest = read(&out.join("MANIFEST"));
    let listed: Vec<&str> = manifest.lines().collect();
    let mut stack = vec![out.clone()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let rel = p.strip_prefix(&out).unwrap().to_string_lossy().to_string();
            assert!(
                listed.contains(&rel.as_str()) || rel == "peer-contact.md" || rel == "notes.txt",
                "{rel} is neither written nor an input"
            );
        }
    }
    check_links(&out);
    check_links(&committed());
}
