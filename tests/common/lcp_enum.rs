//! Brute-force facts about small LCPs `w = M z + q ⊥ z ≥ 0`, independent of any pivoting code: every vertex
//! solution by enumeration of supports, and the P-matrix test. Shared by `tests/lcp_classics.rs` and
//! `tests/lcp_siconos.rs` (included with `#[path]`).

// Index loops over matrix rows read like the formulas they implement (as in the library).
#![allow(clippy::needless_range_loop)]

use faer::Mat;
use rollbem::solvers::Lcp;

/// The largest absolute entry of M and q, and at least 1: the scale of the enumeration's tolerances.
pub fn scale(p: &Lcp) -> f64 {
    let n = p.size();
    let mut s = p.q().iter().fold(1.0_f64, |a, v| a.max(v.abs()));
    for j in 0..n {
        for i in 0..n {
            s = s.max(p.m()[(i, j)].abs());
        }
    }
    s
}

/// Brute-force enumeration of the solutions of `w = M z + q ⊥ z ≥ 0` (n ≤ 10).
///
/// Every nonempty solution set has a vertex (it is a finite union of polyhedra inside the orthant, which contain no
/// line), and the positive variables of a vertex have linearly independent columns in `[I, −M]`. So it suffices to
/// try every *support* S — for each i, w_i basic, z_i basic, or neither (3ⁿ choices; "neither" covers degenerate
/// vertices whose complementary principal block is singular) — keep those whose columns are independent, solve
/// `[I, −M]_S x = q` (consistent, unique) and keep x ≥ 0. This is the enumeration of complementary bases
/// (`M_αα z_α = −q_α`, `w_ᾱ = q_ᾱ + M_ᾱα z_α`) extended to singular principal blocks; it returns every vertex
/// solution (deduplicated), and an empty list proves the LCP has no solution (up to the tolerance).
pub fn enumerate(p: &Lcp) -> Vec<Vec<f64>> {
    let n = p.size();
    assert!(n <= 10, "enumeration is for small problems");
    let s = scale(p);
    let tol = 1e-9 * s;
    let mut found: Vec<Vec<f64>> = Vec::new();
    let total = 3usize.pow(n as u32);
    for code in 0..total {
        // Decode: 0 = neither, 1 = w_i, 2 = z_i.
        let mut kinds = vec![0u8; n];
        let mut c = code;
        for k in kinds.iter_mut() {
            *k = (c % 3) as u8;
            c /= 3;
        }
        let cols: Vec<(u8, usize)> = kinds.iter().enumerate().filter(|(_, &k)| k != 0).map(|(i, &k)| (k, i)).collect();
        let k = cols.len();
        // Augmented n × (k+1) system [A | q].
        let mut a = vec![vec![0.0; k + 1]; n];
        for (c, &(kind, j)) in cols.iter().enumerate() {
            for (i, row) in a.iter_mut().enumerate() {
                row[c] = if kind == 1 { f64::from(u8::from(i == j)) } else { -p.m()[(i, j)] };
            }
        }
        for (i, row) in a.iter_mut().enumerate() {
            row[k] = p.q()[i];
        }
        // Gaussian elimination with partial pivoting; a column without a pivot means dependent columns.
        let mut rows: Vec<usize> = (0..n).collect();
        let mut independent = true;
        for c in 0..k {
            let (best, &r) = rows[c..]
                .iter()
                .enumerate()
                .max_by(|x, y| a[*x.1][c].abs().total_cmp(&a[*y.1][c].abs()))
                .expect("rows left");
            if a[r][c].abs() <= 1e-12 * s {
                independent = false;
                break;
            }
            rows.swap(c, c + best);
            let pr = a[r].clone();
            for &i in &rows[c + 1..] {
                let f = a[i][c] / pr[c];
                if f != 0.0 {
                    for (x, y) in a[i].iter_mut().zip(&pr).skip(c) {
                        *x -= f * y;
                    }
                }
            }
        }
        if !independent {
            continue;
        }
        // Consistency of the rows left over.
        if rows[k..].iter().any(|&i| a[i][k].abs() > tol) {
            continue;
        }
        let mut x = vec![0.0; k];
        for c in (0..k).rev() {
            let r = rows[c];
            let mut v = a[r][k];
            for (cc, xv) in x.iter().enumerate().skip(c + 1) {
                v -= a[r][cc] * xv;
            }
            x[c] = v / a[r][c];
        }
        if x.iter().any(|&v| v < -tol) {
            continue;
        }
        let mut z = vec![0.0; n];
        for (c, &(kind, j)) in cols.iter().enumerate() {
            if kind == 2 {
                z[j] = x[c].max(0.0);
            }
        }
        // Independent check of the conditions on the original data.
        let w = p.w_of(&z).unwrap();
        if w.iter().any(|&v| v < -1e-8 * s) || z.iter().zip(&w).any(|(a, b)| (a * b).abs() > 1e-8 * s * s) {
            continue;
        }
        let zs = z.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        if !found.iter().any(|f| f.iter().zip(&z).all(|(a, b)| (a - b).abs() <= 1e-8 * zs)) {
            found.push(z);
        }
    }
    found
}

/// Every principal minor positive (the definition of a P-matrix; CPS Def. 3.3.1), by LU of each principal block.
pub fn is_p_matrix(m: &Mat<f64>) -> bool {
    let n = m.nrows();
    (1..1usize << n).all(|mask| {
        let idx: Vec<usize> = (0..n).filter(|i| mask >> i & 1 == 1).collect();
        let k = idx.len();
        let mut a: Vec<Vec<f64>> = idx.iter().map(|&i| idx.iter().map(|&j| m[(i, j)]).collect()).collect();
        let mut det = 1.0;
        for c in 0..k {
            let r = (c..k).max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs())).expect("rows");
            if a[r][c] == 0.0 {
                return false;
            }
            if r != c {
                a.swap(r, c);
                det = -det;
            }
            det *= a[c][c];
            for i in c + 1..k {
                let f = a[i][c] / a[c][c];
                for j in c..k {
                    a[i][j] -= f * a[c][j];
                }
            }
        }
        det > 0.0
    })
}
