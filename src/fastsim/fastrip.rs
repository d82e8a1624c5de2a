//! FaStrip: the strip theory of steady rolling with spin, combined with FASTSIM (O. Sichani, R. Enblom,
//! M. Berg, "An alternative to FASTSIM for tangential solution of the wheel–rail contact", Vehicle System
//! Dynamics 54 (2016) 748–764), in the variant of CONTACT's module 3 with M = 5 ("modified FaStrip",
//! `m_solvpt.f90`), so that `examples/fastsim.inp` cases 4 and 7 can be reproduced (tests/fastsim.rs).
//!
//! # The method
//!
//! Each row y = y_j of the grid is a strip, treated as a 2D rolling contact of half-length a_j (Haines &
//! Ollerton's strip theory) with Hertz's pressure along it, `pn = pmax √(a_j² − x²)/a`, `pmax = 3N/(2πab)`. In
//! the strip, Carter's solution generalised to a lateral creepage and spin gives an adhesion area at the leading
//! edge, `x > −a_j + 2d_j` (rolling along +x), and the tractions there
//!
//! ```text
//!   px = μ pmax (κ √(a_j² − x²) − κ  √((a_j − d_j)² − (x − d_j)²)) / a
//!   py = μ pmax (λ √(a_j² − x²) − λ' √((a_j − d_j)² − (x − d_j)²)) / a,      λ' = λ − φ'
//! ```
//!
//! with the non-dimensional creepages (CONTACT's signs: creepages of body 1, tractions on body 1)
//!
//! ```text
//!   ξ' = −4(1 − ν) G C11 ξ / (2π² μ pmax),   η' = −4(1 − ν) G C22 η / (2π² μ pmax),
//!   φ' = −3 √(ab) G C23 φ / (2π μ pmax),
//! ```
//!
//! the slip-area length `d_j = (√(η'² + (1 − φ'²)(ξ' − φ' y_j/a)²) + η' φ') / (1 − φ'²) · a/(1 − ν)` and the
//! direction `(κ, λ) = (ξ' − φ' y_j/a, η' + φ' d_j/a) / |·|`. Where the square root's argument is negative, d_j < 0
//! or φ' = 1, the strip slides entirely. Kalker's C_ij (Table E.3, [`crate::theory::kalker`]) in these scalings make
//! the strip theory reproduce Kalker's linear theory at vanishing creepage: for ξ alone, Σ_j of the strips' forces is
//! `−(2/π) G C11 ξ ∫ a_j dy = −G ab C11 ξ`, and for φ alone the lateral force is `−G (ab)^{3/2} C23 φ`
//! (tests/fastsim.rs checks both limits).
//!
//! The slip area is where FaStrip leans on FASTSIM: every element is first solved by FASTSIM
//! ([`super::solve`], with the options' flexibilities and the elliptic bound), then in each strip the elements of
//! the strip theory's adhesion area take the strip tractions above and are in adhesion, and the others in contact
//! slip with FASTSIM's traction direction scaled to μ pn. CONTACT's variant keeps a strip's FASTSIM solution
//! unchanged where the strip tractions would exceed μ pmax at one of its adhesion elements; so does this one. That
//! check is against the peak pressure, not the local bound μ pn: with spin, the strip theory's adhesion tractions
//! can exceed the local bound near the strips' ends, and neither program corrects them. In `fastsim.inp`'s case 4
//! (44 × 44) 38 adhesion elements exceed it, the worst by 3.4× (CONTACT's own per-element output shows the same,
//! tests/fastsim.rs); in case 7 (220 × 220) the worst is 7.2× (the report's spin table).
//! [`super::Solution::bound_ratio`] reports the worst ratio |p|/(μ pn), so a caller sees it.
//!
//! # Decisions (each needed to reproduce CONTACT's numbers, or taken where CONTACT is silent)
//!
//! * **The ellipse.** The strip theory's a, b (and so pmax and a/b for the C_ij) are the equivalent ellipse of the
//!   element division on CONTACT's grid ([`super::Grid::Contact`]): Kik & Piotrowski's ellipse (2008), which keeps the
//!   contact's area (the elements in contact times dx dy) and its length-to-width ratio (the extents of the
//!   elements in contact along x and y). On [`super::Grid::Strips`], whose elements follow the ellipse exactly, it is
//!   the contact's own ellipse. a_j is the half-extent of the row's elements in contact.
//! * **The traction bound** must be [`super::Bound::Elliptic`] (Hertz's pressure, CONTACT's B = 2): the strip
//!   theory presumes Hertz's pressure, and a parabolic bound in the slip area would contradict it. A parabolic
//!   bound is refused by name.
//! * **The rolling direction.** CONTACT's code applies the +x formulas for χ = 180° too. Here rolling along −x is the
//!   point reflection of rolling along +x: the adhesion area is at the leading edge −x, and the spin's lateral
//!   term changes sign (`η' + φ'd/a` becomes `η' − φ'd/a`, λ' = λ + φ'), so that the solution for (ξ, η, −φ) along −x
//!   at (x, y) is the solution for (ξ, η, φ) along +x at (−x, −y) (tested). CONTACT's χ = 180° FaStrip is not
//!   compared.
//! * **The slope reduction** of Spiryagin et al. (2013) that CONTACT can apply to FASTSIM's flexibilities is not
//!   applied (CONTACT's K0_MF = ALFAMF = 1 in fastsim.inp make it the identity).

use super::{solve, Bound, Contact, Creepages, Direction, Element, Grid, Options, Solution, State};
use crate::error::ArgumentError;
use crate::theory::kalker;
use std::f64::consts::PI;

/// The strip theory's ellipse and its non-dimensional creepages (module docs).
struct StripTheory {
    /// The ellipse's semi-axis along x (length).
    a: f64,
    /// Hertz's peak pressure 3N/(2πab) of the ellipse (force/length²).
    pmax: f64,
    /// Friction coefficient.
    mu: f64,
    /// Poisson's ratio.
    nu: f64,
    /// ξ', η' and φ'.
    xi: f64,
    eta: f64,
    phi: f64,
    /// +1 rolling along +x, −1 along −x: the sign of the spin's lateral term and of x in the strip's frame.
    sense: f64,
}

impl StripTheory {
    fn new(contact: &Contact, cr: &Creepages, a: f64, b: f64, sense: f64) -> Result<StripTheory, ArgumentError> {
        let c = kalker::creep_coefficients(a, b, contact.nu)?;
        let (g, nu, mu) = (contact.shear_modulus, contact.nu, contact.mu);
        let pmax = 1.5 * contact.normal_force / (PI * a * b);
        let linear = 4.0 * (1.0 - nu) * g / (2.0 * PI * PI * mu * pmax);
        Ok(StripTheory {
            a,
            pmax,
            mu,
            nu,
            xi: -linear * c.c11 * cr.xi,
            eta: -linear * c.c22 * cr.eta,
            phi: -3.0 * (a * b).sqrt() * g * c.c23 * cr.phi / (2.0 * PI * mu * pmax),
            sense,
        })
    }

    /// The strip at y of half-length `aj`: its slip-area length d_j (`None`: the strip slides entirely) and
    /// (κ, λ, λ').
    fn strip(&self, y: f64) -> (Option<f64>, [f64; 3]) {
        let (xi, eta, phi_x, phi_y) = (self.xi, self.eta, self.phi, self.sense * self.phi);
        let long = xi - phi_x * y / self.a;
        // |φ'| = 1 (CONTACT tests φ' = 1 alone; φ' = −1 divides by zero below and also slides): the strip slides.
        let d = if (1.0 - phi_x * phi_x).abs() <= 2e-6 {
            None
        } else {
            let discr = eta * eta + (1.0 - phi_x * phi_x) * long * long;
            let d = (discr.max(0.0).sqrt() + eta * phi_y) / (1.0 - phi_x * phi_x) * self.a / (1.0 - self.nu);
            (discr >= 0.0 && d >= 0.0).then_some(d)
        };
        let lat = eta + phi_y * d.unwrap_or(0.0) / self.a;
        let norm = (long * long + lat * lat).max(1e-20).sqrt();
        let (kappa, lambda) = (long / norm, lat / norm);
        (d, [kappa, lambda, lambda - phi_y])
    }
}

/// Solves the steady rolling problem by FaStrip (module docs): FASTSIM with `options`, then the strip theory in the
/// adhesion areas (Sichani et al. 2016, as CONTACT's M = 5). Units and signs as [`solve`]'s. The strip tractions
/// can exceed the traction bound μ pn (module docs); [`Solution::bound_ratio`] reports the worst ratio. Errors:
/// those of [`solve`], a parabolic bound (`bound`), and the equivalent ellipse's a/b outside Kalker's table.
pub fn fastrip(contact: &Contact, creepages: &Creepages, options: &Options) -> Result<Solution, ArgumentError> {
    if options.bound != Bound::Elliptic {
        let msg = "FaStrip's strip theory presumes Hertz's pressure: use Bound::Elliptic (CONTACT's B = 2)";
        return Err(ArgumentError::new("fastsim::fastrip", "bound", msg));
    }
    let fastsim = solve(contact, creepages, options)?;
    let (mx, my) = options.grid.size();
    let (a, b, dy) = match options.grid {
        Grid::Contact { scale, .. } => {
            let (dx, dy) = (2.0 * scale * contact.a / mx as f64, 2.0 * scale * contact.b / my as f64);
            match equivalent_ellipse(&fastsim.elements, mx, dx, dy) {
                Some((a, b)) => (a, b, dy),
                None => return Ok(fastsim),
            }
        }
        Grid::Strips { .. } => (contact.a, contact.b, 2.0 * contact.b / my as f64),
    };
    let sense = if options.direction == Direction::PlusX { 1.0 } else { -1.0 };
    let theory = StripTheory::new(contact, creepages, a, b, sense)
        .map_err(|e| ArgumentError::new("fastsim::fastrip", "equivalent ellipse", e.to_string()))?;
    let mut elements = fastsim.elements;
    for row in elements.chunks_mut(mx) {
        strip(&theory, row, dy);
    }
    Ok(super::totals(elements, fastsim.coefficients, fastsim.flexibilities, contact.mu))
}

/// Kik & Piotrowski's equivalent ellipse (a, b) of the elements in contact on a grid of mx columns of dx × dy
/// elements: the area n dx dy and the ratio of the extents along x and y kept. `None` without contact.
fn equivalent_ellipse(elements: &[Element], mx: usize, dx: f64, dy: f64) -> Option<(f64, f64)> {
    let (mut n, mut ix_range, mut iy_range) = (0usize, (usize::MAX, 0), (usize::MAX, 0));
    for (i, e) in elements.iter().enumerate() {
        if e.state != State::Exterior {
            let (ix, iy) = (i % mx, i / mx);
            n += 1;
            ix_range = (ix_range.0.min(ix), ix_range.1.max(ix));
            iy_range = (iy_range.0.min(iy), iy_range.1.max(iy));
        }
    }
    if n == 0 {
        return None;
    }
    let area = n as f64 * dx * dy;
    let length = dx * (ix_range.1 - ix_range.0 + 1) as f64;
    let width = dy * (iy_range.1 - iy_range.0 + 1) as f64;
    let c = (area / PI).sqrt();
    Some((c * (length / width).sqrt(), c * (width / length).sqrt()))
}

/// The strip theory in one row of elements of width `dy` (module docs): the adhesion area's tractions, the slip
/// area's FASTSIM directions scaled to the bound; the row is left as FASTSIM solved it where the strip tractions
/// exceed μ pmax.
fn strip(theory: &StripTheory, row: &mut [Element], dy: f64) {
    let inside: Vec<usize> = (0..row.len()).filter(|&i| row[i].state != State::Exterior).collect();
    let (Some(&first), Some(&last)) = (inside.first(), inside.last()) else { return };
    let dx = row[first].area / dy;
    let aj = (0.5 * (row[last].x - row[first].x + dx)).max(1e-10);
    let (d, [kappa, lambda, lambda_a]) = theory.strip(row[first].y);
    // A strip that slides entirely: a slip area longer than the strip (no element is in x > −a_j + 2d).
    let d = d.unwrap_or(aj + 1.0);
    // x in the frame where rolling is along +x: the adhesion area is x > −a_j + 2d at the leading edge.
    let sticks = |x: f64| theory.sense * x > -aj + 2.0 * d;
    let strip_traction = |x: f64| {
        let xs = theory.sense * x;
        let cnt = (aj * aj - xs * xs).max(0.0).sqrt() / theory.a;
        let adh = ((aj - d).powi(2) - (xs - d).powi(2)).max(0.0).sqrt() / theory.a;
        (kappa * (cnt - adh), lambda * cnt - lambda_a * adh)
    };
    let exceeds = inside.iter().any(|&i| {
        sticks(row[i].x) && {
            let (fx, fy) = strip_traction(row[i].x);
            fx * fx + fy * fy > 1.0
        }
    });
    if exceeds {
        return;
    }
    let scale = theory.mu * theory.pmax;
    for &i in &inside {
        let e = &mut row[i];
        if sticks(e.x) {
            let (fx, fy) = strip_traction(e.x);
            (e.px, e.py, e.state) = (scale * fx, scale * fy, State::Adhesion);
        } else {
            let p = e.px.hypot(e.py).max(1e-10);
            let limit = theory.mu * e.pn;
            (e.px, e.py, e.state) = (e.px * limit / p, e.py * limit / p, State::Slip);
        }
    }
}
