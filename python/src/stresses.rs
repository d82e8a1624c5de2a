//! `rollbem.Stresses`: a run's subsurface stress field ([`rollbem::stresses::StressResult`]) as 2D NumPy arrays.
//!
//! Axes and signs as in `rollbem::stresses`: x along the surface, depth z measured from the flat into the wheel;
//! plane strain, tension positive (on the loaded surface σ_zz = −p and τ_xz = −q); the scene's stress unit. Every
//! field is an array of shape (nz, nx): row j is depth `depth[j]`, column i is `x[i]`; NaN where a point has no value.
//!
//! Every array is made once, on first access, and kept read-only (as a run's node arrays, `crate::report`):
//! `st["von_mises"] is st["von_mises"]`.

use crate::convert::to_python;
use crate::report::read_only;
use numpy::ndarray::Array2;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use rollbem::stresses::{StressQuantity, StressResult};
use std::collections::BTreeMap;

/// The subsurface stresses of one run on the `[stresses]` grid.
#[pyclass(name = "Stresses", module = "rollbem", frozen)]
pub struct PyStresses {
    inner: StressResult,
    /// `x`, `depth` and `surface_x`, made on first access.
    axes: PyOnceLock<[Py<PyArray1<f64>>; 3]>,
    /// The field of every quantity computed, made on first access.
    fields: PyOnceLock<BTreeMap<&'static str, Py<PyArray2<f64>>>>,
    /// The surface values of every quantity computed, made on first access.
    surfaces: PyOnceLock<BTreeMap<&'static str, Py<PyArray1<f64>>>>,
}

/// The `KeyError` of a quantity name that is not a stress quantity, or was not computed.
fn unknown(quantity: &str, known: bool) -> PyErr {
    let what = if known {
        format!("'{quantity}' was not computed (see `[stresses] quantities`)")
    } else {
        format!(
            "'{quantity}' is not a stress quantity (sxx, szz, txz, syy, principal_shear, von_mises, orthogonal_shear)"
        )
    };
    pyo3::exceptions::PyKeyError::new_err(what)
}

impl PyStresses {
    /// Wrap a run's stresses.
    pub fn new(inner: StressResult) -> PyStresses {
        PyStresses { inner, axes: PyOnceLock::new(), fields: PyOnceLock::new(), surfaces: PyOnceLock::new() }
    }

    /// The kept axes `[x, depth, surface_x]`.
    fn axes(&self, py: Python<'_>) -> PyResult<&[Py<PyArray1<f64>>; 3]> {
        self.axes.get_or_try_init(py, || -> PyResult<_> {
            let g = self.inner.grid;
            let arr =
                |v: Vec<f64>| -> PyResult<Py<PyArray1<f64>>> { Ok(read_only(PyArray1::from_vec(py, v))?.unbind()) };
            Ok([
                arr((0..g.points[0]).map(|i| g.x_at(i)).collect())?,
                arr((0..g.points[1]).map(|j| g.depth_at(j)).collect())?,
                arr(self.inner.surface.as_ref().map(|s| s.x.clone()).unwrap_or_default())?,
            ])
        })
    }

    /// The computed quantity named `quantity`, or the `KeyError`.
    fn quantity(&self, quantity: &str) -> PyResult<StressQuantity> {
        let q = StressQuantity::from_name(quantity).ok_or_else(|| unknown(quantity, false))?;
        if self.inner.quantities.contains(&q) {
            Ok(q)
        } else {
            Err(unknown(quantity, true))
        }
    }

    /// The values of a quantity, row-major, NaN where refused; `None` when it was not computed.
    fn values(&self, q: StressQuantity) -> Option<Vec<f64>> {
        if !self.inner.quantities.contains(&q) {
            return None;
        }
        if let Some(v) = self.inner.values.as_ref().and_then(|f| f.values.get(q.name())) {
            return Some(v.iter().map(|x| x.unwrap_or(f64::NAN)).collect());
        }
        let field = &self.inner.field;
        (!field.stress.is_empty())
            .then(|| (0..field.stress.len()).map(|k| field.value(q, k).unwrap_or(f64::NAN)).collect())
    }
}

#[pymethods]
impl PyStresses {
    /// x of the grid's columns (length unit), shape (nx,), read-only.
    #[getter]
    fn x(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(self.axes(py)?[0].clone_ref(py))
    }

    /// Depth of the grid's rows below the flat (length unit, into the wheel), shape (nz,), read-only.
    #[getter]
    fn depth(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(self.axes(py)?[1].clone_ref(py))
    }

    /// The grid's shape (nz, nx): the shape of every field.
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.inner.grid.points[1], self.inner.grid.points[0])
    }

    /// The quantities computed (`sxx`, `szz`, `txz`, `syy`, `principal_shear`, `von_mises`, `orthogonal_shear`).
    #[getter]
    fn quantities(&self) -> Vec<&'static str> {
        self.inner.quantities.iter().map(|q| q.name()).collect()
    }

    /// The field of a quantity (stress unit, tension positive), shape (nz, nx), float64, read-only (NaN where a
    /// point has no value); `KeyError` for a name that is not a stress quantity or a quantity not computed.
    fn __getitem__(&self, py: Python<'_>, quantity: &str) -> PyResult<Py<PyArray2<f64>>> {
        let q = self.quantity(quantity)?;
        let fields = self.fields.get_or_try_init(py, || -> PyResult<_> {
            let (nz, nx) = self.shape();
            let mut out = BTreeMap::new();
            for q in &self.inner.quantities {
                let Some(v) = self.values(*q) else { continue };
                let a = Array2::from_shape_vec((nz, nx), v).map_err(|e| {
                    pyo3::exceptions::PyRuntimeError::new_err(format!("stress field of the wrong size: {e}"))
                })?;
                out.insert(q.name(), read_only(PyArray2::from_owned_array(py, a))?.unbind());
            }
            Ok(out)
        })?;
        fields.get(q.name()).map(|a| a.clone_ref(py)).ok_or_else(|| unknown(quantity, true))
    }

    fn __contains__(&self, quantity: &str) -> bool {
        StressQuantity::from_name(quantity).is_some_and(|q| self.inner.quantities.contains(&q))
    }

    /// The maximum (largest |value|, sign kept; stress unit) of each quantity and where (`x`, `depth`: length
    /// unit): `{quantity: {"value", "x", "depth"}}` (`None` for a quantity without a value anywhere).
    #[getter]
    fn maxima<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
        let d = pyo3::types::PyDict::new(py);
        for (q, m) in &self.inner.maxima {
            d.set_item(q.name(), to_python(py, m)?)?;
        }
        Ok(d)
    }

    /// The body whose field this is: `"wheel"`, or `"counter_body"` for an elastic counter-body's own field (depth
    /// measured into it).
    #[getter]
    fn body(&self) -> &str {
        &self.inner.body
    }

    /// x of the surface points (depth 0, the contact elements' centres; length unit), shape (n_surface,),
    /// read-only; empty when the run has none. The maxima include these points: a sliding contact's stresses peak
    /// there.
    #[getter]
    fn surface_x(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(self.axes(py)?[2].clone_ref(py))
    }

    /// The values of a quantity at the surface points (`surface_x`; stress unit, tension positive), shape
    /// (n_surface,), float64, read-only (NaN where a point has no value); `KeyError` as for `st[quantity]`.
    fn surface(&self, py: Python<'_>, quantity: &str) -> PyResult<Py<PyArray1<f64>>> {
        let q = self.quantity(quantity)?;
        let surfaces = self.surfaces.get_or_try_init(py, || -> PyResult<_> {
            let mut out = BTreeMap::new();
            for q in &self.inner.quantities {
                let v = match &self.inner.surface {
                    Some(s) => match s.values.get(q.name()) {
                        Some(v) => v.iter().map(|x| x.unwrap_or(f64::NAN)).collect(),
                        None => continue,
                    },
                    None => Vec::new(),
                };
                out.insert(q.name(), read_only(PyArray1::from_vec(py, v))?.unbind());
            }
            Ok(out)
        })?;
        surfaces
            .get(q.name())
            .map(|a| a.clone_ref(py))
            .ok_or_else(|| pyo3::exceptions::PyRuntimeError::new_err(format!("surface values of `{quantity}` missing")))
    }

    /// Number of refused points per reason (`outside_body`, `near_boundary`, `singular`).
    #[getter]
    fn refused(&self) -> std::collections::BTreeMap<String, usize> {
        self.inner.refused.clone()
    }

    /// Wall-clock time of the evaluation (seconds).
    #[getter]
    fn time_s(&self) -> f64 {
        self.inner.time_s
    }

    fn __repr__(&self) -> String {
        let (nz, nx) = self.shape();
        format!("<rollbem.Stresses of the {} {nz}×{nx}: {}>", self.inner.body, self.quantities().join(", "))
    }
}
