//! LCP files in the plain-text format of the LCP test collection of Siconos numerics
//! (`numerics/src/LCP/test/data/lcp_*.dat`), so that rollbem's LCPs can be handed to other solvers and classic
//! test problems can be read back.
//!
//! ## The format (as Siconos reads and writes it)
//! Siconos reads an LCP with `linearComplementarity_newFromFile` (`numerics/src/LCP/LinearComplementarityProblem.c`):
//! the problem size n, then a `NumericsMatrix` (`NM_new_from_file` in `numerics/src/tools/NumericsMatrix.c`), then
//! the `size1` entries of q. A dense `NumericsMatrix` is its storage type (`0` = `NM_DENSE`), `size0`, `size1`, the
//! two sizes again (written `size0<TAB>size1`), and then the `size0·size1` entries **in Siconos' storage order,
//! which is column-major**: `NM_write_in_file` prints `matrix0[i]` for i = 0, 1, … and breaks the line every
//! `size1` entries, so each line of a Siconos-written file is a *column* of M. Every number is read by `fscanf`
//! and separated by any whitespace; the LCP is `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0`, as in
//! [`crate::solvers::Lcp`]. For n = 2:
//!
//! ```text
//! 2              problem size n
//! 0              storage type: dense
//! 2              size0
//! 2              size1
//! 2 2            size0 size1 (again; Siconos writes a tab between them)
//! 2 1            column 0 of M: M00 M10
//! 1 2            column 1 of M: M01 M11
//! -5 -6          q
//! ```
//!
//! Siconos reads nothing after q, and its collection uses this: `lcp_CPS_1.dat` ends with a free-text remark
//! (the book and remark the problem comes from). rollbem does the same, with one deliberate strictness: the
//! remark must not *start* with a number, because extra numbers after q are what a file with a wrong size looks
//! like. [`to_string_with_remark`] writes such a remark (each line prefixed with `# `) and [`parse_with_remark`]
//! returns it.
//!
//! Only the dense storage (type 0) is supported; Siconos' sparse-block (1) and sparse (2) storages are reported as
//! [`Error::Unsupported`].
//!
//! Numbers are written with Rust's shortest round-trip representation (`{:e}`), so write → read is exact to the
//! bit; Siconos (`%le`) reads them unchanged.

use crate::error::{Error, Result};
use crate::solvers::Lcp;
use faer::Mat;
use std::fmt::Write as _;
use std::path::Path;

/// Largest problem size accepted from a file (a dense 20000² matrix is already 3.2 GB).
pub const MAX_SIZE: usize = 20_000;

/// Storage type of a dense `NumericsMatrix` (`NM_DENSE`).
const NM_DENSE: usize = 0;

/// Read an LCP file; errors name the file and the line (or the token count) of the problem.
pub fn read(path: &Path) -> Result<Lcp> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
    parse(&text, path)
}

/// Parse the text of an LCP file (`path` only names the file in errors). Anything after q is ignored, as Siconos
/// does, provided it does not start with a number (see the module docs).
pub fn parse(text: &str, path: &Path) -> Result<Lcp> {
    parse_with_remark(text, path).map(|(lcp, _)| lcp)
}

/// Parse like [`parse`], and also return the free-text remark after q (trimmed; empty if there is none).
pub fn parse_with_remark(text: &str, path: &Path) -> Result<(Lcp, String)> {
    let mut tok = Tokens::new(text, path);
    let n = tok.size("the problem size n")?;
    let storage = tok.integer("the matrix storage type")?;
    if storage != NM_DENSE {
        let what = match storage {
            1 => "sparse-block (NM_SPARSE_BLOCK)".to_string(),
            2 => "sparse (NM_SPARSE)".to_string(),
            s => format!("unknown ({s})"),
        };
        return Err(Error::Unsupported {
            path: path.to_path_buf(),
            message: format!(
                "line {}: matrix storage type {what}: only dense matrices (storage type 0) are supported",
                tok.last_line
            ),
        });
    }
    for what in ["size0 (rows of M)", "size1 (columns of M)", "size0 (repeated)", "size1 (repeated)"] {
        let s = tok.integer(what)?;
        if s != n {
            return Err(tok.error(format!("{what} is {s} but the problem size n is {n}: M must be n × n")));
        }
    }
    // Column-major, as NM_new_from_file fills `matrix0`.
    let mut data = Vec::with_capacity(n * n);
    for k in 0..n * n {
        let (i, j) = (k % n, k / n);
        data.push(tok.number(&format!("M[{}, {}] (entry {} of {} of M, column-major)", i + 1, j + 1, k + 1, n * n))?);
    }
    let mut q = Vec::with_capacity(n);
    for i in 0..n {
        q.push(tok.number(&format!("q[{}] (entry {} of {} of q)", i + 1, i + 1, n))?);
    }
    let remark = tok.rest();
    if let Some(first) = remark.split_whitespace().next() {
        if looks_numeric(first) {
            let extra = remark.split_whitespace().take_while(|t| looks_numeric(t)).count();
            let line = tok.next_line();
            return Err(tok.error_at(
                line,
                format!(
                    "{extra} extra number(s) after the {n} entries of q: M or q has the wrong size \
                     (a trailing remark must start with text)"
                ),
            ));
        }
    }
    let m = Mat::from_fn(n, n, |i, j| data[j * n + i]);
    Ok((Lcp { m, q }, remark.trim().to_string()))
}

/// Write in the same format, full round-trip precision, atomically (a temporary file renamed into place).
pub fn write(lcp: &Lcp, path: &Path) -> Result<()> {
    crate::io::write_atomic(path, &to_string(lcp))
}

/// The file text of an LCP: Siconos' dense layout, one column of M per line, then q; every number in Rust's
/// shortest round-trip form (`{:e}`).
pub fn to_string(lcp: &Lcp) -> String {
    let n = lcp.size();
    let mut s = String::with_capacity(24 * n * (n + 1) + 32);
    let _ = writeln!(s, "{n}\n{NM_DENSE}\n{n}\n{n}\n{n}\t{n}");
    for j in 0..n {
        for i in 0..n {
            if i > 0 {
                s.push(' ');
            }
            let _ = write!(s, "{:e}", lcp.m[(i, j)]);
        }
        s.push('\n');
    }
    for (i, v) in lcp.q.iter().enumerate() {
        if i > 0 {
            s.push(' ');
        }
        let _ = write!(s, "{v:e}");
    }
    s.push('\n');
    s
}

/// [`to_string`] followed by a blank line and a free-text remark (origin, known solutions, …), each of its lines
/// prefixed with `# ` so that it can never be mistaken for data. Siconos ignores it; [`parse_with_remark`] returns it.
pub fn to_string_with_remark(lcp: &Lcp, remark: &str) -> String {
    let mut s = to_string(lcp);
    if !remark.trim().is_empty() {
        s.push('\n');
        for line in remark.trim_end().lines() {
            s.push_str(if line.is_empty() { "#" } else { "# " });
            s.push_str(line);
            s.push('\n');
        }
    }
    s
}

/// A token that is a number written as such (so a remark may start with a word like `Infinitely`).
fn looks_numeric(t: &str) -> bool {
    t.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.')) && t.parse::<f64>().is_ok()
}

/// Whitespace-separated tokens with their line numbers.
struct Tokens<'a> {
    text: &'a str,
    path: &'a Path,
    /// Byte offset of the next unread character.
    pos: usize,
    /// Line (1-based) of `pos`.
    line: usize,
    /// Line of the last token read.
    last_line: usize,
    /// Tokens read so far.
    count: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str, path: &'a Path) -> Self {
        Tokens { text, path, pos: 0, line: 1, last_line: 1, count: 0 }
    }

    fn skip_space(&mut self) {
        let rest = &self.text[self.pos..];
        let skipped = rest.len() - rest.trim_start().len();
        self.line += rest[..skipped].bytes().filter(|&b| b == b'\n').count();
        self.pos += skipped;
    }

    /// Line of the next token (or of the end of the text).
    fn next_line(&mut self) -> usize {
        self.skip_space();
        self.line
    }

    fn next(&mut self, what: &str) -> Result<&'a str> {
        self.skip_space();
        let rest = &self.text[self.pos..];
        if rest.is_empty() {
            return Err(self.error_at(
                self.line,
                format!("unexpected end of file after {} number(s): expected {what}", self.count),
            ));
        }
        let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
        self.pos += len;
        self.last_line = self.line;
        self.count += 1;
        Ok(&rest[..len])
    }

    fn integer(&mut self, what: &str) -> Result<usize> {
        let t = self.next(what)?;
        t.parse::<usize>().map_err(|_| self.error(format!("expected {what} (a non-negative integer), found `{t}`")))
    }

    fn size(&mut self, what: &str) -> Result<usize> {
        let n = self.integer(what)?;
        if n == 0 || n > MAX_SIZE {
            return Err(self.error(format!("{what} is {n}: expected 1 ≤ n ≤ {MAX_SIZE}")));
        }
        Ok(n)
    }

    fn number(&mut self, what: &str) -> Result<f64> {
        let t = self.next(what)?;
        match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(self.error(format!("{what} is `{t}`: entries must be finite"))),
            Err(_) => Err(self.error(format!("expected {what} (a number), found `{t}`"))),
        }
    }

    /// Everything after the last token read.
    fn rest(&self) -> &'a str {
        &self.text[self.pos..]
    }

    fn error(&self, message: String) -> Error {
        self.error_at(self.last_line, message)
    }

    fn error_at(&self, line: usize, message: String) -> Error {
        Error::Parse { path: self.path.to_path_buf(), message: format!("line {line}: {message}") }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p() -> &'static Path {
        Path::new("t.dat")
    }

    fn msg(text: &str) -> String {
        match parse(text, p()) {
            Err(Error::Parse { message, .. }) => message,
            Err(e) => panic!("expected a parse error, got {e}"),
            Ok(_) => panic!("expected a parse error for {text:?}"),
        }
    }

    #[test]
    fn reads_the_dense_layout_column_major() {
        // The layout of Siconos' lcp_deudeu.dat-style files (NM_write_in_file: one column per line); the matrix is
        // non-symmetric so that a row-major reading would be caught.
        let (lcp, remark) =
            parse_with_remark("2\n0\n2\n2\n2\t2\n1 3\n2 4\n-5 -6\n\nsome remark\n", p()).expect("valid file");
        assert_eq!((lcp.m[(0, 0)], lcp.m[(1, 0)], lcp.m[(0, 1)], lcp.m[(1, 1)]), (1.0, 3.0, 2.0, 4.0));
        assert_eq!(lcp.q, vec![-5.0, -6.0]);
        assert_eq!(remark, "some remark");
    }

    #[test]
    fn malformed_files_are_errors_with_line_numbers() {
        assert!(msg("").contains("line 1: unexpected end of file after 0"));
        assert!(msg("0\n0\n0\n0\n0 0\n").contains("problem size n is 0"));
        assert!(msg("20001\n").contains("20001"));
        assert!(msg("99999999999999999999999\n").contains("non-negative integer"));
        assert!(msg("2\n0\n2\n3\n").contains("line 4: size1 (columns of M) is 3"));
        assert!(msg("2\n0\n2\n2\n2 2\n1 2\n3 x\n-1 -1\n").contains("line 7: expected M[2, 2]"));
        assert!(msg("2\n0\n2\n2\n2 2\n1 2\n3 NaN\n-1 -1\n").contains("line 7: M[2, 2]"));
        assert!(msg("2\n0\n2\n2\n2 2\n1 2\n3 4\n-1 inf\n").contains("finite"));
        assert!(msg("2\n0\n2\n2\n2 2\n1 2\n3 4\n-1\n").contains("end of file after 11 number(s): expected q[2]"));
        assert!(msg("2\n0\n2\n2\n2 2\n1 2\n3 4\n-1 -1\n\n7 8\n").contains("line 10: 2 extra number(s)"));
        assert!(matches!(parse("2\n1\n2\n2\n", p()), Err(Error::Unsupported { .. })));
        // A remark may start with a word that Rust would parse as a float.
        assert!(parse("1\n0\n1\n1\n1 1\n2\n-1\nInfinity of solutions? no.\n", p()).is_ok());
    }

    #[test]
    fn round_trip_is_bitwise() {
        let vals = [0.1, -0.0, 1.0 / 3.0, f64::MAX, f64::MIN_POSITIVE, 5e-324, -2.5e300, 123456789.0];
        let n = 3;
        let lcp = Lcp { m: Mat::from_fn(n, n, |i, j| vals[(i * n + j) % vals.len()]), q: vec![-1.0, 0.0, 1e-17] };
        let back = parse(&to_string_with_remark(&lcp, "origin\n\n3.0 is not data"), p()).expect("round trip");
        for j in 0..n {
            for i in 0..n {
                assert_eq!(back.m[(i, j)].to_bits(), lcp.m[(i, j)].to_bits());
            }
        }
        assert!(back.q.iter().zip(&lcp.q).all(|(a, b)| a.to_bits() == b.to_bits()));
    }
}
