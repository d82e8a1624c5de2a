//! LCP files in the plain-text format of the LCP test collection of Siconos numerics
//! (`numerics/src/LCP/test/data/lcp_*.dat`), so that rollbem's LCPs can be handed to other solvers and classic
//! test problems can be read back.
//!
//! ## The format (as Siconos reads and writes it)
//! The layouts below were read off Siconos 4.4.0's source (Debian source package `siconos` 4.4.0+dfsg-2); the
//! collection itself is in `reference/lcp/siconos/`. Siconos reads an LCP with `linearComplementarity_newFromFile`
//! (`numerics/src/LCP/LinearComplementarityProblem.c`): the problem size n, then a `NumericsMatrix`
//! (`NM_new_from_file` in `numerics/src/tools/NumericsMatrix.c`), then the `size1` entries of q. A dense
//! `NumericsMatrix` is its storage type (`0` = `NM_DENSE`), `size0`, `size1`, the two sizes again (written
//! `size0<TAB>size1`), and then the `size0·size1` entries **in Siconos' storage order, which is column-major**:
//! `NM_write_in_file` prints `matrix0[i]` for i = 0, 1, … and breaks the line every `size1` entries, so each line
//! of a Siconos-written file is a *column* of M. Every number is read by `fscanf` and separated by any whitespace;
//! the LCP is `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0`, as in [`crate::solvers::Lcp`]. For n = 2:
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
//! ## Sparse-block storage (type 1)
//! Three files of Siconos' collection (`lcp_deudeu_block.dat`, `lcp_ortiz_block.dat`, `lcp_trivial_block.dat`)
//! store M as a `SparseBlockStructuredMatrix` (SBM). After the storage type `1`, `size0` and `size1` (*not*
//! repeated), `SBM_write_in_file` (`numerics/src/tools/SparseBlockMatrix.c`, read back by `SBM_new_from_file`)
//! writes:
//!
//! ```text
//! nbblocks                        number of stored (nonzero) blocks; 0 = M is all zero, and nothing else follows
//! blocknumber0                    number of block rows
//! blocknumber1                    number of block columns
//! blocksize0[0..blocknumber0]     CUMULATIVE row counts: block row r holds rows blocksize0[r-1] .. blocksize0[r]-1
//! blocksize1[0..blocknumber1]     cumulative column counts, likewise
//! filled1                         (index of the last nonempty block row) + 2: the length of index1_data
//! filled2                         length of index2_data = the number of stored blocks
//! index1_data[0..filled1]         compressed-row pointers: block row r stores the blocks
//!                                 index1_data[r] .. index1_data[r+1]-1
//! index2_data[0..filled2]         block column of each stored block
//! then, for each stored block b in order: the number b, and its rows·columns entries in COLUMN-MAJOR order
//! ```
//!
//! (one number per line in Siconos' files, but any whitespace separates them, as for `fscanf`). rollbem converts
//! the blocks to the dense M it works with; blocks not stored are zero. A file is refused, with the line of the
//! offending number, when it is not what `SBM_write_in_file` can produce: cumulative sizes that do not increase
//! or do not end at n, `filled2 ≠ nbblocks`, row pointers that do not start at 0, decrease or do not end at
//! `filled2`, a block column out of range, the same block stored twice, or a block number out of sequence
//! (Siconos only prints a warning for the last one and reads on). For example, `lcp_ortiz_block.dat` is
//!
//! ```text
//! 4  1  4  4          n, storage type 1, size0, size1
//! 4  2  2             nbblocks, blocknumber0, blocknumber1
//! 2 4   2 4           blocksize0, blocksize1 (two 2 × 2 block rows and columns)
//! 3  4                filled1, filled2
//! 0 2 4   0 1 0 1     index1_data, index2_data: row 0 holds blocks 0, 1 (columns 0, 1); row 1 blocks 2, 3
//! 0  3 -1 1 2         block 0 = M[0..2, 0..2] = [[3, 1], [-1, 2]], column-major
//! 1  0 1 -1 1         block 1 = M[0..2, 2..4]; then blocks 2 and 3
//! …  q
//! ```
//!
//! Siconos' sparse (compressed-column, type 2) storage is reported as [`Error::Unsupported`]; rollbem writes only
//! the dense storage.
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

/// Storage type of a sparse-block `NumericsMatrix` (`NM_SPARSE_BLOCK`, a `SparseBlockStructuredMatrix`).
const NM_SPARSE_BLOCK: usize = 1;

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
    if storage != NM_DENSE && storage != NM_SPARSE_BLOCK {
        let what = match storage {
            2 => "sparse (NM_SPARSE)".to_string(),
            s => format!("unknown ({s})"),
        };
        return Err(Error::Unsupported {
            path: path.to_path_buf(),
            message: format!(
                "line {}: matrix storage type {what}: only dense (0) and sparse-block (1) matrices are supported",
                tok.last_line
            ),
        });
    }
    let sizes: &[&str] = if storage == NM_DENSE {
        &["size0 (rows of M)", "size1 (columns of M)", "size0 (repeated)", "size1 (repeated)"]
    } else {
        &["size0 (rows of M)", "size1 (columns of M)"]
    };
    for what in sizes {
        let s = tok.integer(what)?;
        if s != n {
            return Err(tok.error(format!("{what} is {s} but the problem size n is {n}: M must be n × n")));
        }
    }
    // Column-major, as NM_new_from_file fills `matrix0`. Memory stays proportional to the text until the whole file
    // has been read: nothing reserves more numbers than the rest of the text can hold ([`Tokens::room_for`]), and
    // sparse blocks are kept as read; the dense n × n matrix is allocated only for a complete, valid file (a
    // truncated or hostile one of a few bytes declaring n = 20000 must not cost 3.2 GB).
    let matrix = if storage == NM_DENSE {
        let mut data = Vec::with_capacity(tok.room_for(n * n));
        for k in 0..n * n {
            let (i, j) = (k % n, k / n);
            data.push(
                tok.number(|| format!("M[{}, {}] (entry {} of {} of M, column-major)", i + 1, j + 1, k + 1, n * n))?,
            );
        }
        Matrix::Dense(data)
    } else {
        Matrix::Blocks(read_sparse_block(&mut tok, n)?)
    };
    let mut q = Vec::with_capacity(tok.room_for(n));
    for i in 0..n {
        q.push(tok.number(|| format!("q[{}] (entry {} of {} of q)", i + 1, i + 1, n))?);
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
    let m = match matrix {
        Matrix::Dense(data) => Mat::from_fn(n, n, |i, j| data[j * n + i]),
        Matrix::Blocks(blocks) => {
            let mut m = Mat::zeros(n, n);
            for b in &blocks {
                let rows = b.rows.len();
                for (k, &v) in b.values.iter().enumerate() {
                    m[(b.rows.start + k % rows, b.cols.start + k / rows)] = v;
                }
            }
            m
        }
    };
    Ok((Lcp { m, q }, remark.trim().to_string()))
}

/// M as read from the file, before the dense n × n matrix is built.
enum Matrix {
    /// The n² entries, column-major.
    Dense(Vec<f64>),
    /// The stored blocks of a sparse-block matrix (the others are zero).
    Blocks(Vec<Block>),
}

/// One stored block of a sparse-block matrix.
struct Block {
    /// Rows of M it covers.
    rows: std::ops::Range<usize>,
    /// Columns of M it covers.
    cols: std::ops::Range<usize>,
    /// Its `rows.len() · cols.len()` entries, column-major.
    values: Vec<f64>,
}

/// Read the `SparseBlockStructuredMatrix` part of a file (after the storage type and the two sizes): its stored
/// blocks, validated as described in the module docs.
fn read_sparse_block(tok: &mut Tokens, n: usize) -> Result<Vec<Block>> {
    let nbblocks = tok.integer("nbblocks (the number of stored blocks)")?;
    if nbblocks == 0 {
        // SBM_write_in_file writes only this 0 for a matrix without blocks: M is zero.
        return Ok(Vec::new());
    }
    let nb0 = block_count(tok, n, "blocknumber0", "rows")?;
    let nb1 = block_count(tok, n, "blocknumber1", "columns")?;
    let start0 = cumulative_sizes(tok, nb0, n, "blocksize0", "row")?;
    let start1 = cumulative_sizes(tok, nb1, n, "blocksize1", "column")?;
    let (filled1, filled2) = fill_counts(tok, nbblocks, nb0, nb1)?;
    let rowptr = row_pointers(tok, filled1, filled2)?;
    let blockcol = block_columns(tok, filled2, nb1)?;
    check_no_block_twice(tok, &rowptr, &blockcol, nb1)?;
    block_values(tok, &rowptr, &blockcol, &start0, &start1)
}

/// Read `blocknumber0` or `blocknumber1`: the number of block rows or columns, 1 to n.
fn block_count(tok: &mut Tokens, n: usize, name: &str, dim: &str) -> Result<usize> {
    let nb = tok.integer(&format!("{name} (the number of block {dim})"))?;
    if nb == 0 || nb > n {
        return Err(tok.error(format!("{name} is {nb}: expected 1 ≤ {name} ≤ n = {n}")));
    }
    Ok(nb)
}

/// Read `filled1` (the number of row pointers) and `filled2` (the number of stored blocks, which must be
/// `nbblocks` and fit in the `nb0 × nb1` block positions).
fn fill_counts(tok: &mut Tokens, nbblocks: usize, nb0: usize, nb1: usize) -> Result<(usize, usize)> {
    let filled1 = tok.integer("filled1 (the number of row pointers)")?;
    if filled1 < 2 || filled1 > nb0 + 1 {
        return Err(tok.error(format!(
            "filled1 is {filled1}: expected 2 ≤ filled1 ≤ blocknumber0 + 1 = {} (one row pointer per block row up to \
             the last nonempty one, plus one)",
            nb0 + 1
        )));
    }
    let filled2 = tok.integer("filled2 (the number of stored blocks)")?;
    if filled2 != nbblocks {
        return Err(tok.error(format!("filled2 is {filled2} but nbblocks is {nbblocks}: they must be equal")));
    }
    if filled2 > nb0 * nb1 {
        return Err(tok.error(format!("filled2 is {filled2}: more blocks than the {nb0} × {nb1} block positions of M")));
    }
    Ok((filled1, filled2))
}

/// Read the `filled1` compressed-row pointers `index1_data`: starting at 0, never decreasing, ending at `filled2`.
fn row_pointers(tok: &mut Tokens, filled1: usize, filled2: usize) -> Result<Vec<usize>> {
    let mut rowptr = Vec::with_capacity(filled1);
    for r in 0..filled1 {
        let p = tok.integer(&format!("index1_data[{r}] (row pointer of block row {r})"))?;
        let ok = if r == 0 { p == 0 } else { p >= rowptr[r - 1] && p <= filled2 };
        if !ok {
            let expected = if r == 0 {
                "0".to_string()
            } else {
                format!("between index1_data[{}] = {} and filled2 = {filled2}", r - 1, rowptr[r - 1])
            };
            return Err(tok.error(format!("index1_data[{r}] is {p}: expected {expected}")));
        }
        rowptr.push(p);
    }
    if rowptr[filled1 - 1] != filled2 {
        return Err(tok.error(format!(
            "index1_data[{}] is {}: the last row pointer must be filled2 = {filled2}",
            filled1 - 1,
            rowptr[filled1 - 1]
        )));
    }
    Ok(rowptr)
}

/// Read the block column `index2_data` of each of the `filled2` stored blocks (each below `nb1`).
fn block_columns(tok: &mut Tokens, filled2: usize, nb1: usize) -> Result<Vec<usize>> {
    let mut blockcol = Vec::with_capacity(tok.room_for(filled2));
    for b in 0..filled2 {
        let c = tok.integer(&format!("index2_data[{b}] (block column of block {b})"))?;
        if c >= nb1 {
            return Err(tok.error(format!("index2_data[{b}] is {c}: expected a block column < blocknumber1 = {nb1}")));
        }
        blockcol.push(c);
    }
    Ok(blockcol)
}

/// Refuse a block stored twice. The same block twice can only be in the same block row: remember, per block
/// column, the last row using it.
fn check_no_block_twice(tok: &Tokens, rowptr: &[usize], blockcol: &[usize], nb1: usize) -> Result<()> {
    let mut last_row = vec![usize::MAX; nb1];
    for r in 0..rowptr.len() - 1 {
        for b in rowptr[r]..rowptr[r + 1] {
            let c = blockcol[b];
            if std::mem::replace(&mut last_row[c], r) == r {
                return Err(
                    tok.error(format!("index2_data[{b}] is {c}: block ({r}, {c}) is stored twice in block row {r}"))
                );
            }
        }
    }
    Ok(())
}

/// Read the stored blocks in order, each its number and then its entries, column-major; block r, c spans rows
/// `start0[r] .. start0[r + 1]` and columns `start1[c] .. start1[c + 1]`.
fn block_values(
    tok: &mut Tokens,
    rowptr: &[usize],
    blockcol: &[usize],
    start0: &[usize],
    start1: &[usize],
) -> Result<Vec<Block>> {
    let mut blocks = Vec::with_capacity(blockcol.len());
    for r in 0..rowptr.len() - 1 {
        for b in rowptr[r]..rowptr[r + 1] {
            let c = blockcol[b];
            let number = tok.integer(&format!("the number of block {b}"))?;
            if number != b {
                return Err(tok.error(format!("block number {number} where block {b} was expected (blocks in order)")));
            }
            let (r0, r1, c0, c1) = (start0[r], start0[r + 1], start1[c], start1[c + 1]);
            let rows = r1 - r0;
            let count = rows * (c1 - c0);
            let mut values = Vec::with_capacity(tok.room_for(count));
            for k in 0..count {
                let (i, j) = (r0 + k % rows, c0 + k / rows);
                values.push(tok.number(|| {
                    format!(
                        "M[{}, {}] (entry {} of block {b}, rows {}..{}, columns {}..{}, column-major)",
                        i + 1,
                        j + 1,
                        k + 1,
                        r0 + 1,
                        r1,
                        c0 + 1,
                        c1
                    )
                })?);
            }
            blocks.push(Block { rows: r0..r1, cols: c0..c1, values });
        }
    }
    Ok(blocks)
}

/// Read `nb` cumulative block sizes (`blocksize0` or `blocksize1`) and return the block starts `[0, s₀, …, n]`:
/// block r spans `start[r] .. start[r + 1]`.
fn cumulative_sizes(tok: &mut Tokens, nb: usize, n: usize, name: &str, dim: &str) -> Result<Vec<usize>> {
    let mut start = vec![0];
    for r in 0..nb {
        let s = tok.integer(&format!("{name}[{r}] (cumulative {dim} count of block {r})"))?;
        let prev = start[r];
        if s <= prev {
            return Err(
                tok.error(format!("{name}[{r}] is {s}: the cumulative {dim} counts must increase (previous {prev})"))
            );
        }
        start.push(s);
    }
    if start[nb] != n {
        return Err(tok.error(format!(
            "{name}[{}] is {}: the cumulative {dim} counts must end at n = {n}",
            nb - 1,
            start[nb]
        )));
    }
    Ok(start)
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
        self.next_with(|| what.to_string())
    }

    /// The next token; `what` describes it in an error and is called only then (building the description of
    /// each of the n² entries of M up front took most of the time of reading a large file).
    fn next_with(&mut self, what: impl Fn() -> String) -> Result<&'a str> {
        self.skip_space();
        let rest = &self.text[self.pos..];
        if rest.is_empty() {
            return Err(self.error_at(
                self.line,
                format!("unexpected end of file after {} number(s): expected {}", self.count, what()),
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

    fn number(&mut self, what: impl Fn() -> String) -> Result<f64> {
        let t = self.next_with(&what)?;
        match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(self.error(format!("{} is `{t}`: entries must be finite", what()))),
            Err(_) => Err(self.error(format!("expected {} (a number), found `{t}`", what()))),
        }
    }

    /// A capacity for `count` more numbers, but no more than the rest of the text can hold (a number and its
    /// separator take two bytes at least): what a file declares must not reserve memory its text does not back.
    fn room_for(&self, count: usize) -> usize {
        count.min(self.rest().len() / 2 + 1)
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
        assert!(matches!(parse("2\n2\n2\n2\n", p()), Err(Error::Unsupported { .. })));
        assert!(matches!(parse("2\n7\n2\n2\n", p()), Err(Error::Unsupported { .. })));
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

    /// `lcp_ortiz_block.dat` of Siconos' collection, as `SBM_write_in_file` wrote it (one number per line, tabs after
    /// the integers of a list). Its dense equivalent is `lcp_ortiz.dat`: by rows, M = [[3, 1, 0, −1], [−1, 2, 1, 1],
    /// [0, 1, 3, −1], [0, 0, 1, 2]], q = (−2, 1, −1, 1) (read off the dense file, whose lines are columns).
    const ORTIZ_BLOCK: &str = "4\n1\n4\n4\n4\n2\n2\n2\t4\t\n2\t4\t\n3\n4\n0\t2\t4\t\n0\t1\t0\t1\t\n\
        0\n 3.0e+00\n -1.0e+00\n 1.0e+00\n 2.0e+00\n\
        1\n 0.0e+00\n 1.0e+00\n -1.0e+00\n 1.0e+00\n\
        2\n 0.0e+00\n 0.0e+00\n 1.0e+00\n 0.0e+00\n\
        3\n 3.0e+00\n 1.0e+00\n -1.0e+00\n 2.0e+00\n\
         -2.0e+00  1.0e+00  -1.0e+00  1.0e+00 ";

    fn dense_rows(lcp: &Lcp) -> Vec<Vec<f64>> {
        (0..lcp.size()).map(|i| (0..lcp.size()).map(|j| lcp.m[(i, j)]).collect()).collect()
    }

    #[test]
    fn reads_the_sparse_block_layout() {
        let lcp = parse(ORTIZ_BLOCK, p()).expect("valid file");
        let rows = [[3.0, 1.0, 0.0, -1.0], [-1.0, 2.0, 1.0, 1.0], [0.0, 1.0, 3.0, -1.0], [0.0, 0.0, 1.0, 2.0]];
        assert_eq!(dense_rows(&lcp), rows.map(|r| r.to_vec()).to_vec());
        assert_eq!(lcp.q, vec![-2.0, 1.0, -1.0, 1.0]);
    }

    #[test]
    fn sparse_block_with_unequal_blocks_and_missing_ones() {
        // Hand-made: n = 3, block rows {0} and {1, 2}, block columns {0, 1} and {2}; stored: block 0 = (row 0,
        // column block 0) = M[0, 0..2] = [1, 2]; block 1 = (row block 1, column block 1) = M[1..3, 2] = [5, 6]; the
        // blocks (0, 1) and (1, 0) are absent, hence zero. Dense equivalent, by rows: [[1, 2, 0], [0, 0, 5],
        // [0, 0, 6]], q = (−1, −2, −3). Entries of block 0 are column-major over a 1 × 2 block: 1 then 2.
        let text = "3\n1\n3\n3\n2\n2\n2\n1 3\n2 3\n3\n2\n0 1 2\n0 1\n0\n1\n2\n1\n5\n6\n-1 -2 -3\n";
        let lcp = parse(text, p()).expect("valid file");
        assert_eq!(dense_rows(&lcp), vec![vec![1.0, 2.0, 0.0], vec![0.0, 0.0, 5.0], vec![0.0, 0.0, 6.0]]);
        assert_eq!(lcp.q, vec![-1.0, -2.0, -3.0]);
        // A last block row without blocks is not listed (filled1 = 2 < blocknumber0 + 1): dense [[0, 7], [0, 0]].
        let lcp = parse("2\n1\n2\n2\n1\n2\n2\n1 2\n1 2\n2\n1\n0 1\n1\n0\n7\n1 1\n", p()).expect("valid");
        assert_eq!(dense_rows(&lcp), vec![vec![0.0, 7.0], vec![0.0, 0.0]]);
        // nbblocks = 0: M = 0 and nothing else of the matrix follows.
        let lcp = parse("2\n1\n2\n2\n0\n3 4\n", p()).expect("valid");
        assert_eq!(dense_rows(&lcp), vec![vec![0.0, 0.0], vec![0.0, 0.0]]);
        assert_eq!(lcp.q, vec![3.0, 4.0]);
    }

    #[test]
    fn malformed_sparse_block_files_are_errors_with_line_numbers() {
        // Start from the valid one-line-per-number 2 × 2 file (one block) and break one thing at a time.
        //            1  2  3  4  5  6  7  8  9  10 11 12  13 14  15 16 17 18 19 (line)
        let good =
            ["2", "1", "2", "2", "1", "1", "1", "2", "2", "2", "1", "0 1", "0", "0", "2", "1", "1", "2", "-5 -6"];
        let with = |line: usize, text: &str| {
            let mut v = good.to_vec();
            v[line - 1] = text;
            v.join("\n")
        };
        let lcp = parse(&good.join("\n"), p()).expect("the base file is valid");
        assert_eq!(dense_rows(&lcp), vec![vec![2.0, 1.0], vec![1.0, 2.0]]);
        assert!(msg(&with(3, "3")).contains("line 3: size0 (rows of M) is 3"));
        assert!(msg(&with(6, "3")).contains("line 6: blocknumber0 is 3"));
        assert!(msg(&with(8, "3")).contains("line 8: blocksize0[0] is 3: the cumulative row counts must end at n = 2"));
        assert!(msg(&with(9, "0")).contains("line 9: blocksize1[0] is 0: the cumulative column counts must increase"));
        assert!(msg(&with(10, "3")).contains("line 10: filled1 is 3"));
        assert!(msg(&with(11, "2")).contains("line 11: filled2 is 2 but nbblocks is 1"));
        assert!(msg(&with(12, "1 1")).contains("line 12: index1_data[0] is 1: expected 0"));
        assert!(msg(&with(12, "0 0")).contains("line 12: index1_data[1] is 0: the last row pointer must be filled2"));
        assert!(msg(&with(13, "1")).contains("line 13: index2_data[0] is 1: expected a block column < blocknumber1"));
        assert!(msg(&with(14, "5")).contains("line 14: block number 5 where block 0 was expected"));
        assert!(msg(&with(16, "x")).contains("line 16: expected M[2, 1] (entry 2 of block 0, rows 1..2, columns 1..2"));
        assert!(msg(&with(19, "-5")).contains("expected q[2]"));
        assert!(msg(&with(19, "-5 -6 7")).contains("line 19: 1 extra number(s)"));
        // The same block twice in a row: one block row, two block columns, both stored blocks in block column 0.
        let twice = "2\n1\n2\n2\n2\n1\n2\n2\n1 2\n2\n2\n0 2\n0 0\n0\n1\n1\n1\n1\n1\n-1 -1\n";
        assert!(msg(twice).contains("line 13: index2_data[1] is 0: block (0, 0) is stored twice"));
        // Truncated in the middle of a block.
        assert!(msg(&good[..16].join("\n")).contains("line 16: unexpected end of file"));
    }
}
