//! FASTSIM and creep-force tables from Python: `rollbem.fastsim(...)` (one case, [`rollbem::fastsim::solve`]) and
//! `rollbem.creep_table(spec, out, ...)` ([`rollbem::creeptable::run_table`]); the tables are read back by the pure
//! Python `rollbem.creeptable`.

use crate::errors::{to_py, Failure};
use crate::worker;
use numpy::{IntoPyArray, PyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::creeptable::{run_table_with, FastsimArgs, TableOptions};
use rollbem::sweep::Shard;
use std::path::PathBuf;

/// The key of a flag's error: `--normal-force` → `normal_force`.
fn as_key(e: rollbem::Error) -> rollbem::Error {
    match e {
        rollbem::Error::Invalid { path, field, message } if field.starts_with("--") => {
            rollbem::Error::Invalid { path, field: field.trim_start_matches("--").replace('-', "_"), message }
        }
        other => other,
    }
}

/// One steady-rolling case of an elliptic contact by FASTSIM (Kalker's simplified theory), CONTACT's conventions
/// (creepages of body 1 relative to body 2, forces on body 1, rolling along +x by default; units consistent, e.g.
/// mm, N, N/mm², φ in rad/mm). Returns a dict: the inputs, `fx`, `fy`, `mz`, `fn_discrete`, `n_contact`,
/// `n_adhesion`, `n_slip`, `flexibilities` (L1, L2, L3), `coefficients` (C11, C22, C23) and, with
/// `elements=True`, per-element arrays `x`, `y`, `pn`, `px`, `py`, `state` (0 exterior, 1 adhesion, 2 slip), x
/// fastest. Errors: `InputError` naming the argument.
#[pyfunction]
#[pyo3(signature = (*, a, b, shear_modulus, nu, mu, normal_force, xi = 0.0, eta = 0.0, phi = 0.0,
    flexibility = "weighted", bound = "parabolic", direction = "+x", mx = 100,
    my = 100, contact_grid = None, elements = false))]
#[allow(clippy::too_many_arguments)]
pub fn fastsim<'py>(
    py: Python<'py>,
    a: f64,
    b: f64,
    shear_modulus: f64,
    nu: f64,
    mu: f64,
    normal_force: f64,
    xi: f64,
    eta: f64,
    phi: f64,
    flexibility: &str,
    bound: &str,
    direction: &str,
    mx: usize,
    my: usize,
    contact_grid: Option<f64>,
    elements: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let args = FastsimArgs {
        a,
        b,
        shear_modulus,
        nu,
        mu,
        normal_force,
        xi,
        eta,
        phi,
        flexibility: flexibility.to_string(),
        bound: bound.to_string(),
        direction: direction.to_string(),
        mx,
        my,
        contact_grid,
        json: None,
        csv: None,
    };
    let fail = |e: rollbem::Error| to_py(py, Failure::Rollbem(as_key(e)));
    let (_, _, _, s) = py.detach(|| args.solve()).map_err(fail)?;
    let d = PyDict::new(py);
    for (k, v) in [("a", a), ("b", b), ("shear_modulus", shear_modulus), ("nu", nu), ("mu", mu)] {
        d.set_item(k, v)?;
    }
    for (k, v) in [("normal_force", normal_force), ("xi", xi), ("eta", eta), ("phi", phi)] {
        d.set_item(k, v)?;
    }
    for (k, v) in [("flexibility", &args.flexibility), ("bound", &args.bound), ("direction", &args.direction)] {
        d.set_item(k, v)?;
    }
    d.set_item("mx", mx)?;
    d.set_item("my", my)?;
    d.set_item("contact_grid", contact_grid)?;
    for (k, v) in [("fx", s.fx), ("fy", s.fy), ("mz", s.mz), ("fn_discrete", s.fn_discrete)] {
        d.set_item(k, v)?;
    }
    for (k, v) in [("n_contact", s.n_contact), ("n_adhesion", s.n_adhesion), ("n_slip", s.n_slip)] {
        d.set_item(k, v)?;
    }
    d.set_item("flexibilities", s.flexibilities.to_vec())?;
    let k = s.coefficients;
    d.set_item("coefficients", vec![k.c11, k.c22, k.c23])?;
    if elements {
        let col = |f: &dyn Fn(&rollbem::fastsim::Element) -> f64| -> Bound<'py, PyArray1<f64>> {
            s.elements.iter().map(f).collect::<Vec<f64>>().into_pyarray(py)
        };
        d.set_item("x", col(&|e| e.x))?;
        d.set_item("y", col(&|e| e.y))?;
        d.set_item("pn", col(&|e| e.pn))?;
        d.set_item("px", col(&|e| e.px))?;
        d.set_item("py", col(&|e| e.py))?;
        let state: Vec<i8> = s
            .elements
            .iter()
            .map(|e| match e.state {
                rollbem::fastsim::State::Exterior => 0,
                rollbem::fastsim::State::Adhesion => 1,
                rollbem::fastsim::State::Slip => 2,
            })
            .collect();
        d.set_item("state", state.into_pyarray(py))?;
    }
    Ok(d)
}

/// Runs a creep-table spec (README "Creep-force tables") into `out` (a CSV, with the `.npz` beside it for a whole
/// table): all of it or `shard` "k/n", resumed from its journal with `resume=True`. Returns a dict: `total`,
/// `cases`, `ran`, `resumed`, `statuses` (solved, gross_sliding, not_converged, refused), `npz` (its path or None).
/// Errors: `InputError` naming the spec's key, `OutputError`. Ctrl-C stops it before its next chunk of cases (the
/// journal keeps the finished ones: `resume=True` goes on).
#[pyfunction]
#[pyo3(signature = (spec, out, *, shard = None, resume = false, allow_large = false))]
pub fn creep_table<'py>(
    py: Python<'py>,
    spec: PathBuf,
    out: PathBuf,
    shard: Option<String>,
    resume: bool,
    allow_large: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let shard = match shard {
        None => None,
        Some(s) => Some(s.parse::<Shard>().map_err(|message| {
            let error = rollbem::Error::Invalid { path: spec.clone(), field: "shard".into(), message };
            to_py(py, Failure::Rollbem(error))
        })?),
    };
    let options = TableOptions { shard, resume, allow_large, dry_run: false };
    let o = worker::run(py, move |cancel| Ok(run_table_with(&spec, &out, &options, cancel)?))?;
    let d = PyDict::new(py);
    for (k, v) in [("total", o.total), ("cases", o.cases), ("ran", o.ran), ("resumed", o.resumed)] {
        d.set_item(k, v)?;
    }
    let names = ["solved", "gross_sliding", "not_converged", "refused"];
    let statuses = PyDict::new(py);
    for (k, v) in names.iter().zip(o.statuses) {
        statuses.set_item(k, v)?;
    }
    d.set_item("statuses", statuses)?;
    d.set_item("npz", o.npz.map(|p| p.display().to_string()))?;
    Ok(d)
}
