//! The house rules, checked on the source:
//!
//! - no import circle between the library's top-level modules, nor between the sibling files (and sub-folders) of
//!   any module folder: the paths a file names through `crate::`, `super::` and `self::` (grouped `use` trees
//!   expanded; doc comments, comments and `#[cfg(test)]` items excluded) are resolved to modules, and for every
//!   folder the graph "child module → the sibling modules it names" has no cycle. A folder's own `mod.rs` (or
//!   `X.rs` beside folder `X/`) is the folder's root, not a sibling: its items (`super::write_atomic`) are not
//!   sibling references;
//! - no function of the library over 100 lines (from its `fn` line to its closing brace at the same indentation);
//! - every `#[ignore]`d test of `tests/` is run by CI (`.ci/run` runs `cargo test --release --test NAME -- --ignored`
//!   for each file that has one).

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

/// The code of a file without its comments and its `#[cfg(test)]` items (a `mod tests { … }` block up to its
/// closing brace at the attribute's indentation, or a one-line item such as `mod test_support;`).
fn code(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut kept = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let l = lines[i];
        let t = l.trim_start();
        if t.starts_with("#[cfg(test)]") {
            let indent = &l[..l.len() - t.len()];
            // Skip further attributes, then the item: to its `;` or to its closing brace.
            let mut k = i + 1;
            while k < lines.len() && lines[k].trim_start().starts_with("#[") {
                k += 1;
            }
            let item = lines.get(k).copied().unwrap_or("");
            i = if item.trim_end().ends_with(';') || item.trim_end().ends_with('}') {
                k + 1
            } else {
                let close = format!("{indent}}}");
                (k..lines.len()).find(|&j| lines[j] == close).map_or(lines.len(), |j| j + 1)
            };
            continue;
        }
        kept.push(l.split("//").next().unwrap_or(""));
        i += 1;
    }
    kept.join("\n")
}

/// The module path of a source file: `plot/chart.rs` → `plot::chart`; `plot/mod.rs` → `plot`; `lib.rs` → the
/// crate root (empty).
fn module_of(rel: &Path) -> Vec<String> {
    let mut m: Vec<String> = rel.iter().map(|s| s.to_string_lossy().into_owned()).collect();
    let last = m.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        m.push(stem.to_string());
    }
    m
}

/// Identifiers, `::`, braces and commas of some code (string literals skipped; anything else is one token `?`).
fn tokens(code: &str) -> Vec<String> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        if ch.is_alphanumeric() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(c[start..i].iter().collect());
            continue;
        }
        if ch == '"' {
            i += 1;
            while i < c.len() && c[i] != '"' {
                i += if c[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push("?".into());
            continue;
        }
        if ch == ':' && c.get(i + 1) == Some(&':') {
            out.push("::".into());
            i += 2;
            continue;
        }
        if !ch.is_whitespace() {
            out.push(if matches!(ch, '{' | '}' | ',') { ch.to_string() } else { "?".into() });
        }
        i += 1;
    }
    out
}

/// The paths of a path or `use` tree starting at token `i` (`a::b::{c, d::{e, self}}` → `a::b::c`, `a::b::d::e`,
/// `a::b::d`), and the token after it.
fn path_tree(t: &[String], mut i: usize) -> (Vec<Vec<String>>, usize) {
    let is_ident = |s: &str| s.chars().all(|ch| ch.is_alphanumeric() || ch == '_');
    let mut prefix: Vec<String> = Vec::new();
    loop {
        match t.get(i).map(String::as_str) {
            Some("{") => {
                let mut all = Vec::new();
                i += 1;
                while i < t.len() && t[i] != "}" {
                    let (subs, next) = path_tree(t, i);
                    all.extend(subs.into_iter().map(|s| [prefix.clone(), s].concat()));
                    // Skip what follows an entry and is not a path (`as name`, `*`) up to the next entry.
                    i = next;
                    while i < t.len() && t[i] != "," && t[i] != "}" {
                        i += 1;
                    }
                    if t.get(i).map(String::as_str) == Some(",") {
                        i += 1;
                    }
                }
                return (all, i + 1);
            }
            // `self` in a group names the path before the group.
            Some("self") if prefix.is_empty() && t.get(i + 1).map(String::as_str) != Some("::") => {
                return (vec![Vec::new()], i + 1)
            }
            Some(s) if is_ident(s) => {
                prefix.push(s.to_string());
                i += 1;
                if t.get(i).map(String::as_str) == Some("::") {
                    i += 1;
                    continue;
                }
                return (vec![prefix], i);
            }
            _ => return (vec![prefix], i),
        }
    }
}

/// The module paths (absolute, from the crate root) that the code of module `module` names through `crate::`,
/// `super::` and `self::`.
fn referenced_paths(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let t = tokens(code);
    let mut out = Vec::new();
    for i in 0..t.len() {
        let starts = matches!(t[i].as_str(), "crate" | "super" | "self")
            && t.get(i + 1).map(String::as_str) == Some("::")
            && (i == 0 || t[i - 1] != "::");
        if !starts {
            continue;
        }
        for p in path_tree(&t, i).0 {
            let mut base: Vec<String> = module.to_vec();
            let mut rest = p.as_slice();
            match rest.first().map(String::as_str) {
                Some("crate") => {
                    base.clear();
                    rest = &rest[1..];
                }
                Some("self") => rest = &rest[1..],
                _ => {}
            }
            while rest.first().map(String::as_str) == Some("super") {
                base.pop();
                rest = &rest[1..];
            }
            out.push([base, rest.to_vec()].concat());
        }
    }
    out
}

/// Every library source file (the binary's `main.rs` excluded) as (module path, code).
fn library() -> Vec<(Vec<String>, String)> {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    files.sort();
    files
        .into_iter()
        .filter(|f| f.strip_prefix(src()).unwrap() != Path::new("main.rs"))
        .map(|f| (module_of(f.strip_prefix(src()).unwrap()), code(&std::fs::read_to_string(&f).unwrap())))
        .collect()
}

/// The modules with child modules (the crate root included), each with its children.
fn folders(lib: &[(Vec<String>, String)]) -> BTreeMap<Vec<String>, BTreeSet<String>> {
    let mut f: BTreeMap<Vec<String>, BTreeSet<String>> = BTreeMap::new();
    for (m, _) in lib {
        for k in 0..m.len() {
            f.entry(m[..k].to_vec()).or_default().insert(m[k].clone());
        }
    }
    f
}

/// In folder `folder`: child module → the sibling modules its files name.
fn graph(lib: &[(Vec<String>, String)], folder: &[String]) -> BTreeMap<String, BTreeSet<String>> {
    let children = folders(lib).remove(folder).unwrap_or_default();
    let mut g: BTreeMap<String, BTreeSet<String>> = children.iter().map(|c| (c.clone(), BTreeSet::new())).collect();
    for (m, code) in lib {
        if m.len() <= folder.len() || !m.starts_with(folder) {
            continue;
        }
        let child = &m[folder.len()];
        for p in referenced_paths(code, m) {
            if p.len() > folder.len() && p.starts_with(folder) {
                let target = &p[folder.len()];
                if target != child && children.contains(target) {
                    g.get_mut(child).unwrap().insert(target.clone());
                }
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

/// Every circle of a folder's graph, one line each.
fn circles(g: &BTreeMap<String, BTreeSet<String>>, folder: &[String]) -> Vec<String> {
    let at = if folder.is_empty() { "crate".to_string() } else { folder.join("::") };
    g.keys().filter_map(|m| cycle(g, m).map(|c| format!("in {at}: {} → {m}", c.join(" → ")))).collect()
}

#[test]
fn the_reference_parser_reads_grouped_uses_and_paths() {
    // Expected by reading the snippet: what module `plot::chart` names, resolved from the crate root.
    let snippet = "use super::{axis::{min_max, Axis}, draw::*, write_atomic};\n\
                   use super::legend::{self, Plan as P};\n\
                   let s = \"crate::report::x\"; // crate::sweep::y\n\
                   fn f() { crate::plot::style::Rgb(0, 0, 0); self::inner::g(); super::super::theory::hertz::a(); }\n\
                   #[cfg(test)]\nmod tests {\n    use crate::pipeline::Model;\n}\n";
    let module: Vec<String> = vec!["plot".into(), "chart".into()];
    let got: BTreeSet<String> = referenced_paths(&code(snippet), &module).iter().map(|p| p.join("::")).collect();
    let want: BTreeSet<String> = [
        "plot::axis::min_max",
        "plot::axis::Axis",
        "plot::draw",
        "plot::write_atomic",
        "plot::legend",
        "plot::legend::Plan",
        "plot::style::Rgb",
        "plot::chart::inner::g",
        "theory::hertz::a",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    assert_eq!(got, want);
}

#[test]
fn no_import_circle_between_top_level_modules() {
    let lib = library();
    let g = graph(&lib, &[]);
    assert!(g.len() > 20, "the source tree was read ({} modules)", g.len());
    assert!(g.values().map(BTreeSet::len).sum::<usize>() > 50, "references between top-level modules were found");
    // The check can fail: a graph with a planted circle is caught.
    let mut planted = g.clone();
    planted.entry("scene".into()).or_default().insert("pipeline".into());
    assert!(cycle(&planted, "scene").is_some(), "a planted circle scene → pipeline → … → scene must be found");
    let found = circles(&g, &[]);
    assert!(found.is_empty(), "import circles: {found:#?}");
}

#[test]
fn no_import_circle_between_sibling_files_of_a_module() {
    let lib = library();
    let folders = folders(&lib);
    let inner: Vec<&Vec<String>> = folders.keys().filter(|f| !f.is_empty()).collect();
    assert!(inner.len() >= 10, "the module folders were found: {inner:?}");
    // Sibling references are seen: plot's chart draws with draw.rs' helpers.
    let plot = graph(&lib, &["plot".to_string()]);
    assert!(plot["chart"].contains("draw"), "plot::chart → plot::draw must be seen: {plot:?}");
    // The check can fail: a planted circle in a folder is caught.
    let mut planted = plot.clone();
    planted.get_mut("draw").unwrap().insert("chart".into());
    assert!(!circles(&planted, &["plot".to_string()]).is_empty(), "a planted circle draw → chart → draw is found");
    let mut found = Vec::new();
    for folder in inner {
        found.extend(circles(&graph(&lib, folder), folder));
    }
    assert!(found.is_empty(), "import circles between sibling files: {found:#?}");
}

/// Whether a trimmed line starts a function: `[pub[(…)]] [const] [async] [unsafe] [extern "…"] fn name`.
fn starts_fn(t: &str) -> bool {
    let mut t = t;
    if let Some(r) = t.strip_prefix("pub") {
        t = if r.starts_with('(') { r.split_once(')').map_or("", |x| x.1) } else { r };
        t = t.trim_start();
    }
    loop {
        if let Some(r) = ["const ", "async ", "unsafe "].iter().find_map(|q| t.strip_prefix(q)) {
            t = r.trim_start();
        } else if let Some(r) = t.strip_prefix("extern \"") {
            t = r.split_once('"').map_or("", |x| x.1).trim_start();
        } else {
            break;
        }
    }
    t.starts_with("fn ")
}

#[test]
fn no_function_over_100_lines() {
    assert!(starts_fn("pub(crate) const fn f() {") && starts_fn("pub(in crate::a) async fn g()"));
    assert!(!starts_fn("let fn_name = 1;") && !starts_fn("// fn f"));
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut long = Vec::new();
    let mut functions = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let t = l.trim_start();
            let indent = &l[..l.len() - t.len()];
            if !starts_fn(t) {
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
            functions += 1;
            let one_line = lines[open].trim_end().ends_with('}');
            let end =
                if one_line { Some(open) } else { (open..lines.len()).find(|&k| lines[k] == format!("{indent}}}")) };
            match end {
                Some(end) if end + 1 - i > 100 => {
                    long.push(format!("{}:{} ({} lines)", f.display(), i + 1, end + 1 - i))
                }
                Some(_) => {}
                None => long.push(format!("{}:{} (no closing brace at the fn's indentation)", f.display(), i + 1)),
            }
        }
    }
    assert!(functions > 1000, "the functions were found ({functions})");
    assert!(long.is_empty(), "functions over 100 lines: {long:#?}");
}

/// The `#[ignore]`d tests of `tests/`, by file stem (`tests/sweep.rs` → `sweep`).
fn files_with_ignored_tests() -> BTreeSet<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let mut out = BTreeSet::new();
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "rs") {
            let text = std::fs::read_to_string(&p).unwrap();
            if text.lines().any(|l| l.trim_start().starts_with("#[ignore")) {
                out.insert(p.file_stem().unwrap().to_string_lossy().into_owned());
            }
        }
    }
    out
}

#[test]
fn every_ignored_test_is_run_by_ci() {
    // An ignored test that nothing runs can rot unseen: CI (`.ci/run`) runs each file's ignored tests with
    // `cargo test --release --test NAME -- --ignored`.
    let ci = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(".ci/run")).unwrap();
    let files = files_with_ignored_tests();
    assert!(files.contains("slurm") && files.contains("sweep"), "the ignored tests were found: {files:?}");
    let run = |name: &str| {
        ci.lines().any(|l| {
            let l = l.trim_start();
            !l.starts_with('#') && l.contains(&format!("cargo test --release --test {name} -- --ignored"))
        })
    };
    let missing: Vec<&String> = files.iter().filter(|f| !run(f)).collect();
    assert!(missing.is_empty(), "ignored tests that .ci/run does not run: {missing:?}");
}
