//! Fuzz target `scene`: arbitrary bytes (decoded lossily as UTF-8) → `Scene::from_toml`, which parses and validates
//! a scene. It must return `Ok` or `Err`, never panic; an `Err` must carry a message.
//!
//! Parse and validate only: running the parsed scenes through the pipeline is left to a later target (the run API
//! is being replaced).
#![no_main]

mod toml_mutator;

use libfuzzer_sys::fuzz_target;
use rollbem::scene::Scene;
use std::path::Path;

// Half libFuzzer's byte-level mutations, half structure-aware ones that keep the input TOML (`toml_mutator.rs`).
libfuzzer_sys::fuzz_mutator!(|data: &mut [u8], size: usize, max_size: usize, seed: u32| {
    toml_mutator::mutate(data, size, max_size, seed, include_str!("../dicts/scene.dict"))
});

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Err(e) = Scene::from_toml(&text, Path::new("<fuzz>")) {
        assert!(!e.to_string().trim().is_empty(), "an error without a message");
    }
});
