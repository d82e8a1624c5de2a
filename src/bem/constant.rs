//! Closed-form integrals of the Kelvin kernels over a straight constant element (REFERENCES.md; Brebbia &
//! Dominguez ch. 5).
//!
//! For an element from `A` with unit tangent `t`, outward normal `n = (t_y, −t_x)` and length `L`, and a source
//! `ξ`, let `u` run along the element from `u₁ = (A − ξ)·t` to `u₂ = u₁ + L` and `d = (A − ξ)·n`, so that
//! `r = u t + d n`, `r² = u² + d²` and `∂r/∂n = d/r`. Every term of U* and T* then integrates in closed form;
//! `atan(u/d)` (not `atan2`) keeps the antiderivatives continuous along the element for `d ≠ 0`, and every
//! `d·atan(u/d)` term tends to 0 as `d → 0`. When the source is the element's own midpoint (`d = 0`,
//! `u₁ = −L/2`), the principal value of ∫T* vanishes (H's diagonal block is then set by the rigid-body
//! condition) and ∫U* = [−(3 − 4ν)(L ln(L/2) − L) δ_lk + L t_l t_k] / (8π G (1 − ν)).

use super::kelvin::Kelvin;

/// Integrals of T*_lk and U*_lk over the straight element `a → b` for a source at `src`.
/// Returns `(h, g)` with `h[l][k] = ∫T*_lk ds`, `g[l][k] = ∫U*_lk ds`. `self_element` means `src` is the
/// element's midpoint: `h` is then returned as zero (set later from the rigid-body condition).
#[inline]
pub fn integrate(
    a: [f64; 2],
    b: [f64; 2],
    src: [f64; 2],
    self_element: bool,
    k: &Kelvin,
) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
    let el = Straight::new(a, b);
    if self_element {
        return (Default::default(), el.self_g(k));
    }
    let ra2 = (a[0] - src[0]).powi(2) + (a[1] - src[1]).powi(2);
    let rb2 = (b[0] - src[0]).powi(2) + (b[1] - src[1]).powi(2);
    el.integrate(src, ra2.ln(), rb2.ln(), k)
}

/// A straight element with its frame precomputed (the assembly's hot loop reuses it for every source).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Straight {
    /// Start vertex.
    pub a: [f64; 2],
    /// End vertex.
    pub b: [f64; 2],
    /// Unit tangent from a to b.
    pub t: [f64; 2],
    /// Outward normal (t_y, −t_x).
    pub n: [f64; 2],
    /// Length.
    pub len: f64,
}

impl Straight {
    /// Frame of the element `a → b`.
    pub fn new(a: [f64; 2], b: [f64; 2]) -> Straight {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = dx.hypot(dy);
        let t = [dx / len, dy / len];
        Straight { a, b, t, n: [t[1], -t[0]], len }
    }

    /// ∫U* over the element for a source at its own midpoint (closed form, REFERENCES.md).
    #[inline]
    pub fn self_g(&self, k: &Kelvin) -> [[f64; 2]; 2] {
        let len = self.len;
        let lnterm = len * (0.5 * len).ln() - len;
        let mut g = [[0.0; 2]; 2];
        for l in 0..2 {
            for m in 0..2 {
                let delta = if l == m { 1.0 } else { 0.0 };
                g[l][m] = k.cu * (-k.a34 * lnterm * delta + len * self.t[l] * self.t[m]);
            }
        }
        g
    }

    /// Closed-form `(h, g)` for a source `src` off the element, given `ln r²` at both vertices (shared between
    /// neighbouring elements by the caller). With `u₁, u₂, d` as in the module docs, the subtended angle
    /// `Θ = atan(u₂/d) − atan(u₁/d) = atan2(d L, d² + u₁u₂)` is the only inverse trigonometric function needed.
    #[inline]
    pub fn integrate(&self, src: [f64; 2], ln_ra2: f64, ln_rb2: f64, k: &Kelvin) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let (t, n, len) = (self.t, self.n, self.len);
        let ax = [self.a[0] - src[0], self.a[1] - src[1]];
        let u1 = ax[0] * t[0] + ax[1] * t[1];
        let u2 = u1 + len;
        let d = ax[0] * n[0] + ax[1] * n[1];
        let ra2 = u1 * u1 + d * d;
        let rb2 = u2 * u2 + d * d;
        let theta = (d * len).atan2(d * d + u1 * u2);
        let g_ln = 0.5 * (u2 * ln_rb2 - u1 * ln_ra2) - len + d * theta;
        let g_tt = len - d * theta;
        let g_tn = 0.5 * d * (ln_rb2 - ln_ra2);
        let g_nn = d * theta;
        let w = 0.5 * d * (u2 / rb2 - u1 / ra2);
        let h_tt = 0.5 * theta - w;
        let h_tn = -0.5 * d * d * (1.0 / rb2 - 1.0 / ra2);
        let h_nn = w + 0.5 * theta;
        let h_la = 0.5 * (ln_rb2 - ln_ra2);
        let mut h = [[0.0; 2]; 2];
        let mut g = [[0.0; 2]; 2];
        for l in 0..2 {
            for m in 0..2 {
                let delta = if l == m { 1.0 } else { 0.0 };
                let tt = t[l] * t[m];
                let tn = t[l] * n[m] + n[l] * t[m];
                let nn = n[l] * n[m];
                g[l][m] = k.cu * (-k.a34 * delta * g_ln + tt * g_tt + tn * g_tn + nn * g_nn);
                let anti = t[l] * n[m] - t[m] * n[l];
                h[l][m] =
                    -k.ct * (k.b12 * delta * theta + 2.0 * (tt * h_tt + tn * h_tn + nn * h_nn) - k.b12 * anti * h_la);
            }
        }
        (h, g)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute-force reference: composite Gauss–Legendre (5 points on 4000 panels) of the kernels of kelvin.rs.
    fn brute(a: [f64; 2], b: [f64; 2], src: [f64; 2], k: &Kelvin) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let gp = [-0.906179845938664, -0.5384693101056831, 0.0, 0.5384693101056831, 0.906179845938664];
        let gw = [0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891];
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = dx.hypot(dy);
        let n = [dy / len, -dx / len];
        let panels = 4000;
        let mut h = [[0.0; 2]; 2];
        let mut g = [[0.0; 2]; 2];
        for p in 0..panels {
            for q in 0..5 {
                let s = (p as f64 + 0.5 * (gp[q] + 1.0)) / panels as f64;
                let x = [a[0] + s * dx, a[1] + s * dy];
                let w = gw[q] * 0.5 * len / panels as f64;
                let u = k.u(x, src);
                let t = k.t(x, n, src);
                for l in 0..2 {
                    for m in 0..2 {
                        g[l][m] += w * u[l][m];
                        h[l][m] += w * t[l][m];
                    }
                }
            }
        }
        (h, g)
    }

    #[test]
    fn closed_form_matches_brute_force_quadrature() {
        let k = Kelvin::new(1.0, 0.3);
        let (a, b) = ([0.3, -0.1], [0.5, 0.25]);
        for src in [[0.0, 0.0], [0.9, 0.1], [0.42, 0.05], [0.1, -0.4]] {
            let (h, g) = integrate(a, b, src, false, &k);
            let (hb, gb) = brute(a, b, src, &k);
            for l in 0..2 {
                for m in 0..2 {
                    assert!((h[l][m] - hb[l][m]).abs() < 1e-9, "h {src:?} {l}{m}: {} vs {}", h[l][m], hb[l][m]);
                    assert!((g[l][m] - gb[l][m]).abs() < 1e-9, "g {src:?} {l}{m}: {} vs {}", g[l][m], gb[l][m]);
                }
            }
        }
    }

    #[test]
    fn self_element_u_integral_matches_limit_of_offset_source() {
        // Reference: the regular closed form for a source a tiny distance off the midpoint converges to the
        // singular formula (continuity of the single-layer potential).
        let k = Kelvin::new(1.0, 0.2);
        let (a, b) = ([0.0, 0.0], [0.3, 0.4]);
        let mid = [0.15, 0.2];
        let (_, g0) = integrate(a, b, mid, true, &k);
        let off = [mid[0] + 1e-9 * 0.8, mid[1] - 1e-9 * 0.6];
        let (_, g1) = integrate(a, b, off, false, &k);
        for l in 0..2 {
            for m in 0..2 {
                assert!((g0[l][m] - g1[l][m]).abs() < 1e-7, "{l}{m}: {} vs {}", g0[l][m], g1[l][m]);
            }
        }
    }
}
