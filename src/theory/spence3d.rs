//! Spence's receding stick zone for dissimilar spheres: the axisymmetric counterpart of [`super::spence`]
//! ([`spence_sphere_c_over_a`], [`spence_sphere_beta_over_mu`])
//!
//! Setting: two elastic bodies of revolution (or a sphere on a half-space) with Dundurs' β ≠ 0, pressed together by
//! a normal load growing monotonically from zero at zero tangential force; Coulomb friction μ; the pressure taken as
//! Hertz's, `p = p0 √(1 − r²/a²)` (Goodman's approximation: the shear's effect on the pressure, O(βμ), neglected —
//! the approximation in which `c/a` depends on `β/μ` alone, as in 2D). The shear is radial, `q(r)` on body 1.
//! **Derived here** (Spence's self-similarity argument, carried out for the circle): the relation was not found
//! verbatim in the sources at hand (Spence, J. Elasticity 5 (1975) 297–319 treats both geometries; Johnson,
//! *Contact Mechanics* §5.x discusses them), so it is derived below and checked independently in the tests.
//!
//! ## Result
//!
//! ```text
//!   β/μ = 2k K(k′) / ln((1 + k)/(1 − k)) = K(k′) / (artanh(k)/k),      k = c/a,  k′ = √(1 − k²)
//! ```
//!
//! (`K` the complete elliptic integral of the first kind, modulus argument). The 2D result is `β/μ = K(k′)/K(k)`:
//! the sphere has `artanh(k)/k` where the cylinder has `K(k)` (`→ 1` and `→ π/2` as `k → 0`).
//! Consequences: full stick only as `β/μ → 0` (`1 − k ≈ 2 exp(−πμ/|β|)`: an exponentially thin slip annulus), and
//! `c/a ≈ 4 e^{−|β|/μ}` for large `β/μ` (2D: `4 e^{−π|β|/(2μ)}`). Values: `β/μ = 0.5, 1, 1.5, 2, 3 →
//! c/a = 0.9962, 0.9038, 0.7015, 0.4851, 0.1953` (2D: 0.9852, 0.7071, 0.3659, 0.1716, 0.0359): the sphere keeps
//! more of its contact in stick. At CONTACT's `spence35` pair (`β = 0.5`, `μ = 0.2986`, `β/μ = 1.6745`)
//! `c/a = 0.6233` — CONTACT finds 0.49 there because at `βμ = 0.15` the coupling this
//! approximation drops is not small (as in 2D, [`super::spence_coupled`]).
//!
//! ## Derivation
//!
//! *Compliances.* Cerruti's surface kernel is, in Fourier space, `2πK[δ/|k| − ν kk/|k|³]` (`K = 1/(2πG)`), so a
//! tangential field that is a gradient (`q̂ ∥ k`, e.g. any radial `q(r)`) sees `2πK(1 − ν)/|k|` — exactly the normal
//! kernel. For the pair, the relative radial displacement due to `q` is therefore `k_d` times the radial component
//! of the Newtonian potential of the vector field `q`, with the same `k_d = (1−ν₁)K₁ + (1−ν₂)K₂` as the normal
//! problem ([`crate::halfspace::kernel`]); writing `q = dΨ/dr` with `Ψ(r) = −∫_r^∞ q` (zero outside the contact),
//! that is `k_d d/dr U[Ψ]`, `U[f](r) = ∬ f/ρ dA`. The pressure's contribution is `−k_c P(r)/r` (`P(r)` the load
//! inside radius r; Johnson eq. 3.41a for one body), `k_c = β k_d`. So
//! `g_r(r) = k_d [d/dr U[Ψ] − β P(r)/r]`.
//!
//! *Self-similarity* (Spence). With `p0 ∝ a`, `g_r(r; a) = a² G(r/a)`; a point that enters the stick zone at
//! `a = r/κ` keeps its `g_r` from then on, so in the stick zone `g_r = C r²` (κ = c/a constant). In the slip annulus
//! `q = σμp`.
//!
//! *Abel representation.* Write an axisymmetric density as `f(r) = ∫_r^1 h(t) dt/√(t² − r²)` (a superposition of
//! flat-punch densities `1/√(t² − r²)`, whose potential is π² inside radius t and `2π asin(t/r)` outside). Then for
//! `r` inside the support `d/dr U[f] = −(2π/r) ∫_0^r t h(t) dt/√(r² − t²)`, an Abel transform, inverted by
//! `t h(t) = (2/π) d/dt ∫_0^t r S(r) dr/√(t² − r²)` with `S = −r (d/dr U[f])/(2π)`. With `a = p0 = 1`:
//!
//! - the stick condition's `C r²` term gives `h_C(t) = −(3C̃/(4π)) t²` (`C̃ = C/k_d`);
//! - the pressure term `β P(r)/r`, `P(r) = (2π/3)[1 − (1 − r²)^{3/2}]`, gives `β h₁(t)` with
//!   `h₁(t) = −(1/π)[t + ½(1 − t²) ln((1 + t)/(1 − t))]` (the inner integral in closed form:
//!   `∫_0^t r(1−r²)^{3/2} dr/√(t²−r²) = ½[(t/4)(5 − 3t²) + (3/8)(1 − t²)² ln((1+t)/(1−t))]`);
//! - the full-slip density `Ψ_μ(r) = −σμ ∫_r^1 √(1 − s²) ds` has `h_μ(t) = −σμ m₁(t)`,
//!   `m₁(t) = (2t/π)[K(k′_t) − E(k′_t)]`, `k′_t = √(1 − t²)` (by parts and `r² = 1 − k′_t² sin²φ`).
//!
//! `Ψ` equals `Ψ_μ` on `c < r < 1`, so its `h` is `h_μ` there; on `[0, c]` the stick condition makes it
//! `h_C + β h₁`. `q = Ψ′` is bounded at `r = c` only if `h` is continuous at `c`, and Spence's argument (the slip
//! direction just outside `c` and the stick inequality just inside need opposite signs of the `√(c − r)` term of
//! `q − σμp`) requires its derivative to be continuous too: two conditions, `h_C + βh₁ = h_μ` and
//! `h_C′ + βh₁′ = h_μ′` at `t = c`. Eliminating `C̃`: `2H(c) = cH′(c)` with `H = βh₁ + σμm₁`, i.e.
//! `β(2h₁ − ch₁′) = −σμ(2m₁ − cm₁′)`. With `2h₁ − th₁′ = −(1/π) ln((1+t)/(1−t))`, `m₁′ = (2/π)(K − 2E)` and
//! `2m₁ − tm₁′ = (2/π) t K(k′_t)` this is the result, with `σ = sgn β` (the friction on body 1 points outwards for
//! β > 0, as in 2D: its surface slips inwards).
//!
//! *Checks* (tests below): the closed forms `h₁`, `m₁` against quadrature of their defining integrals; and the
//! solution itself, with `U[Ψ]` evaluated by direct quadrature of the ring potential `4sK(k)/(r + s)` (no Abel
//! transform): `g_r/r²` constant in the stick zone to 1e-5 (the quadrature's and the central difference's error), `|q| < μp` inside it, and the slip inwards (`g_r/r²`
//! increasing) in the annulus. rollbem's 3D coupled path at small βμ converges to it as the grid refines
//! (`tests/contact3d.rs`).

use super::special::agm;
use std::f64::consts::FRAC_PI_2;

/// Spence's `|β|/μ` for the stick-radius ratio `k = c/a` of a sphere (module docs):
/// `K(√(1 − k²)) / (artanh(k)/k)`; `+∞` at `k = 0`, `0` at `k = 1`. `k` outside `[0, 1]` (or NaN) gives NaN.
pub fn spence_sphere_beta_over_mu(c_over_a: f64) -> f64 {
    let k = c_over_a;
    if !(0.0..=1.0).contains(&k) {
        return f64::NAN;
    }
    if k == 0.0 {
        return f64::INFINITY;
    }
    if k == 1.0 {
        return 0.0;
    }
    // K(k′) = π/(2 AGM(1, k)): the complementary modulus of k′ is k itself, exact even where 1 − k² rounds to 1.
    FRAC_PI_2 / agm(1.0, k) * k / k.atanh()
}

/// Spence's stick-zone ratio `c/a` for the monotonic normal loading of two dissimilar spheres (elastic bodies of
/// revolution) at zero tangential force, Hertzian pressure assumed (module docs): the root of
/// [`spence_sphere_beta_over_mu`]` = |β|/μ`. `1` for `β = 0`, `→ 0` as `|β|/μ → ∞` (`≈ 4e^{−|β|/μ}`); NaN for NaN.
pub fn spence_sphere_c_over_a(beta_over_mu: f64) -> f64 {
    let b = beta_over_mu.abs();
    if b.is_nan() {
        return f64::NAN;
    }
    if b == 0.0 {
        return 1.0;
    }
    if b > 30.0 {
        // K(k′) = ln(4/k) + O(k² ln k), artanh(k)/k = 1 + O(k²): below k = 4e^{−30} the corrections are < 1e-24.
        return 4.0 * (-b).exp();
    }
    // Bisection on ln k (the function decreases monotonically from +∞ to 0 over (0, 1)).
    let (mut lo, mut hi) = (-40.0_f64, 0.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if spence_sphere_beta_over_mu(mid.exp()) > b {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-16 {
            break;
        }
    }
    (0.5 * (lo + hi)).exp()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::special::{elliptic_e, elliptic_k};
    use crate::theory::test_support::*;
    use std::f64::consts::PI;

    /// `h₁` of the module docs.
    fn h1(t: f64) -> f64 {
        -(t + 0.5 * (1.0 - t * t) * ((1.0 + t) / (1.0 - t)).ln()) / PI
    }

    /// `m₁` of the module docs.
    fn m1(t: f64) -> f64 {
        let kp = ((1.0 - t) * (1.0 + t)).sqrt();
        2.0 * t / PI * (elliptic_k(kp) - elliptic_e(kp))
    }

    #[test]
    fn inverse_limits_and_asymptotics() {
        // Expected: the inverse inverts; the limits k → 1 (β/μ → 0) and k → 0 (β/μ ≈ ln(4/k)); monotone.
        // (Below β/μ ≈ 0.1, 1 − c/a ≈ 2e^{−πμ/β} is under the spacing of doubles near 1: c/a rounds to 1.)
        for b in [0.3, 0.5, 1.0, 1.6745, 2.0, 5.0, 20.0] {
            let k = spence_sphere_c_over_a(b);
            assert!(close(spence_sphere_beta_over_mu(k), b, 1e-12 * b), "b={b}: k={k}");
        }
        assert_eq!(spence_sphere_c_over_a(0.0), 1.0);
        assert_eq!(spence_sphere_c_over_a(-1.0), spence_sphere_c_over_a(1.0));
        assert!(spence_sphere_c_over_a(f64::NAN).is_nan() && spence_sphere_beta_over_mu(1.5).is_nan());
        let b = 25.0;
        assert!(close(spence_sphere_c_over_a(b), 4.0 * (-b).exp(), 1e-12 * 4.0 * (-b).exp()));
        assert!(close(spence_sphere_c_over_a(31.0), 4.0 * (-31.0f64).exp(), 1e-300));
        let mut last = 1.0;
        for i in 2..200 {
            let k = spence_sphere_c_over_a(0.05 * i as f64);
            assert!(k < last, "not decreasing at {}", 0.05 * i as f64);
            last = k;
        }
        // The values quoted in the module docs.
        for (b, k) in [(0.5, 0.9962), (1.0, 0.9038), (1.5, 0.7015), (2.0, 0.4851), (3.0, 0.1953), (1.6745, 0.6233)] {
            assert!((spence_sphere_c_over_a(b) - k).abs() < 5e-5, "{b}: {}", spence_sphere_c_over_a(b));
        }
    }

    #[test]
    fn abel_ingredients_match_their_integrals() {
        // Expected: h₁ from its definition t h₁(t) = (2/π) d/dt ∫_0^t r S₁(r) dr/√(t² − r²),
        // S₁ = −[1 − (1 − r²)^{3/2}]/3 (quadrature, then a fourth-order central difference); m₁ from
        // m₁(t) = (2t/π) ∫_t^1 √((1 − r²)/(r² − t²)) dr (quadrature).
        for t in [0.1, 0.35, 0.6, 0.85] {
            // r = t sin θ removes the end-point singularity.
            let j = |t: f64| {
                let s1 = |r: f64| -(1.0 - (1.0 - r * r).powf(1.5)) / 3.0;
                quad(&|th: f64| t * th.sin() * s1(t * th.sin()), &[0.0, std::f64::consts::FRAC_PI_2], 1e-15, 0.0)
            };
            let num = 2.0 / PI * d4(&j, t, 1e-3) / t;
            assert!(close(num, h1(t), 1e-8), "h1({t}): {num} vs {}", h1(t));
            // r² = t² + (1 − t²) sin²φ removes the end-point singularity.
            let kp2 = 1.0 - t * t;
            let f = |p: f64| kp2 * p.cos().powi(2) / (t * t + kp2 * p.sin().powi(2)).sqrt();
            let m = 2.0 * t / PI * quad(&f, &[0.0, std::f64::consts::FRAC_PI_2], 1e-15, 0.0);
            assert!(close(m, m1(t), 1e-10), "m1({t}): {m} vs {}", m1(t));
        }
    }

    /// The potential of an axisymmetric density by direct quadrature of the ring potential: `U[f](r) =
    /// ∫_0^1 f(s) 4s K(k_s)/(r + s) ds`, `k_s = 2√(rs)/(r + s)` (no Abel transform).
    fn potential(f: &dyn Fn(f64) -> f64, r: f64, kinks: &[f64]) -> f64 {
        // K(k_s) = π/(2 AGM(1, k′_s)) with k′_s = |r − s|/(r + s) exactly (no cancellation next to the ring).
        let ring = |s: f64| f(s) * 4.0 * s * (FRAC_PI_2 / agm(1.0, (r - s).abs() / (r + s))) / (r + s);
        let mut pts = vec![0.0, r, 1.0];
        pts.extend(kinks.iter().filter(|&&k| k > 0.0 && k < 1.0));
        pts.sort_by(f64::total_cmp);
        pts.dedup();
        quad(&ring, &pts, 1e-12, 0.0)
    }

    #[test]
    fn the_solution_meets_the_stick_and_slip_conditions() {
        // Expected: with β/μ from the closed form (μ = 1, σ = +1, a = p0 = 1), the traction built from the derived
        // h (module docs) satisfies, by direct potential quadrature: g_r/r² constant in the stick zone (Spence's
        // self-similar stick condition), |q| < p there, q = p in the annulus (by construction) with g_r/r²
        // increasing (slip rate inwards, opposed by the outward friction).
        for c in [0.4, 0.75] {
            let b = spence_sphere_beta_over_mu(c);
            let gam = (b * h1(c) + m1(c)) / (c * c);
            let h = move |t: f64| if t < c { -gam * t * t + b * h1(t) } else { -m1(t) };
            // Ψ(r) = ∫_r^1 h(t) dt/√(t² − r²) with t = √(r² + u²): a smooth integrand in u but for the kink of h at
            // t = c; composite Gauss–Legendre (40 points per piece).
            let rule = crate::bem::quadrature::gauss_legendre(40).unwrap();
            let psi = move |r: f64| {
                if r >= 1.0 {
                    return 0.0;
                }
                let top = ((1.0 - r) * (1.0 + r)).sqrt();
                let mut cuts = vec![0.0, top];
                if r < c {
                    cuts.insert(1, ((c - r) * (c + r)).sqrt());
                }
                let mut sum = 0.0;
                for w in cuts.windows(2) {
                    let (m, hw) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
                    for (x, wt) in rule.iter() {
                        let t = (r * r + (m + hw * x).powi(2)).sqrt();
                        sum += hw * wt * h(t) / t;
                    }
                }
                sum
            };
            let dr = 1e-4;
            let g_over_r2 = |r: f64| {
                let du = (potential(&psi, r + dr, &[c]) - potential(&psi, r - dr, &[c])) / (2.0 * dr);
                let load = 2.0 * PI / 3.0 * (1.0 - (1.0 - r * r).powf(1.5));
                (du - b * load / r) / (r * r)
            };
            let stick: Vec<f64> = [0.3, 0.6, 0.9].iter().map(|f| g_over_r2(f * c)).collect();
            for g in &stick {
                assert!(close(*g, stick[0], 1e-5 * stick[0].abs()), "c = {c}: g/r² {stick:?}");
            }
            let slip: Vec<f64> = [0.25, 0.5, 0.8].iter().map(|f| g_over_r2(c + f * (1.0 - c))).collect();
            eprintln!("c = {c}: g/r² stick {stick:?}, slip {slip:?}");
            assert!(slip[0] > stick[2] && slip[1] > slip[0] && slip[2] > slip[1], "c = {c}: slip g/r² {slip:?}");
            for f in [0.2, 0.5, 0.8, 0.97] {
                let r = f * c;
                let q = (psi(r + dr) - psi(r - dr)) / (2.0 * dr);
                let p = (1.0 - r * r).sqrt();
                assert!(q > 0.0 && q < p, "c = {c}, r = {r}: q {q} vs p {p}");
            }
            for f in [0.3, 0.7] {
                let r = c + f * (1.0 - c);
                let q = (psi(r + dr) - psi(r - dr)) / (2.0 * dr);
                assert!(close(q, (1.0 - r * r).sqrt(), 1e-6), "c = {c}, slip r = {r}: q {q}");
            }
        }
    }
}
