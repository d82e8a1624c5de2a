//! Lemke's method warm-started from a guessed basis (`rollbem::solvers::lemke::solve_warm`), against the cold start
//! (`lemke::solve`) on the frictional LCPs of the reference scenes and on the classic LCPs of `lcp_classics.rs`.
//!
//! Expected values: the cold start's answer (itself checked against enumerations and the physics elsewhere) where
//! the solution is unique — every P-matrix LCP (CPS §3.3), and the contact forces of the frictional LCPs (the
//! multipliers of separated or sticking nodes are not unique, the forces are: `tests/friction.rs`); elsewhere the LCP
//! conditions themselves. Pivot counts: a perfect guess (the cold solution's own support) needs none, a guess off by
//! a few indices a few, measured here with margins.

#![allow(clippy::needless_range_loop)]

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
#[path = "common/lcp_enum.rs"]
mod lcp_enum;

use faer::Mat;
use lcp_enum::{enumerate, is_p_matrix, scale};
use rollbem::scene::Scene;
use rollbem::solvers::lemke::{self, LemkeOutcome, LemkeSettings};
use rollbem::solvers::{Lcp, Termination};
use rollbem::source::{self, Blocks};
use std::path::Path;

/// The LCP conditions on the original data: z ≥ 0, w = Mz + q ≥ 0, z_i w_i = 0.
fn assert_solves(p: &Lcp, out: &LemkeOutcome, what: &str) {
    assert_eq!(out.status, Termination::Solved, "{what}: {}", out.message);
    let s = scale(p);
    let zs = out.z.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
    let tol = 1e-10 * s * zs;
    let w = p.w_of(&out.z).unwrap();
    for i in 0..p.size() {
        assert!(out.z[i] >= 0.0, "{what}: z[{i}] = {}", out.z[i]);
        assert!(w[i] >= -tol, "{what}: w[{i}] = {}", w[i]);
        assert!((out.z[i] * w[i]).abs() <= tol * zs, "{what}: z[{i}] w[{i}] = {}", out.z[i] * w[i]);
    }
}

/// max |a_i − b_i| over the first `k` entries ≤ 1e-10 max |b|.
fn assert_agree(a: &[f64], b: &[f64], k: usize, what: &str) {
    let bmax = b.iter().fold(1e-300_f64, |m, v| m.max(v.abs()));
    let d = (0..k).fold(0.0_f64, |m, i| m.max((a[i] - b[i]).abs()));
    assert!(d <= 1e-10 * bmax, "{what}: max|z_warm − z_cold| = {d:.3e}, max|z_cold| = {bmax:.3e}");
}

fn support(z: &[f64]) -> Vec<bool> {
    z.iter().map(|&v| v > 0.0).collect()
}

/// The support with a few indices flipped: two basic z's made nonbasic, one nonbasic made basic (deterministic).
fn off_by_three(z: &[f64]) -> Vec<bool> {
    let mut g = support(z);
    let on: Vec<usize> = (0..g.len()).filter(|&i| g[i]).collect();
    let off: Vec<usize> = (0..g.len()).filter(|&i| !g[i]).collect();
    for &i in [on.first(), on.get(on.len() / 2)].into_iter().flatten() {
        g[i] = false;
    }
    if let Some(&i) = off.get(off.len() / 3) {
        g[i] = true;
    }
    g
}

/// The frictional (and frictionless) LCPs of the reference scenes, with the number of contact-force unknowns (the
/// first entries of z), plus a coupled variant of the Cattaneo scene (the peer benchmark's family).
fn reference_lcps() -> Vec<(String, Lcp, usize)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes");
    let mut names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    names.sort();
    let mut out = Vec::new();
    let mut scenes: Vec<(String, Scene)> = names
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| (p.file_stem().unwrap().to_string_lossy().into_owned(), Scene::from_file(p).unwrap()))
        .collect();
    let mut coupled = Scene::from_file(&dir.join("cattaneo-decoupled.toml")).unwrap();
    coupled = coupled
        .edit(|d| {
            d.contact.coupling = true;
            d.mesh.contact_elements = 100;
        })
        .unwrap();
    scenes.push(("cattaneo-coupled-100".into(), coupled));
    for (name, s) in scenes {
        let fl = source::build(&s, Blocks::All).unwrap().flex;
        let Ok(p) = rollbem::pipeline::stages::scene_problem(&s, &fl) else { continue };
        if !matches!(p.kind(), rollbem::formulation::ProblemKind::GrossSliding { .. }) {
            out.push((name, p.lcp().expect("an LCP below gross sliding").clone(), fl.n()));
        }
    }
    assert!(out.len() >= 10, "the reference scenes give frictional LCPs ({} found)", out.len());
    out
}

#[test]
fn warm_start_on_the_frictional_lcps_of_the_reference_scenes() {
    let st = LemkeSettings::default();
    let mut saved = (0usize, 0usize);
    for (name, lcp, nf) in reference_lcps() {
        let cold = lemke::solve(&lcp, &st);
        if cold.status != Termination::Solved {
            // Solved by the contact solver with flipped slack signs (another LCP): not this test's business.
            continue;
        }
        if cold.pivots == 0 {
            continue;
        }
        // Perfect guess: the cold solution's own support. No pivot; the same point.
        let w = lemke::solve_warm(&lcp, &st, &support(&cold.z));
        assert_solves(&lcp, &w, &format!("{name}, perfect guess"));
        assert!(w.pivots <= 1, "{name}, perfect guess: {} pivots ({})", w.pivots, w.message);
        assert_agree(&w.z, &cold.z, lcp.size(), &format!("{name}, perfect guess"));
        // Off by three indices: a few pivots, the same contact forces.
        let w3 = lemke::solve_warm(&lcp, &st, &off_by_three(&cold.z));
        assert_solves(&lcp, &w3, &format!("{name}, off by three"));
        assert!(w3.pivots <= 12, "{name}, off by three: {} pivots, cold {} ({})", w3.pivots, cold.pivots, w3.message);
        assert_agree(&w3.z, &cold.z, nf, &format!("{name}, off by three"));
        saved.0 += cold.pivots;
        saved.1 += w3.pivots;
        // Bad guesses: every z basic, the complement of the support, none. They still solve, to the same forces.
        let n = lcp.size();
        let complement: Vec<bool> = support(&cold.z).iter().map(|b| !b).collect();
        for (what, g) in [("all true", vec![true; n]), ("complement", complement), ("all false", vec![false; n])] {
            let wb = lemke::solve_warm(&lcp, &st, &g);
            assert_solves(&lcp, &wb, &format!("{name}, {what}"));
            assert_agree(&wb.z, &cold.z, nf, &format!("{name}, {what}"));
        }
        // No guessed z: the warm start is the cold start (covering vector B e = e), pivot for pivot.
        let w0 = lemke::solve_warm(&lcp, &st, &vec![false; n]);
        assert_eq!(w0.pivots, cold.pivots, "{name}: {}", w0.message);
        assert_eq!(w0.z, cold.z, "{name}");
    }
    assert!(saved.0 > 0 && saved.1 * 5 < saved.0, "pivots cold {} vs warm (off by three) {}", saved.0, saved.1);
}

#[test]
fn a_guess_of_the_wrong_length_falls_back_to_the_cold_start() {
    let lcp = Lcp::new(Mat::from_fn(2, 2, |i, j| if i == j { 2.0 } else { 1.0 }), vec![-5.0, -6.0]).unwrap();
    let st = LemkeSettings::default();
    let w = lemke::solve_warm(&lcp, &st, &[true]);
    let cold = lemke::solve(&lcp, &st);
    assert_eq!(w.status, Termination::Solved);
    assert_eq!(w.z, cold.z);
    assert!(w.message.contains("warm start abandoned") && w.message.contains("cold start"), "{}", w.message);
}

/// Murty's example (lcp_classics.rs): lower triangular, unit diagonal, 2 below; a P-matrix, unique solution.
fn murty(n: usize) -> Lcp {
    let m = Mat::from_fn(n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => 1.0,
        std::cmp::Ordering::Greater => 2.0,
        std::cmp::Ordering::Less => 0.0,
    });
    let q = (0..n).map(|i| -((n - i)..=n).map(|k| 2f64.powi(k as i32)).sum::<f64>()).collect();
    Lcp::new(m, q).unwrap()
}

struct Rng(u64);
impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

#[test]
fn warm_start_on_murty_and_random_p_matrices_finds_the_unique_solution() {
    // P-matrices: exactly one solution for every q (CPS §3.3): any guess must end at the cold start's z.
    let st = LemkeSettings::default();
    let mut problems: Vec<(String, Lcp)> = (2..=10).map(|n| (format!("Murty n={n}"), murty(n))).collect();
    let mut rng = Rng(0x5eed_0003);
    for case in 0..60 {
        let n = 2 + case % 9;
        let b: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.uniform()).collect()).collect();
        let k: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.uniform()).collect()).collect();
        let m = Mat::from_fn(n, n, |i, j| {
            (0..n).map(|l| b[l][i] * b[l][j]).sum::<f64>() + if i == j { 0.1 } else { 0.0 } + k[i][j] - k[j][i]
        });
        let q: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        problems.push((format!("random P case {case}"), Lcp::new(m, q).unwrap()));
    }
    let mut pivots = (0, 0);
    for (name, p) in problems {
        assert!(is_p_matrix(p.m()), "{name}");
        let n = p.size();
        let cold = lemke::solve(&p, &st);
        assert_solves(&p, &cold, &name);
        let sols = enumerate(&p);
        assert_eq!(sols.len(), 1, "{name}");
        let perfect = lemke::solve_warm(&p, &st, &support(&cold.z));
        assert!(perfect.pivots <= 1, "{name}: {} pivots ({})", perfect.pivots, perfect.message);
        let mut one_off = support(&cold.z);
        one_off[n / 2] = !one_off[n / 2];
        let one = lemke::solve_warm(&p, &st, &one_off);
        // Measured: 2 pivots for most, at most 6 (n = 5 with every basic value of the guessed basis infeasible).
        assert!(one.pivots <= 6, "{name}, one index off: {} pivots ({})", one.pivots, one.message);
        pivots.0 += cold.pivots;
        pivots.1 += one.pivots;
        let complement: Vec<bool> = support(&cold.z).iter().map(|b| !b).collect();
        for (what, out) in [
            ("perfect", perfect),
            ("one off", one),
            ("all true", lemke::solve_warm(&p, &st, &vec![true; n])),
            ("complement", lemke::solve_warm(&p, &st, &complement)),
        ] {
            let what = format!("{name}, {what}");
            assert_solves(&p, &out, &what);
            assert_agree(&out.z, &sols[0], n, &what);
            assert_agree(&out.z, &cold.z, n, &what);
        }
    }
    // Measured: 136 pivots one index off against 265 cold over these 69 problems.
    assert!(3 * pivots.1 < 2 * pivots.0, "one index off: {} pivots in all, cold: {}", pivots.1, pivots.0);
}

#[test]
fn warm_start_on_degenerate_and_infeasible_classics() {
    // Degenerate problems (ties; lcp_classics.rs): any guess ends at a solution (checked by the LCP conditions and
    // against the enumeration of vertex solutions). Infeasible problems: a ray, as from the cold start.
    let st = LemkeSettings::default();
    let lcp = |rows: &[&[f64]], q: &[f64]| {
        let n = q.len();
        Lcp::new(Mat::from_fn(n, n, |i, j| rows[i][j]), q.to_vec()).unwrap()
    };
    let degenerate = [
        lcp(&[&[1., 1., 1.], &[1., 1., 1.], &[1., 1., 2.]], &[-1., -1., -1.]),
        lcp(&[&[2., 1., 1.], &[1., 2., 1.], &[1., 1., 2.]], &[-1., -1., -1.]),
        lcp(&[&[1., 2., 0., 1.], &[2., 1., 1., 0.], &[0., 1., 1., 1.], &[1., 0., 1., 1.]], &[0., -1., 0., -1.]),
        lcp(&[&[1., 1., 2., 2.], &[1., 1., 2., 2.], &[2., 2., 5., 5.], &[2., 2., 5., 5.]], &[-1., -1., -2., -2.]),
        lcp(&[&[1., 1., -1.], &[-1., 1., 1.], &[1., -1., 1.]], &[0., 0., -1.]),
        lcp(
            &[
                &[0., 0., 1., 1., 0.],
                &[0., 0., 1., 0., 1.],
                &[-1., -1., 0., 0., 0.],
                &[-1., 0., 0., 0., 0.],
                &[0., -1., 0., 0., 0.],
            ],
            &[-1., -1., 1., 1., 1.],
        ),
    ];
    for (c, p) in degenerate.iter().enumerate() {
        let n = p.size();
        let sols = enumerate(p);
        // Every guess: all 2ⁿ subsets.
        for mask in 0..(1usize << n) {
            let g: Vec<bool> = (0..n).map(|i| mask & (1 << i) != 0).collect();
            let out = lemke::solve_warm(p, &st, &g);
            let what = format!("degenerate case {c}, guess {g:?}");
            assert_solves(p, &out, &what);
            let zs = out.z.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
            assert!(
                sols.iter().any(|s| paired(s, &out.z).all(|(a, b)| (a - b).abs() <= 1e-9 * zs)),
                "{what}: z = {:?} is not an enumerated solution",
                out.z
            );
        }
    }
    let infeasible = [lcp(&[&[0., 0.], &[0., 1.]], &[-1., 1.]), lcp(&[&[-1., 0.], &[0., -1.]], &[-1., -1.])];
    for (c, p) in infeasible.iter().enumerate() {
        assert!(enumerate(p).is_empty(), "infeasible case {c}");
        for g in [vec![false, false], vec![true, false], vec![true, true]] {
            let out = lemke::solve_warm(p, &st, &g);
            assert_eq!(out.status, Termination::RayTermination, "infeasible case {c}, guess {g:?}: {}", out.message);
        }
    }
}

#[test]
fn warm_start_from_the_previous_load_step() {
    // The intended use: the support of the previous load step's solution as the guess. The coupled Cattaneo scene
    // (the peer benchmark's family) with the tangential load raised in steps of 10 % of μP towards 0.6 μP: the
    // forces of each step agree with its cold start, in far fewer pivots (measured: 5, 5, 21, 28, 20 pivots against
    // 132, 132, 134, 145, 148 cold).
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes");
    let mut s = Scene::from_file(&dir.join("cattaneo-decoupled.toml")).unwrap();
    s = s
        .edit(|d| {
            d.contact.coupling = true;
            d.mesh.contact_elements = 100;
        })
        .unwrap();
    let st = LemkeSettings::default();
    let p_load = s.document().drive.normal_load.unwrap();
    let mu = s.document().contact.friction;
    let mut guess: Option<Vec<bool>> = None;
    let (mut cold_total, mut warm_total) = (0, 0);
    for step in 1..=6 {
        s = s.edit(|d| d.drive.tangential_load = Some(0.1 * step as f64 * mu * p_load)).unwrap();
        let fl = source::build(&s, Blocks::All).unwrap().flex;
        let p = rollbem::pipeline::stages::scene_problem(&s, &fl).unwrap();
        let lcp = p.lcp().expect("an LCP below gross sliding").clone();
        let cold = lemke::solve(&lcp, &st);
        assert_solves(&lcp, &cold, &format!("step {step}, cold"));
        if let Some(g) = &guess {
            let w = lemke::solve_warm(&lcp, &st, g);
            let what = format!("step {step}, warm");
            assert_solves(&lcp, &w, &what);
            assert_agree(&w.z, &cold.z, fl.n(), &what);
            cold_total += cold.pivots;
            warm_total += w.pivots;
        }
        guess = Some(support(&cold.z));
    }
    assert!(4 * warm_total < cold_total, "pivots: warm {warm_total}, cold {cold_total}");
}
