//! `rollbem._core`: the Python binding of rollbem (PyO3), the extension module of the `rollbem` package
//! (`python/rollbem/`, which adds the exceptions, `sweep` and the type stubs).
//!
//! The binding is a thin layer over the library's model API: [`scene::PyScene`] wraps a validated
//! [`rollbem::scene::Scene`], [`model::PyModel`] a [`rollbem::pipeline::Model`] built once and solved many times,
//! [`report::PyReport`] the result document with node results as NumPy arrays, [`stresses::PyStresses`] a stress
//! field as 2D arrays. Long work runs off the interpreter, interruptible ([`worker`]); the library's errors become
//! Python exceptions naming the key ([`errors`]). It needs no `unsafe` of its own (PyO3's macros generate the FFI).

#![forbid(unsafe_code)]
#![warn(missing_docs)]
// A cdylib: every item is private, and its docs are read with `cargo doc --document-private-items`.
#![allow(rustdoc::private_intra_doc_links)]

mod convert;
mod creep;
mod drive;
mod errors;
mod model;
mod plugin;
mod report;
mod scene;
mod space;
mod stresses;
mod sweep;
mod worker;

use pyo3::prelude::*;

/// The extension module.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<scene::PyScene>()?;
    m.add_class::<model::PyModel>()?;
    m.add_class::<report::PyReport>()?;
    m.add_class::<report::PyRun>()?;
    m.add_class::<report::PyStep>()?;
    m.add_class::<report::PyResiduals>()?;
    m.add_class::<stresses::PyStresses>()?;
    m.add_class::<space::PySpaceScene>()?;
    m.add_class::<space::PySpaceModel>()?;
    m.add_class::<space::PySpaceReport>()?;
    m.add_class::<space::PySpaceStep>()?;
    m.add_function(wrap_pyfunction!(space::run3d, m)?)?;
    m.add("ELEMENT_STATES", rollbem::results::space::ELEMENT_STATES.to_vec())?;
    m.add_function(wrap_pyfunction!(model::run, m)?)?;
    m.add_function(wrap_pyfunction!(model::_rust_creep_curve, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::_sweep_rows, m)?)?;
    m.add_function(wrap_pyfunction!(plugin::register_solver, m)?)?;
    m.add_function(wrap_pyfunction!(creep::fastsim, m)?)?;
    m.add_function(wrap_pyfunction!(creep::creep_table, m)?)?;
    m.add("NODE_STATES", report::NODE_STATES.to_vec())?;
    m.add("SCHEMA_VERSION", rollbem::results::SCHEMA_VERSION)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
