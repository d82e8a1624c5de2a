//! Fuzz target `lcp_file`: arbitrary bytes (decoded lossily as UTF-8) → `lcp_io::parse` (Siconos' plain LCP format,
//! dense and sparse-block storage). It must return `Ok` or `Err`, never panic. A parsed LCP of size
//! n ≤ `MAX_SOLVE_SIZE` is then solved by both Lemke engines (block-revised `solve`, dense `solve_dense`) with a
//! capped pivot budget: they must end with a status, never panic, and return z and w of size n.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rollbem::lcp_io;
use rollbem::solvers::lemke::{self, dense::solve_dense, LemkeSettings};
use std::path::Path;

/// Largest LCP solved: keeps one execution within a millisecond or so.
const MAX_SOLVE_SIZE: usize = 30;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let lcp = match lcp_io::parse(&text, Path::new("<fuzz>")) {
        Ok(lcp) => lcp,
        Err(e) => {
            assert!(!e.to_string().trim().is_empty(), "an error without a message");
            return;
        }
    };
    let n = lcp.size();
    if n > MAX_SOLVE_SIZE {
        return;
    }
    // Pivot budget 5 n + 100 (the default is 50 n + 100): every engine path is reached, no input can stall.
    let settings = LemkeSettings { max_pivots_per_unknown: 5, refactor_every: 7, ..LemkeSettings::default() };
    for (engine, out) in [("block", lemke::solve(&lcp, &settings)), ("dense", solve_dense(&lcp, &settings))] {
        assert_eq!((out.z.len(), out.w.len()), (n, n), "{engine}: z and w must have the LCP's size");
        assert!(out.pivots <= 5 * n + 100, "{engine}: {} pivots beyond the budget", out.pivots);
    }
});
