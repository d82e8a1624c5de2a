//! Kalker's Table E.3 as transcribed (`rollbem::theory::kalker`) against an independent computation of the same
//! coefficients: CONTACT's exact half-space solver (the peer; not its table) in steady rolling at vanishing creepage,
//! full adhesion, on two or three grids, extrapolated to zero element size. Data and how it was made:
//! `reference/contact3d/fastsim/kalker_linear.csv` and the README beside it.
//!
//! With c = √(ab), creepage 1e-6 (ξ or η) or φ = 1e-6/c, CONTACT's forces on body 1 give
//! `C11 = −Fx/(G c² 1e-6)`, `C22 = −Fy/(G c² 1e-6)` (η), `C23 = −Fy/(G c² 1e-6)` (φ), and for η also
//! `Mz/(G c³ 1e-6) = C23` (Kalker's `Mz = −G c³ (−C23 η + c C33 φ)`), a second estimate of C23.

use rollbem::theory::kalker::creep_coefficients;
use std::collections::BTreeMap;
use std::collections::HashMap;

fn csv(name: &str) -> Vec<HashMap<String, String>> {
    let path = format!("{}/reference/contact3d/fastsim/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut r = csv::Reader::from_path(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let head: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records().map(|rec| head.iter().cloned().zip(rec.unwrap().iter().map(String::from)).collect()).collect()
}

fn num(row: &HashMap<String, String>, key: &str) -> f64 {
    row[key].trim().parse().unwrap_or_else(|_| panic!("{key} = {:?}", row[key]))
}

/// Per (a, b, ν) and grid size n: [C11, C22, C23 from Fy(φ), C23 from Mz(η)] computed by CONTACT.
type Computed = BTreeMap<(String, String, String), BTreeMap<usize, [f64; 4]>>;

fn computed() -> Computed {
    const G: f64 = 82_000.0;
    let mut out: Computed = BTreeMap::new();
    for r in csv("kalker_linear.csv") {
        assert_eq!(num(&r, "nslip"), 0.0, "the linear theory: no slip");
        let (a, b) = (num(&r, "a"), num(&r, "b"));
        let c = (a * b).sqrt();
        let s = G * c * c * 1e-6;
        let key = (r["a"].clone(), r["b"].clone(), r["nu"].clone());
        let entry = out.entry(key).or_default().entry(num(&r, "mx") as usize).or_insert([f64::NAN; 4]);
        if num(&r, "xi") != 0.0 {
            entry[0] = -num(&r, "fx") / s;
        } else if num(&r, "eta") != 0.0 {
            entry[1] = -num(&r, "fy") / s;
            entry[3] = num(&r, "mz") / (s * c);
        } else {
            assert!((num(&r, "phi") * c - 1e-6).abs() < 1e-12);
            entry[2] = -num(&r, "fy") / s;
        }
    }
    out
}

/// First-order Richardson extrapolation from grids n1 < n2 (CONTACT's steady-rolling difference is O(h)).
fn extrapolate(n1: usize, c1: f64, n2: usize, c2: f64) -> f64 {
    (n2 as f64 * c2 - n1 as f64 * c1) / (n2 - n1) as f64
}

#[test]
fn table_e3_agrees_with_contacts_exact_solver() {
    // Expected: Table E.3 (as transcribed) within 1.5 % of CONTACT's exact coefficients extrapolated from its two
    // finest grids. Where three grids exist the two extrapolations agree within 0.3 % (measured: 0.07 % on the
    // circle), and the table rounds to three digits (≤ 0.1 %); the 1.5 % bounds the largest difference found
    // (1.15 %, C23 at a/b = 0.2: see the report of this branch), which is Kalker's or the peer's, not the
    // transcription's. It tells the ν columns and the two branches apart (≥ 10 % apart), not neighbouring rows in g
    // (2–3 % apart: theory::kalker's smoothness test does that).
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    for ((a, b, nu), grids) in computed() {
        let (a, b, nu): (f64, f64, f64) = (a.parse().unwrap(), b.parse().unwrap(), nu.parse().unwrap());
        let table = creep_coefficients(a, b, nu).unwrap();
        let want = [table.c11, table.c22, table.c23, table.c23];
        let sizes: Vec<usize> = grids.keys().copied().collect();
        assert!(sizes.len() >= 2, "a/b = {}: grids {sizes:?}", a / b);
        let (n1, n2) = (sizes[sizes.len() - 2], sizes[sizes.len() - 1]);
        for (i, name) in ["C11", "C22", "C23 (Fy, φ)", "C23 (Mz, η)"].iter().enumerate() {
            let got = extrapolate(n1, grids[&n1][i], n2, grids[&n2][i]);
            let rel = (got - want[i]) / want[i];
            let raw: Vec<String> = grids.iter().map(|(n, v)| format!("{n}: {:.4}", v[i])).collect();
            println!(
                "a/b = {:.1}, ν = {nu}: {name} table {:.4}, CONTACT {} → {got:.4} ({:+.2} %)",
                a / b,
                want[i],
                raw.join(", "),
                100.0 * rel
            );
            assert!(rel.abs() < 0.015, "a/b = {}, ν = {nu}, {name}: {got} vs {}", a / b, want[i]);
            worst = worst.max(rel.abs());
            compared += 1;
        }
        // Where three grids exist, the two extrapolations agree: the O(h) model holds.
        if sizes.len() >= 3 {
            let n0 = sizes[sizes.len() - 3];
            let (g0, g1, g2) = (&grids[&n0], &grids[&n1], &grids[&n2]);
            for (i, ((&c0, &c1), &c2)) in g0.iter().zip(g1).zip(g2).enumerate() {
                let e1 = extrapolate(n0, c0, n1, c1);
                let e2 = extrapolate(n1, c1, n2, c2);
                println!("  extrapolations {n0}/{n1} and {n1}/{n2} of coefficient {i}: {e1:.4}, {e2:.4}");
                assert!((e1 - e2).abs() < 0.003 * e2, "{e1} vs {e2}");
            }
        }
    }
    println!("{compared} coefficients compared, largest difference {:.2} %", 100.0 * worst);
    assert!(compared >= 20);
}
