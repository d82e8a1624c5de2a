//! `rollbem.Stresses`: a run's subsurface stress field ([`rollbem::stresses::StressResult`]) as 2D NumPy arrays.
//!
//! Axes and signs as in `rollbem::stresses`: x along the surface, depth z measured from the flat into the wheel;
//! plane strain, tension positive (on the loaded surface σ_zz = −p and τ_xz = −q); the scene's stress unit. Every
//! field is an array of shape (nz, nx): row j is depth `depth[j]`, column i is `x[i]`; NaN where a point has no value.

use crate::convert::to_python;
use numpy::ndarray::Array2;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use rollbem::stresses::{StressQuantity, StressResult};

/// The subsurface stresses of one run on the `[stresses]` grid.
#[pyclass(name = "Stresses", module = "rollbem", frozen)]
pub struct PyStresses {
    inner: StressResult,
}

impl PyStresses {
    /// Wrap a run's stresses.
    pub fn new(inner: StressResult) -> PyStresses {
        PyStresses { inner }
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
    /// x of the grid's columns (length unit), shape (nx,).
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let g = self.inner.grid;
        PyArray1::from_vec(py, (0..g.points[0]).map(|i| g.x_at(i)).collect())
    }

    /// Depth of the grid's rows below the flat (length unit, into the wheel), shape (nz,).
    #[getter]
    fn depth<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let g = self.inner.grid;
        PyArray1::from_vec(py, (0..g.points[1]).map(|j| g.depth_at(j)).collect())
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

    /// The field of a quantity, shape (nz, nx), float64 (NaN where a point has no value); `KeyError` for a quantity
    /// not computed.
    fn __getitem__<'py>(&self, py: Python<'py>, quantity: &str) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let q = StressQuantity::from_name(quantity)
            .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err(format!("unknown stress quantity `{quantity}`")))?;
        let v = self.values(q).ok_or_else(|| {
            pyo3::exceptions::PyKeyError::new_err(format!(
                "`{quantity}` was not computed (see `[stresses] quantities`)"
            ))
        })?;
        let (nz, nx) = self.shape();
        let a = Array2::from_shape_vec((nz, nx), v)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("stress field of the wrong size: {e}")))?;
        Ok(PyArray2::from_owned_array(py, a))
    }

    fn __contains__(&self, quantity: &str) -> bool {
        StressQuantity::from_name(quantity).is_some_and(|q| self.inner.quantities.contains(&q))
    }

    /// The maximum (largest |value|, sign kept) of each quantity and where: `{quantity: {"value", "x", "depth"}}`
    /// (`None` for a quantity without a value anywhere).
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

    /// x of the surface points (depth 0, the contact elements' centres), shape (n_surface,); empty when the run has
    /// none. The maxima include these points: a sliding contact's stresses peak there.
    #[getter]
    fn surface_x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.inner.surface.as_ref().map(|s| s.x.clone()).unwrap_or_default())
    }

    /// The values of a quantity at the surface points (`surface_x`), shape (n_surface,), float64 (NaN where a point
    /// has no value); `KeyError` for a quantity not computed.
    fn surface<'py>(&self, py: Python<'py>, quantity: &str) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let q = StressQuantity::from_name(quantity)
            .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err(format!("unknown stress quantity `{quantity}`")))?;
        if !self.inner.quantities.contains(&q) {
            return Err(pyo3::exceptions::PyKeyError::new_err(format!(
                "`{quantity}` was not computed (see `[stresses] quantities`)"
            )));
        }
        let v = match &self.inner.surface {
            Some(s) => s.values.get(q.name()).map(|v| v.iter().map(|x| x.unwrap_or(f64::NAN)).collect()),
            None => Some(Vec::new()),
        };
        let v = v.ok_or_else(|| {
            pyo3::exceptions::PyRuntimeError::new_err(format!("surface values of `{quantity}` missing"))
        })?;
        Ok(PyArray1::from_vec(py, v))
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
