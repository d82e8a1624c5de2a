//! What the tests of the `sweep` command share (`tests/sweep_resume.rs`, `tests/sweep_soak.rs`, `tests/slurm.rs`,
//! included with `#[path]`): the binary, files, the journal's path, a CSV with its timing columns masked, and the
//! peak memory a run reports.

#![allow(dead_code)]

#[path = "paired.rs"]
mod paired;
use paired::paired;
use rollbem::sweep::PROVENANCE_COLUMNS;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The journal of an output: `OUT.partial`.
pub fn partial(out: &Path) -> PathBuf {
    PathBuf::from(format!("{}.partial", out.display()))
}

/// The header and the rows of a CSV with the timing columns blanked.
pub fn masked(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut r = csv::Reader::from_path(path).unwrap();
    let h: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    let rows = r
        .records()
        .map(|x| {
            let x = x.unwrap();
            paired(x.iter().collect::<Vec<_>>(), &h)
                .map(|(c, n)| if PROVENANCE_COLUMNS.contains(&n.as_str()) { String::new() } else { c.to_string() })
                .collect()
        })
        .collect();
    (h, rows)
}

/// The peak memory (MB) in a sweep's closing line (`...; peak memory 8.4 MB)`).
pub fn peak_mb(stdout: &str) -> f64 {
    let at = stdout.find("peak memory ").expect("the closing line says the peak memory") + "peak memory ".len();
    stdout[at..].split_whitespace().next().unwrap().parse().unwrap()
}

/// Run a command to success and return its standard output; a failure shows both outputs.
pub fn run(cmd: &mut Command) -> String {
    let o = cmd.output().unwrap();
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{cmd:?} failed: {out}\n{err}");
    out.into_owned()
}

/// Start a sweep (`cmd`, writing `out`) and SIGKILL it once its journal holds `bytes` bytes (or, with `bytes` = 0,
/// after `delay_ms`: possibly while it validates). Returns whether it was still running when killed.
pub fn kill_at(cmd: &mut Command, out: &Path, bytes: u64, delay_ms: u64) -> bool {
    let mut child = cmd.stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
    let journal = partial(out);
    if bytes == 0 {
        std::thread::sleep(Duration::from_millis(delay_ms));
    } else {
        while std::fs::metadata(&journal).map_or(0, |m| m.len()) < bytes {
            if child.try_wait().unwrap().is_some() {
                return false;
            }
            std::thread::sleep(Duration::from_micros(200));
        }
    }
    let running = child.try_wait().unwrap().is_none();
    child.kill().unwrap();
    child.wait().unwrap();
    running
}
