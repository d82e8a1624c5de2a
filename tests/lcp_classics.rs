//! Classic hard LCPs for Lemke's algorithm (both engines: the block-revised `lemke::solve` and the dense reference
//! `lemke::solve_dense`), each checked against an independent brute-force enumeration, plus the LCP file format
//! (`rollbem::lcp_io`) and the reference problems stored in `reference/lcp/`.
//!
//! Where the expected values come from is said at every test: the enumeration below (a finite, exhaustive search
//! of the vertices of the solution set), a theorem (Cottle, Pang & Stone, *The Linear Complementarity Problem*,
//! 1992, "CPS"; Murty, *Linear Complementarity, Linear and Nonlinear Programming*, 1988), or a published pivot count.

// Index loops over matrix rows read like the formulas they implement (as in the library).
#![allow(clippy::needless_range_loop)]

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
#[path = "common/lcp_enum.rs"]
mod lcp_enum;

use faer::Mat;
use lcp_enum::{enumerate, is_p_matrix, scale};
use rollbem::lcp_io;
use rollbem::solvers::lemke::{self, LemkeOutcome, LemkeSettings};
use rollbem::solvers::{Lcp, Termination};
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------------------------

fn lcp(rows: &[&[f64]], q: &[f64]) -> Lcp {
    let n = q.len();
    assert!(rows.len() == n && rows.iter().all(|r| r.len() == n), "M must be {n} × {n}");
    Lcp::new(Mat::from_fn(n, n, |i, j| rows[i][j]), q.to_vec()).unwrap()
}

/// The LCP conditions for Lemke's answer, on the original data: z ≥ 0, w = Mz + q ≥ 0, z_i w_i = 0.
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

/// Lemke's answer is one of the enumerated vertex solutions.
fn assert_is_enumerated(out: &LemkeOutcome, sols: &[Vec<f64>], what: &str) {
    let zs = out.z.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
    assert!(
        sols.iter().any(|s| paired(s, &out.z).all(|(a, b)| (a - b).abs() <= 1e-9 * zs)),
        "{what}: Lemke's z = {:?} is not among the enumerated solutions {sols:?}",
        out.z
    );
}

fn both(p: &Lcp) -> [(&'static str, LemkeOutcome); 2] {
    let s = LemkeSettings::default();
    [("block", lemke::solve(p, &s)), ("dense", rollbem::solvers::lemke::dense::solve_dense(p, &s))]
}

/// Textbook Lemke (CPS Algorithm 4.4.5; Murty 1988 §2.2): dense tableau `w − M z − d z₀ = q`, covering vector d, no
/// scaling, lexicographic ratio test with the rows of B⁻¹ (the tableau's w-columns), z₀ chosen when tied. Returns
/// (solved?, z, pivots including the first z₀ pivot). Used only to reproduce published pivot counts, which are
/// stated for the covering vector e and the unscaled problem.
fn textbook_lemke(p: &Lcp, d: &[f64]) -> (bool, Vec<f64>, usize) {
    let n = p.size();
    let cols = 2 * n + 1; // w_0..w_{n-1}, z_0..z_{n-1}, z0
    let mut t = vec![vec![0.0; cols + 1]; n];
    for i in 0..n {
        t[i][i] = 1.0;
        for j in 0..n {
            t[i][n + j] = -p.m()[(i, j)];
        }
        t[i][2 * n] = -d[i];
        t[i][cols] = p.q()[i];
    }
    let mut basis: Vec<usize> = (0..n).collect();
    if p.q().iter().all(|&v| v >= 0.0) {
        return (true, vec![0.0; n], 0);
    }
    let pivot = |t: &mut Vec<Vec<f64>>, r: usize, c: usize| {
        let pv = t[r][c];
        for v in t[r].iter_mut() {
            *v /= pv;
        }
        let pr = t[r].clone();
        for (i, row) in t.iter_mut().enumerate() {
            if i != r && row[c] != 0.0 {
                let f = row[c];
                for (x, y) in row.iter_mut().zip(&pr) {
                    *x -= f * y;
                }
            }
        }
    };
    // Lexicographic key of row i for entering column c: (rhs, B⁻¹ row) / pivot entry.
    let key = |t: &Vec<Vec<f64>>, i: usize, c: usize| -> Vec<f64> {
        std::iter::once(t[i][cols]).chain((0..n).map(|k| t[i][k])).map(|v| v / t[i][c]).collect()
    };
    let lexmin = |t: &Vec<Vec<f64>>, rows: &[usize], c: usize, sign: f64| -> usize {
        *rows
            .iter()
            .min_by(|&&a, &&b| {
                let (ka, kb) = (key(t, a, c), key(t, b, c));
                ka.iter()
                    .zip(&kb)
                    .map(|(x, y)| (sign * x).total_cmp(&(sign * y)))
                    .find(|o| o.is_ne())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .expect("rows")
    };
    // First pivot: z0 enters; the row with the lexicographically smallest (q_i, e_i)/(−d_i)·(−1) leaves, which makes
    // every other row lexicographically positive.
    let all: Vec<usize> = (0..n).filter(|&i| d[i] > 0.0).collect();
    let r0 = lexmin(&t, &all, 2 * n, -1.0);
    let mut leaving = basis[r0];
    pivot(&mut t, r0, 2 * n);
    basis[r0] = 2 * n;
    let mut pivots = 1;
    loop {
        let entering = if leaving < n { leaving + n } else { leaving - n };
        let cand: Vec<usize> = (0..n).filter(|&i| t[i][entering] > 1e-12).collect();
        if cand.is_empty() {
            return (false, vec![0.0; n], pivots);
        }
        let theta = cand.iter().map(|&i| t[i][cols] / t[i][entering]).fold(f64::INFINITY, f64::min);
        let tied: Vec<usize> = cand
            .iter()
            .copied()
            .filter(|&i| t[i][cols] / t[i][entering] <= theta + 1e-12 * (1.0 + theta.abs()))
            .collect();
        let r = tied.iter().copied().find(|&i| basis[i] == 2 * n).unwrap_or_else(|| lexmin(&t, &tied, entering, 1.0));
        leaving = basis[r];
        pivot(&mut t, r, entering);
        basis[r] = entering;
        pivots += 1;
        if leaving == 2 * n {
            let mut z = vec![0.0; n];
            for (i, &b) in basis.iter().enumerate() {
                if (n..2 * n).contains(&b) {
                    z[b - n] = t[i][cols];
                }
            }
            return (true, z, pivots);
        }
        assert!(pivots < 1 << 16, "textbook Lemke: too many pivots");
    }
}

/// The row factors D_r of the Ruiz equilibration both engines use (`rollbem::solvers::lemke::equilibrate`), so that
/// their pivot counts can be compared with textbook Lemke on the covering vector they effectively use, d = D_r⁻¹e
/// (`D_r w = D_r M D_c z' + D_r q + e z₀` is `w = M z + q + D_r⁻¹e z₀`).
fn ruiz_rows(m: &Mat<f64>) -> Vec<f64> {
    rollbem::solvers::lemke::equilibrate(m).0
}

/// Small deterministic generator (SplitMix64), so that the "random" problems are fixed.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [-1, 1).
    fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    /// Uniform integer in [lo, hi].
    fn int(&mut self, lo: i64, hi: i64) -> f64 {
        (lo + (self.next_u64() % (hi - lo + 1) as u64) as i64) as f64
    }
}

// ---------------------------------------------------------------------------------------------------------------
// The classics
// ---------------------------------------------------------------------------------------------------------------

/// Murty's example (Murty 1978, "Computational complexity of complementary pivot methods", Math. Prog. Study 7;
/// Murty 1988 ch. 6): M̃(n) lower triangular with m_ii = 1 and m_ij = 2 for i > j, and
/// q̃(n)_i = −(2ⁿ + 2ⁿ⁻¹ + … + 2ⁿ⁻ⁱ⁺¹). M̃(n) is a P-matrix (triangular, unit diagonal), so the solution is unique.
fn murty(n: usize) -> Lcp {
    let m = Mat::from_fn(n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => 1.0,
        std::cmp::Ordering::Greater => 2.0,
        std::cmp::Ordering::Less => 0.0,
    });
    let q = (0..n).map(|i| -((n - i)..=n).map(|k| 2f64.powi(k as i32)).sum::<f64>()).collect();
    Lcp::new(m, q).unwrap()
}

#[test]
fn murty_exponential_example() {
    // Expected pivot count: Murty (1978) proved that Lemke's method with covering vector e needs 2ⁿ pivot steps on
    // (q̃(n), M̃(n)) (restated by Cottle 1980, "Observations on a class of nasty LCPs", Discrete Appl. Math. 2:
    // 2ⁿ pivots for Lemke on Murty's lower-triangular example, 2ⁿ − 1 for Murty's principal pivoting method on
    // Fathi's symmetric positive definite example). The textbook tableau Lemke below, which counts the first z₀
    // pivot, reproduces 2ⁿ exactly; rollbem's engines equilibrate M first (Ruiz), which is Lemke with a different
    // covering vector d = D_r⁻¹e: their count is not Murty's, and is asserted equal to the textbook count for that d.
    // The answer of every engine is checked against the enumeration (n ≤ 8) and against the unique solution.
    eprintln!("Murty's example (q̃(n), M̃(n)): pivots by n");
    eprintln!("{:>3} {:>8} {:>10} {:>14} {:>8} {:>8}", "n", "2^n", "textbook e", "textbook D_r⁻¹e", "block", "dense");
    for n in 2..=10 {
        let p = murty(n);
        let (ok, zt, tb) = textbook_lemke(&p, &vec![1.0; n]);
        assert!(ok, "textbook Lemke must solve a P-matrix LCP (CPS §4.4: Lemke processes P-matrices)");
        assert_eq!(tb, 1 << n, "Murty 1978: 2^n pivots with covering vector e, n = {n}");
        let [(_, blk), (_, dns)] = both(&p);
        for (name, out) in [("block", &blk), ("dense", &dns)] {
            assert_solves(&p, out, &format!("Murty n={n} ({name})"));
            // Unique solution (P-matrix, CPS Thm 3.3.7): the textbook answer, and the enumeration for n ≤ 8.
            for (a, b) in paired(&out.z, &zt) {
                assert!(
                    (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
                    "Murty n={n} ({name}): z = {:?}, textbook {zt:?}",
                    out.z
                );
            }
        }
        if n <= 8 {
            let sols = enumerate(&p);
            assert_eq!(sols.len(), 1, "P-matrix: exactly one solution (CPS §3.3, Samelson–Thrall–Wesler)");
            assert_is_enumerated(&blk, &sols, &format!("Murty n={n}"));
            assert_is_enumerated(&dns, &sols, &format!("Murty n={n}"));
        }
        // Both engines follow the same pivot path (src/solvers/lemke/block.rs docs), and that path is the textbook
        // one for the covering vector D_r⁻¹e of their row equilibration (replicated by `ruiz_rows`).
        assert_eq!(blk.pivots, dns.pivots, "Murty n={n}: engines disagree on the pivot path");
        let d: Vec<f64> = ruiz_rows(p.m()).iter().map(|r| 1.0 / r).collect();
        let (ok_d, _, tb_d) = textbook_lemke(&p, &d);
        assert!(ok_d);
        assert_eq!(blk.pivots, tb_d, "Murty n={n}: engines vs textbook Lemke with covering vector D_r⁻¹e");
        eprintln!("{n:>3} {:>8} {tb:>10} {tb_d:>14} {:>8} {:>8}", 1 << n, blk.pivots, dns.pivots);
    }
}

#[test]
fn murty_beyond_ten_ends_solved_or_at_the_pivot_limit() {
    // Equilibration postpones Murty's exponential growth but does not remove it (measured: 12, 24, 90, 356 pivots
    // for n = 11, 12, 14, 16; the limit 50 n + 100 is reached by n = 20). Expected: never a wrong answer — either
    // Solved and the unique solution (checked against textbook Lemke), or NotConverged at the pivot limit.
    for n in [12, 16, 20] {
        let p = murty(n);
        let limit = LemkeSettings::default().max_pivots_per_unknown * n + 100;
        for (engine, out) in both(&p) {
            eprintln!("Murty n = {n} ({engine}): {} after {} pivots", out.status, out.pivots);
            match out.status {
                Termination::Solved => {
                    assert_solves(&p, &out, engine);
                    let (_, zt, _) = textbook_lemke(&p, &vec![1.0; n]);
                    assert!(paired(&out.z, &zt).all(|(a, b)| (a - b).abs() <= 1e-9 * (1.0 + b.abs())));
                }
                Termination::NotConverged => assert_eq!(out.pivots, limit),
                s => panic!("Murty n = {n} ({engine}): unexpected {s}: {}", out.message),
            }
        }
    }
}

#[test]
fn murty_upper_triangular_with_q_minus_e() {
    // The form of the Siconos collection's lcp_exp_murty.dat (read column-major: upper triangular, 1 on the
    // diagonal, 2 above; q = −e). P-matrix, so a unique solution (CPS §3.3, Samelson–Thrall–Wesler); its value is from the
    // enumeration. With q = −e every ratio of the first pivot ties: this also exercises the initial tie rule.
    for n in 2..=8 {
        let m = Mat::from_fn(n, n, |i, j| {
            if i == j {
                1.0
            } else if i < j {
                2.0
            } else {
                0.0
            }
        });
        let p = Lcp::new(m, vec![-1.0; n]).unwrap();
        let sols = enumerate(&p);
        assert_eq!(sols.len(), 1);
        for (name, out) in both(&p) {
            assert_solves(&p, &out, &format!("upper Murty n={n} ({name})"));
            assert_is_enumerated(&out, &sols, &format!("upper Murty n={n} ({name})"));
        }
    }
}

/// Degenerate problems: repeated entries of q, zeros in q, repeated rows and columns of M.
fn degenerate_cases() -> Vec<(&'static str, Lcp)> {
    vec![
        (
            "all q equal, M with repeated rows/columns",
            lcp(&[&[1., 1., 1.], &[1., 1., 1.], &[1., 1., 2.]], &[-1., -1., -1.]),
        ),
        ("all q equal, SPD", lcp(&[&[2., 1., 1.], &[1., 2., 1.], &[1., 1., 2.]], &[-1., -1., -1.])),
        (
            "zeros in q",
            lcp(&[&[1., 2., 0., 1.], &[2., 1., 1., 0.], &[0., 1., 1., 1.], &[1., 0., 1., 1.]], &[0., -1., 0., -1.]),
        ),
        (
            "repeated rows and columns, ties at every step",
            lcp(&[&[1., 1., 2., 2.], &[1., 1., 2., 2.], &[2., 2., 5., 5.], &[2., 2., 5., 5.]], &[-1., -1., -2., -2.]),
        ),
        (
            "q = 0 except one entry, I + cyclic skew",
            lcp(&[&[1., 1., -1.], &[-1., 1., 1.], &[1., -1., 1.]], &[0., 0., -1.]),
        ),
        (
            "LP-KKT with a degenerate vertex (skew M, copositive-plus)",
            // min −x1 − x2 s.t. x1 + x2 ≤ 1, x1 ≤ 1, x2 ≤ 1: three constraints active at (1, 0) and (0, 1).
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
        ),
    ]
}

#[test]
fn degenerate_problems_with_ties_terminate_correctly() {
    // Expected: a solution exists (enumeration non-empty) and every M here is copositive-plus (PSD or skew), so
    // Lemke with the lexicographic rule must terminate with one (CPS §4.4: the lexicographic rule never repeats a basis; Thm 4.4.13); the answer must satisfy
    // the LCP conditions and be one of the enumerated vertices.
    for (name, p) in degenerate_cases() {
        let sols = enumerate(&p);
        assert!(!sols.is_empty(), "{name}: the enumeration finds a solution");
        for (engine, out) in both(&p) {
            assert_solves(&p, &out, &format!("{name} ({engine})"));
            assert_is_enumerated(&out, &sols, &format!("{name} ({engine})"));
        }
    }
}

#[test]
fn random_degenerate_integer_problems() {
    // Small-integer copositive-plus problems (M = AᵀA + S or M = S, S skew; q in {−3..1}, many zeros and repeats): ties in
    // almost every ratio test. Expected, by CPS Thm 4.4.13: Solved iff the enumeration finds a solution, and
    // RayTermination iff it finds none; both engines agree on the status.
    let mut rng = Rng(0x5eed_0001);
    let (mut solved, mut rays) = (0, 0);
    for case in 0..300 {
        let n = 2 + case % 5;
        let a: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.int(-1, 1)).collect()).collect();
        let s: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.int(-1, 1)).collect()).collect();
        // Even cases PSD (AᵀA + skew), odd cases skew only (LP-KKT-like, often infeasible).
        let psd = if case % 2 == 0 { 1.0 } else { 0.0 };
        let m = Mat::from_fn(n, n, |i, j| psd * (0..n).map(|k| a[k][i] * a[k][j]).sum::<f64>() + s[i][j] - s[j][i]);
        let q: Vec<f64> = (0..n).map(|_| rng.int(-3, 1)).collect();
        let p = Lcp::new(m, q).unwrap();
        let sols = enumerate(&p);
        for (engine, out) in both(&p) {
            let what = format!("case {case} ({engine}): M = {:?}, q = {:?}", p.m(), p.q());
            if sols.is_empty() {
                assert_eq!(out.status, Termination::RayTermination, "{what}: infeasible by enumeration");
            } else {
                assert_solves(&p, &out, &what);
                if sols.len() == 1 {
                    assert_is_enumerated(&out, &sols, &what);
                }
            }
        }
        if sols.is_empty() {
            rays += 1;
        } else {
            solved += 1;
        }
    }
    eprintln!("random degenerate integer problems: {solved} solvable, {rays} infeasible");
    assert!(solved > 50 && rays > 10, "the sample covers both outcomes");
}

#[test]
fn infinitely_many_solutions() {
    // CPS Remark 4.1.14 (Siconos lcp_CPS_1.dat): M = [[1,1],[1,1]], q = (−1,−1): the solutions are the segment
    // z1 + z2 = 1, z ≥ 0 (w = 0). The enumeration finds its two vertices; Lemke must return a point of the segment.
    let p = lcp(&[&[1., 1.], &[1., 1.]], &[-1., -1.]);
    let sols = enumerate(&p);
    assert_eq!(sols.len(), 2, "{sols:?}");
    for (engine, out) in both(&p) {
        assert_solves(&p, &out, engine);
        assert!((out.z[0] + out.z[1] - 1.0).abs() < 1e-14, "{engine}: z = {:?}", out.z);
    }
    // A ray of solutions: w1 ≡ 0, so z = (t, 1) solves it for every t ≥ 0 (by hand); one vertex, (0, 1).
    let p = lcp(&[&[0., 0.], &[0., 1.]], &[0., -1.]);
    assert_eq!(enumerate(&p), vec![vec![0.0, 1.0]]);
    for (engine, out) in both(&p) {
        assert_solves(&p, &out, engine);
    }
}

#[test]
fn infeasible_problems_end_on_a_secondary_ray() {
    // Expected status: RayTermination. Infeasibility is proved by the enumeration (no solution) and, for the first
    // two cases, also by a row with q_r < 0 and m_rj ≤ 0 for all j (CPS ch. 4 intro: then w_r < 0 for every
    // z ≥ 0).
    let cases = [
        ("M = −I", lcp(&[&[-1., 0.], &[0., -1.]], &[-1., -1.])),
        // Copositive-plus (skew, hence PSD): for such M a secondary ray proves infeasibility (CPS Thm 4.4.13).
        ("skew M (copositive-plus)", lcp(&[&[0., 1.], &[-1., 0.]], &[-1., -1.])),
        // KKT system of an infeasible LP (x1 ≥ 1 and −x1 ≥ 0): M = [[0, −Aᵀ], [A, 0]] is skew, copositive-plus.
        ("LP-KKT of an infeasible LP", lcp(&[&[0., -1., 1.], &[1., 0., 0.], &[-1., 0., 0.]], &[1., -1., 0.])),
    ];
    for (name, p) in cases {
        assert!(enumerate(&p).is_empty(), "{name}: the enumeration must find no solution");
        for (engine, out) in both(&p) {
            assert_eq!(out.status, Termination::RayTermination, "{name} ({engine}): {}", out.message);
        }
    }
    // The LP-KKT case has no row certificate (each row has a positive entry): only the enumeration (and the
    // LP's own infeasibility) proves it, which is the interesting case for Thm 4.4.13.
}

/// A solvable LCP on which Lemke (covering vector e) ends on a secondary ray. M = [[−1, 1], [1, −1]] is not
/// copositive (x = e1 gives xᵀMx = −1), so none of the classes Lemke is known to process (P, copositive-plus, …,
/// CPS §4.4) covers it; q = (1, −1) is solved by z = (1, 0) (w = 0), yet the first z₀-pivot leads to an unblocked column:
/// z₂ enters, and raising it raises z₀ and w₁ (worked by hand, confirmed by the enumeration and the textbook tableau).
fn lemke_fails_on_a_solvable_problem() -> Lcp {
    lcp(&[&[-1., 1.], &[1., -1.]], &[1., -1.])
}

#[test]
fn solvable_problem_where_lemke_ends_on_a_ray() {
    // A documented limitation of Lemke's method, not a bug: a secondary ray proves infeasibility only for the
    // classes of M it processes (copositive-plus: CPS Thm 4.4.13; P-matrices, …). rollbem's own LCPs are
    // copositive(-plus) by construction (see src/formulation.rs), so they never fall in this case.
    // Expected: the enumeration finds a solution, and Lemke (both engines, and the textbook tableau) ends on a ray.
    let p = lemke_fails_on_a_solvable_problem();
    let sols = enumerate(&p);
    assert!(!sols.is_empty(), "solvable by enumeration");
    let (ok, _, _) = textbook_lemke(&p, &[1.0, 1.0]);
    assert!(!ok, "the textbook Lemke ends on a ray too");
    for (engine, out) in both(&p) {
        assert_eq!(out.status, Termination::RayTermination, "{engine}: {}", out.message);
    }
}

#[test]
fn random_p_matrices_have_one_solution_that_lemke_finds() {
    // P-matrices (checked: every principal minor > 0): the LCP has exactly one solution for every q (CPS §3.3,
    // Samelson–Thrall–Wesler), and Lemke processes P-matrices (CPS §4.4; Murty 1988 ch. 2). Expected value: the single
    // solution found by the enumeration. Three families, fixed seed: positive definite (BᵀB + δI + skew),
    // strictly diagonally dominant with positive diagonal (non-symmetric, not PD in general), and products of the
    // two kinds of triangular P-matrices (non-symmetric, not diagonally dominant).
    let mut rng = Rng(0x5eed_0002);
    for case in 0..120 {
        let n = 2 + case % 7;
        let m = match case % 3 {
            0 => {
                let b: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.uniform()).collect()).collect();
                let s: Vec<Vec<f64>> = (0..n).map(|_| (0..n).map(|_| rng.uniform()).collect()).collect();
                Mat::from_fn(n, n, |i, j| {
                    (0..n).map(|k| b[k][i] * b[k][j]).sum::<f64>() + if i == j { 0.1 } else { 0.0 } + s[i][j] - s[j][i]
                })
            }
            1 => {
                let mut m = Mat::from_fn(n, n, |_, _| rng.uniform());
                for i in 0..n {
                    let off: f64 = (0..n).filter(|&j| j != i).map(|j| m[(i, j)].abs()).sum();
                    m[(i, i)] = off + 0.05 + 0.5 * (rng.uniform() + 1.0);
                }
                m
            }
            _ => {
                // Lower-triangular with positive diagonal and large off-diagonal entries (Murty-like): P.
                let mut m = Mat::from_fn(n, n, |i, j| if i > j { 3.0 * rng.uniform() } else { 0.0 });
                for i in 0..n {
                    m[(i, i)] = 0.2 + rng.uniform().abs();
                }
                m
            }
        };
        let q: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        let p = Lcp::new(m, q).unwrap();
        assert!(is_p_matrix(p.m()), "case {case}: not a P-matrix");
        let sols = enumerate(&p);
        assert_eq!(sols.len(), 1, "case {case}: a P-matrix LCP has exactly one solution");
        for (engine, out) in both(&p) {
            let what = format!("P case {case} ({engine})");
            assert_solves(&p, &out, &what);
            assert_is_enumerated(&out, &sols, &what);
        }
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Files
// ---------------------------------------------------------------------------------------------------------------

#[test]
fn write_then_read_is_identical_and_solves_identically() {
    // Expected: bitwise equality (lcp_io writes the shortest round-trip representation), hence identical pivots
    // and an identical z from the same deterministic engine.
    let dir = tempfile::tempdir().expect("temp dir");
    let mut rng = Rng(0x5eed_0003);
    let mut problems: Vec<Lcp> = degenerate_cases().into_iter().map(|(_, p)| p).collect();
    problems.push(murty(7));
    for _ in 0..5 {
        let n = 6;
        problems.push(
            Lcp::new(
                Mat::from_fn(n, n, |i, j| rng.uniform() + if i == j { 4.0 } else { 0.0 }),
                (0..n).map(|_| rng.uniform() / 3.0).collect(),
            )
            .unwrap(),
        );
    }
    for (k, p) in problems.iter().enumerate() {
        let path = dir.path().join(format!("p{k}.dat"));
        lcp_io::write(p, &path).expect("write");
        let back = lcp_io::read(&path).expect("read");
        let n = p.size();
        assert_eq!(back.size(), n);
        for j in 0..n {
            for i in 0..n {
                assert_eq!(back.m()[(i, j)].to_bits(), p.m()[(i, j)].to_bits(), "problem {k}: M[{i},{j}]");
            }
        }
        assert!(paired(back.q(), p.q()).all(|(a, b)| a.to_bits() == b.to_bits()), "problem {k}: q");
        for solve in [lemke::solve, rollbem::solvers::lemke::dense::solve_dense] {
            let s = LemkeSettings::default();
            let (a, b) = (solve(p, &s), solve(&back, &s));
            assert_eq!(a.status, b.status);
            assert_eq!(a.pivots, b.pivots);
            assert!(paired(&a.z, &b.z).all(|(x, y)| x.to_bits() == y.to_bits()), "problem {k}: z differs");
        }
    }
}

#[test]
fn siconos_layout_is_column_major() {
    // The QP example of the Siconos collection's lcp_CPS_4.dat (a KKT system [[Q, −Aᵀ], [A, 0]] of
    // min ½xᵀQx + cᵀx s.t. x1 + x2 + x3 ≥ 6), written here in Siconos' layout: each line is a COLUMN of M
    // (NM_write_in_file prints the column-major array `matrix0`). Read column-major, the last row of M is
    // (1, 1, 1, 0): w4 = x1 + x2 + x3 − 6, a feasible QP whose LCP has a solution (enumeration). Read row-major, the
    // last row would be (−1, −1, −1, 0) and w4 = −(x1 + x2 + x3) − 6 < 0: infeasible — which is how the orientation
    // is verified here.
    let text = "4\n0\n4\n4\n4\t4\n11 0 10 1\n0 11 10 1\n10 10 21 1\n-1 -1 -1 0\n50 50 10 -6\n";
    let p = lcp_io::parse(text, Path::new("cps4.dat")).expect("parse");
    assert_eq!((p.m()[(3, 0)], p.m()[(0, 3)]), (1.0, -1.0));
    let sols = enumerate(&p);
    assert!(!sols.is_empty(), "column-major reading gives a solvable LCP");
    for (engine, out) in both(&p) {
        assert_solves(&p, &out, engine);
        assert_is_enumerated(&out, &sols, engine);
    }
    let transposed = Lcp::new(Mat::from_fn(4, 4, |i, j| p.m()[(j, i)]), p.q().to_vec()).unwrap();
    assert!(enumerate(&transposed).is_empty(), "the row-major reading would be infeasible");
}

fn reference_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/lcp")
}

/// The problems stored in reference/lcp/ (file name, remark written after q, problem, expected outcome).
fn reference_problems() -> Vec<(&'static str, &'static str, Lcp, Termination)> {
    vec![
        (
            "murty_n6.dat",
            "Murty's exponential example, n = 6: M lower triangular (1 on the diagonal, 2 below),\n\
             q_i = -(2^6 + ... + 2^(6-i+1)). Murty 1978; Murty 1988 ch. 6. Unique solution (P-matrix);\n\
             textbook Lemke (covering vector e) takes 2^6 = 64 pivots.",
            murty(6),
            Termination::Solved,
        ),
        (
            "cps_segment.dat",
            "Infinitely many solutions: z1 + z2 = 1, z >= 0 (Cottle-Pang-Stone 1992, Remark 4.1.14).",
            lcp(&[&[1., 1.], &[1., 1.]], &[-1., -1.]),
            Termination::Solved,
        ),
        (
            "degenerate_ties.dat",
            "Degenerate: repeated rows and columns of M and repeated entries of q (ties in every ratio test).\n\
             M is PSD (copositive-plus); solvable (enumeration).",
            degenerate_cases().swap_remove(3).1,
            Termination::Solved,
        ),
        (
            "lp_kkt_infeasible.dat",
            "KKT LCP of the infeasible LP {x1 >= 1, -x1 >= 0}: M = [[0, -A^T], [A, 0]] is skew, hence\n\
             copositive-plus; no solution (enumeration), so Lemke must end on a secondary ray (CPS Thm 4.4.13).",
            lcp(&[&[0., -1., 1.], &[1., 0., 0.], &[-1., 0., 0.]], &[1., -1., 0.]),
            Termination::RayTermination,
        ),
        (
            "lemke_ray_solvable.dat",
            "Solvable (enumeration) but Lemke ends on a secondary ray: M is not copositive, outside the classes\n\
             Lemke processes (CPS 4.4). A documented limitation of the method, not a solver bug.",
            lemke_fails_on_a_solvable_problem(),
            Termination::RayTermination,
        ),
    ]
}

#[test]
fn reference_files_load_and_lemke_matches_the_enumeration() {
    // The files are the in-code problems above written by lcp_io (regenerate with ROLLBEM_REGEN_LCP=1). Expected
    // outcome per file: as listed (from the enumeration and the theorems cited in each remark).
    let regen = std::env::var_os("ROLLBEM_REGEN_LCP").is_some();
    for (file, remark, p, expected) in reference_problems() {
        let path = reference_dir().join(file);
        let text = lcp_io::to_string_with_remark(&p, remark);
        if regen {
            std::fs::create_dir_all(reference_dir()).expect("mkdir");
            std::fs::write(&path, &text).expect("write reference file");
        }
        let on_disk = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(on_disk, text, "{file} is out of date (ROLLBEM_REGEN_LCP=1 regenerates it)");
        let (back, rem) = lcp_io::parse_with_remark(&on_disk, &path).expect("parse");
        assert!(rem.starts_with("# "), "{file}: remark kept");
        let loaded = lcp_io::read(&path).expect("read");
        assert_eq!(loaded.q(), back.q());
        let sols = enumerate(&loaded);
        for (engine, out) in both(&loaded) {
            assert_eq!(out.status, expected, "{file} ({engine}): {}", out.message);
            if expected == Termination::Solved {
                assert_solves(&loaded, &out, file);
                if file != "cps_segment.dat" {
                    assert_is_enumerated(&out, &sols, file);
                }
            }
        }
        assert_eq!(sols.is_empty(), file == "lp_kkt_infeasible.dat", "{file}: enumeration");
    }
}
