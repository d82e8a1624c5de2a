//! Sweeps from Python: [`rollbem::sweep::sweep_rows`] run on a worker thread, its rows as lists of typed cells
//! (`rollbem.sweep` in `rollbem/__init__.py` makes them dicts, or a pandas DataFrame).

use crate::errors::{to_py, Failure};
use crate::worker;
use pyo3::prelude::*;
use rollbem::sweep::{sweep_table_with, Shard, SweepRow};
use std::path::PathBuf;

/// A CSV cell as a Python value: empty → `None`, an integer → int, a number → float, anything else → str.
fn cell<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    if text.is_empty() {
        return Ok(py.None().into_bound(py));
    }
    if let Ok(v) = text.parse::<i64>() {
        return Ok(v.into_pyobject(py)?.into_any());
    }
    if let Ok(v) = text.parse::<f64>() {
        return Ok(v.into_pyobject(py)?.into_any());
    }
    Ok(text.into_pyobject(py)?.into_any())
}

/// The cell of `name` in a row (`case` is the row's case number).
fn text(row: &SweepRow, name: &str) -> String {
    match name {
        "case" => row.case.to_string(),
        _ => row.cell(name),
    }
}

/// A sweep's columns and its rows of cells.
type Rows<'py> = (Vec<String>, Vec<Vec<Bound<'py, PyAny>>>);

/// Run the sweep spec at `spec` (its shard `k/n`, or all of it): (the columns of the sweep CSV, one list of cells per
/// row), rows sorted by case then solver, the cells typed (`None` where empty). Runs the cases in parallel. A sweep
/// of 3D half-space scenes has its own columns (README, "Sweeps").
#[pyfunction]
#[pyo3(signature = (spec, shard = None))]
pub fn _sweep_rows<'py>(py: Python<'py>, spec: PathBuf, shard: Option<String>) -> PyResult<Rows<'py>> {
    let shard = match shard {
        None => None,
        Some(s) => Some(s.parse::<Shard>().map_err(|message| {
            let error = rollbem::Error::Invalid { path: spec.clone(), field: "shard".into(), message };
            to_py(py, Failure::Rollbem(error))
        })?),
    };
    let (header, rows) = worker::run(py, move |cancel| Ok(sweep_table_with(&spec, shard, false, cancel)?))?;
    let columns = header.names;
    let mut out = Vec::with_capacity(rows.len());
    for row in &rows {
        out.push(columns.iter().map(|c| cell(py, &text(row, c))).collect::<PyResult<Vec<_>>>()?);
    }
    Ok((columns, out))
}
