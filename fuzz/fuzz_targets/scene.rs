//! Fuzz target `scene`: arbitrary bytes (decoded lossily as UTF-8) → `Scene::from_toml`, which parses and validates
//! a scene. It must return `Ok` or `Err`, never panic; an `Err` must carry a message.
//!
//! A valid scene is then run through the model API (`bounded.rs`): if its mesh has at most
//! `bounded::MAX_RUN_ELEMENTS` elements and its load path at most `bounded::MAX_SUBSTEPS` substeps, its iteration
//! budgets are capped, `Model::build`, `Model::lcp` and `Model::solve` must each return `Ok` or an `Err` with a
//! message, and the report's runs must be consistent (a solved run with finite residuals, resultants and nodal
//! values; an unsolved one without residuals or resultants, with a message).
#![no_main]

mod bounded;
mod toml_mutator;

use libfuzzer_sys::fuzz_target;
use rollbem::scene::Scene;
use std::path::Path;

// A quarter libFuzzer's byte-level mutations, three quarters structure-aware ones that keep the input TOML
// (`toml_mutator.rs`).
libfuzzer_sys::fuzz_mutator!(|data: &mut [u8], size: usize, max_size: usize, seed: u32| {
    toml_mutator::mutate(data, size, max_size, seed, include_str!("../dicts/scene.dict"))
});

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match Scene::from_toml(&text, Path::new("<fuzz>")) {
        Ok(scene) => {
            bounded::run(&scene);
        }
        Err(e) => assert!(!e.to_string().trim().is_empty(), "an error without a message"),
    }
});
