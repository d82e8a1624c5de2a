//! Kalker's creep coefficients of the linear theory of rolling contact (no slip) for an elliptic contact of
//! semi-axes a (along the rolling direction x) and b (lateral, y): J.J. Kalker, *Three-dimensional elastic bodies
//! in rolling contact*, Kluwer 1990, Table E.3.
//!
//! In the limit of vanishing creepages the whole contact adheres and the creep forces are linear in the creepages
//! (longitudinal ξ, lateral η, spin φ [1/length]), with `c = √(ab)` and G the combined modulus of rigidity:
//!
//! ```text
//!   Fx = −G c² C11 ξ,      Fy = −G c² (C22 η + c C23 φ),      Mz = −G c³ (−C23 η + c C33 φ)
//! ```
//!
//! (Kalker's signs; CONTACT's convention of [`crate::fastsim`]: forces on body 1, creepages of body 1 relative to
//! body 2, so a positive ξ gives a negative Fx.)
//!
//! # The data and where it comes from
//!
//! [`TABLE_E3`] holds C11, C22 and C23 for ν = 0, 1/4, 1/2 and g = 0.1, 0.2, …, 1.0 in the two branches of the
//! table: `a ≤ b` with g = a/b, and `a ≥ b` with g = b/a (the table's own layout). The numbers are Kalker's
//! (three significant digits) as CONTACT transcribes them in its public source (E.A.H. Vollebregt, CONTACT,
//! Apache-2.0, `src/m_hertz.f90`, subroutine `linrol`, the commit named in `reference/contact3d/README.md`); they are
//! data here, the code is ours. CONTACT's second copy (`src/usetab_table.f90`) reads 1.15 for C23 at a/b = 0.8,
//! ν = 1/4, where `m_hertz.f90` reads 1.25: the latter fits its row (1.14, 1.25, 1.36 down the column; 1.13, 1.25,
//! 1.40 across ν) and is the one kept (tested: the column is smooth).
//!
//! C33 is not transcribed by CONTACT, and no second public source of the table was found while writing this module:
//! it is left out rather than quoted from memory.
//!
//! Checks of the transcription: the tests below (C11 = C22 at ν = 0, as the theory requires; the branches meet at
//! a/b = 1; smooth columns; Kalker's slender-ellipse limits) and `tests/kalker.rs`, which computes the coefficients
//! anew with CONTACT's exact half-space solver at vanishing creepage (a/b = 0.2, 1, 5 at ν = 1/4 and a/b = 1 at
//! ν = 0, 1/2, extrapolated in the element size): all 20 values within 1 % of the table (largest 0.75 %).
//!
//! # Interpolation (the same as CONTACT's `linrol`, stated here so the numbers can be reproduced)
//!
//! * In the ellipse: linear in g = min(a/b, b/a) between the table's rows (spacing 0.1), in the branch that
//!   `a ≤ b` or `a > b` selects; at a/b = 1 both branches hold the same row (tested).
//! * In ν: for each coefficient, the quadratic through the three columns is taken **in 1/C**,
//!   `1/C(ν) = Σ_k ℓ_k(ν) / C(ν_k)` with ℓ_k the Lagrange polynomials on ν_k = 0, 1/4, 1/2. In Kalker's slender
//!   limit g → 0 (a ≪ b), `C11 → π²/(4(1 − ν))` and `C22 → π²/4`, whose inverses are linear in ν: the rule is exact
//!   there, and it reproduces the three columns exactly.
//! * Outside the table (a/b < 0.1 or > 10, ν < 0 or > 1/2) [`creep_coefficients`] refuses the argument; CONTACT
//!   switches to Kalker's slender-ellipse asymptotes for g < 0.101 (so at g = 0.1 exactly it uses them rather than
//!   the row), which are not reproduced here.

use crate::error::ArgumentError;

/// Kalker's Table E.3 (C11, C22, C23): `TABLE_E3[branch][row][coefficient][nu]`. Branch 0: a ≤ b, g = a/b; branch 1:
/// a ≥ b, g = b/a; row k (0-based) is g = (k + 1)/10; coefficient 0, 1, 2 = C11, C22, C23; ν column 0, 1, 2 =
/// 0, 1/4, 1/2. Dimensionless. Source: see the module docs.
// 3.14 is Kalker's C22 (twice), not an approximation of π.
#[allow(clippy::approx_constant)]
pub const TABLE_E3: [[[[f64; 3]; 3]; 10]; 2] = [
    [
        [[2.51, 3.31, 4.85], [2.51, 2.52, 2.53], [0.334, 0.473, 0.731]],
        [[2.59, 3.37, 4.81], [2.59, 2.63, 2.66], [0.483, 0.603, 0.809]],
        [[2.68, 3.44, 4.80], [2.68, 2.75, 2.81], [0.607, 0.715, 0.889]],
        [[2.78, 3.53, 4.82], [2.78, 2.88, 2.98], [0.720, 0.823, 0.977]],
        [[2.88, 3.62, 4.83], [2.88, 3.01, 3.14], [0.827, 0.929, 1.07]],
        [[2.98, 3.72, 4.91], [2.98, 3.14, 3.31], [0.930, 1.03, 1.18]],
        [[3.09, 3.81, 4.97], [3.09, 3.28, 3.48], [1.03, 1.14, 1.29]],
        [[3.19, 3.91, 5.05], [3.19, 3.41, 3.65], [1.13, 1.25, 1.40]],
        [[3.29, 4.01, 5.12], [3.29, 3.54, 3.82], [1.23, 1.36, 1.51]],
        [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63]],
    ],
    [
        [[10.7, 11.7, 12.9], [10.7, 12.8, 16.0], [12.2, 14.6, 18.0]],
        [[6.96, 7.78, 8.82], [6.96, 8.14, 9.79], [5.72, 6.63, 7.89]],
        [[5.57, 6.34, 7.34], [5.57, 6.40, 7.51], [3.79, 4.32, 5.01]],
        [[4.84, 5.57, 6.57], [4.84, 5.48, 6.31], [2.88, 3.24, 3.70]],
        [[4.37, 5.10, 6.11], [4.37, 4.90, 5.56], [2.35, 2.62, 2.96]],
        [[4.06, 4.78, 5.80], [4.06, 4.50, 5.04], [2.01, 2.23, 2.50]],
        [[3.82, 4.54, 5.58], [3.82, 4.21, 4.67], [1.76, 1.95, 2.18]],
        [[3.65, 4.36, 5.42], [3.65, 3.99, 4.39], [1.58, 1.75, 1.94]],
        [[3.51, 4.22, 5.30], [3.51, 3.81, 4.16], [1.44, 1.59, 1.77]],
        [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63]],
    ],
];

/// The Poisson ratios of the table's columns.
pub const TABLE_E3_NU: [f64; 3] = [0.0, 0.25, 0.5];

/// Kalker's creep coefficients at one ellipse and Poisson ratio (dimensionless; see the module docs for their
/// meaning and signs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct CreepCoefficients {
    /// C11: longitudinal force per longitudinal creepage, `Fx = −G c² C11 ξ`.
    pub c11: f64,
    /// C22: lateral force per lateral creepage, `Fy = −G c² C22 η`.
    pub c22: f64,
    /// C23: lateral force per spin, `Fy = −G c³ C23 φ` (and, with the opposite sign, the spin moment per lateral
    /// creepage).
    pub c23: f64,
}

/// Kalker's C11, C22, C23 for the ellipse of semi-axes `a` (rolling direction) and `b` (any length unit, only the
/// ratio a/b matters) and Poisson ratio `nu`, interpolated in Table E.3 as the module docs state. Errors: a or b
/// not finite and > 0, a/b outside [0.1, 10], ν outside [0, 1/2] (the table's range).
pub fn creep_coefficients(a: f64, b: f64, nu: f64) -> Result<CreepCoefficients, ArgumentError> {
    const F: &str = "kalker::creep_coefficients";
    for (name, v) in [("a", a), ("b", b)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(ArgumentError::new(F, name, format!("must be a finite length > 0, is {v}")));
        }
    }
    if !(0.0..=0.5).contains(&nu) {
        return Err(ArgumentError::new(F, "nu", format!("must be in [0, 0.5] (Table E.3's range), is {nu}")));
    }
    let ratio = a / b;
    // A relative slack of 1e-12 lets a/b = 0.1 or 10 computed in floating point through.
    if !(0.1 * (1.0 - 1e-12)..=10.0 * (1.0 + 1e-12)).contains(&ratio) {
        return Err(ArgumentError::new(F, "a", format!("a/b must be in [0.1, 10] (Table E.3's range), is {ratio}")));
    }
    let (branch, g) = if ratio <= 1.0 { (0, ratio) } else { (1, 1.0 / ratio) };
    // Row k holds g = (k + 1)/10: between rows k and k + 1 with weight t on the upper one.
    let s = (10.0 * g - 1.0).clamp(0.0, 9.0);
    let k = (s.floor() as usize).min(8);
    let t = s - k as f64;
    let c = |i: usize| {
        let at = |j: usize| (1.0 - t) * TABLE_E3[branch][k][i][j] + t * TABLE_E3[branch][k + 1][i][j];
        interpolate_nu([at(0), at(1), at(2)], nu)
    };
    Ok(CreepCoefficients { c11: c(0), c22: c(1), c23: c(2) })
}

/// The quadratic in 1/C through the columns ν = 0, 1/4, 1/2, evaluated at `nu` (module docs).
fn interpolate_nu(col: [f64; 3], nu: f64) -> f64 {
    let [n0, n1, n2] = TABLE_E3_NU;
    let l0 = (nu - n1) * (nu - n2) / ((n0 - n1) * (n0 - n2));
    let l1 = (nu - n0) * (nu - n2) / ((n1 - n0) * (n1 - n2));
    let l2 = (nu - n0) * (nu - n1) / ((n2 - n0) * (n2 - n1));
    1.0 / (l0 / col[0] + l1 / col[1] + l2 / col[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn table_rows_are_returned_at_their_own_g_and_nu() {
        // Expected: the table itself (interpolation reproduces its nodes), e.g. a/b = 1, ν = 1/4: 4.12, 3.67, 1.47;
        // a/b = 5 (g = b/a = 0.2 in the a > b branch), ν = 1/4: 7.78, 8.14, 6.63; a/b = 0.2, ν = 1/4: 3.37, 2.63, 0.603.
        for (a, b, nu, want) in [
            (1.0, 1.0, 0.25, [4.12, 3.67, 1.47]),
            (5.0, 1.0, 0.25, [7.78, 8.14, 6.63]),
            (0.2, 1.0, 0.25, [3.37, 2.63, 0.603]),
            (10.0, 1.0, 0.5, [12.9, 16.0, 18.0]),
            (0.1, 1.0, 0.0, [2.51, 2.51, 0.334]),
        ] {
            let c = creep_coefficients(a, b, nu).unwrap();
            for (got, want) in [c.c11, c.c22, c.c23].into_iter().zip(want) {
                assert!((got - want).abs() < 1e-12 * want, "a/b={} nu={nu}: {got} vs {want}", a / b);
            }
        }
    }

    #[test]
    fn nu_zero_gives_c11_equal_c22_in_every_row() {
        // Expected (theory): at ν = 0 the half-space's tangential point-force response is u_x = Q_x/(2πG r), u_y = 0
        // (Boussinesq–Cerruti), so the longitudinal (ξ) and lateral (η) no-slip problems have the same kernel and
        // domain: C11 = C22 exactly. A transcription slip in either column would break it.
        for branch in &TABLE_E3 {
            for row in branch {
                assert_eq!(row[0][0], row[1][0]);
            }
        }
    }

    #[test]
    fn branches_meet_at_the_circle_and_columns_are_smooth() {
        // Expected: a/b = 1 is the last row of both branches (the same ellipse). Each column is a smooth function of
        // g sampled at spacing 0.1: its second differences are under 6 % of its values, after scaling the a > b
        // branch by Kalker's slender-limit growth (C11, C22 ~ 1/g, C23 ~ g^-3/2, as CONTACT's asymptotes) so that it
        // is smooth too. The largest found is 5.2 % (C23, ν = 0, first rows of a ≤ b); a slip of one unit in the
        // second digit of an entry near 1 (usetab_table.f90's 1.15 for C23(0.8, 1/4)) gives 17 %.
        assert_eq!(TABLE_E3[0][9], TABLE_E3[1][9]);
        for branch in 0..2 {
            for i in 0..3 {
                for j in 0..3 {
                    let scale = |k: usize| {
                        let g = (k + 1) as f64 / 10.0;
                        if branch == 0 {
                            1.0
                        } else if i == 2 {
                            g.powf(1.5)
                        } else {
                            g
                        }
                    };
                    let col: Vec<f64> = (0..10).map(|k| TABLE_E3[branch][k][i][j] * scale(k)).collect();
                    for w in col.windows(3) {
                        let d2 = (w[0] - 2.0 * w[1] + w[2]).abs();
                        assert!(d2 < 0.06 * w[1], "branch {branch} coefficient {i} nu#{j}: {col:?}");
                    }
                }
            }
        }
        let mut slipped = TABLE_E3[0];
        slipped[7][2][1] = 1.15;
        let col: Vec<f64> = (0..10).map(|k| slipped[k][2][1]).collect();
        assert!(col.windows(3).any(|w| (w[0] - 2.0 * w[1] + w[2]).abs() >= 0.06 * w[1]));
    }

    #[test]
    fn slender_limit_matches_kalkers_asymptotes() {
        // Expected (Kalker's closed-form slender-ellipse asymptotes, as CONTACT's `linrol` states them): as g = a/b → 0, C11 → π²/(4(1 − ν)) and C22 → π²/4
        // (each strip across the ellipse behaves as a 2D no-slip contact: plane strain for ξ, anti-plane for η).
        // The table's first row (g = 0.1) lies within 2.6 % of these limits and nearer to them than the second row
        // (g = 0.2): the table approaches the closed form.
        for (j, nu) in TABLE_E3_NU.iter().enumerate() {
            for (i, limit) in [(0, PI * PI / (4.0 * (1.0 - nu))), (1, PI * PI / 4.0)] {
                let (r1, r2) = (TABLE_E3[0][0][i][j], TABLE_E3[0][1][i][j]);
                assert!((r1 - limit).abs() < 0.026 * limit, "C{}{} nu={nu}: {r1} vs {limit}", i + 1, i + 1);
                assert!((r1 - limit).abs() < (r2 - limit).abs(), "C{}{} nu={nu}", i + 1, i + 1);
            }
        }
        // ν = 0, a/b = 0.1: C11 = 2.51 against π²/4 = 2.4674.
        assert!((TABLE_E3[0][0][0][0] - PI * PI / 4.0).abs() < 0.045);
    }

    #[test]
    fn interpolation_in_g_and_nu() {
        // Expected: linear in g between the rows (a/b = 0.25 is halfway between 0.2 and 0.3: ν = 0 column, C11 =
        // (2.59 + 2.68)/2; a/b = 4 is g = b/a = 0.25 in the a > b branch: C22 at ν = 1/2 = (9.79 + 7.51)/2); in ν the harmonic rule of
        // the module docs: at ν = 0.125 it is 1/C = (3/8)/C0 + (3/4)/C1 − (1/8)/C2 (Lagrange weights at 1/8).
        let c = creep_coefficients(0.25, 1.0, 0.0).unwrap();
        assert!((c.c11 - 0.5 * (2.59 + 2.68)).abs() < 1e-12);
        let c = creep_coefficients(4.0, 1.0, 0.5).unwrap();
        assert!((c.c22 - 0.5 * (9.79 + 7.51)).abs() < 1e-12, "{}", c.c22);
        let c = creep_coefficients(1.0, 1.0, 0.125).unwrap();
        let want = 1.0 / (0.375 / 3.40 + 0.75 / 4.12 - 0.125 / 5.20);
        assert!((c.c11 - want).abs() < 1e-12, "{} vs {want}", c.c11);
    }

    #[test]
    fn bad_arguments_are_refused_naming_the_argument() {
        // Expected: the documented ranges.
        for (a, b, nu, arg) in [
            (-1.0, 1.0, 0.25, "a"),
            (1.0, f64::NAN, 0.25, "b"),
            (1.0, 1.0, 0.6, "nu"),
            (1.0, 1.0, f64::NAN, "nu"),
            (0.05, 1.0, 0.25, "a"),
            (11.0, 1.0, 0.25, "a"),
        ] {
            let e = creep_coefficients(a, b, nu).unwrap_err();
            assert_eq!(e.argument, arg, "{e:?}");
        }
    }
}
