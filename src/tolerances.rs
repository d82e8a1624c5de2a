//! Every tolerance rollbem's checks use, in one place, named per quantity. Tests and the harness import these
//! rather than writing bare numbers. Each says where it comes from.

/// A solver's answer is refused (status `numerical_error`) when its largest solver-independent residual exceeds
/// this, whatever the solver claims.
pub const RESIDUAL_REFUSE: f64 = 1e-8;

/// Residual a direct (pivoting or polished) solve must reach: round-off of a well-scaled dense solve.
pub const RESIDUAL_DIRECT: f64 = 1e-10;

/// Lemke's complementarity residual bound: ≤ 1e-12 relative, round-off of a pivoting solve with one step of iterative
/// refinement on an equilibrated problem.
pub const LEMKE_COMPLEMENTARITY: f64 = 1e-12;

/// Equilibrium of a load-driven solution: resultant equals the drive load to this relative error (the equilibrium
/// rows are part of the LCP, so a pivoting solve meets them to round-off).
pub const LOAD_RESULTANT: f64 = 1e-10;

/// Hertz half-width and peak pressure from the elliptic fit, constant elements, ≥ 20 elements across the contact
/// (REFERENCES.md: about 1 % needs h ≤ 0.1a; 1.5 % leaves room for the node-based fit at 20 elements).
pub const HERTZ_CONSTANT: f64 = 0.015;

/// Same for discontinuous quadratic elements (1 %: measured errors are below 0.1 % at 20 elements across).
pub const HERTZ_QUADRATIC: f64 = 0.01;

/// Minimum number of elements across the contact width (2a/h) for the Hertz tolerances above to apply.
pub const HERTZ_MIN_ELEMENTS: f64 = 20.0;

/// Largest a/R for which Hertz's half-space theory is a fair reference (REFERENCES.md: a/R ≈ 0.02–0.1).
pub const HERTZ_MAX_A_OVER_R: f64 = 0.1;

/// Two solvers agree on pressures when max |p₁ − p₂| ≤ this × p0 (Lemke and clarabel with its polish agree to
/// round-off; 1e-6 leaves room for an iterative solver at its default tolerance).
pub const SOLVER_AGREEMENT: f64 = 1e-6;

/// Subsurface stresses of the BEM wheel with constant elements ([`crate::stresses`]): a grid point closer to an
/// element than this many of the element's lengths is refused (`near_boundary`). The Somigliana quadrature is
/// accurate up to the boundary, but constant elements' displacements jump by about u′h between elements, and the
/// jumps spoil the field within a few element lengths (crate::bem::stress, "Interpolation"). Measured under a Hertz
/// contact against McEwen's field (tests/stresses.rs, `near_boundary_reach_is_where_the_bem_field_goes_wrong`:
/// a/R = 0.0025, 100 elements across, points across two elements at x = 0 … 1.1a): the largest error is 19 % of
/// p0 at 0.5 element lengths below the surface, 2.2 % at 1, 0.45 % at 2.5 and 0.42 % at 5 (what remains there is
/// the finite wheel's difference from the half-plane).
pub const STRESS_NEAR_BOUNDARY_CONSTANT: f64 = 2.5;

/// The same for discontinuous quadratic elements (smaller jumps, quadratic data): the largest error is 5.3 % of p0
/// at 0.1 element lengths, 2.7 % at 0.2, 0.86 % at 0.5 and 0.38 % at 1 (same test, 34 elements across).
pub const STRESS_NEAR_BOUNDARY_QUADRATIC: f64 = 0.5;

/// Unit invariance: the same scene in different units gives pressures equal to this relative error (every length is
/// divided by L0 and every stress by E internally, so only round-off remains).
pub const UNIT_INVARIANCE: f64 = 1e-9;

/// An iterative solver (NORM-TANG) stopped at a relative tolerance τ is held to residuals of at most this many τ
/// (and never less than [`RESIDUAL_DIRECT`] / [`RESIDUAL_REFUSE`]): its claim is "converged to τ", so a residual
/// of order τ is honest, and one far above it is refused.
pub const ITERATIVE_RESIDUAL_FACTOR: f64 = 100.0;

/// Cattaneo–Mindlin: stick-zone half-width and centre within this many contact elements ("within about
/// one element", the resolution of a nodal stick/slip state; the stick edge lies somewhere inside the element between a sticking and a slipping node).
pub const CATTANEO_ELEMENTS: f64 = 1.0;

/// Node states of two solvers are compared only where both are decisive: pressure above this fraction of p_max
/// and | |q| − μp | above this fraction of μ p_max (a node at the stick/slip boundary to within an iterative
/// solver's tolerance may legitimately be called either).
pub const STATE_MARGIN: f64 = 1e-6;

/// Warn when the estimated condition number of the rearranged BEM system exceeds this: with double precision the
/// flexibility then carries fewer than about 6 correct digits (ε·κ ≈ 1e-6), the accuracy the checks demand.
pub const BEM_CONDITION_WARN: f64 = 1e10;

/// Warn when the estimated condition number of the contact flexibility (normal or tangential block) exceeds this.
pub const FLEXIBILITY_CONDITION_WARN: f64 = 1e10;

/// Warn when the relative asymmetry ‖K − Kᵀ‖/‖K‖ of the normal flexibility exceeds this: the symmetric QP solved by
/// clarabel (before its polish) and the PGS convergence theory assume near symmetry.
pub const ASYMMETRY_WARN: f64 = 1e-2;

/// The rearranged BEM system is refused as singular (exit 4) when the ratio of the largest to the smallest |U_ii| of
/// its LU factors exceeds this: with double precision (ε ≈ 2e-16) fewer than about two correct digits would remain.
pub const BEM_SINGULAR_PIVOT_RATIO: f64 = 1e14;

/// A node counts as separated when its pressure is below this fraction of the peak pressure: ten thousand times
/// the round-off of a pivoting solve of a well-scaled problem, far below any physical pressure of interest.
pub const SEPARATED_PRESSURE: f64 = 1e-9;

/// A contact node sticks when |q| < μp (1 − STICK_MARGIN); at |q| = μp to within this relative margin it is at the
/// slip limit (the pivoting solvers put slipping nodes exactly on the cone, to round-off).
pub const STICK_MARGIN: f64 = 1e-9;

/// Relative band around |Q| = μP treated as the sliding limit (full slip, shift indeterminate) when both P and Q
/// are prescribed: a load given to 9 significant digits at μP is meant to be at the limit.
pub const SLIDING_LIMIT_BAND: f64 = 1e-9;

/// Cattaneo–Mindlin's shear is compared only at nodes more than this many contact elements away from ±a and ±c,
/// where the analytic traction has infinite slopes and a nodal comparison measures where the discrete edge falls
/// rather than the traction.
pub const CATTANEO_EDGE_ELEMENTS: f64 = 1.5;

/// Largest a/R at which Cattaneo–Mindlin is a fair reference for a coupled wheel at ν = 0.5: a finite wheel keeps
/// a normal–tangential coupling of order a/R through its curvature and bending even where Dundurs' β = 0.
/// Measured (top-arc wheel, μ = 0.5, Q/P = 0.3): the stick zone is off-centre by −0.16a at a/R = 0.0087, −0.08a at
/// 0.0044 and 0 at 0.0022; 0.01 keeps the offset under one element at the meshes used.
pub const CATTANEO_MAX_A_OVER_R_AT_NU_HALF: f64 = 0.01;

/// clarabel box QP (NORM-TANG's TANG step): an interior-point answer within this fraction of its box's width from
/// both bounds is taken as free (off the Coulomb limit) when the active-set polish fixes the free set.
pub const BOX_FREE_FRACTION: f64 = 1e-7;

/// clarabel box QP polish: a polished answer is accepted as a box-LCP solution of the nonsymmetric problem when no
/// bound is violated by more than this fraction of the box scale and no gradient sign is wrong by more than this
/// fraction of the gradient scale.
pub const BOX_POLISH_ACCEPT: f64 = 1e-9;

/// A solution is refused as `kinematics_out_of_range` when the wheel's rigid rotation φ moves its contact points by
/// more than this many contact half-widths: |φ|R > ROTATION_ARC_MAX · a. The linearised kinematics give a node
/// at x the gap change φx, the exact rotation of a round wheel about its centre changes no gap at all; the
/// difference puts the lever arms of the moment equilibrium off by φR (the pressure centre, which the moment
/// equation places, is off by φR of a contact whose scale is a) and the approach off by R(1 − cos φ) ≈ Rφ²/2, i.e.
/// (φR/a)² times the contact's gap scale a²/(2R). At φR = a/10 both are at most 10 % and 1 % of the contact's own
/// scales; beyond that the answer says more about the linearisation than about the wheel. (The reference and hard
/// scenes that hold or do not load the rotation have φ = 0; a free wheel under Q = 0.1P reaches φR ≈ 6a.)
pub const ROTATION_ARC_MAX: f64 = 0.1;

/// When a contact reaches the edge of the candidate zone, the zone suggested is this factor times the half-width
/// the contact needs, |x_c| + a (pressure centre offset plus Hertz's half-width at the run's load): Hertz's a is a
/// half-space estimate (a finite wheel's contact, friction and a moment change it by a few to some tens of per
/// cent) and the outermost node must end up separated, with room to spare, for the run to pass.
pub const ZONE_WIDTH_FACTOR: f64 = 1.5;

/// Fewest contact elements across a loaded contact (contact nodes in contact / nodes per element) for a run to
/// pass its resolution check: with k elements across, each edge is known to ±h/2, so the width 2a only to ±1/k;
/// below 4 (±25 %) the nodal answer does not approximate a pressure distribution (a one-node contact has no width
/// at all). The seed's own coarse meshes resolve their frictional contacts with 4–5 nodes (figs. 12–17), where its
/// figures are still read. Override per scene with `[checks] contact_elements`.
pub const MIN_CONTACT_ELEMENTS: f64 = 4.0;

/// A Farkas certificate of the static-admissibility LP ([`crate::admissible`]) is accepted only if it verifies in
/// our own arithmetic: every node's virtual motion inside the dual friction cone to this fraction of the largest
/// virtual displacement, and the loads' virtual work negative by more than this fraction of |load|·|motion|
/// (round-off of the certificate's O(n) sums is ~1e-14; a certificate violated by more is not a proof).
pub const FARKAS_MARGIN: f64 = 1e-9;
