//! The files of a running sweep: its **journal**, where every case's rows are appended as the case finishes, and
//! the **sorted write** that turns a journal (or several shard CSVs: `sweep-merge`) into the sweep's CSV.
//!
//! A journal is the sweep's CSV in the order its cases finished, under a first line that says what it is
//! ([`MARKER`]) and a second that says which cases it is of ([`super::identity`]), beside the output
//! (`OUT.partial`). Each case's rows go in one write of whole lines, sorted by solver;
//! the file is never rewritten in place, only appended to, and synced to disk every few seconds, so a run killed at
//! any point leaves the rows of every case it finished, then at most one case cut short — the last one written,
//! possibly missing rows or ending in a cut line. `--resume` therefore drops the journal's last case (and a cut last
//! line) and runs it again ([`super::plan`]).
//!
//! Rows are single lines: no cell holds a line break (messages are written on one line and the spec refuses grid
//! values with one), so the last line break of a file is where its complete rows end.
//!
//! The sorted write reads the files block by block — a block is the consecutive rows of one case — and keeps only
//! the blocks' places (24 bytes a case), never the rows: a sweep of any size is sorted in bounded memory. Its output
//! follows the rules of [`crate::io`]: a regular file is written to a temporary file beside it and renamed over it,
//! a FIFO or device is written through, `-` is standard output, a symbolic link is followed.

use super::identity::IDENTITY_PREFIX;
use super::row::{Header, RowStatus, SweepRow};
use crate::error::{Error, Result};
use std::fs::{File, OpenOptions};
use std::io::{BufRead, BufReader, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The first line of a journal.
pub const MARKER: &str =
    "# rollbem sweep journal: the rows of a sweep not yet finished, in the order its cases finished \
     (`rollbem sweep --resume` continues it)";

/// How often a journal is synced to disk (a kill loses nothing written; a crash of the machine, at most this).
const SYNC_EVERY: Duration = Duration::from_secs(2);

fn write_err(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |source| Error::Write { path: path.to_path_buf(), source }
}

fn read_err(path: &Path) -> impl Fn(std::io::Error) -> Error + '_ {
    move |source| Error::Io { path: path.to_path_buf(), source }
}

/// The CSV text of rows under a header of swept keys `keys`, one line each.
fn csv_lines(keys: &[String], rows: &[SweepRow]) -> Vec<u8> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.write_record(r.record(keys)).expect("writing to memory");
    }
    w.into_inner().expect("writing to memory")
}

/// A journal open for appending.
#[derive(Debug)]
pub struct Journal {
    file: File,
    path: PathBuf,
    keys: Vec<String>,
    synced: Instant,
}

impl Journal {
    /// A new journal (an old one at `path` is replaced): the marker, the sweep's identity line
    /// ([`super::identity::Identity::line`]) and the header. Written to a temporary file renamed into place, so a
    /// journal always has all three.
    pub fn create(path: &Path, keys: &[String], kind: super::Kind, identity: &str) -> Result<Journal> {
        let werr = write_err(path);
        let mut name = path.as_os_str().to_owned();
        name.push(format!(".tmp-{}", std::process::id()));
        let tmp = PathBuf::from(name);
        let made = (|| {
            let mut file = File::create(&tmp).map_err(&werr)?;
            let mut w = csv::Writer::from_writer(Vec::new());
            w.write_record(super::row::header_of(keys, kind)).expect("writing to memory");
            let head =
                [format!("{MARKER}\n{identity}").into_bytes(), w.into_inner().expect("writing to memory")].concat();
            file.write_all(&head).map_err(&werr)?;
            file.sync_data().map_err(&werr)?;
            std::fs::rename(&tmp, path).map_err(&werr)
        })();
        if made.is_err() {
            let _ = std::fs::remove_file(&tmp);
        }
        made?;
        let file = OpenOptions::new().append(true).open(path).map_err(&werr)?;
        Ok(Journal { file, path: path.to_path_buf(), keys: keys.to_vec(), synced: Instant::now() })
    }

    /// Reopen a journal to append after its first `keep` bytes (what follows them, a case that may be incomplete
    /// and a cut line, is removed).
    pub fn reopen(path: &Path, keys: &[String], keep: u64) -> Result<Journal> {
        let werr = write_err(path);
        let file = OpenOptions::new().append(true).open(path).map_err(&werr)?;
        file.set_len(keep).and_then(|_| file.sync_data()).map_err(&werr)?;
        Ok(Journal { file, path: path.to_path_buf(), keys: keys.to_vec(), synced: Instant::now() })
    }

    /// Append one case's rows (sorted by solver), in one write.
    pub fn append(&mut self, rows: &[SweepRow]) -> Result<()> {
        let werr = write_err(&self.path);
        self.file.write_all(&csv_lines(&self.keys, rows)).map_err(&werr)?;
        if self.synced.elapsed() >= SYNC_EVERY {
            self.file.sync_data().map_err(&werr)?;
            self.synced = Instant::now();
        }
        Ok(())
    }

    /// Sync what was appended.
    pub fn finish(self) -> Result<()> {
        self.file.sync_data().map_err(write_err(&self.path))
    }
}

/// The consecutive rows of one case in a file, by byte range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Block {
    /// The case.
    pub case: u32,
    /// Which of the files being read.
    pub file: u32,
    /// Byte offset of its first row.
    pub start: u64,
    /// Byte offset just after its last row.
    pub end: u64,
}

/// What a scan found besides the blocks.
#[derive(Debug, Clone)]
pub struct Scanned {
    /// The header.
    pub header: Header,
    /// Whether the file ends in a cut line (not ending with a line break), left out of the blocks.
    pub cut: bool,
    /// Where the header ends (the first block's start, or the file's complete lines' end when it has no row).
    pub rows_start: u64,
}

/// A journal's identity line (its second line, without the line break), or `None` when it has none (a journal of
/// an older rollbem). Reads the first two lines only.
pub fn read_identity(path: &Path) -> Result<Option<String>> {
    let rerr = read_err(path);
    let mut input = BufReader::new(File::open(path).map_err(&rerr)?);
    let mut line = Vec::new();
    for _ in 0..2 {
        line.clear();
        input.read_until(b'\n', &mut line).map_err(&rerr)?;
    }
    let text = String::from_utf8_lossy(&line);
    Ok(text.strip_suffix('\n').filter(|l| l.starts_with(IDENTITY_PREFIX)).map(str::to_string))
}

/// The offset just after the last line break of a file of `len` bytes (0 without one).
fn complete_len(file: &mut File, len: u64) -> std::io::Result<u64> {
    let mut end = len;
    let mut buf = vec![0u8; 64 * 1024];
    while end > 0 {
        let from = end.saturating_sub(buf.len() as u64);
        let chunk = &mut buf[..(end - from) as usize];
        file.seek(SeekFrom::Start(from))?;
        file.read_exact(chunk)?;
        if let Some(k) = chunk.iter().rposition(|&b| b == b'\n') {
            return Ok(from + k as u64 + 1);
        }
        end = from;
    }
    Ok(0)
}

/// Read a sweep CSV (`journal` false) or a journal (true) block by block, each block's rows read typed (a row that
/// does not read is an error naming its line) and handed to `each` with the block, never kept. A cut last line is
/// left out and said (`Scanned::cut`); a journal given as a CSV, or a CSV as a journal, is an error, and so is a
/// header other than `expect` when one is given.
pub fn scan(
    path: &Path,
    file_no: u32,
    journal: bool,
    expect: Option<&[String]>,
    mut each: impl FnMut(Block, &[SweepRow]) -> Result<()>,
) -> Result<Scanned> {
    let rerr = read_err(path);
    let mut file = File::open(path).map_err(&rerr)?;
    let len = file.metadata().map_err(&rerr)?.len();
    let complete = complete_len(&mut file, len).map_err(&rerr)?;
    file.seek(SeekFrom::Start(0)).map_err(&rerr)?;
    let mut input = BufReader::new(file.take(complete));
    let bad = |message: String| Error::Parse { path: path.to_path_buf(), message };
    let mut first = Vec::new();
    let marked = input.fill_buf().map_err(&rerr)?.starts_with(b"# rollbem sweep journal");
    let mut offset = 0;
    let mut identity = None;
    if marked {
        offset = input.read_until(b'\n', &mut first).map_err(&rerr)? as u64;
        if input.fill_buf().map_err(&rerr)?.starts_with(IDENTITY_PREFIX.as_bytes()) {
            let mut line = Vec::new();
            offset += input.read_until(b'\n', &mut line).map_err(&rerr)? as u64;
            identity = Some(String::from_utf8_lossy(&line).trim_end_matches('\n').to_string());
        }
    }
    match (journal, marked) {
        (true, false) => return Err(bad("not a sweep journal: its first line is not the journal's".into())),
        (false, true) => {
            return Err(bad("a sweep's journal, not its CSV: the sweep has not finished (it is running, or was \
                            stopped); finish it with `rollbem sweep --resume`"
                .into()))
        }
        _ => {}
    }
    let mut rd = csv::Reader::from_reader(input);
    let perr = |e: csv::Error| bad(e.to_string());
    let names: Vec<String> = rd.headers().map_err(perr)?.iter().map(str::to_string).collect();
    if let Some(want) = expect.filter(|h| *h != names) {
        let kind = |n: &[String]| Header::parse(n, path).map(|h| h.kind).ok();
        let why = match (kind(&names), kind(want)) {
            (Some(theirs), Some(ours)) if theirs != ours => format!(
                "its columns are those of a sweep of {}, this sweep's cases are {}: it was written by another sweep",
                theirs.describe(),
                ours.describe()
            ),
            _ => "its columns are not this sweep's: it was written for another sweep spec or version of rollbem".into(),
        };
        return Err(super::invalid(path, "header", why));
    }
    let header = Header::parse(&names, path)?;
    let rows_start = offset + rd.position().byte();
    let mut record = csv::StringRecord::new();
    let mut rows: Vec<SweepRow> = Vec::new();
    let mut block = Block { case: 0, file: file_no, start: rows_start, end: rows_start };
    loop {
        let start = offset + rd.position().byte();
        let line = rd.position().line() as usize + usize::from(marked) + usize::from(identity.is_some());
        if !rd.read_record(&mut record).map_err(perr)? {
            break;
        }
        let row = SweepRow::from_record(&header, &record, path, line)?;
        let case = u32::try_from(row.case).map_err(|_| bad(format!("line {line}: case {} is too large", row.case)))?;
        if !rows.is_empty() && case != block.case {
            each(block, &rows)?;
            rows.clear();
        }
        if rows.is_empty() {
            block = Block { case, file: file_no, start, end: start };
        }
        rows.push(row);
        block.end = offset + rd.position().byte();
    }
    if !rows.is_empty() {
        each(block, &rows)?;
    }
    Ok(Scanned { header, cut: complete < len, rows_start })
}

/// Where an output goes, by the rules of [`crate::io`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// `-`: standard output.
    Stdout,
    /// An existing FIFO, character device or socket: written through.
    Through(PathBuf),
    /// A regular file (existing or new; a symbolic link's final target): replaced by a temporary file renamed over it.
    File(PathBuf),
}

impl Target {
    /// The target of an output path; a folder or a symbolic link to nothing is refused ([`Error::Write`]).
    pub fn of(path: &Path) -> Result<Target> {
        let refuse = |why: &str| Error::Write { path: path.to_path_buf(), source: std::io::Error::other(why) };
        if crate::io::is_stdout(path) {
            return Ok(Target::Stdout);
        }
        let link = std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
        let resolved = if link {
            std::fs::canonicalize(path).map_err(|_| refuse("it is a symbolic link to nothing"))?
        } else {
            path.to_path_buf()
        };
        Ok(match std::fs::metadata(&resolved) {
            Ok(m) if m.is_dir() => return Err(refuse("it is a folder")),
            Ok(m) if !m.is_file() => Target::Through(resolved),
            _ => Target::File(resolved),
        })
    }

    /// Write the output, its content streamed by `fill`: nothing is left half-written at a regular file (a
    /// temporary file beside it, renamed over it when `fill` has succeeded).
    pub fn write<T>(&self, given: &Path, fill: impl FnOnce(&mut dyn Write) -> Result<T>) -> Result<T> {
        let werr = write_err(given);
        match self {
            Target::Stdout => {
                let mut out = std::io::BufWriter::new(std::io::stdout().lock());
                let t = fill(&mut out)?;
                out.flush().map_err(&werr)?;
                Ok(t)
            }
            Target::Through(p) => {
                let mut out = std::io::BufWriter::new(OpenOptions::new().write(true).open(p).map_err(&werr)?);
                let t = fill(&mut out)?;
                out.flush().map_err(&werr)?;
                Ok(t)
            }
            Target::File(p) => {
                let dir = p.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
                let name = p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
                let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
                let written = (|| {
                    let mut out = std::io::BufWriter::new(File::create(&tmp).map_err(&werr)?);
                    let t = fill(&mut out)?;
                    out.flush().map_err(&werr)?;
                    std::fs::rename(&tmp, p).map_err(&werr)?;
                    Ok(t)
                })();
                if written.is_err() {
                    let _ = std::fs::remove_file(&tmp);
                }
                written
            }
        }
    }
}

/// Counts of a sorted write.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Written {
    /// Rows written.
    pub rows: usize,
    /// Of which with status `error`.
    pub errors: usize,
}

/// Write the blocks of `files` (each case once: checked by the caller) sorted by case, each case's rows by solver,
/// under `header`, to `out` by the rules of [`Target`].
pub fn write_sorted(files: &[PathBuf], mut blocks: Vec<Block>, header: &Header, out: &Path) -> Result<Written> {
    blocks.sort_unstable_by_key(|b| b.case);
    let solver = header.names.iter().position(|n| n == "solver").expect("a parsed header has `solver`");
    let status = header.names.iter().position(|n| n == "status").expect("a parsed header has `status`");
    let werr = write_err(out);
    Target::of(out)?.write(out, |w| {
        // One CSV reader per file (building a reader builds its parser: once per file, not once per block),
        // moved to each block's offset.
        let mut opened: Vec<Option<csv::Reader<BufReader<File>>>> = files.iter().map(|_| None).collect();
        let mut cw = csv::Writer::from_writer(w);
        let cerr = |e: csv::Error| Error::Write { path: out.to_path_buf(), source: std::io::Error::other(e) };
        cw.write_record(&header.names).map_err(cerr)?;
        let mut n = Written::default();
        for b in &blocks {
            let path = &files[b.file as usize];
            let changed =
                |e: csv::Error| Error::Parse { path: path.clone(), message: format!("changed while it was read: {e}") };
            let rd = match &mut opened[b.file as usize] {
                Some(r) => r,
                slot => {
                    let f = File::open(path).map_err(read_err(path))?;
                    slot.insert(
                        csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(BufReader::new(f)),
                    )
                }
            };
            let mut at = csv::Position::new();
            at.set_byte(b.start);
            rd.seek_raw(SeekFrom::Start(b.start), at).map_err(changed)?;
            let mut records: Vec<csv::StringRecord> = Vec::new();
            while rd.position().byte() < b.end {
                let mut r = csv::StringRecord::new();
                if !rd.read_record(&mut r).map_err(changed)? {
                    break;
                }
                if r.len() != header.names.len() {
                    return Err(Error::Parse {
                        path: path.clone(),
                        message: format!(
                            "changed while it was read: a row of {} fields under a header of {}",
                            r.len(),
                            header.names.len()
                        ),
                    });
                }
                records.push(r);
            }
            if rd.position().byte() != b.end {
                return Err(Error::Parse {
                    path: path.clone(),
                    message: format!(
                        "changed while it was read: a block ends at byte {}, not {}",
                        rd.position().byte(),
                        b.end
                    ),
                });
            }
            records.sort_by(|x, y| x.get(solver).cmp(&y.get(solver)));
            for r in &records {
                n.rows += 1;
                n.errors += usize::from(r.get(status) == Some(RowStatus::Error.name()));
                cw.write_record(r).map_err(cerr)?;
            }
        }
        cw.flush().map_err(&werr)?;
        Ok(n)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_complete_length_is_after_the_last_line_break() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("f");
        for (text, want) in [("", 0), ("abc", 0), ("a\n", 2), ("a\nbc", 2), ("a\nb\n", 4)] {
            std::fs::write(&p, text).unwrap();
            let mut f = File::open(&p).unwrap();
            assert_eq!(complete_len(&mut f, text.len() as u64).unwrap(), want, "{text:?}");
        }
        // Longer than one read chunk.
        let long = format!("x\n{}", "y".repeat(200_000));
        std::fs::write(&p, &long).unwrap();
        assert_eq!(complete_len(&mut File::open(&p).unwrap(), long.len() as u64).unwrap(), 2);
    }
}
