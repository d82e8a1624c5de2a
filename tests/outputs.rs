//! Output targets of the command line (`rollbem::io`): `-` is standard output, a FIFO is written through (never
//! replaced by a regular file), a symbolic link is followed (the link stays a link), a link to nothing is refused
//! with exit code 3 and nothing created. No test writes to a device file.

use std::path::Path;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

fn scene() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml")
}

#[test]
fn json_dash_prints_the_document_and_the_table_goes_to_stderr() {
    let o = bin().args(["run", "--quiet", "--json", "-"]).arg(scene()).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let doc = rollbem::results::Report::from_json(&String::from_utf8_lossy(&o.stdout), Path::new("<stdout>"))
        .expect("stdout is exactly one result document");
    assert_eq!(doc.scene.name(), "half-plane-hertz");
    assert!(String::from_utf8_lossy(&o.stderr).contains("checks:"), "the table goes to stderr");
    // Two outputs cannot share standard output.
    let o = bin().args(["run", "--json", "-", "--csv", "-"]).arg(scene()).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_fifo_is_written_through_and_stays_a_fifo() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("out.json");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    // The reader runs beside the command (opening a FIFO for writing waits for a reader).
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let o = bin().args(["run", "--quiet", "--json"]).arg(&fifo).arg(scene()).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let text = reader.join().unwrap();
    assert!(rollbem::results::Report::from_json(&text, &fifo).is_ok(), "the reader got the document");
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "still a FIFO");
}

#[test]
fn a_symlink_is_followed_and_a_dangling_one_refused() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("real.json");
    std::fs::write(&target, "old").unwrap();
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let o = bin().args(["run", "--quiet", "--json"]).arg(&link).arg(scene()).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link stays a link");
    assert!(rollbem::results::Report::read(&target).is_ok(), "its target holds the document");

    let dangling = dir.path().join("dangling.json");
    std::os::unix::fs::symlink(dir.path().join("nowhere/x.json"), &dangling).unwrap();
    let o = bin().args(["run", "--quiet", "--json"]).arg(&dangling).arg(scene()).output().unwrap();
    assert_eq!(o.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&o.stderr).contains("does not exist"));
    assert!(!dir.path().join("nowhere").exists(), "nothing created");
}
