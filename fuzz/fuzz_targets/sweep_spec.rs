//! Fuzz target `sweep_spec`: arbitrary bytes (decoded lossily as UTF-8) → `SweepSpec::from_toml`, which must return
//! `Ok` or `Err`, never panic. A spec that parses, with at most `MAX_CASES` cases, is then expanded into its
//! variants (`SweepSpec::cases`), each parsed and validated as a scene, against fixed reference base scenes: the
//! spec's `base` is replaced by `reference/scenes/hertz-hub-fine.toml` and any grid's own `base` by
//! `reference/sweeps/bases/half-plane-cattaneo.toml` (the fuzzer's paths could name any file, `/dev/zero` among
//! them). Expanding must return `Ok` with `len()` cases, or `Err`, never panic. Nothing is run.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rollbem::sweep::SweepSpec;
use std::path::{Path, PathBuf};

/// Largest number of variants built for one input.
const MAX_CASES: usize = 64;

fn reference(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("reference").join(rel)
}

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let spec_path = reference("sweeps/fuzz.toml");
    let mut spec = match SweepSpec::from_toml(&text, &spec_path) {
        Ok(spec) => spec,
        Err(e) => {
            assert!(!e.to_string().trim().is_empty(), "an error without a message");
            return;
        }
    };
    // The number of cases, counted without overflow (each grid value is a non-empty array).
    let cases = spec.grid.iter().try_fold(0usize, |sum, g| {
        let product = g.values().try_fold(1usize, |p, v| p.checked_mul(v.as_array().map_or(1, Vec::len)))?;
        sum.checked_add(product)
    });
    let Some(cases) = cases.filter(|&c| c <= MAX_CASES) else { return };
    assert_eq!(spec.len(), cases);
    spec.base = reference("scenes/hertz-hub-fine.toml");
    for b in spec.grid_base.iter_mut().flatten() {
        *b = reference("sweeps/bases/half-plane-cattaneo.toml");
    }
    if let Ok(built) = spec.cases(&spec_path) {
        assert_eq!(built.len(), cases, "one case per grid point");
        assert!(built.iter().enumerate().all(|(i, c)| c.index == i), "cases numbered from 0 in order");
    }
});
