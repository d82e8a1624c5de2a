//! The house rules, checked on the source: no import circle between the library's top-level modules (a module's
//! `crate::X` references, doc comments and tests excluded, form a graph without cycles), and no function of the
//! library over 100 lines (from its `fn` line to its closing brace at the same indentation).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The code of a file without its tests and comments.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

/// Top-level module → the top-level modules it refers to.
fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in files {
        let rel = f.strip_prefix(src()).unwrap().to_string_lossy().into_owned();
        if rel == "main.rs" || rel == "lib.rs" {
            continue;
        }
        let top = rel.split('/').next().unwrap().trim_end_matches(".rs").to_string();
        let c = code(&std::fs::read_to_string(&f).unwrap());
        let deps = g.entry(top.clone()).or_default();
        for (i, _) in c.match_indices("crate::") {
            let name: String = c[i + 7..].chars().take_while(|ch| ch.is_alphanumeric() || *ch == '_').collect();
            if name != top && !name.is_empty() {
                deps.insert(name);
            }
        }
    }
    g
}

/// A cycle through `start`, if any (depth-first).
fn cycle(g: &BTreeMap<String, BTreeSet<String>>, start: &str) -> Option<Vec<String>> {
    fn walk(
        g: &BTreeMap<String, BTreeSet<String>>,
        at: &str,
        start: &str,
        path: &mut Vec<String>,
        seen: &mut BTreeSet<String>,
    ) -> bool {
        for next in g.get(at).into_iter().flatten() {
            if next == start {
                return true;
            }
            if seen.insert(next.clone()) {
                path.push(next.clone());
                if walk(g, next, start, path, seen) {
                    return true;
                }
                path.pop();
            }
        }
        false
    }
    let mut path = vec![start.to_string()];
    let mut seen = BTreeSet::new();
    walk(g, start, start, &mut path, &mut seen).then_some(path)
}

#[test]
fn no_import_circle_between_top_level_modules() {
    let g = graph();
    assert!(g.len() > 20, "the source tree was read ({} modules)", g.len());
    // The check can fail: a graph with a planted circle is caught.
    let mut planted = g.clone();
    planted.entry("scene".into()).or_default().insert("pipeline".into());
    assert!(cycle(&planted, "scene").is_some(), "a planted circle scene → pipeline → … → scene must be found");
    for m in g.keys() {
        if let Some(c) = cycle(&g, m) {
            panic!("import circle: {} → {m}", c.join(" → "));
        }
    }
}

#[test]
fn no_function_over_100_lines() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut long = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let t = l.trim_start();
            let indent = &l[..l.len() - t.len()];
            let is_fn = ["fn ", "pub fn ", "pub(crate) fn ", "pub(super) fn ", "const fn ", "pub const fn "]
                .iter()
                .any(|p| t.starts_with(p));
            if !is_fn {
                continue;
            }
            // The body opens on this or a following line; a declaration without a body ends with `;`.
            let Some(open) = (i..lines.len()).find(|&k| lines[k].contains('{') || lines[k].trim_end().ends_with(';'))
            else {
                continue;
            };
            if !lines[open].contains('{') {
                continue;
            }
            let one_line = lines[open].trim_end().ends_with('}');
            let end = if one_line {
                open
            } else {
                (open..lines.len()).find(|&k| lines[k] == format!("{indent}}}")).unwrap_or(open)
            };
            if end + 1 - i > 100 {
                long.push(format!("{}:{} ({} lines)", f.display(), i + 1, end + 1 - i));
            }
        }
    }
    assert!(long.is_empty(), "functions over 100 lines: {long:#?}");
}
