//! Hertz line contact ([`Hertz2D`]): the library's one Hertz type, used by the theories here, the references a
//! run is checked against ([`crate::references`]) and the reports.
//!
//! Johnson, *Contact Mechanics*, 1985, §4.2 (REFERENCES.md): a cylinder of (effective) radius `R` pressed on a flat
//! by a load `P` per unit thickness, plane strain, contact modulus `E*` (`E/(1 − ν²)` on a rigid flat):
//!
//! ```text
//!   a² = 4PR/(πE*),   p0 = 2P/(πa) = aE*/(2R),   p(x) = p0 √(1 − x²/a²)
//! ```
//!
//! Valid for a ≪ R. The approach is *not* a Hertz result in 2D (it depends on the support), so comparisons are
//! made at equal load.

use super::special::semi;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// 2D Hertz line contact: half-width `a`, peak pressure `p0` and load `P = π a p0 / 2` per unit thickness (any
/// consistent units; pressure compressive positive). Serialized as `half_width`, `peak_pressure`, `load` (the
/// report's `references.hertz`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Hertz2D {
    /// Contact half-width a (length).
    #[serde(rename = "half_width")]
    pub a: f64,
    /// Peak pressure p0 (stress).
    #[serde(rename = "peak_pressure")]
    pub p0: f64,
    /// Normal load P per unit thickness (force/length): `π a p0 / 2` to round-off, and exactly the load given to
    /// [`Hertz2D::from_load`].
    pub load: f64,
}

impl Hertz2D {
    /// From half-width and peak pressure directly (the load is `π a p0 / 2`).
    pub fn new(a: f64, p0: f64) -> Self {
        Self { a, p0, load: 0.5 * PI * a * p0 }
    }

    /// From load per unit length `P`, effective radius `R` and contact modulus `E*`:
    /// `a² = 4PR/(πE*)`, `p0 = 2P/(πa)`.
    pub fn from_load(p: f64, r: f64, e_star: f64) -> Self {
        let a = (4.0 * p * r / (PI * e_star)).sqrt();
        Self { a, p0: 2.0 * p / (PI * a), load: p }
    }

    /// From the half-width `a` the contact is to have, effective radius `R` and contact modulus `E*`: the load
    /// `P = πE*a²/(4R)` and `p0 = aE*/(2R)`.
    pub fn from_half_width(a: f64, r: f64, e_star: f64) -> Self {
        Self { a, p0: a * e_star / (2.0 * r), load: PI * e_star * a * a / (4.0 * r) }
    }

    /// Effective radius consistent with `E*`: `R = a E*/(2 p0)`.
    pub fn radius(&self, e_star: f64) -> f64 {
        self.a * e_star / (2.0 * self.p0)
    }

    /// Hertz pressure `p(x) = p0 √(1 − x²/a²)` (0 outside the contact).
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * semi(x, self.a) / self.a
    }

    /// The Hertz contact fitting nodal pressures `(x_i, p_i)` (nodes with p > 0): `p² = p0² (1 − x²/a²)` by linear
    /// least squares in x², as REFERENCES.md recommends (the last loaded node only brackets a within ±h/2). `None`
    /// with fewer than two loaded nodes or a fit that is not a semi-ellipse. Its load is `π a p0 / 2`.
    pub fn fit(x: &[f64], p: &[f64]) -> Option<Self> {
        // p² = A + B x² by linear least squares over nodes with p > 0.
        let pts: Vec<(f64, f64)> = x.iter().zip(p).filter(|(_, &p)| p > 0.0).map(|(&x, &p)| (x * x, p * p)).collect();
        if pts.len() < 2 {
            return None;
        }
        let n = pts.len() as f64;
        let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
        let (mx, my) = (sx / n, sy / n);
        let (sxx, sxy) =
            pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + (x - mx) * (x - mx), b + (x - mx) * (y - my)));
        if sxx <= 0.0 {
            return None;
        }
        let b = sxy / sxx;
        let a0 = my - b * mx;
        if a0 <= 0.0 || b >= 0.0 {
            return None;
        }
        Some(Self::new((-a0 / b).sqrt(), a0.sqrt()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::test_support::*;

    #[test]
    fn hertz_relations() {
        // Expected: definitions a² = 4PR/(πE*), p0 = 2P/(πa); ∫p dx = P by quadrature.
        let (p, r, e) = (1234.0, 0.05, 2.1e11 / (1.0 - 0.09));
        let h = Hertz2D::from_load(p, r, e);
        assert!(close(h.a * h.a, 4.0 * p * r / (PI * e), 1e-15 * h.a * h.a));
        assert_eq!(h.load, p);
        assert!(close(Hertz2D::new(h.a, h.p0).load, p, 1e-12 * p));
        assert!(close(h.radius(e), r, 1e-12 * r));
        let total = quad(&|x| h.pressure(x), &[-h.a, h.a], 1e-13, 0.0);
        assert!(close(total, p, 1e-12 * p), "∫p = {total}");
        // The inverse: the contact of half-width a is the contact at its load.
        let g = Hertz2D::from_half_width(h.a, r, e);
        assert!(close(g.load, p, 1e-12 * p) && close(g.p0, h.p0, 1e-12 * h.p0), "{g:?} vs {h:?}");
    }

    #[test]
    fn seed_data_of_references_md() {
        // Expected: REFERENCES.md's seed figures, R = 1, E = 94500, ν = 0.1 (rigid flat): a/R = 0.05 ↔ P = 187.42,
        // p0 = 2386.4.
        let h = Hertz2D::from_load(187.42, 1.0, 94500.0 / (1.0 - 0.01));
        assert!((h.a - 0.05).abs() < 1e-5);
        assert!((h.p0 - 2386.4).abs() < 0.5);
    }

    #[test]
    fn fit_recovers_an_exact_ellipse() {
        // Expected: nodal values of an exact Hertz pressure give back its a and p0.
        let h = Hertz2D::from_load(5.0, 2.0, 1000.0 / (1.0 - 0.09));
        let xs: Vec<f64> = (0..15).map(|i| -0.9 * h.a + 0.13 * h.a * i as f64).collect();
        let ps: Vec<f64> = xs.iter().map(|&x| h.pressure(x)).collect();
        let f = Hertz2D::fit(&xs, &ps).unwrap();
        assert!((f.a / h.a - 1.0).abs() < 1e-12 && (f.p0 / h.p0 - 1.0).abs() < 1e-12);
        assert!(Hertz2D::fit(&xs[..1], &ps[..1]).is_none(), "one node does not fit an ellipse");
    }

    #[test]
    fn serialized_as_the_report_names_it() {
        // Expected: the report schema's `references.hertz` keys (half_width, peak_pressure, load).
        let h = Hertz2D::from_load(2.0, 1.0, 3.0);
        let v = serde_json::to_value(h).unwrap();
        assert_eq!(v["half_width"], h.a);
        assert_eq!(v["peak_pressure"], h.p0);
        assert_eq!(v["load"], 2.0);
        assert_eq!(serde_json::from_value::<Hertz2D>(v).unwrap(), h);
    }
}
