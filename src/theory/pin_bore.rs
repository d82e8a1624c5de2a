//! Theory 8, the pin in a bore (Persson 1964; Ciavarella & Decuzzi, IJSS 38, 2001): a frictionless pin of radius R
//! in a circular hole of radius R + ΔR of an infinite plate of the same material (plane strain), pressed by a force P
//! per unit thickness. The contact arc |θ| ≤ b (θ from the line of the load) grows from Hertzian (b of a few
//! degrees) to conformal (tens of degrees); at zero clearance b is independent of the load.
//!
//! The closed forms of Ciavarella & Decuzzi were not at hand verbatim, so this module derives the problem and
//! solves it by an independent, spectrally accurate method (it shares nothing with the BEM):
//!
//! **Compliance** (derived here from the Michell solution, plane strain, κ = 3 − 4ν, shear modulus μ). A boundary
//! pressure p_n cos nθ (n ≥ 2) without shear moves a solid disc's boundary radially by
//! −(p_n R/4μ)[κ/(n+1) + 1/(n−1)] cos nθ and the hole's boundary of an infinite plate by
//! +(p_n R/4μ)[κ/(n−1) + 1/(n+1)] cos nθ; a uniform pressure by −p₀R(κ−1)/4μ and +p₀R/2μ. The gap opens by their
//! difference, with 1/E* = (κ+1)/4μ = 2(1 − ν²)/E:
//!
//! ```text
//!   w(θ) = (R/E*) [ p̄₀ + Σ_{n≥2} 2n/(n²−1) p_n cos nθ ] + (the n = 1 term)
//! ```
//!
//! The n = 1 term is a cos θ, indistinguishable from a rigid approach of the pin (in an infinite plate the pin's
//! displacement is not even defined), so it joins the approach D as one unknown. Summed over n,
//! `w(θ) = (R/(πE*)) ∫ p(φ) G(θ − φ) dφ` with `G(x) = −½ − ½ cos x − 2 cos x ln|2 sin(x/2)|`.
//!
//! **Contact condition** on |θ| ≤ b, with the exact gap linearised in ΔR (g₀ = ΔR(1 − cos θ)):
//! `ΔR(1 − cos θ) − D cos θ + w(θ) = 0`, p ≥ 0 bounded at ±b. Its derivative is a Cauchy singular equation,
//!
//! ```text
//!   (1/π) ∫_{−b}^{b} p(φ) S(θ − φ) dφ = (E* C / R) sin θ,   S = −G′ = cot(x/2) − (3/2) sin x − 2 sin x ln|2 sin(x/2)|,
//! ```
//!
//! C = ΔR + D, solved for C = 1 (p̂) by Gauss–Chebyshev collocation for the bounded solution (Erdogan & Gupta
//! 1972), the logarithmic parts of the kernels integrated exactly on the Chebyshev expansion (Mason & Handscomb:
//! ∫ ln|x − t| T_m(t)/√(1 − t²) dt = −π T_m(x)/m, −π ln 2 for m = 0). The equation at θ = 0 fixes D = C k(b),
//! k = (1/π)∫ p̂ G, so C = ΔR/(1 − k(b)), and
//!
//! ```text
//!   P = E* C J(b),  J = ∫ p̂(φ) cos φ dφ;     p(0) = (E* C / R) p̂(0).
//! ```
//!
//! At small b this is Hertz's line contact with 1/R* = 1/R − 1/(R + ΔR) ≈ ΔR/R² (P = πE*ΔR b²/4, checked in the
//! tests); at zero clearance k(b₀) = 1 fixes the angle b₀ whatever the load.

use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// The dimensionless solution of the pin-in-bore problem at contact half-angle `b` (radians): everything scales with
/// E*, ΔR and R as the module docs say.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PinBore {
    /// Contact half-angle b (radians).
    pub half_angle: f64,
    /// J(b) = ∫ p̂ cos φ dφ: P = E* C J.
    pub j: f64,
    /// k(b): the approach D = k C.
    pub k: f64,
    /// p̂(0): the peak pressure p(0) = E* C p̂(0) / R.
    pub p_hat_peak: f64,
}

impl PinBore {
    /// Solve at half-angle `b` ∈ (0, π/2] with `n` collocation nodes (even, ≥ 8; 64 gives about 1e-8).
    pub fn at_half_angle(b: f64, n: usize) -> PinBore {
        let n = n.max(8) & !1;
        let np1 = (n + 1) as f64;
        let sigma: Vec<f64> = (1..=n).map(|k| (k as f64 * PI / np1).cos()).collect();
        let weight: Vec<f64> = (1..=n).map(|k| PI / np1 * (k as f64 * PI / np1).sin().powi(2)).collect();
        // Collocation points: zeros of T_{n+1}, without the middle one (s = 0, where the odd equation is 0 = 0).
        let s: Vec<f64> =
            (1..=n + 1).filter(|&j| 2 * j != n + 2).map(|j| ((2 * j - 1) as f64 * PI / (2.0 * np1)).cos()).collect();
        let u_table: Vec<Vec<f64>> = (0..n).map(|m| sigma.iter().map(|&x| cheb_u(m, x)).collect()).collect();
        let lam = |x: f64| log_matrix_row(x, &weight, &u_table);
        let mut a = DMatrix::<f64>::zeros(n, n);
        let mut rhs = DVector::<f64>::zeros(n);
        for (row, &sj) in s.iter().enumerate() {
            let l = lam(sj);
            let (sb, cb) = (b * sj).sin_cos();
            for k in 0..n {
                let x = b * (sj - sigma[k]);
                let regular = (0.5 * x).cos() / (0.5 * x).sin()
                    - 2.0 / x
                    - 1.5 * x.sin()
                    - 2.0 * x.sin() * (sinc_log(x) + b.ln());
                let (sk, ck) = (b * sigma[k]).sin_cos();
                a[(row, k)] = 2.0 / PI * weight[k] / (sj - sigma[k]) + b / PI * weight[k] * regular
                    - 2.0 * b / PI * l[k] * (sb * ck - cb * sk);
            }
            rhs[row] = sb;
        }
        let u = a.lu().solve(&rhs).unwrap_or_else(|| DVector::from_element(n, f64::NAN));
        let j: f64 = (0..n).map(|k| b * weight[k] * u[k] * (b * sigma[k]).cos()).sum();
        // k = (b/π) ∫ √(1−σ²) u G(bσ) dσ, G = −½ − ½cos x − 2cos x (ln|2sin(x/2)/x| + ln b) − 2cos x ln|σ|.
        let l0 = lam(0.0);
        let mut kk = 0.0;
        for i in 0..n {
            let x = b * sigma[i];
            let g = -0.5 - 0.5 * x.cos() - 2.0 * x.cos() * (sinc_log(x) + b.ln());
            kk += b / PI * (weight[i] * u[i] * g - 2.0 * l0[i] * u[i] * x.cos());
        }
        // u(0) from its expansion in U_m: c_m = (2/π) Σ W_k u_k U_m(σ_k), U_m(0) = sin((m+1)π/2).
        let peak: f64 = (0..n)
            .step_by(2)
            .map(|m| {
                let c: f64 = (0..n).map(|k| 2.0 / PI * weight[k] * u[k] * u_table[m][k]).sum();
                c * if (m / 2) % 2 == 0 { 1.0 } else { -1.0 }
            })
            .sum();
        PinBore { half_angle: b, j, k: kk, p_hat_peak: peak }
    }

    /// P/(E* ΔR) = J/(1 − k): the load per unit thickness that opens the contact to this half-angle.
    pub fn load_over_estar_clearance(&self) -> f64 {
        self.j / (1.0 - self.k)
    }

    /// p(0)·R/P = p̂(0)/J: the peak pressure per mean load (independent of the clearance).
    pub fn peak_times_radius_over_load(&self) -> f64 {
        self.p_hat_peak / self.j
    }

    /// The half-angle at a load P (per unit thickness) with clearance ΔR > 0, pin radius R irrelevant
    /// (P/(E*ΔR) fixes b), by bisection on b ∈ (10⁻⁴, π/2) of J − (P/(E*ΔR))(1 − k), which is finite everywhere
    /// (P/(E*ΔR) = J/(1 − k) itself grows without bound as b tends to the zero-clearance angle b₀, where 1 − k
    /// vanishes, and changes sign beyond it: every load has its b below b₀). `None` for a load that is not finite
    /// and positive, or below the one at b = 10⁻⁴.
    pub fn at_load(load_over_estar_clearance: f64, n: usize) -> Option<PinBore> {
        if !(load_over_estar_clearance > 0.0 && load_over_estar_clearance.is_finite()) {
            return None;
        }
        let f = |b: f64| {
            let s = PinBore::at_half_angle(b, n);
            s.j - load_over_estar_clearance * (1.0 - s.k)
        };
        bisect(f, 1e-4, 0.5 * PI).map(|b| PinBore::at_half_angle(b, n))
    }

    /// Zero clearance: the half-angle b₀ with k(b₀) = 1 (load-independent), `None` if there is none below π/2.
    pub fn zero_clearance(n: usize) -> Option<PinBore> {
        bisect(|b| 1.0 - PinBore::at_half_angle(b, n).k, 1e-3, 0.5 * PI).map(|b| PinBore::at_half_angle(b, n))
    }
}

/// A root of `f` in [lo, hi] by bisection, if it changes sign there.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Option<f64> {
    let (mut flo, fhi) = (f(lo), f(hi));
    if flo * fhi > 0.0 || !(flo.is_finite() && fhi.is_finite()) {
        return None;
    }
    while hi - lo > 1e-13 * hi {
        let mid = 0.5 * (lo + hi);
        let fm = f(mid);
        if fm * flo > 0.0 {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// ln|2 sin(x/2) / x| (smooth for |x| < 2π; 0 at x = 0).
fn sinc_log(x: f64) -> f64 {
    if x.abs() < 1e-8 {
        -x * x / 24.0
    } else {
        (2.0 * (0.5 * x).sin() / x).abs().ln()
    }
}

/// Chebyshev polynomial of the second kind U_m(x).
fn cheb_u(m: usize, x: f64) -> f64 {
    let (mut u0, mut u1) = (1.0, 2.0 * x);
    if m == 0 {
        return u0;
    }
    for _ in 1..m {
        let u2 = 2.0 * x * u1 - u0;
        u0 = u1;
        u1 = u2;
    }
    u1
}

/// Chebyshev polynomial of the first kind T_m(x), |x| ≤ 1.
fn cheb_t(m: usize, x: f64) -> f64 {
    (m as f64 * x.clamp(-1.0, 1.0).acos()).cos()
}

/// The row λ_k(x) with ∫ √(1−σ²) v(σ) ln|x − σ| dσ = Σ_k λ_k v(σ_k) for v interpolated in U_0..U_{n−1} at the
/// nodes: √(1−t²) U_m = (T_m − T_{m+2})/(2√(1−t²)) and ∫ ln|x−t| T_m/√(1−t²) dt = −π T_m(x)/m (−π ln 2 for m = 0).
/// `u_table[m][k]` = U_m(σ_k).
fn log_matrix_row(x: f64, weight: &[f64], u_table: &[Vec<f64>]) -> Vec<f64> {
    let n = weight.len();
    let l = |m: usize| if m == 0 { -PI * 2f64.ln() } else { -PI * cheb_t(m, x) / m as f64 };
    let lm: Vec<f64> = (0..n).map(|m| 0.5 * (l(m) - l(m + 2))).collect();
    (0..n)
        .map(|k| {
            let s: f64 = (0..n).map(|m| u_table[m][k] * lm[m]).sum();
            2.0 / PI * weight[k] * s
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_angles_are_hertz() {
        // Expected: Hertz with 1/R* = ΔR/R²: P/(E*ΔR) = π b²/4 and p(0)R/P = 2/(π b) (a = Rb, p0 = 2P/(πa)), to
        // O(b²).
        for b in [0.01_f64, 0.03] {
            let s = PinBore::at_half_angle(b, 64);
            let hertz = PI * b * b / 4.0;
            assert!((s.load_over_estar_clearance() / hertz - 1.0).abs() < 2.0 * b * b + 1e-6, "{s:?} vs {hertz}");
            let peak = 2.0 / (PI * b);
            assert!((s.peak_times_radius_over_load() / peak - 1.0).abs() < 2.0 * b * b + 1e-6, "{s:?}");
        }
    }

    #[test]
    fn a_load_gives_back_its_half_angle() {
        // Expected: at_load inverts load_over_estar_clearance (a round trip, 1e-9 in b) from Hertzian to near the
        // zero-clearance angle, where the load grows without bound (the old bisection on J/(1 − k) − P over
        // (0, π/2) found no sign change and returned None at every load).
        for b in [0.05_f64, 0.5, 1.0, 1.4] {
            let load = PinBore::at_half_angle(b, 64).load_over_estar_clearance();
            let s = PinBore::at_load(load, 64).expect("a half-angle");
            assert!((s.half_angle - b).abs() < 1e-9, "b {b}: {s:?}");
        }
        assert!(PinBore::at_load(-1.0, 64).is_none() && PinBore::at_load(f64::NAN, 64).is_none());
    }

    #[test]
    fn converged_in_the_collocation_nodes() {
        // Expected: the solution at 64 and 128 nodes agrees to 1e-6 (the method's own convergence).
        for b in [0.1, 0.8, 1.4] {
            let (c, f) = (PinBore::at_half_angle(b, 64), PinBore::at_half_angle(b, 128));
            assert!((c.j / f.j - 1.0).abs() < 1e-6 && (c.k - f.k).abs() < 1e-6, "{c:?} {f:?}");
            assert!((c.p_hat_peak / f.p_hat_peak - 1.0).abs() < 1e-6, "{c:?} {f:?}");
        }
    }
}
