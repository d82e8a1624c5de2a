//! Diametrally compressed disk
//!
//! (a) [`disk_point_loads`]: Timoshenko & Goodier, *Theory of Elasticity* (3rd ed.) §41: radius R,
//! loads P at (0, ±R) pushing inwards, `r1² = x² + (R − y)²`, `r2² = x² + (R + y)²`:
//!
//! ```text
//!   σ_xx = −(2P/π)[ x²(R − y)/r1⁴ + x²(R + y)/r2⁴ − 1/(2R) ]
//!   σ_yy = −(2P/π)[ (R − y)³/r1⁴ + (R + y)³/r2⁴ − 1/(2R) ]
//!   τ_xy =  (2P/π)[ x(R − y)²/r1⁴ − x(R + y)²/r2⁴ ]
//! ```
//!
//! Centre: σ_xx = P/(πR) = 2P/(πd), σ_yy = −3P/(πR) = −6P/(πd).
//!
//! (b) [`hondros`]: uniform radial pressure `p` on the two arcs |θ| < α, |θ − π| < α (θ measured
//! from the loading axis +y; total load `P = 2pR sin α`, [`hondros_load`]). Hondros' (1959) series,
//! `ρ = r/R`:
//!
//! ```text
//!   σ_r  = −2pα/π − (2p/π) Σ_{n≥1} [1 − (1 − 1/n)ρ²] ρ^{2n−2} sin 2nα cos 2nθ
//!   σ_θ  = −2pα/π + (2p/π) Σ_{n≥1} [1 − (1 + 1/n)ρ²] ρ^{2n−2} sin 2nα cos 2nθ
//!   τ_rθ =  (2p/π) Σ_{n≥1} (1 − ρ²) ρ^{2n−2} sin 2nα sin 2nθ
//! ```
//!
//! summed here in closed form (u = ρ², φ± = 2(α ± θ)):
//! `σ_r = −2pα/π − (p/π)[(1 − u)(A₊ + A₋) + B₊ + B₋]`, `σ_θ = −2pα/π + (p/π)[(1 − u)(A₊ + A₋) − B₊ − B₋]`,
//! `τ_rθ = (p/π)(1 − u)(C₋ − C₊)` with `A = sin φ/Δ`, `C = (cos φ − u)/Δ`, `Δ = 1 − 2u cos φ + u²`,
//! `B = atan2(u sin φ, 1 − u cos φ)`. On the loaded diameter this reduces to Hondros' formulas
//! `σ_θ, σ_r = (2p/π)[±(1 − ρ²) sin 2α/(1 − 2ρ² cos 2α + ρ⁴) − arctan(((1 + ρ²)/(1 − ρ²)) tan α)]`
//! (upper sign σ_θ = σ_xx, lower sign σ_r = σ_yy) and on the transverse diameter to
//! `σ_r = (2p/π)[(1 − ρ²) sin 2α/(1 + 2ρ² cos 2α + ρ⁴) − arctan(((1 − ρ²)/(1 + ρ²)) tan α)]` (= σ_xx),
//! `σ_θ = −(2p/π)[(1 − ρ²) sin 2α/(1 + 2ρ² cos 2α + ρ⁴) + arctan(((1 − ρ²)/(1 + ρ²)) tan α)]` (= σ_yy),
//! see [`hondros_loaded_diameter`], [`hondros_transverse_diameter`]. As α → 0 at fixed P it tends to
//! (a) away from the loads.

use super::stress::Stress2D;
use std::f64::consts::PI;

/// Disk of radius `radius` under two equal and opposite point loads `p` (per unit thickness) at
/// `(0, ±R)`, pushing towards the centre (Timoshenko & Goodier §41). Stresses at `(x, y)` inside.
pub fn disk_point_loads(radius: f64, p: f64, x: f64, y: f64) -> Stress2D {
    let (a1, a2) = (radius - y, radius + y);
    let r1 = x * x + a1 * a1;
    let r2 = x * x + a2 * a2;
    let (r14, r24) = (r1 * r1, r2 * r2);
    let k = 2.0 * p / PI;
    let u = 0.5 / radius;
    Stress2D {
        xx: -k * (x * x * a1 / r14 + x * x * a2 / r24 - u),
        yy: -k * (a1 * a1 * a1 / r14 + a2 * a2 * a2 / r24 - u),
        xy: k * (x * a1 * a1 / r14 - x * a2 * a2 / r24),
    }
}

/// Total load `P = 2 p R sin α` of Hondros' radial pressure `p` over arcs of half-angle `alpha`.
pub fn hondros_load(radius: f64, pressure: f64, alpha: f64) -> f64 {
    2.0 * pressure * radius * alpha.sin()
}

/// Hondros' polar stresses `(σ_r, σ_θ, τ_rθ)` at `u = ρ²`, angle `theta` from the loading axis.
fn hondros_polar(pressure: f64, alpha: f64, u: f64, theta: f64) -> (f64, f64, f64) {
    let parts = |phi: f64| {
        let (s, c) = phi.sin_cos();
        let den = 1.0 - 2.0 * u * c + u * u;
        (s / den, (u * s).atan2(1.0 - u * c), (c - u) / den)
    };
    let (ap, bp, cp) = parts(2.0 * (alpha + theta));
    let (am, bm, cm) = parts(2.0 * (alpha - theta));
    let k = pressure / PI;
    let base = -2.0 * pressure * alpha / PI;
    let sr = base - k * ((1.0 - u) * (ap + am) + bp + bm);
    let st = base + k * ((1.0 - u) * (ap + am) - bp - bm);
    let tr = k * (1.0 - u) * (cm - cp);
    (sr, st, tr)
}

/// Hondros (1959) full-field solution: disk of radius `radius`, uniform radial pressure `pressure`
/// on the arcs |θ| < α and |θ − π| < α around `(0, ±R)` (θ from the +y axis). Cartesian stresses at
/// `(x, y)`, |(x, y)| ≤ R (closed-form sum of Hondros' series, module docs §7).
pub fn hondros(radius: f64, pressure: f64, alpha: f64, x: f64, y: f64) -> Stress2D {
    let u = (x * x + y * y) / (radius * radius);
    // point = r(−sin θ, cos θ): θ counter-clockwise from +y.
    let theta = (-x).atan2(y);
    let (sr, st, tr) = hondros_polar(pressure, alpha, u, theta);
    let (s, c) = theta.sin_cos();
    Stress2D {
        xx: sr * s * s + st * c * c + 2.0 * tr * s * c,
        yy: sr * c * c + st * s * s - 2.0 * tr * s * c,
        xy: (st - sr) * s * c + tr * (s * s - c * c),
    }
}

/// Hondros' published formulas on the loaded diameter `x = 0` at `y` (|y| < R): returns
/// `(σ_xx, σ_yy)` = (σ_θ, σ_r); τ_xy = 0 there.
pub fn hondros_loaded_diameter(radius: f64, pressure: f64, alpha: f64, y: f64) -> (f64, f64) {
    let u = (y / radius).powi(2);
    let t1 = (1.0 - u) * (2.0 * alpha).sin() / (1.0 - 2.0 * u * (2.0 * alpha).cos() + u * u);
    let t2 = ((1.0 + u) / (1.0 - u) * alpha.tan()).atan();
    let k = 2.0 * pressure / PI;
    (k * (t1 - t2), -k * (t1 + t2))
}

/// Hondros' published formulas on the transverse diameter `y = 0` at `x` (|x| ≤ R): returns
/// `(σ_xx, σ_yy)` = (σ_r, σ_θ); τ_xy = 0 there.
pub fn hondros_transverse_diameter(radius: f64, pressure: f64, alpha: f64, x: f64) -> (f64, f64) {
    let u = (x / radius).powi(2);
    let t1 = (1.0 - u) * (2.0 * alpha).sin() / (1.0 + 2.0 * u * (2.0 * alpha).cos() + u * u);
    let t2 = ((1.0 - u) / (1.0 + u) * alpha.tan()).atan();
    let k = 2.0 * pressure / PI;
    (k * (t1 - t2), -k * (t1 + t2))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;

    fn equilibrium_residual(f: &dyn Fn(f64, f64) -> Stress2D, x: f64, y: f64, h: f64) -> (f64, f64) {
        let r1 = d4(&|t| f(t, y).xx, x, h) + d4(&|t| f(x, t).xy, y, h);
        let r2 = d4(&|t| f(t, y).xy, x, h) + d4(&|t| f(x, t).yy, y, h);
        (r1, r2)
    }

    /// `∇²(σxx + σyy)` relative to `|∂²/∂x²| + |∂²/∂y²|` of the same trace.
    fn laplacian_trace(f: &dyn Fn(f64, f64) -> Stress2D, x: f64, y: f64, h: f64) -> f64 {
        let tr = |x: f64, y: f64| {
            let s = f(x, y);
            s.xx + s.yy
        };
        let (a, b) = (d4_2(&|t| tr(t, y), x, h), d4_2(&|t| tr(x, t), y, h));
        (a + b) / (a.abs() + b.abs())
    }

    const INTERIOR: [(f64, f64); 8] =
        [(0.0, 0.0), (0.3, 0.2), (-0.5, 0.4), (0.6, -0.6), (-0.2, -0.7), (0.8, 0.1), (0.0, 0.6), (-0.45, -0.1)];

    #[test]
    fn disk_point_loads_timoshenko_goodier() {
        // Expected: Timoshenko & Goodier §41 centre values σ_xx = 2P/(πd), σ_yy = −6P/(πd); numerical
        // equilibrium and compatibility (∇²(σxx + σyy) = 0) by finite differences; traction-free
        // rim (away from the loads); resultant ∫σ_yy(x, 0) dx = −P by quadrature.
        let (r, p) = (0.5, 1000.0);
        let f = |x: f64, y: f64| disk_point_loads(r, p, x, y);
        let c = f(0.0, 0.0);
        assert!(close(c.xx, 2.0 * p / (PI * 2.0 * r), 1e-10) && close(c.yy, -6.0 * p / (PI * 2.0 * r), 1e-10));
        let scale = p / (r * r);
        for (xr, yr) in INTERIOR {
            let (r1, r2) = equilibrium_residual(&f, xr * r, yr * r, 1e-3 * r);
            assert!(r1.abs() < 1e-8 * scale && r2.abs() < 1e-8 * scale, "({xr},{yr}): {r1:e} {r2:e}");
            let lap = laplacian_trace(&f, xr * r, yr * r, 2e-3 * r);
            assert!(lap.abs() < 1e-6, "({xr},{yr}): relative ∇² = {lap:e}");
        }
        for deg in [0.0, 20.0, 45.0, 70.0, 85.0, 100.0, 160.0, 180.0, 200.0, 250.0, 300.0, 330.0] {
            let psi = f64::to_radians(deg);
            let (nx, ny) = (psi.cos(), psi.sin());
            let s = f(r * nx, r * ny);
            let (tx, ty) = (s.xx * nx + s.xy * ny, s.xy * nx + s.yy * ny);
            assert!(tx.abs() < 1e-9 * p / r && ty.abs() < 1e-9 * p / r, "ψ={deg}: ({tx:e},{ty:e})");
        }
        let total = quad(&|x| f(x, 0.0).yy, &[-r, 0.0, r], 1e-13, 0.0);
        assert!(close(total, -p, 1e-10 * p), "resultant {total}");
    }

    #[test]
    fn hondros_closed_form_matches_series_and_published_diameter_formulas() {
        // Expected: Hondros' series (module docs §7) summed term by term, and Hondros' published
        // closed forms on the two diameters.
        let (r, pr, alpha) = (1.0, 3.0, 0.2);
        for (xr, yr) in INTERIOR.iter().copied().chain([(0.9, 0.3), (-0.2, 0.95)]) {
            let (x, y) = (xr * r, yr * r);
            let rho2 = (x * x + y * y) / (r * r);
            let theta = (-x).atan2(y);
            let (mut sr, mut st, mut tr) = (-2.0 * pr * alpha / PI, -2.0 * pr * alpha / PI, 0.0);
            let mut pw = 1.0; // ρ^{2n−2}
            for n in 1..2000 {
                let nf = n as f64;
                let (s2a, c2t, s2t) = ((2.0 * nf * alpha).sin(), (2.0 * nf * theta).cos(), (2.0 * nf * theta).sin());
                sr -= 2.0 * pr / PI * (1.0 - (1.0 - 1.0 / nf) * rho2) * pw * s2a * c2t;
                st += 2.0 * pr / PI * (1.0 - (1.0 + 1.0 / nf) * rho2) * pw * s2a * c2t;
                tr += 2.0 * pr / PI * (1.0 - rho2) * pw * s2a * s2t;
                pw *= rho2;
                if pw < 1e-18 {
                    break;
                }
            }
            let (csr, cst, ctr) = hondros_polar(pr, alpha, rho2, theta);
            assert!(close(sr, csr, 1e-12 * pr) && close(st, cst, 1e-12 * pr) && close(tr, ctr, 1e-12 * pr));
        }
        for yr in [-0.95, -0.6, -0.2, 0.0, 0.1, 0.5, 0.8, 0.99] {
            let s = hondros(r, pr, alpha, 0.0, yr * r);
            let (sx, sy) = hondros_loaded_diameter(r, pr, alpha, yr * r);
            assert!(close(s.xx, sx, 1e-12 * pr) && close(s.yy, sy, 1e-12 * pr) && s.xy.abs() < 1e-12 * pr);
            let s = hondros(r, pr, alpha, yr * r, 0.0);
            let (sx, sy) = hondros_transverse_diameter(r, pr, alpha, yr * r);
            assert!(close(s.xx, sx, 1e-12 * pr) && close(s.yy, sy, 1e-12 * pr) && s.xy.abs() < 1e-12 * pr);
        }
        // centre: σ_xx = (2p/π)(sin 2α − α), σ_yy = −(2p/π)(sin 2α + α)
        let c = hondros(r, pr, alpha, 0.0, 0.0);
        let s2a = (2.0 * alpha).sin();
        assert!(
            close(c.xx, 2.0 * pr / PI * (s2a - alpha), 1e-13) && close(c.yy, -2.0 * pr / PI * (s2a + alpha), 1e-13)
        );
    }

    #[test]
    fn hondros_equilibrium_and_boundary_conditions() {
        // Expected: equilibrium and compatibility by finite differences; on the rim the traction is
        // −p n on the loaded arcs and 0 elsewhere.
        let (r, pr, alpha) = (0.8, 5.0, 0.3);
        let f = |x: f64, y: f64| hondros(r, pr, alpha, x, y);
        for (xr, yr) in INTERIOR {
            let (r1, r2) = equilibrium_residual(&f, xr * r, yr * r, 1e-3 * r);
            assert!(r1.abs() < 1e-8 * pr / r && r2.abs() < 1e-8 * pr / r, "({xr},{yr}): {r1:e} {r2:e}");
            let lap = laplacian_trace(&f, xr * r, yr * r, 2e-3 * r);
            assert!(lap.abs() < 1e-6, "({xr},{yr}): relative ∇² = {lap:e}");
        }
        for deg in [0.0, 5.0, 10.0, 16.0, 30.0, 60.0, 90.0, 150.0, 170.0, 180.0, 190.0, 200.0, 270.0, 345.0] {
            let theta = f64::to_radians(deg); // from +y, counter-clockwise
            let (nx, ny) = (-theta.sin(), theta.cos());
            let s = f(r * nx, r * ny);
            let (tx, ty) = (s.xx * nx + s.xy * ny, s.xy * nx + s.yy * ny);
            let on_arc = theta.sin().abs() < alpha.sin();
            let (ex, ey) = if on_arc { (-pr * nx, -pr * ny) } else { (0.0, 0.0) };
            assert!(close(tx, ex, 1e-10 * pr) && close(ty, ey, 1e-10 * pr), "θ={deg}: ({tx},{ty}) vs ({ex},{ey})");
        }
    }

    #[test]
    fn hondros_tends_to_point_loads() {
        // Expected: as α → 0 with P = 2pR sin α fixed, Hondros → Timoshenko–Goodier away from the
        // loads; difference O(α²).
        let (r, p) = (1.0, 1.0);
        for alpha in [1e-2, 1e-3] {
            let pr = p / (2.0 * r * f64::sin(alpha));
            assert!(close(hondros_load(r, pr, alpha), p, 1e-14));
            for (xr, yr) in INTERIOR {
                let (a, b) = (hondros(r, pr, alpha, xr, yr), disk_point_loads(r, p, xr, yr));
                let err = (a.xx - b.xx).abs().max((a.yy - b.yy).abs()).max((a.xy - b.xy).abs());
                assert!(err < 20.0 * alpha * alpha * p / r, "α={alpha} ({xr},{yr}): {err:e}");
            }
        }
    }
}
