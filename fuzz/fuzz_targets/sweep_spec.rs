//! Fuzz target `sweep_spec`: arbitrary bytes (decoded lossily as UTF-8) → `SweepSpec::from_toml`, which must return
//! `Ok` or `Err`, never panic; a spec that parses has 1 to `sweep::MAX_CASES` cases. One with at most
//! `MAX_FUZZ_CASES` cases is then expanded into its variants (`SweepSpec::cases`), each parsed and validated as a
//! scene, against fixed reference base scenes: the spec's `base` is replaced by
//! `reference/scenes/hertz-hub-fine.toml` and any grid's own `base` by
//! `reference/sweeps/bases/half-plane-cattaneo.toml` (the fuzzer's paths could name any file, `/dev/zero` among
//! them). Expanding must return `Ok` with `len()` cases, or `Err`, never panic. Nothing is run.
#![no_main]

mod toml_mutator;

use libfuzzer_sys::fuzz_target;
use rollbem::sweep::{SweepSpec, MAX_CASES};
use std::path::{Path, PathBuf};

/// Largest number of variants built for one input.
const MAX_FUZZ_CASES: usize = 64;

fn reference(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("reference").join(rel)
}

// A quarter libFuzzer's byte-level mutations, three quarters structure-aware ones that keep the input TOML
// (`toml_mutator.rs`).
libfuzzer_sys::fuzz_mutator!(|data: &mut [u8], size: usize, max_size: usize, seed: u32| {
    toml_mutator::mutate(data, size, max_size, seed, include_str!("../dicts/sweep_spec.dict"))
});

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
    // A spec that reads has a countable number of cases, within the library's limit.
    let cases = spec.len();
    assert!((1..=MAX_CASES).contains(&cases), "{cases} cases");
    if cases > MAX_FUZZ_CASES {
        return;
    }
    spec.base = reference("scenes/hertz-hub-fine.toml");
    for b in spec.grid_base.iter_mut().flatten() {
        *b = reference("sweeps/bases/half-plane-cattaneo.toml");
    }
    if let Ok(built) = spec.cases(&spec_path) {
        assert_eq!(built.len(), cases, "one case per grid point");
        assert!(built.iter().enumerate().all(|(i, c)| c.index == i), "cases numbered from 0 in order");
    }
});
