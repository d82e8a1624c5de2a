//! A creep table's rows (the CSV layout, [`TABLE_COLUMNS`]) and the table as arrays ([`CreepTable`]).

use super::spec::{Axes, Normalisation};
use super::{CaseStatus, CreepResult};
use crate::error::{Error, Result};
use std::path::Path;

/// The CSV's columns, in order (module docs of `creeptable`, "Files").
pub const TABLE_COLUMNS: [&str; 27] = [
    "case",
    "nu",
    "a_over_b",
    "xi_n",
    "eta_n",
    "phi_n",
    "status",
    "fx_n",
    "fy_n",
    "mz_n",
    "engine",
    "a",
    "b",
    "c11",
    "c22",
    "c23",
    "xi",
    "eta",
    "phi",
    "fx",
    "fy",
    "mz",
    "residual",
    "contact_elements",
    "slip_elements",
    "case_digest",
    "message",
];

/// The status names of a table and their codes in the `.npz` (`status` array).
pub const STATUS_CODES: [(&str, i8); 4] = [("solved", 0), ("gross_sliding", 1), ("not_converged", 2), ("refused", 3)];

/// One row of a creep table: one case (module docs of `creeptable`, "Files").
#[derive(Debug, Clone, PartialEq)]
pub struct TableRow {
    /// The case's index.
    pub case: usize,
    /// ν.
    pub nu: f64,
    /// a/b.
    pub a_over_b: f64,
    /// ξ' (normalised).
    pub xi_n: f64,
    /// η' (normalised).
    pub eta_n: f64,
    /// φ' (normalised).
    pub phi_n: f64,
    /// `solved`, `gross_sliding`, `not_converged` or `refused`.
    pub status: String,
    /// Fx/(μN).
    pub fx_n: Option<f64>,
    /// Fy/(μN).
    pub fy_n: Option<f64>,
    /// Mz/(μN c).
    pub mz_n: Option<f64>,
    /// The engine's name.
    pub engine: String,
    /// Semi-axis a (length).
    pub a: f64,
    /// Semi-axis b (length).
    pub b: f64,
    /// Kalker's C11 at (a/b, ν) (Table E.3), which normalises ξ.
    pub c11: f64,
    /// Kalker's C22, which normalises η.
    pub c22: f64,
    /// Kalker's C23, which normalises φ.
    pub c23: f64,
    /// ξ (physical, CONTACT's sign).
    pub xi: f64,
    /// η (physical).
    pub eta: f64,
    /// φ (rad/length).
    pub phi: f64,
    /// Fx on body 1 (force).
    pub fx: Option<f64>,
    /// Fy on body 1 (force).
    pub fy: Option<f64>,
    /// Mz on body 1 (force·length).
    pub mz: Option<f64>,
    /// The engine's residual (converged or not), when it has one.
    pub residual: Option<f64>,
    /// Elements in contact, when the engine has elements.
    pub contact_elements: Option<usize>,
    /// Elements slipping.
    pub slip_elements: Option<usize>,
    /// The case's digest (16 hex digits).
    pub case_digest: String,
    /// Why a case was refused (empty otherwise).
    pub message: String,
}

/// A number as the table writes it: shortest round-trip form, plain for moderate magnitudes, else exponential.
pub(super) fn fmt_num(x: f64) -> String {
    let m = x.abs();
    if x == 0.0 || (1e-4..1e15).contains(&m) || !x.is_finite() {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

fn opt<T: ToString>(x: Option<T>) -> String {
    x.map(|v| v.to_string()).unwrap_or_default()
}

fn opt_num(x: Option<f64>) -> String {
    x.map(fmt_num).unwrap_or_default()
}

impl TableRow {
    /// The row of case `index` from an engine's answer (or its refusal).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn new(
        case: usize,
        values: [f64; 5],
        engine: &str,
        a: f64,
        b: f64,
        creepages: crate::fastsim::Creepages,
        norm: &Normalisation,
        answer: std::result::Result<CreepResult, String>,
        case_digest: String,
    ) -> TableRow {
        let [nu, a_over_b, xi_n, eta_n, phi_n] = values;
        let mut row = TableRow {
            case,
            nu,
            a_over_b,
            xi_n,
            eta_n,
            phi_n,
            status: "refused".into(),
            fx_n: None,
            fy_n: None,
            mz_n: None,
            engine: engine.to_string(),
            a,
            b,
            c11: norm.coefficients[0],
            c22: norm.coefficients[1],
            c23: norm.coefficients[2],
            xi: creepages.xi,
            eta: creepages.eta,
            phi: creepages.phi,
            fx: None,
            fy: None,
            mz: None,
            residual: None,
            contact_elements: None,
            slip_elements: None,
            case_digest,
            message: String::new(),
        };
        match answer {
            Err(m) => row.message = m,
            Ok(r) => {
                row.status = r.status.name().into();
                row.residual = match r.status {
                    CaseStatus::NotConverged { residual } => Some(residual),
                    _ => r.residual,
                };
                row.contact_elements = r.contact_elements;
                row.slip_elements = r.slip_elements;
                if let (Some(f), false) = (r.forces, matches!(r.status, CaseStatus::NotConverged { .. })) {
                    let (fx, fy, mz) = norm.forces(&f);
                    (row.fx_n, row.fy_n, row.mz_n) = (Some(fx), Some(fy), mz);
                    (row.fx, row.fy, row.mz) = (Some(f.fx), Some(f.fy), f.mz);
                }
            }
        }
        row
    }

    /// The row's cells, in [`TABLE_COLUMNS`] order.
    pub fn cells(&self) -> Vec<String> {
        let n = fmt_num;
        vec![
            self.case.to_string(),
            n(self.nu),
            n(self.a_over_b),
            n(self.xi_n),
            n(self.eta_n),
            n(self.phi_n),
            self.status.clone(),
            opt_num(self.fx_n),
            opt_num(self.fy_n),
            opt_num(self.mz_n),
            self.engine.clone(),
            n(self.a),
            n(self.b),
            n(self.c11),
            n(self.c22),
            n(self.c23),
            n(self.xi),
            n(self.eta),
            n(self.phi),
            opt_num(self.fx),
            opt_num(self.fy),
            opt_num(self.mz),
            opt_num(self.residual),
            opt(self.contact_elements),
            opt(self.slip_elements),
            self.case_digest.clone(),
            self.message.clone(),
        ]
    }

    /// The row as one CSV line (with its newline; quoted where a cell needs it).
    pub fn line(&self) -> String {
        csv_line(&self.cells())
    }

    /// The row from a CSV record in [`TABLE_COLUMNS`] order. Errors name the column.
    pub fn from_record(r: &csv::StringRecord) -> std::result::Result<TableRow, String> {
        if r.len() != TABLE_COLUMNS.len() {
            return Err(format!("{} cells, the table has {} columns", r.len(), TABLE_COLUMNS.len()));
        }
        let cell = |i: usize| r.get(i).unwrap_or("");
        let num =
            |i: usize| cell(i).parse::<f64>().map_err(|_| format!("{}: not a number: {:?}", TABLE_COLUMNS[i], cell(i)));
        let onum = |i: usize| if cell(i).is_empty() { Ok(None) } else { num(i).map(Some) };
        let ocount = |i: usize| {
            if cell(i).is_empty() {
                Ok(None)
            } else {
                cell(i)
                    .parse::<usize>()
                    .map(Some)
                    .map_err(|_| format!("{}: not a count: {:?}", TABLE_COLUMNS[i], cell(i)))
            }
        };
        let status = cell(6).to_string();
        if !STATUS_CODES.iter().any(|(s, _)| *s == status) {
            return Err(format!("status: unknown status {status:?}"));
        }
        Ok(TableRow {
            case: cell(0).parse().map_err(|_| format!("case: not a case number: {:?}", cell(0)))?,
            nu: num(1)?,
            a_over_b: num(2)?,
            xi_n: num(3)?,
            eta_n: num(4)?,
            phi_n: num(5)?,
            status,
            fx_n: onum(7)?,
            fy_n: onum(8)?,
            mz_n: onum(9)?,
            engine: cell(10).to_string(),
            a: num(11)?,
            b: num(12)?,
            c11: num(13)?,
            c22: num(14)?,
            c23: num(15)?,
            xi: num(16)?,
            eta: num(17)?,
            phi: num(18)?,
            fx: onum(19)?,
            fy: onum(20)?,
            mz: onum(21)?,
            residual: onum(22)?,
            contact_elements: ocount(23)?,
            slip_elements: ocount(24)?,
            case_digest: cell(25).to_string(),
            message: cell(26).to_string(),
        })
    }

    /// The `.npz` status code of the row's status.
    pub fn status_code(&self) -> i8 {
        STATUS_CODES.iter().find(|(s, _)| *s == self.status).map_or(3, |(_, c)| *c)
    }

    /// Reads a table CSV's rows (in file order). Errors: the file cannot be read, its header is not
    /// [`TABLE_COLUMNS`], a cell is malformed (naming the line and column).
    pub fn read_csv(path: &Path) -> Result<Vec<TableRow>> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        rows_of(&text, path)
    }
}

/// Rows of a table CSV's text (header first).
pub(super) fn rows_of(text: &str, path: &Path) -> Result<Vec<TableRow>> {
    let bad = |line: usize, m: String| Error::Parse { path: path.to_path_buf(), message: format!("line {line}: {m}") };
    let mut reader = csv::ReaderBuilder::new().has_headers(true).flexible(true).from_reader(text.as_bytes());
    let header = reader.headers().map_err(|e| bad(1, e.to_string()))?.clone();
    if header.iter().ne(TABLE_COLUMNS.iter().copied()) {
        let got: Vec<&str> = header.iter().collect();
        return Err(bad(1, format!("not a creep table: its header is {got:?}, a creep table's is {TABLE_COLUMNS:?}")));
    }
    let mut rows = Vec::new();
    for (i, rec) in reader.records().enumerate() {
        let rec = rec.map_err(|e| bad(i + 2, e.to_string()))?;
        rows.push(TableRow::from_record(&rec).map_err(|m| bad(i + 2, m))?);
    }
    Ok(rows)
}

/// One CSV line of cells.
pub(super) fn csv_line(cells: &[String]) -> String {
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(Vec::new());
    // Writing to a Vec cannot fail.
    let _ = w.write_record(cells);
    String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// The CSV's header line.
pub(super) fn header_line() -> String {
    csv_line(&TABLE_COLUMNS.map(String::from))
}

/// A whole creep table as arrays (module docs of `creeptable`, "Files": the `.npz` layout).
#[derive(Debug, Clone, PartialEq)]
pub struct CreepTable {
    /// The axes.
    pub axes: Axes,
    /// Fx', Fy', Mz' per case, case-major: `forces[3·index + k]` (NaN where the engine gave none).
    pub forces: Vec<f64>,
    /// Status code per case (`STATUS_CODES`).
    pub status: Vec<i8>,
    /// C11, C22, C23 per ellipse: `coefficients[3·(i_ab + n_ab·iν) + k]`.
    pub coefficients: Vec<f64>,
}

/// The sorted distinct values of a column.
fn distinct(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| a.to_bits() == b.to_bits());
    v
}

impl CreepTable {
    /// The table of a complete set of rows: the axes are the distinct values of each coordinate column, and every
    /// case of their product must be there once, at its index. Errors (as text): a missing or repeated case, a row
    /// whose index is not its coordinates'.
    pub fn from_rows(rows: &[TableRow]) -> std::result::Result<CreepTable, String> {
        let axes = Axes {
            nu: distinct(rows.iter().map(|r| r.nu)),
            a_over_b: distinct(rows.iter().map(|r| r.a_over_b)),
            xi: distinct(rows.iter().map(|r| r.xi_n)),
            eta: distinct(rows.iter().map(|r| r.eta_n)),
            phi: distinct(rows.iter().map(|r| r.phi_n)),
        };
        let n = axes.len();
        if rows.len() != n {
            return Err(format!("{} rows for a grid of {} cases: the table is not complete", rows.len(), n));
        }
        let mut forces = vec![f64::NAN; 3 * n];
        let mut status = vec![-1i8; n];
        for r in rows {
            let ok = r.case < n
                && axes.values(r.case).map(f64::to_bits)
                    == [r.nu, r.a_over_b, r.xi_n, r.eta_n, r.phi_n].map(f64::to_bits);
            if !ok {
                return Err(format!("row of case {} is not at its place on the grid", r.case));
            }
            if status[r.case] != -1 {
                return Err(format!("case {} is there twice", r.case));
            }
            status[r.case] = r.status_code();
            for (k, f) in [r.fx_n, r.fy_n, r.mz_n].into_iter().enumerate() {
                forces[3 * r.case + k] = f.unwrap_or(f64::NAN);
            }
        }
        // The coefficients of each ellipse, from its rows (every row of an ellipse holds the same).
        let mut coefficients = vec![f64::NAN; 3 * axes.nu.len() * axes.a_over_b.len()];
        for r in rows {
            let [inu, iab, ..] = axes.coords(r.case);
            let at = 3 * (iab + axes.a_over_b.len() * inu);
            let c = [r.c11, r.c22, r.c23];
            if coefficients[at].is_nan() {
                coefficients[at..at + 3].copy_from_slice(&c);
            } else if coefficients[at..at + 3].iter().zip(c).any(|(a, b)| a.to_bits() != b.to_bits()) {
                return Err(format!("case {}: its C11, C22, C23 differ from its ellipse's other rows", r.case));
            }
        }
        Ok(CreepTable { axes, forces, status, coefficients })
    }

    /// Kalker's linear theory on `axes`, in the normalised form of the module docs of `creeptable`: Fx' = 3ξ',
    /// Fy' = 3η' + φ', Mz' = −3η' C23/C22 where φ' = 0 (NaN elsewhere: C33 is not transcribed); status solved.
    /// A reference for figures; the engine [`super::KalkerLinear`] computes the same in physical units.
    pub fn linear(axes: &Axes) -> CreepTable {
        let n = axes.len();
        let mut forces = Vec::with_capacity(3 * n);
        let mut coefficients = Vec::new();
        for &nu in &axes.nu {
            for &r in &axes.a_over_b {
                let k = crate::theory::kalker::creep_coefficients(r, 1.0, nu).map(|k| [k.c11, k.c22, k.c23]);
                coefficients.extend(k.unwrap_or([f64::NAN; 3]));
            }
        }
        for i in 0..n {
            let [inu, iab, ..] = axes.coords(i);
            let [_, _, xi, eta, phi] = axes.values(i);
            let c = &coefficients[3 * (iab + axes.a_over_b.len() * inu)..][..3];
            let mz = if phi == 0.0 { -3.0 * eta * c[2] / c[1] } else { f64::NAN };
            forces.extend([3.0 * xi, 3.0 * eta + phi, mz]);
        }
        CreepTable { axes: axes.clone(), forces, status: vec![0; n], coefficients }
    }

    /// Reads a table's CSV ([`TableRow::read_csv`], then [`CreepTable::from_rows`]).
    pub fn read_csv(path: &Path) -> Result<CreepTable> {
        let rows = TableRow::read_csv(path)?;
        CreepTable::from_rows(&rows).map_err(|message| Error::Parse { path: path.to_path_buf(), message })
    }

    /// The forces (Fx', Fy', Mz') at grid point (iν, i_ab, iξ, iη, iφ).
    pub fn at(&self, idx: [usize; 5]) -> Option<[f64; 3]> {
        let s = self.axes.shape();
        if idx.iter().zip(s).any(|(&i, n)| i >= n) {
            return None;
        }
        let i = idx.iter().zip(s).fold(0, |acc, (&i, n)| acc * n + i);
        Some([self.forces[3 * i], self.forces[3 * i + 1], self.forces[3 * i + 2]])
    }
}
