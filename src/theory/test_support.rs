//! Numerical helpers of the theory tests: tanh–sinh quadrature, principal-value Hilbert transform, log potential,
//! finite differences and a dense Cholesky solver. They are independent of the closed forms they check.

use std::f64::consts::FRAC_PI_2;

/// Tanh–sinh (double-exponential) quadrature of `f` over `[a, b]`; never evaluates `f` at the
/// end points, so integrable end-point singularities (log, inverse square root) are fine.
/// Stops when two successive levels differ by at most `max(rel·|I|, abs)`.
pub(super) fn tanh_sinh(f: &dyn Fn(f64) -> f64, a: f64, b: f64, rel: f64, abs: f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    let half = 0.5 * (b - a);
    let term = |t: f64| -> f64 {
        let u = FRAC_PI_2 * t.sinh();
        let e = (-2.0 * u.abs()).exp();
        let off = half * 2.0 * e / (1.0 + e);
        let w = FRAC_PI_2 * t.cosh() * 4.0 * e / ((1.0 + e) * (1.0 + e));
        let x = if t >= 0.0 { b - off } else { a + off };
        if off <= 0.0 || x <= a || x >= b {
            0.0
        } else {
            w * half * f(x)
        }
    };
    let tmax = 4.0;
    let mut h = 1.0;
    let mut sum = term(0.0);
    for k in 1..=4 {
        sum += term(k as f64) + term(-(k as f64));
    }
    let mut prev = sum * h;
    for level in 1..=11 {
        h *= 0.5;
        let kmax = (tmax / h) as u32;
        let mut k = 1;
        while k <= kmax {
            let t = k as f64 * h;
            sum += term(t) + term(-t);
            k += 2;
        }
        let cur = sum * h;
        if level >= 3 && (cur - prev).abs() <= (rel * cur.abs()).max(abs) {
            return cur;
        }
        prev = cur;
    }
    prev
}

/// Piecewise tanh–sinh over the sorted, de-duplicated break points `pts`.
pub(super) fn quad(f: &dyn Fn(f64) -> f64, pts: &[f64], rel: f64, abs: f64) -> f64 {
    let mut p: Vec<f64> = pts.to_vec();
    p.sort_by(|a, b| a.partial_cmp(b).unwrap());
    p.dedup_by(|a, b| (*a - *b).abs() < 1e-14);
    p.windows(2).map(|w| tanh_sinh(f, w[0], w[1], rel, abs)).sum()
}

/// Principal value `PV∫_{−a}^{a} q(t)/(x − t) dt` for |x| < a by subtraction of `q(x)`.
pub(super) fn hilbert(q: &dyn Fn(f64) -> f64, x: f64, a: f64, kinks: &[f64]) -> f64 {
    let qx = q(x);
    let g = |t: f64| (q(t) - qx) / (x - t);
    let mut pts = vec![-a, x, a];
    pts.extend(kinks.iter().copied().filter(|k| k.abs() < a));
    quad(&g, &pts, 1e-13, 1e-16) + qx * ((a + x) / (a - x)).ln()
}

/// Log potential `∫_{−a}^{a} q(t) ln(|x − t|/d) dt` (surface displacement kernel).
pub(super) fn log_potential(q: &dyn Fn(f64) -> f64, x: f64, d: f64, a: f64, kinks: &[f64]) -> f64 {
    let g = |t: f64| if t == x { 0.0 } else { q(t) * ((x - t).abs() / d).ln() };
    let mut pts = vec![-a, a];
    pts.extend(kinks.iter().copied().filter(|k| k.abs() < a));
    if x.abs() < a {
        pts.push(x);
    }
    quad(&g, &pts, 1e-13, 1e-16)
}

/// Fourth-order central difference.
pub(super) fn d4(f: &dyn Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (-f(x + 2.0 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2.0 * h)) / (12.0 * h)
}

/// Fourth-order second difference.
pub(super) fn d4_2(f: &dyn Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (-f(x + 2.0 * h) + 16.0 * f(x + h) - 30.0 * f(x) + 16.0 * f(x - h) - f(x - 2.0 * h)) / (12.0 * h * h)
}

/// Solve the SPD system `m x = rhs` (row-major `n × n`) by Cholesky.
pub(super) fn cholesky_solve(m: &[f64], n: usize, rhs: &[f64]) -> Vec<f64> {
    let mut l = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..=i {
            let mut s = m[i * n + j];
            for k in 0..j {
                s -= l[i * n + k] * l[j * n + k];
            }
            l[i * n + j] = if i == j { s.sqrt() } else { s / l[j * n + j] };
        }
    }
    let mut y = vec![0.0; n];
    for i in 0..n {
        let s: f64 = (0..i).map(|k| l[i * n + k] * y[k]).sum();
        y[i] = (rhs[i] - s) / l[i * n + i];
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|k| l[k * n + i] * x[k]).sum();
        x[i] = (y[i] - s) / l[i * n + i];
    }
    x
}

pub(super) fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}
