//! Siconos numerics' LCP test collection (`reference/lcp/siconos/`, 20 files, three of them in sparse-block
//! storage), read by `rollbem::lcp_io` and solved by rollbem's Lemke (`rollbem::solvers::lemke::solve`).
//!
//! Where the expected values come from:
//! - **Siconos' own answer**: `reference/lcp/siconos/siconos_lemke.tsv`, the status, iterations, residual
//!   (`lcp_compute_error`) and z of Siconos' `lcp_lexicolemke` (Debian's libsiconos-numerics-dev 4.4.0), written by
//!   `bash reference/lcp/siconos/regen.sh` (which compiles `benches/peer/driver.c`);
//! - **an enumeration** of every vertex solution for the files with n ≤ 10 (`tests/common/lcp_enum.rs`, which
//!   shares no code with Lemke), and the P-matrix test (every principal minor positive ⇒ exactly one solution,
//!   CPS Thm 3.3.7);
//! - for `lcp_mmc` (n = 26), uniqueness because M is symmetric positive definite (checked here by Cholesky);
//! - the block files' dense twins in the same collection (`lcp_X_block.dat` holds the LCP of `lcp_X.dat`).
//!
//! "Solved" is judged by `rollbem::lcp_residual::residuals` (scaled by s = max(‖q‖∞, ‖M‖∞‖z‖∞)), required below
//! 64 ε: every solved file of the collection is solved to round-off.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
#[path = "common/lcp_enum.rs"]
mod lcp_enum;

use lcp_enum::{enumerate, is_p_matrix};
use rollbem::lcp_io;
use rollbem::lcp_residual::residuals;
use rollbem::solvers::lemke::{self, LemkeSettings};
use rollbem::solvers::{Lcp, Termination};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Residual (max of [`residuals`]) below which an answer counts as exact to round-off.
const ROUND_OFF: f64 = 64.0 * f64::EPSILON;

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("reference/lcp/siconos")
}

/// The files of the collection, sorted by name.
fn files() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir())
        .expect("reference/lcp/siconos")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("lcp_") && n.ends_with(".dat"))
        .collect();
    v.sort();
    v
}

fn read(name: &str) -> Lcp {
    lcp_io::read(&dir().join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// One line of `siconos_lemke.tsv`.
struct SiconosAnswer {
    n: usize,
    solved: bool,
    iterations: usize,
    error: f64,
    z: Vec<f64>,
}

fn siconos_answers() -> BTreeMap<String, SiconosAnswer> {
    let text = std::fs::read_to_string(dir().join("siconos_lemke.tsv")).expect("siconos_lemke.tsv");
    let mut out = BTreeMap::new();
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        assert_eq!(f.len(), 7, "siconos_lemke.tsv: {line}");
        let z: Vec<f64> = f[6].split(',').map(|v| v.parse().expect("z entry")).collect();
        let a = SiconosAnswer {
            n: f[1].parse().expect("n"),
            solved: f[2] == "solved",
            iterations: f[4].parse().expect("iterations"),
            error: f[5].parse().expect("error"),
            z,
        };
        out.insert(f[0].to_string(), a);
    }
    out
}

/// Files where rollbem's Lemke is expected NOT to solve, with the reason (the enumeration's verdict is asserted).
fn expected_failures() -> BTreeMap<&'static str, (bool, &'static str)> {
    // (has a solution?, why Lemke stops without one)
    BTreeMap::from([
        (
            "lcp_CPS_3.dat",
            (
                true,
                "bimatrix game (the file's remark: CPS 2009, Example 4.4.23): M = [[0, A], [B, 0]] with A, B > 0 \
                 and q = −e. It has solutions (the enumeration finds 3 vertices), but M is copositive without being \
                 copositive-plus (z = e₁ gives zᵀMz = 0 and (M + Mᵀ)z ≠ 0), so Lemke's theorem does not apply; with \
                 the covering vector e both Siconos and rollbem stop on a secondary ray after the first pivot",
            ),
        ),
        (
            "lcp_Pang_isolated_sol_perturbed.dat",
            (false, "q of lcp_Pang_isolated_sol perturbed by −1e−4: the enumeration finds no solution"),
        ),
    ])
}

#[test]
fn the_collection_is_all_there() {
    let names = files();
    assert_eq!(names.len(), 20, "{names:?}");
    let answers = siconos_answers();
    assert_eq!(answers.keys().cloned().collect::<Vec<_>>(), names, "siconos_lemke.tsv covers every file");
    for b in ["lcp_deudeu_block.dat", "lcp_ortiz_block.dat", "lcp_trivial_block.dat"] {
        let text = std::fs::read_to_string(dir().join(b)).expect("block file");
        assert_eq!(text.split_whitespace().nth(1), Some("1"), "{b} is in sparse-block storage (type 1)");
    }
}

#[test]
fn block_files_hold_the_lcp_of_their_dense_twins() {
    for twin in ["lcp_deudeu", "lcp_ortiz", "lcp_trivial"] {
        let (dense, block) = (read(&format!("{twin}.dat")), read(&format!("{twin}_block.dat")));
        let n = dense.size();
        assert_eq!(block.size(), n, "{twin}");
        for j in 0..n {
            for i in 0..n {
                assert_eq!(block.m()[(i, j)].to_bits(), dense.m()[(i, j)].to_bits(), "{twin}: M[{i}, {j}]");
            }
        }
        assert_eq!(block.q(), dense.q(), "{twin}: q");
    }
}

#[test]
fn lemke_solves_every_solvable_file_to_round_off_and_agrees_with_siconos() {
    let answers = siconos_answers();
    let failures = expected_failures();
    let st = LemkeSettings::default();
    for name in files() {
        let lcp = read(&name);
        let n = lcp.size();
        let sic = &answers[&name];
        assert_eq!(sic.n, n, "{name}: size in siconos_lemke.tsv");
        let out = lemke::solve(&lcp, &st);
        // The dense reference engine takes the same path.
        let dense = lemke::dense::solve_dense(&lcp, &st);
        assert_eq!((dense.status, dense.pivots), (out.status, out.pivots), "{name}: dense engine");
        let r = residuals(&lcp, &out.z, &out.w).unwrap();
        // The enumeration for small files: every vertex solution, independent of Lemke.
        let sols = (n <= 10).then(|| enumerate(&lcp));
        if let Some(&(solvable, why)) = failures.get(name.as_str()) {
            assert_eq!(out.status, Termination::RayTermination, "{name} ({why}): {}", out.message);
            assert!(!sic.solved, "{name}: Siconos' Lemke does not solve it either ({why})");
            let sols = sols.expect("expected failures are small");
            assert_eq!(!sols.is_empty(), solvable, "{name}: the enumeration says solvable = {}", !sols.is_empty());
            continue;
        }
        assert_eq!(out.status, Termination::Solved, "{name}: {}", out.message);
        assert!(r.max <= ROUND_OFF, "{name}: residuals {r:?}");
        // Siconos solves the same files, and its answer passes rollbem's residuals (to a looser bound: Siconos'
        // tableau accumulates round-off over its pivots; the largest here is tobenna's, 126 iterations).
        assert!(sic.solved, "{name}: Siconos' Lemke reported error {:.1e}", sic.error);
        let rs = residuals(&lcp, &sic.z, &lcp.w_of(&sic.z).unwrap()).unwrap();
        assert!(rs.max <= 1e-12, "{name}: Siconos' z has residuals {rs:?}");
        let zs = out.z.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
        let same_z = |other: &[f64]| paired(&out.z, other).all(|(a, b)| (a - b).abs() <= 1e-9 * zs);
        if let Some(sols) = &sols {
            assert!(same_z_any(&out.z, sols, zs), "{name}: z = {:?} is not an enumerated solution {sols:?}", out.z);
            // One solution for every q (P-matrix): Siconos must have found the same one.
            if is_p_matrix(lcp.m()) {
                assert_eq!(sols.len(), 1, "{name}: a P-matrix LCP has one solution");
                assert!(same_z(&sic.z), "{name}: rollbem z = {:?}, Siconos z = {:?}", out.z, sic.z);
            }
        }
        if name == "lcp_mmc.dat" {
            assert!(is_spd(&lcp), "lcp_mmc: M symmetric positive definite, so the solution is unique");
            assert!(same_z(&sic.z), "lcp_mmc: rollbem z = {:?}, Siconos z = {:?}", out.z, sic.z);
        }
    }
}

fn same_z_any(z: &[f64], sols: &[Vec<f64>], zs: f64) -> bool {
    sols.iter().any(|s| paired(s, z).all(|(a, b)| (a - b).abs() <= 1e-9 * zs))
}

/// M symmetric and its Cholesky factorisation succeeds (all pivots positive).
fn is_spd(lcp: &Lcp) -> bool {
    let n = lcp.size();
    let m = lcp.m();
    if (0..n).any(|i| (0..n).any(|j| m[(i, j)] != m[(j, i)])) {
        return false;
    }
    let mut a: Vec<Vec<f64>> = (0..n).map(|i| (0..n).map(|j| m[(i, j)]).collect()).collect();
    for k in 0..n {
        if a[k][k] <= 0.0 {
            return false;
        }
        let d = a[k][k].sqrt();
        for row in a.iter_mut().skip(k) {
            row[k] /= d;
        }
        for j in k + 1..n {
            for i in j..n {
                a[i][j] -= a[i][k] * a[j][k];
            }
        }
    }
    true
}

#[test]
fn the_data_scale_reads_round_off_where_max_w_and_norm_q_did_not() {
    // The files named in the residual rework: with w of pure round-off, the former max|w| scaling of `lcp solve`
    // printed complementarity 0.57 and "max(0, −w)/|w| = 1.0" for these correct solutions.
    for name in ["lcp_deudeu.dat", "lcp_trivial.dat", "lcp_CPS_4.dat"] {
        let lcp = read(name);
        let out = lemke::solve(&lcp, &LemkeSettings::default());
        let wmax = out.w.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        assert!(wmax < 1e-13, "{name}: w is round-off ({wmax:e})");
        assert!(residuals(&lcp, &out.z, &out.w).unwrap().max <= ROUND_OFF, "{name}");
    }
    // lcp_tobenna: z reaches 570 with |q| ≤ 1. Siconos' own answer reports lcp_compute_error 3.5e-12 (scaled by
    // ‖q‖₂, from siconos_lemke.tsv); the same z on the data scale is ≈ 1e-16: the ‖q‖ scaling reads the round-off
    // of M z (terms of order ‖M‖ ‖z‖) as an error.
    let lcp = read("lcp_tobenna.dat");
    let sic = &siconos_answers()["lcp_tobenna.dat"];
    assert!(sic.error > 1e-12, "Siconos reported {:e}", sic.error);
    let r = residuals(&lcp, &sic.z, &lcp.w_of(&sic.z).unwrap()).unwrap();
    assert!(r.max < 1e-15, "{r:?}");
    assert!((r.siconos_error / sic.error - 1.0).abs() < 0.5, "rollbem recomputes Siconos' measure: {r:?}");
    // Both solvers' answers are solutions, and different ones (tobenna's M is not a P-matrix).
    let out = lemke::solve(&lcp, &LemkeSettings::default());
    assert!(paired(&out.z, &sic.z).any(|(a, b)| (a - b).abs() > 0.1), "two different solutions");
    assert!(sic.iterations > 0 && out.pivots > 0);
}
