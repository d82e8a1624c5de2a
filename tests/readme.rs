//! The README's worked example is a tested artefact (issue 12, item 11): the command it shows is run and its output
//! compared, line by line, with the block in the README. Only the two timing columns of the solver table are masked
//! (the machine decides them) and the solver table's rows are compared cell by cell (their column widths are not);
//! every other line must match character for character. The README block may end with a line `  ...` after which
//! the remaining output lines are not shown.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use std::path::Path;
use std::process::Command;

const COMMAND: &str = "$ rollbem run reference/scenes/hertz-hub-fine.toml --json hertz.json";

/// Mask the timing columns (`solve [s]`, `total [s]`) of the solver table's rows (other cells compared as words): the lines after the header that starts with
/// `solver` and before `checks:`.
fn mask(lines: &[String]) -> Vec<String> {
    let mut in_table = false;
    lines
        .iter()
        .map(|l| {
            if l.starts_with("solver ") {
                in_table = true;
                return l.clone();
            }
            if l.starts_with("checks:") {
                in_table = false;
            }
            if in_table && !l.starts_with(' ') {
                // The two timing columns, `solve [s]` and `total [s]`.
                let mut t: Vec<&str> = l.split_whitespace().collect();
                let n = t.len().saturating_sub(2);
                t.truncate(n);
                format!("{} <solve> <total>", t.join(" "))
            } else {
                l.trim_end().to_string()
            }
        })
        .collect()
}

#[test]
fn readme_worked_example_output_is_what_rollbem_prints() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let start = readme.find(&format!("```text\n{COMMAND}\n")).expect("the worked example block in README.md");
    let body = &readme[start + "```text\n".len() + COMMAND.len() + 1..];
    let block: Vec<String> = body[..body.find("```").unwrap()].lines().map(String::from).collect();
    let (shown, elided) = match block.iter().position(|l| l.trim() == "...") {
        Some(k) => (block[..k].to_vec(), true),
        None => (block.clone(), false),
    };

    let tmp = tempfile::tempdir().unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .current_dir(root)
        .args(["run", "reference/scenes/hertz-hub-fine.toml", "--json"])
        .arg(tmp.path().join("hertz.json"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let actual: Vec<String> = String::from_utf8(o.stdout).unwrap().lines().map(String::from).collect();
    assert!(tmp.path().join("hertz.json").exists());

    let (want, got) = (mask(&shown), mask(&actual));
    if elided {
        assert!(got.len() > want.len(), "the README elides lines, but the output has no more");
    } else {
        assert_eq!(got.len(), want.len(), "line count: the README block is stale");
    }
    // The README's lines against the head of the output (all of it unless the README elides lines).
    for (k, (w, g)) in paired(&want, &got[..want.len()]).enumerate() {
        assert_eq!(w, g, "README worked example, line {}: stale (update the block from the command's output)", k + 1);
    }
}

/// Every flag of every command, as `rollbem <command> --help` lists it, is in the README's table "Every command and
/// its flags" (issue 19, item 9). Expected: clap's own help of the built binary (an independent listing).
#[test]
fn readme_documents_every_flag_of_every_command() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let start = readme.find("## Every command and its flags").expect("the README's command table");
    let table = &readme[start..start + readme[start..].find("\n### ").unwrap()];
    let commands: &[&[&str]] = &[
        &["run"],
        &["check"],
        &["solvers"],
        &["sweep"],
        &["sweep-merge"],
        &["fastsim"],
        &["report"],
        &["plot"],
        &["lcp", "export"],
        &["lcp", "solve"],
    ];
    let mut seen = 0;
    for cmd in commands {
        assert!(table.contains(&format!("`rollbem {}", cmd.join(" "))), "command {cmd:?} not in the table");
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rollbem")).args(*cmd).arg("--help").output().unwrap();
        assert!(out.status.success());
        let help = String::from_utf8(out.stdout).unwrap();
        for flag in help.split_whitespace().filter(|w| w.starts_with("--")) {
            let flag = flag.trim_end_matches([',', '.', ')']);
            let flag = flag.split(['=', '<']).next().unwrap();
            if flag.len() > 2 && flag.chars().skip(2).all(|c| c.is_ascii_lowercase() || c == '-') {
                assert!(table.contains(&format!("`{flag}")), "{flag} of `rollbem {}` not in the README", cmd.join(" "));
                seen += 1;
            }
        }
    }
    assert!(seen >= 20, "only {seen} flags found in the help texts");
}
