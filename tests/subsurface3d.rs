//! Subsurface stresses of the half-space under 3D tractions (`rollbem::halfspace::subsurface`), each test against
//! an independent expected value:
//!
//! - the pointwise integration of Boussinesq's and Cerruti's point-load stresses by Gauss–Legendre quadrature
//!   (the stresses differentiated exactly, by dual numbers, from the textbook point-load displacements; the field
//!   checked to be in equilibrium and to carry the load);
//! - Hertz's circular contact on the z axis (Johnson, *Contact Mechanics*, eq. 3.45), with the discretisation error
//!   measured as the grid refines;
//! - CONTACT's `subsurf.inp` (Kalker 1990 fig. 5.20: one uniformly loaded square; `reference/contact3d/`), CONTACT's
//!   element tractions fed to our formulas and its stresses compared to its printed digits.

use rollbem::bem::quadrature::gauss_legendre;
use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::Drive;
use rollbem::halfspace::subsurface::{Stress, StressBox, Subsurface};
use rollbem::halfspace::tangential::TangentialDrive;
use rollbem::halfspace::{ContactGrid, HalfSpace, Path, PathSettings, PathStatus, Profile, Step};
use std::collections::HashMap;
use std::ops::{Add, Div, Mul, Neg, Sub};

// ---------------------------------------------------------------------------------------------------------------
// Point loads, differentiated by dual numbers.

/// A dual number `v + d ε` (ε² = 0): forward-mode differentiation, exact to rounding.
#[derive(Clone, Copy, Debug)]
struct D {
    v: f64,
    d: f64,
}

impl D {
    fn c(v: f64) -> D {
        D { v, d: 0.0 }
    }
    fn sqrt(self) -> D {
        let s = self.v.sqrt();
        D { v: s, d: self.d / (2.0 * s) }
    }
}
impl Add for D {
    type Output = D;
    fn add(self, o: D) -> D {
        D { v: self.v + o.v, d: self.d + o.d }
    }
}
impl Sub for D {
    type Output = D;
    fn sub(self, o: D) -> D {
        D { v: self.v - o.v, d: self.d - o.d }
    }
}
impl Mul for D {
    type Output = D;
    fn mul(self, o: D) -> D {
        D { v: self.v * o.v, d: self.d * o.v + self.v * o.d }
    }
}
impl Div for D {
    type Output = D;
    fn div(self, o: D) -> D {
        D { v: self.v / o.v, d: (self.d * o.v - self.v * o.d) / (o.v * o.v) }
    }
}
impl Neg for D {
    type Output = D;
    fn neg(self) -> D {
        D { v: -self.v, d: -self.d }
    }
}

/// The displacement `[u_x, u_y, u_z]` (times 4πG) at `(X, Y, z)` relative to a point force `f = [P, Q_x, Q_y]`
/// on the surface of the half-space `z > 0`: Boussinesq (Johnson eq. 3.19, `P` along +z) and Cerruti (eqs.
/// 3.86–3.87, `Q_x` along +x; `Q_y` by x ↔ y), in full (not only at the surface).
fn point_displacement(x: D, y: D, z: D, f: [f64; 3], nu: f64) -> [D; 3] {
    let rho = (x * x + y * y + z * z).sqrt();
    let r3 = rho * rho * rho;
    let rz = rho + z;
    let m = D::c(1.0 - 2.0 * nu);
    let one = D::c(1.0);
    // Boussinesq.
    let bx = x * z / r3 - m * x / (rho * rz);
    let by = y * z / r3 - m * y / (rho * rz);
    let bz = z * z / r3 + D::c(2.0 * (1.0 - nu)) / rho;
    // Cerruti, Q_x.
    let cerruti = |a: D, b: D| {
        let ua = one / rho + a * a / r3 + m * (one / rz - a * a / (rho * rz * rz));
        let ub = a * b / r3 - m * a * b / (rho * rz * rz);
        let uz = a * z / r3 + m * a / (rho * rz);
        (ua, ub, uz)
    };
    let (xx, xy, xz) = cerruti(x, y);
    let (yy, yx, yz) = cerruti(y, x);
    let (p, qx, qy) = (D::c(f[0]), D::c(f[1]), D::c(f[2]));
    [p * bx + qx * xx + qy * yx, p * by + qx * xy + qy * yy, p * bz + qx * xz + qy * yz]
}

/// The stress `[xx, yy, zz, xy, yz, zx]` of the point force `f` at `(X, Y, z)` by Hooke's law from the exact
/// displacement gradient (three dual-number passes).
fn point_stress(x: f64, y: f64, z: f64, f: [f64; 3], nu: f64) -> [f64; 6] {
    let mut g = [[0.0; 3]; 3]; // g[i][j] = ∂u_i/∂x_j
    for j in 0..3 {
        let s = |k: usize, v: f64| D { v, d: if k == j { 1.0 } else { 0.0 } };
        let u = point_displacement(s(0, x), s(1, y), s(2, z), f, nu);
        for (row, ui) in g.iter_mut().zip(u) {
            row[j] = ui.d;
        }
    }
    // With 4πG u given and G = 1: σ = λ tr ε + 2ε, λ = 2ν/(1−2ν), all over 4π.
    let lam = 2.0 * nu / (1.0 - 2.0 * nu);
    let tr = g[0][0] + g[1][1] + g[2][2];
    let k = 1.0 / (4.0 * std::f64::consts::PI);
    [
        k * (lam * tr + 2.0 * g[0][0]),
        k * (lam * tr + 2.0 * g[1][1]),
        k * (lam * tr + 2.0 * g[2][2]),
        k * (g[0][1] + g[1][0]),
        k * (g[1][2] + g[2][1]),
        k * (g[2][0] + g[0][2]),
    ]
}

/// Break points of `[lo, hi]` graded geometrically towards `c` (the point's projection) from panels of `z/4`.
fn panels(lo: f64, hi: f64, c: f64, z: f64) -> Vec<f64> {
    let mut b = vec![lo, hi];
    let c = c.clamp(lo, hi);
    b.push(c);
    let mut s = (z / 4.0).max(1e-6 * (hi - lo));
    while s < hi - lo {
        for v in [c - s, c + s] {
            if v > lo && v < hi {
                b.push(v);
            }
        }
        s *= 2.0;
    }
    b.sort_by(f64::total_cmp);
    b.dedup();
    b
}

/// The stress at `(x, y, z)` of the uniform tractions `f` on the rectangle `[x1, x2] × [y1, y2]`: the point-load
/// stress integrated by composite 20-point Gauss–Legendre on panels graded towards the point.
fn quadrature(rect: [f64; 4], f: [f64; 3], nu: f64, (x, y, z): (f64, f64, f64)) -> [f64; 6] {
    let rule = gauss_legendre(20).unwrap();
    let (bx, by) = (panels(rect[0], rect[1], x, z), panels(rect[2], rect[3], y, z));
    let mut out = [0.0; 6];
    for wx in bx.windows(2) {
        let (hx, mx) = (0.5 * (wx[1] - wx[0]), 0.5 * (wx[1] + wx[0]));
        for wy in by.windows(2) {
            let (hy, my) = (0.5 * (wy[1] - wy[0]), 0.5 * (wy[1] + wy[0]));
            for (s, ws) in rule.iter() {
                for (t, wt) in rule.iter() {
                    let (xi, eta) = (mx + hx * s, my + hy * t);
                    let st = point_stress(x - xi, y - eta, z, f, nu);
                    for k in 0..6 {
                        out[k] += ws * wt * hx * hy * st[k];
                    }
                }
            }
        }
    }
    out
}

/// A 3 × 2 grid of elements 1 × 0.6 with different tractions per element.
fn small_grid() -> (ContactGrid, Vec<[f64; 3]>) {
    let grid = ContactGrid::new(3, 2, 1.0, 0.6, -1.0, -0.3).unwrap();
    let t =
        vec![[1.0, 0.4, -0.3], [0.7, -0.2, 0.1], [0.0, 0.5, 0.0], [0.3, 0.0, 0.25], [1.2, 0.3, 0.3], [0.4, -0.1, 0.0]];
    (grid, t)
}

fn field_of(grid: &ContactGrid, t: &[[f64; 3]], nu: f64) -> Subsurface {
    let body = HalfSpace::new(1.0, nu).unwrap();
    let col = |k: usize| t.iter().map(|v| v[k]).collect::<Vec<f64>>();
    Subsurface::new(grid, &body, &col(0), &col(1), &col(2)).unwrap()
}

/// The closed forms against the quadrature of the point-load stresses, summed over the elements of a 3 × 2 grid
/// with different (p, q_x, q_y) on each, ν = 0, 0.3 and 0.45, at points above element interiors, edges, corners and
/// beside the grid, at depths 1e-3 to 5 element sizes: every component within 1e-10 of the largest traction
/// (measured: 8e-14). Also at one element 10³ sizes away, relative to the stress there (the closed form's
/// cancellation, module docs "Accuracy"; measured 5e-10).
#[test]
fn closed_forms_match_quadrature_of_point_loads() {
    let (grid, t) = small_grid();
    let pts = [
        (0.1, 0.2, 0.3),
        (-0.5, 0.0, 0.05),
        (0.5, 0.3, 0.02),
        (-1.2, -0.25, 0.001),
        (2.5, -1.5, 0.4),
        (0.3, 0.1, 5.0),
        (0.0, -0.6, 0.7),
    ];
    let mut worst = 0.0_f64;
    for nu in [0.0, 0.3, 0.45] {
        let field = field_of(&grid, &t, nu);
        for &p in &pts {
            let ours = field.stress(p.0, p.1, p.2).unwrap().components();
            let mut exact = [0.0; 6];
            for (e, f) in t.iter().enumerate() {
                let (cx, cy) = grid.centre(e % 3, e / 3);
                let rect = [cx - 0.5, cx + 0.5, cy - 0.3, cy + 0.3];
                let q = quadrature(rect, *f, nu, p);
                exact.iter_mut().zip(q).for_each(|(a, b)| *a += b);
            }
            for k in 0..6 {
                let d = (ours[k] - exact[k]).abs();
                worst = worst.max(d);
                assert!(d <= 1e-10, "ν {nu} at {p:?} component {k}: {} vs {}", ours[k], exact[k]);
            }
        }
    }
    println!("closed form vs quadrature: largest difference {worst:.2e} (tractions ≤ 1.2)");
    // One element far away.
    let one = ContactGrid::new(1, 1, 1.0, 1.0, 0.0, 0.0).unwrap();
    let f = [1.0, 0.5, -0.4];
    let field = field_of(&one, &[f], 0.3);
    let p = (800.0, -600.0, 300.0);
    let ours = field.stress(p.0, p.1, p.2).unwrap().components();
    let exact = quadrature([-0.5, 0.5, -0.5, 0.5], f, 0.3, p);
    let scale = exact.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let rel = (0..6).map(|k| (ours[k] - exact[k]).abs()).fold(0.0, f64::max) / scale;
    println!("at 10^3 element sizes: relative difference {rel:.2e} (stress scale {scale:.2e})");
    assert!(rel <= 1e-8, "far field: {rel:e}");
}

/// The expected values of the test above are an elastic field carrying the load: the quadrature field is in
/// equilibrium (div σ = 0 by central differences of step 1e-4, to 1e-6) and its surface tractions inside the element are
/// the applied ones (at depth 1e-7: σ_zz = −p, σ_zx = −q_x, σ_yz = −q_y to 1e-5).
#[test]
fn quadrature_reference_is_an_elastic_field_carrying_the_load() {
    let (f, nu, rect) = ([0.8, 0.5, -0.3], 0.3, [-0.5, 0.5, -0.5, 0.5]);
    let (x, y, z) = (0.2, -0.1, 0.4);
    let h = 1e-4;
    let s = |dx: f64, dy: f64, dz: f64| quadrature(rect, f, nu, (x + dx, y + dy, z + dz));
    let d = |k: usize, axis: usize| {
        let e = |sgn: f64| match axis {
            0 => s(sgn * h, 0.0, 0.0)[k],
            1 => s(0.0, sgn * h, 0.0)[k],
            _ => s(0.0, 0.0, sgn * h)[k],
        };
        (e(1.0) - e(-1.0)) / (2.0 * h)
    };
    // div σ: rows (xx, xy, zx), (xy, yy, yz), (zx, yz, zz); components [xx, yy, zz, xy, yz, zx].
    let div = [d(0, 0) + d(3, 1) + d(5, 2), d(3, 0) + d(1, 1) + d(4, 2), d(5, 0) + d(4, 1) + d(2, 2)];
    assert!(div.iter().all(|v| v.abs() < 1e-6), "div σ = {div:?}");
    let surf = quadrature(rect, f, nu, (0.1, 0.2, 1e-7));
    assert!(
        (surf[2] + f[0]).abs() < 1e-5 && (surf[5] + f[1]).abs() < 1e-5 && (surf[4] + f[2]).abs() < 1e-5,
        "{surf:?}"
    );
}

// ---------------------------------------------------------------------------------------------------------------
// Hertz on the z axis.

/// Johnson eq. 3.45: the stresses on the axis of Hertz's circular contact (a = 1, p0 = 1): (σ_z, σ_r).
fn hertz_axis(z: f64, nu: f64) -> (f64, f64) {
    let sz = -1.0 / (1.0 + z * z);
    let sr = if z == 0.0 {
        -(1.0 + 2.0 * nu) / 2.0
    } else {
        -((1.0 + nu) * (1.0 - z * (1.0 / z).atan()) - 0.5 / (1.0 + z * z))
    };
    (sz, sr)
}

/// The largest |σ_r − σ_z|/2 on the axis of Hertz's contact and its depth (golden-section search on eq. 3.45).
fn hertz_max_shear(nu: f64) -> (f64, f64) {
    let f = |z: f64| {
        let (sz, sr) = hertz_axis(z, nu);
        -0.5 * (sr - sz).abs()
    };
    let (mut a, mut b) = (0.2, 1.0);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let z = 0.5 * (a + b);
    (-f(z), z)
}

/// A grid of (2n+1)² elements of side 1/n centred on the origin, covering Hertz's circle a = 1.
fn hertz_grid(n: usize) -> ContactGrid {
    let m = 2 * n + 3;
    let d = 1.0 / n as f64;
    ContactGrid::new(m, m, d, d, -((n + 1) as f64) * d, -((n + 1) as f64) * d).unwrap()
}

/// The worst error on the axis (z = 0.1 … 3) of σ_zz, σ_xx, σ_yy against eq. 3.45, and the maximum shear and its
/// depth found on the axis (z step 1e-3 around the maximum), for the pressures `p` on `grid`.
fn axis_errors(grid: &ContactGrid, p: &[f64], nu: f64) -> (f64, f64, f64) {
    let body = HalfSpace::new(1.0, nu).unwrap();
    let zero = vec![0.0; p.len()];
    let field = Subsurface::new(grid, &body, p, &zero, &zero).unwrap();
    let mut err = 0.0_f64;
    for k in 1..=30 {
        let z = 0.1 * k as f64;
        let s = field.stress(0.0, 0.0, z).unwrap();
        let (sz, sr) = hertz_axis(z, nu);
        err = err.max((s.zz - sz).abs()).max((s.xx - sr).abs()).max((s.yy - sr).abs());
    }
    let pts: Vec<[f64; 3]> = (0..=400).map(|k| [0.0, 0.0, 0.3 + 1e-3 * k as f64]).collect();
    let f = field.evaluate(&pts).unwrap();
    (err, f.max_shear.value, f.max_shear.at[2])
}

/// Hertz's circle (ν = 0.3, a = 1, p0 = 1) with Hertz's pressure sampled at the element centres: on the z axis the
/// stresses converge to Johnson's eq. 3.45 as the grid refines (worst of σ_zz, σ_xx, σ_yy over z = 0.1 … 3a;
/// measured 9.1e-3, 1.8e-3, 3.9e-4, 8.2e-5 p0 at 5, 10, 20, 40 elements per radius: observed order 2.2–2.3, each
/// halving of the elements dividing the error by 4.7–5.0), and the maximum shear on the axis to Johnson's 0.31 p0
/// at 0.48a (eq. 3.45's own maximum, by golden section here: 0.31002 p0 at z = 0.4809a; at 40 elements per radius
/// 0.31000 at 0.481).
#[test]
fn hertz_axis_stresses_converge_to_johnson() {
    let nu = 0.3;
    let (tau, z_tau) = hertz_max_shear(nu);
    println!("eq. 3.45: max shear {tau:.5} p0 at z = {z_tau:.4} a");
    assert!((tau - 0.31).abs() < 0.005 && (z_tau - 0.48).abs() < 0.01, "{tau} at {z_tau}");
    let mut errs = Vec::new();
    for n in [5, 10, 20, 40] {
        let grid = hertz_grid(n);
        let p = grid.sample(|x, y| (1.0 - x * x - y * y).max(0.0).sqrt());
        let (e, t, zt) = axis_errors(&grid, &p, nu);
        println!("n = {n}: worst axis error {e:.2e} p0; max shear {t:.5} at z = {zt:.3}");
        errs.push((e, t, zt));
    }
    for w in errs.windows(2) {
        assert!(w[1].0 < w[0].0 / 3.5, "error does not fall at order ≥ 1.8: {errs:?}");
    }
    let (e, t, zt) = errs[3];
    assert!(e < 1.2e-4, "{e}");
    assert!((t - tau).abs() < 2e-4 && (zt - z_tau).abs() < 2e-3, "{t} at {zt} vs {tau} at {z_tau}");
}

/// The same with the pressures rollbem's normal solver computes (frictionless sphere, R = 1, on a rigid flat, E*
/// chosen for a = 1, p0 = 1): the solver's discrete Hertz and the stress formulas together, on the axis, against
/// eq. 3.45. Measured worst error 2.7e-4, 8.1e-5 p0 at 10 and 20 elements per radius (max shear 0.30999 at
/// 0.481a).
#[test]
fn hertz_axis_stresses_from_the_normal_solver() {
    let nu = 0.3;
    let e_star = std::f64::consts::PI / 2.0; // p0 = 2E*a/(πR) = 1
    let body = HalfSpace::new(e_star * (1.0 - nu * nu), nu).unwrap();
    let rigid = HalfSpace::new(f64::INFINITY, nu).unwrap();
    let load = 2.0 * std::f64::consts::PI / 3.0; // P = (2/3)π a² p0
    let mut errs = Vec::new();
    for n in [10, 20] {
        let grid = hertz_grid(n);
        let step = Step::new(Drive::Load(load), TangentialDrive::Shift(0.0, 0.0));
        let path = Path::new(grid, body, rigid, Profile::Quadratic { a: 0.5, b: 0.5 }, 0.0, false, vec![step]).unwrap();
        let o = &path.solve(&PathSettings::default(), &Cancel::never()).unwrap()[0];
        assert_eq!(o.status, PathStatus::Solved, "{}", o.message);
        let (e, t, zt) = axis_errors(&grid, &o.pressure, nu);
        println!("solver, n = {n}: worst axis error {e:.2e} p0; max shear {t:.5} at z = {zt:.3}");
        errs.push(e);
    }
    assert!(errs[1] < errs[0] / 2.0 && errs[1] < 1.2e-4, "{errs:?}");
}

// ---------------------------------------------------------------------------------------------------------------
// CONTACT's subsurf.inp.

fn csv(name: &str) -> Vec<HashMap<String, String>> {
    let path = format!("{}/reference/contact3d/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut r = csv::Reader::from_path(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let head: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .filter_map(|rec| {
            let rec = rec.ok()?;
            (rec.len() == head.len()).then(|| head.iter().cloned().zip(rec.iter().map(String::from)).collect())
        })
        .collect()
}

/// A printed number and the unit of its last printed digit (`-5.7279E-14` → 1e-18; `0.403992` → 1e-6).
fn printed(s: &str) -> (f64, f64) {
    let s = s.trim();
    let v: f64 = s.parse().unwrap_or_else(|_| panic!("not a number: {s:?}"));
    let (mant, exp) = match s.find(['E', 'e']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().unwrap()),
        None => (s, 0),
    };
    let decimals = mant.find('.').map_or(0, |i| mant.len() - i - 1) as i32;
    (v, 10f64.powi(exp - decimals))
}

/// One case of `subsurf.inp`: CONTACT's tractions from its element table fed to our formulas, compared on the z
/// axis (x = y = 1e-5, 15 depths 0 … 5 mm) with CONTACT's σ components and von Mises stress. Returns the worst
/// difference in units of the last printed digit, and the worst relative to the traction scale 1.
fn subsurf_case(case: usize) -> (f64, f64) {
    let el = &csv(&format!("subsurf_case{case}_elements.csv"))[0];
    let num = |k: &str| el[k].trim().parse::<f64>().unwrap();
    // One element of 1 × 1 mm centred at CONTACT's (x, y) of the element; G = 1, ν = 0.28 (README, "subsurf").
    let grid = ContactGrid::new(1, 1, 1.0, 1.0, num("x"), num("y")).unwrap();
    let body = HalfSpace::new(2.0 * 1.28, 0.28).unwrap();
    let field = Subsurface::new(&grid, &body, &[num("pn")], &[num("px")], &[num("py")]).unwrap();
    let (mut units, mut abs) = (0.0_f64, 0.0_f64);
    for row in csv(&format!("subsurf_case{case}_axis.csv")) {
        let (x, y, z) = (printed(&row["x"]).0, printed(&row["y"]).0, printed(&row["z"]).0);
        let s = field.stress(x, y, z).unwrap();
        let ours = [
            ("sigxx", s.xx),
            ("sigyy", s.yy),
            ("sigzz", s.zz),
            ("sigxy", s.xy),
            ("sigyz", s.yz),
            ("sigxz", s.zx),
            ("sigvm", s.von_mises()),
            ("sighyd", s.hydrostatic()),
        ];
        for (key, v) in ours {
            let (theirs, unit) = printed(&row[key]);
            let d = (v - theirs).abs();
            abs = abs.max(d);
            // CONTACT's values below 1e-12 of the load are its round-off (e.g. σ_xz = −5.7e-14 at z = 0 under a
            // pressure, exactly 0 in theory): those count by the absolute difference only.
            if theirs.abs() > 1e-12 {
                units = units.max(d / unit);
            }
            // Half a unit of CONTACT's last printed stress digit, plus what half a unit of the 6th digit of the
            // tractions we read from its element table (5e-7 of pn = 1 and of px = 0.999) can move a stress:
            // at most 5e-7 per unit traction, the stress per unit traction being at most 1 on the axis.
            assert!(
                d <= 0.5 * unit + 1e-6 || d <= 1e-12,
                "case {case} z = {z} {key}: ours {v:.9e}, CONTACT {theirs:e} (last digit {unit:e})"
            );
        }
    }
    (units, abs)
}

/// `subsurf.inp` case 1 (pn = 1 on the square, ν = 0.28) and case 2 (pn = 1, px = 0.999): every printed stress on
/// the axis — σ_xx … σ_zz, von Mises, hydrostatic; 15 depths — agrees with CONTACT's within half a unit of its last
/// printed digit (its 5–6 significant digits; the README says which file each comes from) plus 1e-6 for the
/// tractions, which its element table gives to 6 digits (measured: case 1 within 0.50 units, case 2 within 1.0
/// unit — σ_xz = −0.998999 at z = 0 against px = 0.999000 as printed: CONTACT's px is 0.9989995).
#[test]
fn subsurf_inp_stresses_agree_with_contact() {
    for case in [1, 2] {
        let (units, abs) = subsurf_case(case);
        println!("subsurf case {case}: worst {units:.2} units of CONTACT's last digit, {abs:.2e} absolute");
    }
}

/// `subsurf.inp` solved by rollbem: case 1 is the normal problem at FN = 1 N on the one element (pn = FN/area = 1),
/// case 2 adds the tangential force FX = 0.999 μ FN (μ = 1; CONTACT rolls, which on one element in stick gives the
/// same traction): the solved tractions equal CONTACT's element table, so the stresses are those compared above.
#[test]
fn subsurf_inp_tractions_from_rollbem_solvers() {
    let grid = ContactGrid::new(1, 1, 1.0, 1.0, 1e-4, 2e-4).unwrap();
    let body = HalfSpace::new(2.56, 0.28).unwrap();
    for (case, fx) in [(1, 0.0), (2, 0.999)] {
        let el = &csv(&format!("subsurf_case{case}_elements.csv"))[0];
        let num = |k: &str| el[k].trim().parse::<f64>().unwrap();
        let step = Step::new(Drive::Load(1.0), TangentialDrive::Force(fx, 0.0));
        let path = Path::new(grid, body, body, Profile::Quadratic { a: 2.16, b: 2.16 }, 1.0, true, vec![step]).unwrap();
        let o = &path.solve(&PathSettings::default(), &Cancel::never()).unwrap()[0];
        // One element is the whole grid: it touches the grid's edge by construction, so the status says so.
        assert!(matches!(o.status, PathStatus::Solved | PathStatus::ContactAtGridEdge), "{}", o.message);
        let d = (o.pressure[0] - num("pn")).abs().max((o.qx[0] - num("px")).abs()).max((o.qy[0] - num("py")).abs());
        assert!(d <= 5e-6, "case {case}: ours {} {} {}, CONTACT {el:?}", o.pressure[0], o.qx[0], o.qy[0]);
        let ours = Subsurface::new(&grid, &body, &o.pressure, &o.qx, &o.qy).unwrap().stress(1e-5, 1e-5, 0.5).unwrap();
        let theirs = &csv(&format!("subsurf_case{case}_axis.csv"))[5];
        assert!((ours.zz - printed(&theirs["sigzz"]).0).abs() <= 1e-5, "{ours:?}");
        assert!((ours.zx - printed(&theirs["sigxz"]).0).abs() <= 1e-5, "{ours:?}");
    }
}

/// A box grid: the maxima are found where the field has them (Hertz, ν = 0.3: von Mises and Tresca peak on the
/// axis below the surface, Tresca's at 0.48a with 0.31 p0, Johnson §3.4), and the evaluation's cost is printed.
#[test]
fn box_grid_maxima_of_hertz() {
    let grid = hertz_grid(20);
    let p = grid.sample(|x, y| (1.0 - x * x - y * y).max(0.0).sqrt());
    let zero = vec![0.0; p.len()];
    let field = Subsurface::new(&grid, &HalfSpace::new(1.0, 0.3).unwrap(), &p, &zero, &zero).unwrap();
    let b = StressBox::new([-0.5, -0.5, 0.3], [0.5, 0.5, 0.7], [11, 11, 41]);
    let t0 = std::time::Instant::now();
    let f = field.evaluate_box(&b).unwrap();
    println!(
        "box {} points × {} nodes in {:.3} s; von Mises {:.4} at {:?}, Tresca {:.4} at {:?}",
        f.points.len(),
        field.active_nodes(),
        t0.elapsed().as_secs_f64(),
        f.von_mises.value,
        f.von_mises.at,
        f.max_shear.value,
        f.max_shear.at
    );
    let (tau, z_tau) = hertz_max_shear(0.3);
    assert!(f.max_shear.at[0].abs() < 1e-12 && f.max_shear.at[1].abs() < 1e-12);
    assert!((f.max_shear.value - tau).abs() < 1e-3 && (f.max_shear.at[2] - z_tau).abs() <= 0.01);
    assert!(f.von_mises.at[0].abs() < 1e-12 && f.von_mises.at[1].abs() < 1e-12);
    let s: &Stress = &f.stresses[0];
    assert!(s.von_mises() <= f.von_mises.value);
}
