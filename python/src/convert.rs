//! Python values to and from the library's serde types.
//!
//! Inward, a Python mapping (nested dicts, lists, numbers, strings, `None`) becomes a JSON value ([`to_json`]) and
//! then a typed document by serde with the path of the failing key tracked ([`typed`], `serde_path_to_error`), so
//! that an unknown key, a missing key or a wrong type is an `InputError` naming the dotted key, as a range error
//! is (the library's validation names it). TOML text goes the same way ([`toml_document`]). Outward, a serialisable
//! value becomes Python objects through the `json` module ([`to_python`]): the document as `rollbem run --json`
//! writes it.

use crate::errors::{keyed, Failure};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use rollbem::Error;
use serde::de::DeserializeOwned;
use serde_json::{Map, Value};
use std::path::Path;

/// A Python value as JSON; `key` is the dotted key it sits at (for the error of a value of no JSON type or a
/// non-finite number, which a scene cannot hold).
pub fn to_json(obj: &Bound<'_, PyAny>, key: &str, origin: &Path) -> Result<Value, Failure> {
    let bad = |what: String| keyed(origin, key, what);
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if obj.is_instance_of::<PyBool>() {
        return Ok(Value::Bool(obj.extract::<bool>().map_err(|e| bad(e.to_string()))?));
    }
    if obj.is_instance_of::<PyString>() {
        return Ok(Value::String(obj.extract::<String>().map_err(|e| bad(e.to_string()))?));
    }
    if obj.is_instance_of::<PyInt>() || (!obj.is_instance_of::<PyFloat>() && obj.hasattr("__index__").unwrap_or(false))
    {
        if let Ok(v) = obj.extract::<i64>() {
            return Ok(Value::from(v));
        }
        return obj.extract::<u64>().map(Value::from).map_err(|_| bad("an integer out of range".into()));
    }
    if obj.is_instance_of::<PyFloat>() || obj.hasattr("__float__").unwrap_or(false) {
        let v = obj.extract::<f64>().map_err(|e| bad(e.to_string()))?;
        return serde_json::Number::from_f64(v)
            .map(Value::Number)
            .ok_or_else(|| bad(format!("must be a finite number (got {v})")));
    }
    if let Ok(dict) = obj.cast::<PyDict>() {
        return mapping(dict.iter(), key, origin);
    }
    if obj.hasattr("tolist").unwrap_or(false) && obj.hasattr("shape").unwrap_or(false) {
        // A NumPy array: its values as Python lists.
        let list = obj.call_method0("tolist").map_err(|e| bad(e.to_string()))?;
        return to_json(&list, key, origin);
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for (i, item) in obj.try_iter().map_err(|e| bad(e.to_string()))?.enumerate() {
            let item = item.map_err(|e| bad(e.to_string()))?;
            out.push(to_json(&item, &format!("{key}[{i}]"), origin)?);
        }
        return Ok(Value::Array(out));
    }
    if obj.hasattr("items").unwrap_or(false) {
        // Another mapping type.
        let items = obj.call_method0("items").and_then(|i| i.try_iter()).map_err(|e| bad(e.to_string()))?;
        let mut pairs = Vec::new();
        for item in items {
            let (k, v): (Bound<'_, PyAny>, Bound<'_, PyAny>) =
                item.and_then(|i| i.extract()).map_err(|e| bad(e.to_string()))?;
            pairs.push((k, v));
        }
        return mapping(pairs.into_iter(), key, origin);
    }
    let ty = obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into());
    Err(bad(format!("a value of type `{ty}` is not a scene value (numbers, strings, booleans, lists, dicts)")))
}

/// A mapping with string keys as a JSON object.
fn mapping<'py>(
    items: impl Iterator<Item = (Bound<'py, PyAny>, Bound<'py, PyAny>)>,
    key: &str,
    origin: &Path,
) -> Result<Value, Failure> {
    let mut out = Map::new();
    for (k, v) in items {
        let Ok(k) = k.extract::<String>() else {
            return Err(keyed(origin, key, format!("keys must be strings (got {k})")));
        };
        let at = if key.is_empty() { k.clone() } else { format!("{key}.{k}") };
        out.insert(k, to_json(&v, &at, origin)?);
    }
    Ok(Value::Object(out))
}

/// The typed value of a JSON value, with the key of the first error (prefixed by `prefix`, e.g. `drive`).
pub fn typed<T: DeserializeOwned>(value: Value, prefix: &str, origin: &Path) -> Result<T, Failure> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let key = join(prefix, &e.path().to_string());
        let error = Error::Parse { path: origin.to_path_buf(), message: format!("`{key}`: {}", e.inner()) };
        Failure::Keyed { error, key }
    })
}

/// A scene document from TOML text, with the key of the first error; the message is the TOML parser's (line,
/// column and the text), as the CLI prints it.
pub fn toml_document(text: &str, origin: &Path) -> Result<rollbem::scene::document::SceneDocument, Failure> {
    let parse_error =
        |e: toml::de::Error| Error::Parse { path: origin.to_path_buf(), message: e.to_string().trim_end().to_string() };
    let de = toml::Deserializer::parse(text).map_err(|e| Failure::Rollbem(parse_error(e)))?;
    serde_path_to_error::deserialize(de).map_err(|e| {
        let key = e.path().to_string();
        let error = parse_error(e.into_inner());
        if key.is_empty() || key == "." {
            Failure::Rollbem(error)
        } else {
            Failure::Keyed { error, key }
        }
    })
}

/// `prefix.path`, where either may be empty (`serde_path_to_error` writes the root as `.`).
fn join(prefix: &str, path: &str) -> String {
    let path = if path == "." { "" } else { path };
    match (prefix.is_empty(), path.is_empty()) {
        (true, _) => path.to_string(),
        (false, true) => prefix.to_string(),
        (false, false) if path.starts_with('[') => format!("{prefix}{path}"),
        (false, false) => format!("{prefix}.{path}"),
    }
}

/// A serialisable value as Python objects (dicts, lists, floats, ints, strings, `None`), through `json.loads`.
pub fn to_python<'py>(py: Python<'py>, value: &impl serde::Serialize) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("cannot serialise: {e}")))?;
    py.import("json")?.call_method1("loads", (text,))
}
