//! Subsurface stresses, McEwen (1949) ([`mcewen_normal`], [`mcewen_tangential`], [`mcewen_sliding`])
//!
//! With `m + i n = √(a² − (x − iz)²)` (m ≥ 0 for z ≥ 0, n with the sign of x):
//!
//! ```text
//!   m² = ½[√((a² − x² + z²)² + 4x²z²) + (a² − x² + z²)],  n² = ½[√(…) − (a² − x² + z²)]
//!   Hertz pressure p = p0√(1 − x²/a²):
//!     σ_xx = −(p0/a)[ m(1 + (z² + n²)/(m² + n²)) − 2z ]
//!     σ_zz = −(p0/a) m (1 − (z² + n²)/(m² + n²))
//!     τ_xz = −(p0/a) n (m² − z²)/(m² + n²)
//!   tangential traction q = q0√(1 − x²/a²) in +x:
//!     σ_xx =  (q0/a)[ n(2 − (z² − m²)/(m² + n²)) − 2x ]
//!     σ_zz = −(q0/a) n (m² − z²)/(m² + n²)
//!     τ_xz = −(q0/a)[ m(1 + (z² + n²)/(m² + n²)) − 2z ]
//! ```
//!
//! (McEwen 1949; Johnson 1985 §4.2 and §7.1; the τ_xz signs are those of *this* tension-positive,
//! z-into-the-body frame, fixed by comparison with Flamant quadrature.) Full sliding: `q0 = μp0`.
//! On the axis (μ = 0): `σ_xx = −(p0/a)[(a² + 2z²)/√(a² + z²) − 2z]`, `σ_zz = −p0 a/√(a² + z²)`;
//! `max τ1 = 0.3002831 p0` at `z = 0.786151a` (Johnson: 0.30p0 at 0.78a). On the surface under
//! full sliding `τ1 = μ p0` for all |x| < a.
//!
//! Location of max τ1 under full sliding (from [`mcewen_max_tau1`]; cross-checked with SciPy
//! Nelder–Mead during development):
//!
//! | μ   | x/a    | z/a    | τ1max/p0 |
//! |-----|--------|--------|----------|
//! | 0   | 0      | 0.7862 | 0.3003   |
//! | 0.1 | 0.3278 | 0.7390 | 0.3048   |
//! | 0.2 | 0.6252 | 0.6013 | 0.3190   |
//! | 0.3 | 0.8644 | 0.3800 | 0.3449   |
//! | 0.5 | surface plateau | 0 | 0.5000 (= μ, for every |x| < a) |
//!
//! The subsurface maximum moves towards `+x` (direction of `q`) and towards the surface, down to
//! z ≈ 0.125a at x ≈ 0.992a; at μ_t = 0.3779645 (numerically equal to 1/√7 to 1e-11, found by
//! bisection during development) the surface plateau value μp0 overtakes it and for μ > μ_t the
//! maximum is τ1 = μp0 on the whole contact surface (the location jumps to z = 0).

use super::hertz::Hertz2D;
use super::stress::Stress2D;

/// McEwen's `(m, n)` for a point `(x, z)`, z ≥ 0, computed without cancellation.
fn mcewen_mn(a: f64, x: f64, z: f64) -> (f64, f64) {
    let aa = a * a - x * x + z * z;
    let s = aa.hypot(2.0 * x * z);
    let xz2 = (x * z) * (x * z);
    let (m2, n2) = if aa >= 0.0 {
        let m2 = 0.5 * (s + aa);
        (m2, if m2 > 0.0 { xz2 / m2 } else { 0.0 })
    } else {
        let n2 = 0.5 * (s - aa);
        (if n2 > 0.0 { xz2 / n2 } else { 0.0 }, n2)
    };
    (m2.sqrt(), n2.sqrt().copysign(x))
}

/// McEwen stresses under the Hertz pressure `p0√(1 − x²/a²)` at `(x, z)`, z ≥ 0 (depth).
pub fn mcewen_normal(h: &Hertz2D, x: f64, z: f64) -> Stress2D {
    let (m, n) = mcewen_mn(h.a, x, z);
    let d = m * m + n * n;
    if d == 0.0 {
        return Stress2D::default();
    }
    let k = h.p0 / h.a;
    let r = (z * z + n * n) / d;
    Stress2D { xx: -k * (m * (1.0 + r) - 2.0 * z), yy: -k * m * (1.0 - r), xy: -k * n * (m * m - z * z) / d }
}

/// McEwen stresses under the tangential traction `q(x) = q0 √(1 − x²/a²)` acting in `+x` on the
/// half-plane surface, at `(x, z)`, z ≥ 0.
pub fn mcewen_tangential(h: &Hertz2D, q0: f64, x: f64, z: f64) -> Stress2D {
    let (m, n) = mcewen_mn(h.a, x, z);
    let d = m * m + n * n;
    let k = q0 / h.a;
    if d == 0.0 {
        return Stress2D { xx: -2.0 * k * x, yy: 0.0, xy: 0.0 };
    }
    Stress2D {
        xx: k * (n * (2.0 - (z * z - m * m) / d) - 2.0 * x),
        yy: -k * n * (m * m - z * z) / d,
        xy: -k * (m * (1.0 + (z * z + n * n) / d) - 2.0 * z),
    }
}

/// Full sliding: Hertz pressure plus `q = μp` in `+x` (friction on the body pointing `+x`).
pub fn mcewen_sliding(h: &Hertz2D, mu: f64, x: f64, z: f64) -> Stress2D {
    mcewen_normal(h, x, z) + mcewen_tangential(h, mu * h.p0, x, z)
}

/// Closed-form Hertz stresses on the symmetry axis `x = 0` at depth `z` (frictionless):
/// `σ_xx = −(p0/a)[(a² + 2z²)/√(a² + z²) − 2z]`, `σ_zz = −p0 a/√(a² + z²)`, `τ_xz = 0`.
pub fn hertz_axis_stress(h: &Hertz2D, z: f64) -> Stress2D {
    let s = (h.a * h.a + z * z).sqrt();
    Stress2D { xx: -h.p0 / h.a * ((h.a * h.a + 2.0 * z * z) / s - 2.0 * z), yy: -h.p0 * h.a / s, xy: 0.0 }
}

/// Maximum of τ1 on the axis of a frictionless Hertz line contact: returns `(z/a, τ1/p0)`
/// (golden-section search; ≈ (0.786151, 0.300283)).
pub fn hertz_axis_max_tau1() -> (f64, f64) {
    let h = Hertz2D::new(1.0, 1.0);
    let f = |z: f64| hertz_axis_stress(&h, z).principal_shear();
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (0.2, 2.0);
    for _ in 0..200 {
        let m1 = hi - g * (hi - lo);
        let m2 = lo + g * (hi - lo);
        if f(m1) < f(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
        if hi - lo < 1e-13 {
            break;
        }
    }
    let z = 0.5 * (lo + hi);
    (z, f(z))
}

/// Location and value of a field maximum, in units of `a` and `p0`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct FieldMax {
    /// x/a of the maximum.
    pub x: f64,
    /// z/a (depth) of the maximum; 0 means on the surface.
    pub z: f64,
    /// Maximum value divided by p0.
    pub value: f64,
}

/// Maximise `f(x, z)` over `|x| ≤ 1.5, 0 ≤ z ≤ 1.5`: grid search then compass refinement.
fn maximize_2d(f: &dyn Fn(f64, f64) -> f64) -> FieldMax {
    let step0 = 0.025;
    let mut best = FieldMax { x: 0.0, z: 0.0, value: f64::NEG_INFINITY };
    for i in 0..=120 {
        for j in 0..=60 {
            let (x, z) = (-1.5 + step0 * i as f64, step0 * j as f64);
            let v = f(x, z);
            if v > best.value {
                best = FieldMax { x, z, value: v };
            }
        }
    }
    let dirs = [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)];
    let mut step = step0;
    while step > 1e-10 {
        let mut moved = false;
        for (dx, dz) in dirs {
            let (x, z) = (best.x + dx * step, (best.z + dz * step).max(0.0));
            let v = f(x, z);
            if v > best.value {
                best = FieldMax { x, z, value: v };
                moved = true;
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    best
}

/// Global maximum of the principal shear τ1 under full sliding (Hertz pressure + `q = μp` in `+x`).
/// For μ > 0.37796 (≈ 1/√7) the maximum is the surface value `τ1 = μp0`, attained on the whole contact
/// (|x| < a, z = 0); the returned `x` is then just one point of that plateau.
pub fn mcewen_max_tau1(mu: f64) -> FieldMax {
    let h = Hertz2D::new(1.0, 1.0);
    maximize_2d(&|x, z| mcewen_sliding(&h, mu, x, z).principal_shear())
}

/// Global maximum of the plane-strain von Mises stress under full sliding (Poisson ratio `nu`).
pub fn mcewen_max_von_mises(mu: f64, nu: f64) -> FieldMax {
    let h = Hertz2D::new(1.0, 1.0);
    maximize_2d(&|x, z| mcewen_sliding(&h, mu, x, z).von_mises_plane_strain(nu))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    /// Flamant superposition over the Hertz-shaped distribution w(t) = w0 √(1 − t²/a²), t = a sin θ.
    fn flamant(h: &Hertz2D, w0: f64, tangential: bool, x: f64, z: f64) -> Stress2D {
        let mut pts = vec![-FRAC_PI_2, FRAC_PI_2];
        for j in [-3.0, -1.0, 0.0, 1.0, 3.0] {
            let t: f64 = x + j * z;
            if t.abs() < h.a {
                pts.push((t / h.a).asin());
            }
        }
        let comp = |k: usize| {
            let f = |th: f64| {
                let t = h.a * th.sin();
                let w = w0 * h.a * th.cos() * th.cos();
                let xx = x - t;
                let r2 = xx * xx + z * z;
                let kern = if tangential {
                    [xx * xx * xx, xx * z * z, xx * xx * z][k]
                } else {
                    [xx * xx * z, z * z * z, xx * z * z][k]
                };
                -2.0 / PI * w * kern / (r2 * r2)
            };
            quad(&f, &pts, 1e-14, 1e-17)
        };
        Stress2D { xx: comp(0), yy: comp(1), xy: comp(2) }
    }

    #[test]
    fn mcewen_matches_flamant_quadrature() {
        // Expected: Flamant line-load fields (Johnson ch. 2) integrated numerically over the Hertz
        // pressure and over q = q0√(1 − x²/a²); required ≤ 1e-8 relative at ≥ 10 points.
        let h = Hertz2D::new(1.3, 2.0);
        let q0 = 0.6;
        let pts = [
            (0.0, 0.5),
            (0.3, 0.2),
            (-0.7, 0.1),
            (1.5, 0.4),
            (0.2, 2.0),
            (-1.2, 0.05),
            (0.9, 0.7),
            (0.0, 0.05),
            (1.2, 0.02),
            (-0.4, 1.0),
            (2.5, 1.5),
            (0.5, 1.02),
        ];
        let mut worst: f64 = 0.0;
        for (xr, zr) in pts {
            let (x, z) = (xr * h.a, zr * h.a);
            for tangential in [false, true] {
                let (cf, num) = if tangential {
                    (mcewen_tangential(&h, q0, x, z), flamant(&h, q0, true, x, z))
                } else {
                    (mcewen_normal(&h, x, z), flamant(&h, h.p0, false, x, z))
                };
                let mag = cf.xx.abs().max(cf.yy.abs()).max(cf.xy.abs());
                let err = (cf.xx - num.xx).abs().max((cf.yy - num.yy).abs()).max((cf.xy - num.xy).abs()) / mag;
                worst = worst.max(err);
                assert!(err < 1e-8, "({xr},{zr}) tangential={tangential}: rel err {err:e}");
            }
        }
        eprintln!("McEwen vs Flamant quadrature: worst relative error {worst:.2e}");
        assert!(worst < 1e-8);
    }

    #[test]
    fn mcewen_surface_and_axis_values() {
        // Expected: boundary conditions σ_zz = −p, τ_xz = −q at z = 0; surface σ_xx = −p − 2q0x/a;
        // on the axis the general formulas reduce to the axis closed form; under full sliding
        // τ1 = μp0 on the whole contact surface.
        let h = Hertz2D::new(1.0, 1.0);
        let mu = 0.25;
        for x in [-0.99, -0.5, 0.0, 0.3, 0.8] {
            let s = mcewen_sliding(&h, mu, x, 0.0);
            let p = h.pressure(x);
            assert!(close(s.yy, -p, 1e-14) && close(s.xy, -mu * p, 1e-14));
            assert!(close(s.xx, -p - 2.0 * mu * h.p0 * x / h.a, 1e-14));
            assert!(close(s.principal_shear(), mu * h.p0, 1e-14));
        }
        for z in [0.01, 0.3, 0.786, 2.0, 10.0] {
            let (s1, s2) = (mcewen_normal(&h, 0.0, z), hertz_axis_stress(&h, z));
            assert!(close(s1.xx, s2.xx, 1e-14) && close(s1.yy, s2.yy, 1e-14) && s1.xy.abs() < 1e-15);
        }
    }

    #[test]
    fn hertz_axis_max_shear_johnson() {
        // Expected: Johnson (1985) §4.2: max τ1 = 0.30 p0 at z = 0.78a; checked to 3 digits
        // (0.300, 0.786). Precise values cross-checked with SciPy during development.
        let (z, t) = hertz_axis_max_tau1();
        assert!(close(z, 0.786, 5e-4) && close(t, 0.300, 5e-4), "z={z}, τ={t}");
        assert!(close(z, 0.786_151, 2e-6) && close(t, 0.300_283_1, 1e-7));
        let m = mcewen_max_tau1(0.0);
        assert!(m.x.abs() < 1e-6 && close(m.z, z, 1e-6) && close(m.value, t, 1e-12));
    }

    #[test]
    fn mcewen_max_tau1_moves_towards_surface() {
        // Expected: SciPy Nelder–Mead maxima of τ1 over (x, z) under full sliding (development
        // cross-check, independent optimiser): μ = 0.1: (0.32782, 0.73898, 0.3048273);
        // 0.2: (0.62517, 0.60132, 0.3189885); 0.3: (0.86442, 0.38001, 0.3448811);
        // 0.5: surface plateau τ1 = μp0. The depth decreases monotonically with μ.
        let refs = [
            (0.1, 0.32782, 0.73898, 0.304_827_3),
            (0.2, 0.62517, 0.60132, 0.318_988_5),
            (0.3, 0.86442, 0.38001, 0.344_881_1),
        ];
        let mut last_z = mcewen_max_tau1(0.0).z;
        for (mu, x, z, v) in refs {
            let m = mcewen_max_tau1(mu);
            assert!(close(m.x, x, 2e-4) && close(m.z, z, 2e-4) && close(m.value, v, 2e-7), "μ={mu}: {m:?}");
            assert!(m.z < last_z);
            last_z = m.z;
        }
        let m = mcewen_max_tau1(0.5);
        assert!(m.z == 0.0 && close(m.value, 0.5, 1e-12) && m.x.abs() < 1.0, "{m:?}");
        // transition between 0.375 and 0.38 (development bisection: ≈ 0.377)
        assert!(mcewen_max_tau1(0.375).z > 0.05);
        assert!(mcewen_max_tau1(0.38).z == 0.0);
    }

    #[test]
    fn von_mises_plane_strain() {
        // Expected: definition via principal stresses (σ1, σ2, σ3 = ν(σ1 + σ2)); SciPy cross-check of
        // the frictionless maximum for ν = 0.3: 0.5575162 p0 at z = 0.70429a on the axis.
        let s = Stress2D { xx: -1.3, yy: 0.4, xy: 0.7 };
        let nu = 0.27;
        let (a, b) = s.principal();
        let c = nu * (a + b);
        let vm = (0.5 * ((a - b).powi(2) + (b - c).powi(2) + (c - a).powi(2))).sqrt();
        assert!(close(s.von_mises_plane_strain(nu), vm, 1e-14));
        let m = mcewen_max_von_mises(0.0, 0.3);
        assert!(m.x.abs() < 1e-6 && close(m.z, 0.704_29, 2e-5) && close(m.value, 0.557_516_2, 1e-7), "{m:?}");
    }
}
