//! Analytic reference solutions for a 2D (plane strain, line contact) contact-mechanics
//! verification harness.
//!
//! Everything is per unit thickness, `f64`, SI-agnostic (any consistent units). All functions are
//! pure. Every closed form below is checked in the `tests` module against an *independent*
//! numerical computation (quadrature of half-plane Green's functions, finite-difference equilibrium
//! checks, an incremental frictional contact solver); each test states where its expected value
//! comes from.
//!
//! # 0. Conventions
//!
//! * `x` tangential surface coordinate, `z` depth **into** the body (for the half-plane solutions).
//!   Stresses are **tension positive**. [`Stress2D`] holds in-plane Cartesian components
//!   `(xx, yy, xy)`; for half-plane fields the second axis is `z` (so `yy` = σ_zz, `xy` = τ_xz).
//! * Normal pressure `p(x) ≥ 0` is compressive. The tangential traction `q(x)` is the `x`-component
//!   of the traction that the counter-body exerts **on the body considered** (Cattaneo, M–D, Carter:
//!   the elastic body / the cylinder; Spence: body 1). On the surface of a half-plane `z ≥ 0`:
//!   σ_zz = −p and τ_xz = −q.
//! * Contact modulus (plane strain) `1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2` (elastic body on a rigid
//!   flat: `E* = E/(1 − ν²)`), see [`contact_modulus`]. `R` is the effective radius
//!   `1/R = 1/R1 + 1/R2`.
//! * Dundurs' β (plane strain), body 1 first (see [`dundurs_beta`]):
//!   `β = [(1 − 2ν1)/G1 − (1 − 2ν2)/G2] / [2((1 − ν1)/G1 + (1 − ν2)/G2)]`.
//!   β = 0 for identical materials and for an incompressible body on a rigid one.
//!
//! ## Half-plane surface compliance (Johnson 1985, ch. 2, line loading of a half-space)
//!
//! For a half-plane `z > 0` loaded by `p(x)`, `q(x)`, the surface displacement gradients are
//!
//! ```text
//!   ∂ū_x/∂x = −((1−2ν)(1+ν)/E) p(x) − (2(1−ν²)/(πE)) PV∫ q(t)/(x−t) dt
//!   ∂ū_z/∂x = −(2(1−ν²)/(πE)) PV∫ p(t)/(x−t) dt + ((1−2ν)(1+ν)/E) q(x)     (ū_z into the body)
//! ```
//!
//! so the tangential surface displacement is the logarithmic potential
//! `ū_x(x) = −(2(1−ν²)/(πE)) ∫ q(t) ln|x − t| dt + const`. The sign was checked against the
//! Flamant/McEwen stress field: at the surface σ_zz = −p and, for pure `q`,
//! σ_xx = −(2/π) PV∫ q/(x−t) dt, hence ε_xx = ((1−ν²)/E)(σ_xx − ν σ_zz/(1−ν)) reproduces the kernel
//! (test `surface_strain_from_mcewen_matches_compliance_kernel`). The x–x influence is invariant
//! under the reflection `z → −z`, so the same formula holds for a body occupying `z < 0` (the
//! cylinder above the flat). For two bodies, with `q` acting on body 1 and `−q` on body 2, the
//! relative tangential displacement `g = u_x1 − u_x2` satisfies
//!
//! ```text
//!   ∂g/∂x = −(2/(πE*)) [ π β p(x) + PV∫ q(t)/(x−t) dt ]                                  (0.1)
//! ```
//!
//! (body 1 above, body 2 below, both described in their own inward coordinates). With β = 0 the
//! pressure does not enter: normal and tangential problems decouple, and the tangential problem
//! only involves `E*`.
//!
//! # 1. Hertz line contact ([`Hertz2D`])
//!
//! `a² = 4PR/(πE*)`, `p0 = 2P/(πa) = aE*/(2R)`, `p(x) = p0 √(1 − x²/a²)`.
//!
//! # 2. Cattaneo–Mindlin, β = 0 ([`cattaneo_traction`])
//!
//! Tangential force `Q` (|Q| < μP) applied after `P`, on the body, in `+x` for `Q > 0`:
//!
//! ```text
//!   q(x) = sgn(Q) μ p0 [ √(1 − x²/a²) − (c/a) √(1 − x²/c²) ]   |x| < c     (stick)
//!   q(x) = sgn(Q) μ p(x)                                         c < |x| < a (slip)
//!   c/a  = √(1 − |Q|/(μP))
//! ```
//!
//! Source: Cattaneo (1938), Mindlin (1949); 2D form in Johnson (1985) §7.2. Both semi-ellipses
//! have a constant Hilbert transform difference on |x| < c, so the stick zone displaces rigidly
//! (verified numerically with the log kernel in the tests).
//!
//! # 3. Mindlin–Deresiewicz in 2D, β = 0, constant P ([`md_traction`], [`md_displacement`], [`md_cycle_dissipation`])
//!
//! Write `f(x; c) = (μ p0/a) √(c² − x²)₊`, so `f(x; a) = μ p(x)`. By superposition (the 2D
//! analogue of Johnson §7.3):
//!
//! ```text
//!   loading 0 → Q*      : q = f(a) − f(c*),                 c*²/a² = 1 − Q*/(μP)
//!   unloading Q* → Q    : q = −f(a) + 2 f(c') − f(c*),      c'²/a² = 1 − (Q* − Q)/(2μP)
//!   reloading −Q* → Q   : q =  f(a) − 2 f(c'') + f(c*),     c''²/a² = 1 − (Q* + Q)/(2μP)
//! ```
//!
//! valid for 0 ≤ Q* ≤ μP and −Q* ≤ Q ≤ Q*. The stick zone is |x| < c' (resp. c'').
//!
//! **Tangential displacement and its datum.** In 2D the log kernel makes the absolute displacement
//! of a loaded half-plane undefined; a datum length `D` is needed. We define the *log datum*:
//! surface displacements are normalised as `ū_x(x) = −(2/(πE*)) ∫ q(t) ln(|x − t|/D) dt` and
//! `δ` is the tangential displacement of the counter-body relative to that datum, positive along
//! `+x`; the counter-body carries with it the central zone |x| < min(c*, c') that has never
//! slipped (on unloading the annulus c* < |x| < c' is stuck again but keeps the slip frozen during
//! loading, so it is *not* at δ). Physically `δ` is the displacement of the counter-body relative to
//! the body's surface points at |x| = D, up to O((a/D)²) terms.
//! Using `∫ √(c² − t²) ln|x − t| dt = (π/2)x² + (πc²/2)(ln(c/2) − 1/2)` for |x| ≤ c, the
//! `x²` terms cancel in the stick zone (the weights sum to zero) and, with `γ = c²/a²`,
//! `Φ(γ) = γ ln γ`, `λ = (2/(πE*))(ln(2D/a) + 1/2)`:
//!
//! ```text
//!   δ_load(Q)   = λQ + sgn(Q) (μP/(πE*)) Φ(1 − |Q|/(μP))
//!   δ_unload(Q) = λQ − (μP/(πE*)) [ 2Φ(γ') − Φ(γ*) ]
//!   δ_reload(Q) = λQ + (μP/(πE*)) [ 2Φ(γ'') − Φ(γ*) ]
//! ```
//!
//! (general form `δ = −(μ p0/(aE*)) Σ w_i c_i² (ln(c_i/(2D)) − 1/2)` over the three semi-ellipses).
//! The slope `dδ/dQ = (2/(πE*)) ln(2D/a) − (1/(πE*)) ln γ` on first loading is infinite at gross
//! slip (γ → 0).
//!
//! **Energy per full cycle ±Q*** (loop area `W = ∮ Q dδ = ∫_{−Q*}^{Q*} (δ_unload − δ_reload) dQ`):
//!
//! ```text
//!   W = (2 μ² P² / (π E*)) [ 1 − γ*² + 2 γ* ln γ* ],    γ* = 1 − Q*/(μP)
//!     ≈ 2 Q*³ / (3π E* μP)   for Q* ≪ μP,        → 2μ²P²/(πE*) as Q* → μP.
//! ```
//!
//! *Datum independence.* Changing `D` adds `(2/(πE*)) ln(D'/D) · Q` to every branch, a function
//! of `Q` alone, and `∮ Q d(kQ) = 0` for any constant k; λ therefore cancels in `δ_unload − δ_reload` and `W` is
//! independent of `D` (test `md_loop_area_is_datum_independent_and_equals_dissipation`). More
//! generally, the loop area equals the frictional dissipation for any datum whose displacement
//! depends on the load history only through `Q` (energy argument: `∮⟨q, G dq⟩ = 0` for the
//! symmetric log kernel `G`). A *material point* datum (e.g. the point at depth D on the axis, the
//! brief's suggestion) is not exactly of this kind: its Flamant influence function
//! `g(t) = −(2(1−ν²)/(πE)) ln√(t² + D²) + (1+ν)(1−2ν)t²/(πE(t²+D²)) − 2ν(1+ν)D²/(πE(t²+D²))`
//! (plus a rigid rotation, which is ∝ Q and harmless) is not constant over the contact, so its loop
//! area differs from `W` by O((a/D)²): computed during development (single elastic body on a rigid
//! counter-body, ν = 0.3, quadrature) as +1.5 %/+1.0 % (Q*/μP = 0.2/0.8) at D = 3a,
//! +0.19 %/+0.11 % at D = 10a, +0.021 %/+0.013 % at D = 30a. For a point load the exact relation
//! is `u_x(x, 0) − u_x(0, D) = −(2(1−ν²)Q/(πE)) ln(|x|/D) + (1+ν)Q/(πE)` (Flamant displacement
//! field, checked against Hooke's law by finite differences during development).
//!
//! The closed form `W` is verified against an independent computation of the frictional
//! dissipation `∮∫ |q| |∂s/∂Q| dx dQ` over both half-cycles, with the slip rate obtained from the
//! traction rate through the log kernel by quadrature (measured agreement 5e-12 and 9e-11 relative
//! for Q*/μP = 0.3 and 0.9; required ≤ 1e-6); the δ branch formulas agree with direct log-kernel
//! quadrature of the tractions to ≤ 1e-11.
//!
//! # 4. Carter, steady rolling with traction, β = 0 ([`carter_traction`], [`carter_creepage`], [`carter_slip`])
//!
//! Rolling towards `+x` (leading edge `x = +a`); in the contact frame material flows from `+x` to
//! `−x` at speed `V`. A cylinder surface particle moves at `−V1(1 + ∂u_x/∂x)`, a flat particle at
//! `−V2`, so the slip velocity of the cylinder relative to the flat, normalised by `V`, is
//!
//! ```text
//!   s(x) = ξ − ∂u_x/∂x,        ξ = (V2 − V1)/V = (V − ΩR)/V   (ground frame: centre speed V, spin Ω)
//! ```
//!
//! with `u_x` the cylinder surface displacement and `∂u_x/∂x = −(2/(πE*)) PV∫ q(t)/(x − t) dt`
//! (`E*` of the cylinder if the flat is rigid; β = 0 so `p` contributes nothing). Coulomb:
//! `q = −μp sgn(s)` where `s ≠ 0`, `|q| ≤ μp` where `s = 0`. The solution (Carter 1926; Johnson
//! §8.2) is, with σ = sgn(Q), `c/a = √(1 − |Q|/(μP))`, `d = a − c`:
//!
//! ```text
//!   stick a − 2c < x < a :  q = σ μ p0 [ √(1 − x²/a²) − (c/a) √(1 − (x − d)²/c²) ],  s = 0
//!   slip −a < x < a − 2c :  q = σ μ p(x),   s = −σ (μ/R) √((x − d)² − c²)
//!   creepage            :  ξ = −σ (μa/R) (1 − √(1 − |Q|/(μP)))
//! ```
//!
//! i.e. `|ξ| = (μa/R)(1 − √(1 − |Q|/(μP)))`, saturating (full slip) at `|ξ| ≥ μa/R`.
//! **Sign relation:** ξ and Q have opposite signs. `Q > 0` (force on the cylinder along the rolling
//! direction: driving) ⇔ `ξ < 0` (ΩR > V, the wheel spins faster than free rolling); braking
//! `Q < 0` ⇔ `ξ > 0`. The convention is consistent: in the slip zone `s` has the sign −σ, opposite
//! to `q`, as Coulomb requires. Placing the stick zone at the trailing edge instead gives `s` of the
//! same sign as `q` there (inadmissible) — so the leading-edge stick zone is forced by this
//! convention (tests `carter_*`).
//!
//! # 5. Spence (1975): monotonic normal loading with friction and β ≠ 0 ([`spence_c_over_a`])
//!
//! Setting: two cylinders (or a cylinder on a half-plane) with Dundurs β ≠ 0, loaded monotonically
//! by `P` at zero tangential force; Coulomb friction μ; the pressure is taken as Hertzian (the
//! O(βμ) influence of `q` on `p` is neglected — this is the approximation in which `c/a` depends on
//! β/μ alone). Equation (0.1) with `g = u_x1 − u_x2`; slip zones `q = −μp sgn(ġ)`, stick `ġ = 0`
//! (ġ = rate at fixed x as the load grows).
//!
//! *Derivation (this module).* Self-similarity (Spence's argument) makes `c = κa` with κ constant,
//! and a point `x` that enters the stick zone (at `a = |x|/κ`) keeps the relative displacement it
//! had then; since `g ∝ a² G(x/a)`, in the stick zone `g = C x|x|`, i.e. `∂g/∂x = 2C|x|`. With
//! `q = σ sgn(x) μ p` in `κa < |x| < a`, the stick condition becomes the singular integral equation
//! `πβ p + PV∫ q/(x − t) dt = −Λ|x|` on |x| < c (Λ unknown). Slip-direction and
//! stick-inequality requirements at `x = c` together force the `√(c − |x|)` coefficient of
//! `q − σμp` to vanish (slip just outside `c` requires it to be of sign σ, the stick inequality just
//! inside requires sign −σ). Solving the bounded Cauchy problem for `q'` and imposing (i) continuity
//! of `q` at `±c` and (ii) `∂g/∂x(0) = 0` gives, with `k = c/a`, `k' = √(1 − k²)`,
//!
//! ```text
//!   β/μ = [ π(1 − k') + L(k)/2 − 2M(k) ] / (π K(k)),
//!   L(k) = 2∫₀^k √(1−t²) ln[(√(1−t²) + k')/(√(1−t²) − k')] dt/√(k²−t²),
//!   M(k) = ∫₀^k t² ln[(1 − √(1−t²))/t] dt / (√(1−t²) √(k²−t²)),
//! ```
//!
//! and the numerator turns out to be exactly `π K(k')` (checked by quadrature to 1e-10 in the tests,
//! not proved analytically here). Hence the closed form
//!
//! ```text
//!   K(√(1 − c²/a²)) / K(c/a) = |β|/μ        ⇔   c/a = θ₂²(q)/θ₃²(q),  q = exp(−π|β|/μ)
//! ```
//!
//! (K = complete elliptic integral of the first kind, modulus argument; θ Jacobi theta functions).
//! Checks: the independent incremental half-plane solver (Python/NumPy, 2000 elements per half
//! contact, 0.0005a resolution, no self-similarity assumed) gives 0.985, 0.945, 0.792, 0.7075,
//! 0.377, 0.172, 0.036 for β/μ = 0.5, 0.635, 0.889, 1, 1.48, 2, 3; the formula gives 0.98517,
//! 0.94476, 0.79152, 0.70711, 0.37674, 0.17157, 0.03592 (all within the 0.0005a resolution).
//! The same solver in Rust on a coarse grid is re-run in the tests.
//!
//! Consequences: `β/μ = 1 ⇒ c/a = 1/√2`, `β/μ = 2 ⇒ c/a = 3 − 2√2` (singular moduli). There is
//! **no** finite β/μ with full stick (for β ≠ 0) and **no** complete slip: `1 − c/a ≈ 8 e^{−πμ/|β|}`
//! for small β/μ (slip zones exponentially thin: `< 3e-5 a` for |β|/μ ≤ 0.25, practically full
//! stick) and `c/a ≈ 4 e^{−π|β|/(2μ)}` for large β/μ.
//!
//! **Goodman approximation vs the fully coupled problem.** [`spence_c_over_a`] neglects the
//! influence of `q` on `p`, i.e. the `πβq` term of the normal equation
//! `PV∫ p(t)/(x − t) dt − πβ q(x) = πE* x/(2R)` (same sign conventions as (0.1)). A solver that
//! models both elastic bodies (e.g. a two-body BEM) retains it, and then `c/a` depends on β and μ
//! separately; the change is O(βμ) and not small for large βμ. Coupled incremental computations
//! (development only, Python: a staggered and a monolithic active-set solver, 400 resp. 200
//! elements per half grid, `c/a` resolution ≈ ±0.005; no closed form derived):
//!
//! | β   | μ      | β/μ   | coupled c/a | uncoupled (this fn) |
//! |-----|--------|-------|-------------|---------------------|
//! | 0.1 | 0.1    | 1     | 0.699       | 0.707               |
//! | 0.3 | 0.3    | 1     | 0.645       | 0.707               |
//! | 0.5 | 0.5    | 1     | 0.522 (0.520 monolithic) | 0.707  |
//! | 0.2 | 0.4    | 0.5   | 0.976       | 0.985               |
//! | 0.3 | 0.15   | 2     | 0.145       | 0.172               |
//! | 0.5 | 1.0    | 0.5   | 0.889 (0.888) | 0.985             |
//! | 0.5 | 0.7874 | 0.635 | 0.803 (0.807) | 0.945             |
//! | 0.5 | 0.5624 | 0.889 | 0.607       | 0.791               |
//! | 0.5 | 0.338  | 1.48  | 0.245       | 0.377               |
//! | 0.5 | 0.25   | 2     | 0.099       | 0.172               |
//!
//! The team's reference values (0.5 → 0.83, 0.635 → 0.76, 0.889 → 0.61, 1 → 0.52, 1.48 → 0.25,
//! 2 → 0.10) are **not** the β/μ-only (Goodman) result — they are 0.07–0.19 below it. For
//! β/μ ≥ 0.889 they coincide (±0.005) with the *coupled* problem at |β| = 0.5 (e.g. a rigid
//! cylinder on a ν = 0 half-plane), but at β/μ = 0.5 and 0.635 they match neither (coupled β = 0.5
//! gives 0.889 and 0.803). Their provenance remains unverified.
//!
//! *Slip direction:* with β > 0 (body 1 more compliant in the (1−2ν)/G sense, e.g. an elastic
//! cylinder, body 1, on a rigid flat with ν < 1/2) body 1's surface slips **inwards** (towards the
//! centre) relative to body 2 in the slip zones, and the friction on body 1 points **outwards**:
//! `q = sgn(β) sgn(x) μ p` on body 1 for c < |x| < a (and `−q` on body 2). For a rigid cylinder
//! (body 1) on an elastic half-plane β < 0: the half-plane surface slips inwards, the traction on
//! it is outwards.
//!
//! # 6. Subsurface stresses, McEwen (1949) ([`mcewen_normal`], [`mcewen_tangential`], [`mcewen_sliding`])
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
//!
//! # 7. Diametrally compressed disk
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
//!
//! # Sources
//!
//! K.L. Johnson, *Contact Mechanics*, CUP 1985 (ch. 2, §4.2, §7.1–7.3, §8.2, and the treatment of
//! Spence's problem in ch. 5); D.A. Hills, D. Nowell, A. Sackfield, *Mechanics of Elastic Contacts*,
//! 1993; C. Cattaneo 1938; R.D. Mindlin 1949; R.D. Mindlin & H. Deresiewicz 1953; F.W. Carter 1926;
//! D.A. Spence, J. Elasticity 5 (1975) 297–319; E. McEwen, Phil. Mag. 40 (1949) 454–459;
//! S.P. Timoshenko & J.N. Goodier, *Theory of Elasticity*, 3rd ed. §41; G. Hondros, Aust. J. Appl.
//! Sci. 10 (1959) 243–268; J. Dundurs 1969; J.M. & P.B. Borwein, *Pi and the AGM* (singular moduli).
//! Section/equation numbers are quoted from memory of the standard texts; every formula here is
//! independently re-derived or numerically verified in the tests.

use std::f64::consts::{FRAC_PI_2, PI};
use std::ops::Add;

// ------------------------------------------------------------------------------------------------
// Small private helpers
// ------------------------------------------------------------------------------------------------

/// `√(c² − x²)` for |x| < c, else 0 (computed as (c − x)(c + x) for accuracy near the ends).
fn semi(x: f64, c: f64) -> f64 {
    if x.abs() < c {
        ((c - x) * (c + x)).sqrt()
    } else {
        0.0
    }
}

/// `γ ln γ`, continuous at 0.
fn xlogx(g: f64) -> f64 {
    if g > 0.0 {
        g * g.ln()
    } else {
        0.0
    }
}

/// Arithmetic–geometric mean.
fn agm(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..64 {
        if (a - b).abs() <= 1e-16 * a.abs() {
            break;
        }
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
    }
    0.5 * (a + b)
}

/// Complete elliptic integral of the first kind K(k) (modulus k, not parameter m = k²).
pub fn elliptic_k(k: f64) -> f64 {
    let kp = ((1.0 - k) * (1.0 + k)).sqrt();
    FRAC_PI_2 / agm(1.0, kp)
}

// ------------------------------------------------------------------------------------------------
// Materials and Hertz
// ------------------------------------------------------------------------------------------------

/// Plane-strain contact modulus `E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹`.
/// Pass `f64::INFINITY` for a rigid body (elastic body on a rigid flat: `E* = E/(1 − ν²)`).
pub fn contact_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    let c = |e: f64, nu: f64| if e.is_infinite() { 0.0 } else { (1.0 - nu * nu) / e };
    1.0 / (c(e1, nu1) + c(e2, nu2))
}

/// Dundurs' β for plane strain, body 1 first:
/// `β = [(1 − 2ν1)/G1 − (1 − 2ν2)/G2] / [2((1 − ν1)/G1 + (1 − ν2)/G2)]`, `G = E/(2(1 + ν))`.
/// `f64::INFINITY` marks a rigid body. Elastic body 1 on a rigid body 2: `β = (1 − 2ν)/(2(1 − ν)) > 0`.
pub fn dundurs_beta(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    let inv_g = |e: f64, nu: f64| if e.is_infinite() { 0.0 } else { 2.0 * (1.0 + nu) / e };
    let (k1, k2) = (inv_g(e1, nu1), inv_g(e2, nu2));
    ((1.0 - 2.0 * nu1) * k1 - (1.0 - 2.0 * nu2) * k2) / (2.0 * ((1.0 - nu1) * k1 + (1.0 - nu2) * k2))
}

/// 2D Hertz line contact, described by its half-width `a` and peak pressure `p0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hertz2D {
    /// Contact half-width.
    pub a: f64,
    /// Peak pressure.
    pub p0: f64,
}

impl Hertz2D {
    /// From half-width and peak pressure directly.
    pub fn new(a: f64, p0: f64) -> Self {
        Self { a, p0 }
    }
    /// From load per unit length `P`, effective radius `R` and contact modulus `E*`:
    /// `a² = 4PR/(πE*)`, `p0 = 2P/(πa)`.
    pub fn from_load(p: f64, r: f64, e_star: f64) -> Self {
        let a = (4.0 * p * r / (PI * e_star)).sqrt();
        Self { a, p0: 2.0 * p / (PI * a) }
    }
    /// Normal load per unit length `P = π a p0 / 2`.
    pub fn load(&self) -> f64 {
        0.5 * PI * self.a * self.p0
    }
    /// Effective radius consistent with `E*`: `R = a E*/(2 p0)`.
    pub fn radius(&self, e_star: f64) -> f64 {
        self.a * e_star / (2.0 * self.p0)
    }
    /// Hertz pressure `p(x) = p0 √(1 − x²/a²)` (0 outside the contact).
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * semi(x, self.a) / self.a
    }
}

// ------------------------------------------------------------------------------------------------
// Cattaneo–Mindlin
// ------------------------------------------------------------------------------------------------

/// Cattaneo–Mindlin stick-zone ratio `c/a = √(1 − |Q|/(μP))` (0 at and beyond gross sliding).
pub fn cattaneo_c_over_a(q_over_mu_p: f64) -> f64 {
    (1.0 - q_over_mu_p.abs()).max(0.0).sqrt()
}

/// Cattaneo–Mindlin traction `q(x)` on the body for a tangential force `q_force = Q` applied after
/// the normal load (β = 0). Has the sign of `Q`; |Q| ≥ μP gives gross sliding `q = sgn(Q) μ p`.
pub fn cattaneo_traction(h: &Hertz2D, mu: f64, q_force: f64, x: f64) -> f64 {
    let c = h.a * cattaneo_c_over_a(q_force / (mu * h.load()));
    q_force.signum() * mu * h.p0 / h.a * (semi(x, h.a) - semi(x, c))
}

// ------------------------------------------------------------------------------------------------
// Mindlin–Deresiewicz (2D)
// ------------------------------------------------------------------------------------------------

/// Branch of the tangential load history at constant normal load (Mindlin–Deresiewicz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TangentialPath {
    /// First loading from `Q = 0` (either sign of `Q`, |Q| ≤ μP).
    Loading,
    /// Unloading from `+q_star` down to `Q ∈ [−q_star, q_star]` (0 ≤ q_star ≤ μP).
    Unloading {
        /// Turning-point force `Q* ≥ 0`.
        q_star: f64,
    },
    /// Reloading from `−q_star` up to `Q ∈ [−q_star, q_star]` (0 ≤ q_star ≤ μP).
    Reloading {
        /// Turning-point force magnitude `Q* ≥ 0`.
        q_star: f64,
    },
}

/// Superposition weights: `q(x) = (μ p0/a) Σ w_i √(c_i² − x²)₊`. The second entry is the stick
/// zone of the current branch.
fn md_terms(h: &Hertz2D, mu: f64, path: TangentialPath, q_force: f64) -> [(f64, f64); 3] {
    let mp = mu * h.load();
    let a = h.a;
    let c_of = |r: f64| a * (1.0 - r).max(0.0).sqrt();
    match path {
        TangentialPath::Loading => {
            let s = q_force.signum();
            [(s, a), (-s, c_of(q_force.abs() / mp)), (0.0, a)]
        }
        TangentialPath::Unloading { q_star } => {
            [(-1.0, a), (2.0, c_of((q_star - q_force) / (2.0 * mp))), (-1.0, c_of(q_star / mp))]
        }
        TangentialPath::Reloading { q_star } => {
            [(1.0, a), (-2.0, c_of((q_star + q_force) / (2.0 * mp))), (1.0, c_of(q_star / mp))]
        }
    }
}

/// Mindlin–Deresiewicz traction `q(x)` on the body at current force `q_force = Q` on the given
/// branch (β = 0, constant P). See module docs §3.
pub fn md_traction(h: &Hertz2D, mu: f64, path: TangentialPath, q_force: f64, x: f64) -> f64 {
    let k = mu * h.p0 / h.a;
    k * md_terms(h, mu, path, q_force).iter().map(|&(w, c)| w * semi(x, c)).sum::<f64>()
}

/// Half-width of the current stick zone (no slip increment) on the given branch: `c = a√(1 − |Q|/(μP))` (loading),
/// `c' = a√(1 − (Q* − Q)/(2μP))` (unloading), `c'' = a√(1 − (Q* + Q)/(2μP))` (reloading).
pub fn md_stick_half_width(h: &Hertz2D, mu: f64, path: TangentialPath, q_force: f64) -> f64 {
    md_terms(h, mu, path, q_force)[1].1
}

/// Tangential displacement `δ` of the stick zone (i.e. of the counter-body) relative to the
/// *log datum* of length `d_datum` (module docs §3), positive along `+x`:
/// `δ = −(μ p0/(a E*)) Σ w_i c_i² (ln(c_i/(2D)) − 1/2)`.
/// `e_star` is the contact modulus (for two elastic bodies: the relative displacement).
pub fn md_displacement(h: &Hertz2D, mu: f64, e_star: f64, d_datum: f64, path: TangentialPath, q_force: f64) -> f64 {
    let s: f64 = md_terms(h, mu, path, q_force)
        .iter()
        .map(|&(w, c)| if c > 0.0 { w * c * c * ((c / (2.0 * d_datum)).ln() - 0.5) } else { 0.0 })
        .sum();
    -mu * h.p0 / (h.a * e_star) * s
}

/// Same as [`md_displacement`] but through the explicit branch formulas of the module docs
/// (`λQ ± (μP/(πE*))[…]`); provided as a readable reference, identical up to rounding.
pub fn md_displacement_branches(
    h: &Hertz2D,
    mu: f64,
    e_star: f64,
    d_datum: f64,
    path: TangentialPath,
    q_force: f64,
) -> f64 {
    let mp = mu * h.load();
    let lambda = 2.0 / (PI * e_star) * ((2.0 * d_datum / h.a).ln() + 0.5);
    let k = mp / (PI * e_star);
    match path {
        TangentialPath::Loading => lambda * q_force + q_force.signum() * k * xlogx(1.0 - q_force.abs() / mp),
        TangentialPath::Unloading { q_star } => {
            let g1 = 1.0 - (q_star - q_force) / (2.0 * mp);
            lambda * q_force - k * (2.0 * xlogx(g1) - xlogx(1.0 - q_star / mp))
        }
        TangentialPath::Reloading { q_star } => {
            let g2 = 1.0 - (q_star + q_force) / (2.0 * mp);
            lambda * q_force + k * (2.0 * xlogx(g2) - xlogx(1.0 - q_star / mp))
        }
    }
}

/// Energy dissipated per full cycle `±Q*` at constant `P` (2D, β = 0), per unit length:
/// `W = (2μ²P²/(πE*)) [1 − γ*² + 2γ* ln γ*]`, `γ* = 1 − Q*/(μP)`. Independent of any datum.
/// Returns NaN unless `0 ≤ Q* ≤ μP`.
pub fn md_cycle_dissipation(mu: f64, p_load: f64, e_star: f64, q_star: f64) -> f64 {
    let mp = mu * p_load;
    if !(0.0..=mp).contains(&q_star) {
        return f64::NAN;
    }
    let g = 1.0 - q_star / mp;
    2.0 * mp * mp / (PI * e_star) * (1.0 - g * g + 2.0 * xlogx(g))
}

// ------------------------------------------------------------------------------------------------
// Carter
// ------------------------------------------------------------------------------------------------

/// Carter stick-zone ratio `c/a = √(1 − |Q|/(μP))` (stick zone `a − 2c < x < a`).
pub fn carter_c_over_a(q_over_mu_p: f64) -> f64 {
    cattaneo_c_over_a(q_over_mu_p)
}

/// Carter traction on the cylinder, rolling towards `+x`, total tangential force `Q` on the
/// cylinder (|Q| ≥ μP gives full slip `sgn(Q) μ p`). See module docs §4.
pub fn carter_traction(h: &Hertz2D, mu: f64, q_force: f64, x: f64) -> f64 {
    let c = h.a * carter_c_over_a(q_force / (mu * h.load()));
    let d = h.a - c;
    q_force.signum() * mu * h.p0 / h.a * (semi(x, h.a) - semi(x - d, c))
}

/// Carter creepage `ξ = (V − ΩR)/V` for the force `Q` on the cylinder (|Q| ≤ μP):
/// `ξ = −sgn(Q) (μa/R)(1 − √(1 − |Q|/(μP)))`. `r` is the (effective) radius.
pub fn carter_creepage(h: &Hertz2D, mu: f64, r: f64, q_force: f64) -> f64 {
    let k = carter_c_over_a(q_force / (mu * h.load()));
    -q_force.signum() * mu * h.a / r * (1.0 - k)
}

/// Inverse creepage–force law: `Q = −sgn(ξ) μP [1 − (1 − |ξ|R/(μa))²]`, saturating at
/// `Q = −sgn(ξ) μP` for `|ξ| ≥ μa/R` (full slip).
pub fn carter_force(h: &Hertz2D, mu: f64, r: f64, xi: f64) -> f64 {
    if xi == 0.0 {
        return 0.0;
    }
    let s = (xi.abs() * r / (mu * h.a)).min(1.0);
    -xi.signum() * mu * h.load() * (1.0 - (1.0 - s) * (1.0 - s))
}

/// Carter slip `s(x) = ξ − ∂u_x/∂x` (slip velocity of the cylinder surface relative to the flat,
/// divided by the rolling speed) for |x| ≤ a: 0 in the stick zone, `−sgn(Q)(μ/R)√((x − d)² − c²)`
/// in the slip zone. NaN outside the contact.
pub fn carter_slip(h: &Hertz2D, mu: f64, r: f64, q_force: f64, x: f64) -> f64 {
    if x.abs() > h.a {
        return f64::NAN;
    }
    let c = h.a * carter_c_over_a(q_force / (mu * h.load()));
    let d = h.a - c;
    if x >= h.a - 2.0 * c {
        0.0
    } else {
        let y = x - d;
        -q_force.signum() * mu / r * ((y - c) * (y + c)).max(0.0).sqrt()
    }
}

// ------------------------------------------------------------------------------------------------
// Spence
// ------------------------------------------------------------------------------------------------

/// Jacobi theta sums for nome `q < 1`: returns `(Σ_{n≥0} q^{n(n+1)}, θ3(q), θ4(q))`, so that
/// `θ2(q) = 2 q^{1/4} Σ_{n≥0} q^{n(n+1)}`.
fn theta_sums(q: f64) -> (f64, f64, f64) {
    let (mut s2, mut t3, mut t4) = (1.0, 1.0, 1.0);
    for n in 1..40 {
        let nf = n as f64;
        let e2 = q.powf(nf * (nf + 1.0));
        let e3 = q.powf(nf * nf);
        s2 += e2;
        t3 += 2.0 * e3;
        t4 += if n % 2 == 0 { 2.0 * e3 } else { -2.0 * e3 };
        if e3 < 1e-18 {
            break;
        }
    }
    (s2, t3, t4)
}

/// Spence (1975) central stick-zone ratio `c/a` for monotonic normal loading of a 2D Hertz contact
/// with Dundurs β ≠ 0 and friction μ (Hertzian pressure assumed): the root of
/// `K(√(1 − k²))/K(k) = |β|/μ`, evaluated as `k = θ₂²/θ₃²` at nome `exp(−π|β|/μ)` (or
/// `θ₄²/θ₃²` at nome `exp(−πμ/|β|)` for |β|/μ < 1). `c/a = 1` for β = 0, → 0 as β/μ → ∞.
pub fn spence_c_over_a(beta_over_mu: f64) -> f64 {
    let b = beta_over_mu.abs();
    if b == 0.0 {
        return 1.0;
    }
    if !b.is_finite() {
        return 0.0;
    }
    if b >= 1.0 {
        let q = (-PI * b).exp();
        let (s2, t3, _) = theta_sums(q);
        let r = 2.0 * q.powf(0.25) * s2 / t3;
        r * r
    } else {
        let q = (-PI / b).exp();
        let (_, t3, t4) = theta_sums(q);
        let r = t4 / t3;
        r * r
    }
}

/// Inverse of [`spence_c_over_a`]: `|β|/μ = K(k')/K(k) = AGM(1, k')/AGM(1, k)` for `k = c/a`.
pub fn spence_beta_over_mu(c_over_a: f64) -> f64 {
    let k = c_over_a;
    let kp = ((1.0 - k) * (1.0 + k)).sqrt();
    agm(1.0, kp) / agm(1.0, k)
}

// ------------------------------------------------------------------------------------------------
// Stress fields
// ------------------------------------------------------------------------------------------------

/// In-plane Cartesian stress components, tension positive. For half-plane fields the second axis is
/// the depth `z`: `yy` = σ_zz, `xy` = τ_xz. For the disk it is `y`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stress2D {
    /// σ_xx.
    pub xx: f64,
    /// σ_yy (σ_zz for half-plane fields).
    pub yy: f64,
    /// τ_xy (τ_xz for half-plane fields).
    pub xy: f64,
}

impl Add for Stress2D {
    type Output = Stress2D;
    fn add(self, o: Stress2D) -> Stress2D {
        Stress2D { xx: self.xx + o.xx, yy: self.yy + o.yy, xy: self.xy + o.xy }
    }
}

impl Stress2D {
    /// Multiply all components by `k`.
    pub fn scale(self, k: f64) -> Stress2D {
        Stress2D { xx: k * self.xx, yy: k * self.yy, xy: k * self.xy }
    }
    /// In-plane principal shear `τ1 = √(((σ_xx − σ_yy)/2)² + τ_xy²)`.
    pub fn principal_shear(&self) -> f64 {
        (0.5 * (self.xx - self.yy)).hypot(self.xy)
    }
    /// In-plane principal stresses `(σ1, σ2)`, σ1 ≥ σ2.
    pub fn principal(&self) -> (f64, f64) {
        let m = 0.5 * (self.xx + self.yy);
        let t = self.principal_shear();
        (m + t, m - t)
    }
    /// Von Mises equivalent stress in plane strain, out-of-plane stress `σ_33 = ν(σ_xx + σ_yy)`:
    /// `√(½[(σxx − σyy)² + (σyy − σ33)² + (σ33 − σxx)²] + 3τxy²)`.
    pub fn von_mises_plane_strain(&self, nu: f64) -> f64 {
        let s3 = nu * (self.xx + self.yy);
        let (a, b, c) = (self.xx - self.yy, self.yy - s3, s3 - self.xx);
        (0.5 * (a * a + b * b + c * c) + 3.0 * self.xy * self.xy).sqrt()
    }
}

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

// ------------------------------------------------------------------------------------------------
// Disk
// ------------------------------------------------------------------------------------------------

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

// ================================================================================================
// Tests. Every expected value states its origin. The numerical helpers below (tanh–sinh
// quadrature, principal-value Hilbert transform, log potential, finite differences, a dense
// Cholesky solver and an incremental frictional half-plane solver) are independent of the closed
// forms above and are part of the deliverable.
// ================================================================================================
#[cfg(test)]
mod tests {
    use super::*;

    // -------------------------------------------------------------------------------------------
    // Numerical helpers
    // -------------------------------------------------------------------------------------------

    /// Tanh–sinh (double-exponential) quadrature of `f` over `[a, b]`; never evaluates `f` at the
    /// end points, so integrable end-point singularities (log, inverse square root) are fine.
    /// Stops when two successive levels differ by at most `max(rel·|I|, abs)`.
    fn tanh_sinh(f: &dyn Fn(f64) -> f64, a: f64, b: f64, rel: f64, abs: f64) -> f64 {
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
    fn quad(f: &dyn Fn(f64) -> f64, pts: &[f64], rel: f64, abs: f64) -> f64 {
        let mut p: Vec<f64> = pts.to_vec();
        p.sort_by(|a, b| a.partial_cmp(b).unwrap());
        p.dedup_by(|a, b| (*a - *b).abs() < 1e-14);
        p.windows(2).map(|w| tanh_sinh(f, w[0], w[1], rel, abs)).sum()
    }

    /// Principal value `PV∫_{−a}^{a} q(t)/(x − t) dt` for |x| < a by subtraction of `q(x)`.
    fn hilbert(q: &dyn Fn(f64) -> f64, x: f64, a: f64, kinks: &[f64]) -> f64 {
        let qx = q(x);
        let g = |t: f64| (q(t) - qx) / (x - t);
        let mut pts = vec![-a, x, a];
        pts.extend(kinks.iter().copied().filter(|k| k.abs() < a));
        quad(&g, &pts, 1e-13, 1e-16) + qx * ((a + x) / (a - x)).ln()
    }

    /// Log potential `∫_{−a}^{a} q(t) ln(|x − t|/d) dt` (surface displacement kernel).
    fn log_potential(q: &dyn Fn(f64) -> f64, x: f64, d: f64, a: f64, kinks: &[f64]) -> f64 {
        let g = |t: f64| if t == x { 0.0 } else { q(t) * ((x - t).abs() / d).ln() };
        let mut pts = vec![-a, a];
        pts.extend(kinks.iter().copied().filter(|k| k.abs() < a));
        if x.abs() < a {
            pts.push(x);
        }
        quad(&g, &pts, 1e-13, 1e-16)
    }

    /// Fourth-order central difference.
    fn d4(f: &dyn Fn(f64) -> f64, x: f64, h: f64) -> f64 {
        (-f(x + 2.0 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2.0 * h)) / (12.0 * h)
    }

    /// Fourth-order second difference.
    fn d4_2(f: &dyn Fn(f64) -> f64, x: f64, h: f64) -> f64 {
        (-f(x + 2.0 * h) + 16.0 * f(x + h) - 30.0 * f(x) + 16.0 * f(x - h) - f(x - 2.0 * h)) / (12.0 * h * h)
    }

    /// Solve the SPD system `m x = rhs` (row-major `n × n`) by Cholesky.
    fn cholesky_solve(m: &[f64], n: usize, rhs: &[f64]) -> Vec<f64> {
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

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    // -------------------------------------------------------------------------------------------
    // Hertz, materials
    // -------------------------------------------------------------------------------------------

    #[test]
    fn hertz_relations() {
        // Expected: definitions a² = 4PR/(πE*), p0 = 2P/(πa); ∫p dx = P by quadrature.
        let (p, r, e) = (1234.0, 0.05, 2.1e11 / (1.0 - 0.09));
        let h = Hertz2D::from_load(p, r, e);
        assert!(close(h.a * h.a, 4.0 * p * r / (PI * e), 1e-15 * h.a * h.a));
        assert!(close(h.load(), p, 1e-12 * p));
        assert!(close(h.radius(e), r, 1e-12 * r));
        let total = quad(&|x| h.pressure(x), &[-h.a, h.a], 1e-13, 0.0);
        assert!(close(total, p, 1e-12 * p), "∫p = {total}");
    }

    #[test]
    fn material_parameters() {
        // Expected: Dundurs (1969) limits; E* = E/(1 − ν²) on a rigid flat.
        let (e, nu) = (200e9, 0.3);
        assert!(close(contact_modulus(e, nu, f64::INFINITY, 0.0), e / (1.0 - nu * nu), 1e-3));
        assert!(close(contact_modulus(e, nu, e, nu), 0.5 * e / (1.0 - nu * nu), 1e-3));
        assert!(dundurs_beta(e, nu, e, nu).abs() < 1e-15);
        let b = dundurs_beta(e, nu, f64::INFINITY, 0.0);
        assert!(close(b, (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)), 1e-15));
        assert!(dundurs_beta(e, 0.5, f64::INFINITY, 0.0).abs() < 1e-15);
        assert!(close(dundurs_beta(70e9, 0.33, e, nu), -dundurs_beta(e, nu, 70e9, 0.33), 1e-15));
    }

    #[test]
    fn elliptic_k_values() {
        // Expected: K(0) = π/2; K(1/√2) = Γ(1/4)²/(4√π) = 1.854074677301372 (A&S 17.3);
        // and K(k) by direct quadrature of ∫dθ/√(1 − k²sin²θ).
        assert!(close(elliptic_k(0.0), FRAC_PI_2, 1e-15));
        assert!(close(elliptic_k(0.5f64.sqrt()), 1.854_074_677_301_372, 1e-14));
        for k in [0.1, 0.5, 0.9, 0.999] {
            let kq = quad(&|t: f64| 1.0 / (1.0 - (k * t.sin()).powi(2)).sqrt(), &[0.0, FRAC_PI_2], 1e-14, 0.0);
            assert!(close(elliptic_k(k), kq, 1e-13 * kq));
        }
    }

    // -------------------------------------------------------------------------------------------
    // Compliance sign: McEwen surface stress ↔ Hilbert-transform kernel
    // -------------------------------------------------------------------------------------------

    #[test]
    fn surface_strain_from_mcewen_matches_compliance_kernel() {
        // Expected: at the surface, for pure tangential q, σ_xx = −(2/π) PV∫ q/(x − t) dt (Flamant),
        // so ε_xx = ((1 − ν²)/E) σ_xx = −(2(1 − ν²)/(πE)) PV∫ q/(x − t) dt: the compliance kernel
        // used for M–D and Carter. Hilbert transform by independent quadrature.
        let h = Hertz2D::new(1.0, 1.0);
        let q0 = 0.7;
        let q = |t: f64| q0 * semi(t, h.a) / h.a;
        for x in [-0.9, -0.31, 0.05, 0.5, 0.97] {
            let hq = hilbert(&q, x, h.a, &[]);
            let s = mcewen_tangential(&h, q0, x, 0.0);
            assert!(close(s.xx, -2.0 / PI * hq, 1e-12), "x={x}: {} vs {}", s.xx, -2.0 / PI * hq);
        }
        for x in [-2.0, 1.3, 3.0] {
            let hq = quad(&|t| q(t) / (x - t), &[-h.a, h.a], 1e-13, 0.0);
            let s = mcewen_tangential(&h, q0, x, 0.0);
            assert!(close(s.xx, -2.0 / PI * hq, 1e-12));
        }
    }

    // -------------------------------------------------------------------------------------------
    // Cattaneo–Mindlin
    // -------------------------------------------------------------------------------------------

    #[test]
    fn cattaneo_resultant_bounds_and_rigid_stick_zone() {
        // Expected: ∫q = Q, |q| ≤ μp, and — independently, via the log kernel — the stick zone
        // displaces rigidly (slip u(x) − u(0) = 0 for |x| < c) while the slip zone slips against q.
        let (e_star, mu) = (1.0, 0.3);
        let h = Hertz2D::from_load(1.0, 1.0, e_star);
        let mp = mu * h.load();
        for ratio in [0.3, 0.8, -0.5] {
            let qf = ratio * mp;
            let c = h.a * cattaneo_c_over_a(ratio);
            let q = |t: f64| cattaneo_traction(&h, mu, qf, t);
            let total = quad(&q, &[-h.a, -c, c, h.a], 1e-13, 0.0);
            assert!(close(total, qf, 1e-11 * mp), "∫q = {total} vs Q = {qf}");
            let u = |x: f64| -2.0 / (PI * e_star) * log_potential(&q, x, 1.0, h.a, &[-c, c]);
            let u0 = u(0.0);
            for i in 0..40 {
                let x = -h.a + (i as f64 + 0.5) * 2.0 * h.a / 40.0;
                let qx = q(x);
                assert!(qx.abs() <= mu * h.pressure(x) * (1.0 + 1e-12));
                let s = u(x) - u0;
                if x.abs() < c {
                    assert!(s.abs() < 1e-12, "stick slip {s} at x={x}");
                } else {
                    assert!(close(qx, qf.signum() * mu * h.pressure(x), 1e-14));
                    assert!(s * qx < 0.0, "slip must oppose friction, x={x}");
                }
            }
        }
    }

    // -------------------------------------------------------------------------------------------
    // Mindlin–Deresiewicz
    // -------------------------------------------------------------------------------------------

    fn md_setup() -> (Hertz2D, f64, f64) {
        let e_star = 1.0;
        (Hertz2D::from_load(1.0, 1.0, e_star), 0.4, e_star)
    }

    #[test]
    fn md_branches_are_consistent() {
        // Expected: continuity at the turning points, ∫q = Q (quadrature), |q| ≤ μp, and the two
        // displacement implementations agree.
        let (h, mu, e) = md_setup();
        let mp = mu * h.load();
        let qs = 0.7 * mp;
        let (un, re) = (TangentialPath::Unloading { q_star: qs }, TangentialPath::Reloading { q_star: qs });
        for i in 0..=20 {
            let x = -h.a + i as f64 * h.a / 10.0;
            let l = md_traction(&h, mu, TangentialPath::Loading, qs, x);
            assert!(close(md_traction(&h, mu, un, qs, x), l, 1e-15));
            assert!(close(md_traction(&h, mu, un, -qs, x), -l, 1e-15));
            assert!(close(md_traction(&h, mu, re, qs, x), l, 1e-15));
            assert!(close(md_traction(&h, mu, re, -qs, x), -l, 1e-15));
        }
        for path in [TangentialPath::Loading, un, re] {
            for r in [-0.6, -0.2, 0.1, 0.5] {
                let qf = r * mp;
                let c2 = md_stick_half_width(&h, mu, path, qf);
                let cs = h.a * (1.0f64 - 0.7).sqrt();
                let q = |t: f64| md_traction(&h, mu, path, qf, t);
                let total = quad(&q, &[-h.a, -c2, -cs, cs, c2, h.a], 1e-13, 0.0);
                assert!(close(total, qf, 1e-11 * mp), "{path:?} Q={qf}: ∫q = {total}");
                for i in 0..=40 {
                    let x = -h.a + i as f64 * h.a / 20.0;
                    assert!(q(x).abs() <= mu * h.pressure(x) * (1.0 + 1e-12) + 1e-15);
                }
                for d in [0.7, 3.0, 40.0] {
                    let a1 = md_displacement(&h, mu, e, d, path, qf);
                    let a2 = md_displacement_branches(&h, mu, e, d, path, qf);
                    assert!(close(a1, a2, 1e-13), "{a1} vs {a2}");
                }
            }
        }
    }

    #[test]
    fn md_displacement_matches_log_kernel_and_stick_is_rigid() {
        // Expected: δ = −(2/(πE*)) ∫ q(t) ln(|x_s − t|/D) dt at any stick point x_s, computed by
        // quadrature of the tractions (independent of the closed-form potentials). Also the slip
        // increment between two states of a branch vanishes in the current stick zone and opposes
        // the friction in the slip zone (unloading: q = −μp there, slip increment > 0).
        let (h, mu, e) = md_setup();
        let mp = mu * h.load();
        let qs = 0.8 * mp;
        let cs = h.a * (1.0f64 - 0.8).sqrt();
        let paths = [
            TangentialPath::Loading,
            TangentialPath::Unloading { q_star: qs },
            TangentialPath::Reloading { q_star: qs },
        ];
        let d = 5.0;
        for path in paths {
            for r in [-0.7, -0.3, 0.2, 0.6] {
                let qf = r * mp;
                let c2 = md_stick_half_width(&h, mu, path, qf);
                let q = |t: f64| md_traction(&h, mu, path, qf, t);
                let kinks = [-c2, c2, -cs, cs];
                // points that never slipped: |x| < min(c2, c*) (M–D: the zone c* < |x| < c' is
                // stuck now but carries the slip frozen during loading)
                for xs in [0.0, 0.5 * c2.min(cs)] {
                    let num = -2.0 / (PI * e) * log_potential(&q, xs, d, h.a, &kinks);
                    let cf = md_displacement(&h, mu, e, d, path, qf);
                    assert!(close(num, cf, 1e-11 * cf.abs().max(1e-3)), "{path:?} Q={qf} xs={xs}: {num} vs {cf}");
                }
            }
        }
        // slip increment during unloading from Q = 0.2 μP to Q = 0.1 μP
        let un = TangentialPath::Unloading { q_star: qs };
        let slip = |qf: f64, x: f64| {
            let c2 = md_stick_half_width(&h, mu, un, qf);
            let q = |t: f64| md_traction(&h, mu, un, qf, t);
            let k = [-c2, c2, -cs, cs];
            -2.0 / (PI * e) * (log_potential(&q, x, 1.0, h.a, &k) - log_potential(&q, 0.0, 1.0, h.a, &k))
        };
        let (q1, q2) = (0.2 * mp, 0.1 * mp);
        let c_new = md_stick_half_width(&h, mu, un, q2);
        for i in 0..30 {
            let x = (i as f64 + 0.5) * h.a / 30.0;
            let ds = slip(q2, x) - slip(q1, x);
            if x < c_new {
                assert!(ds.abs() < 1e-12, "stick zone slipped {ds} at {x}");
            } else {
                assert!(ds > 0.0 && md_traction(&h, mu, un, q2, x) < 0.0, "x={x}, ds={ds}");
            }
        }
    }

    /// Slip rate dṡ/dQ (body relative to the stick zone) at `x`, from the traction *rate* through
    /// the log kernel: only the moving semi-ellipse `w₂ f(x; c₂(Q))` changes with Q, and
    /// `d√(c₂² − t²)/dQ = c₂ c₂'(Q)/√(c₂² − t²)`; `c₂'(Q)` by central difference, `t = c₂ sin θ`.
    fn md_slip_rate(h: &Hertz2D, mu: f64, e_star: f64, path: TangentialPath, qf: f64, x: f64) -> f64 {
        let (w2, c2) = md_terms(h, mu, path, qf)[1];
        let eps = 1e-5 * mu * h.load();
        let dc =
            (md_stick_half_width(h, mu, path, qf + eps) - md_stick_half_width(h, mu, path, qf - eps)) / (2.0 * eps);
        let kern = |th: f64| {
            let t = c2 * th.sin();
            if t == x || t == 0.0 {
                0.0
            } else {
                ((x - t).abs() / t.abs()).ln()
            }
        };
        let mut pts = vec![-FRAC_PI_2, 0.0, FRAC_PI_2];
        if x.abs() < c2 {
            pts.push((x / c2).asin());
        }
        let integral = quad(&kern, &pts, 1e-7, 1e-13);
        -(2.0 / (PI * e_star)) * (mu * h.p0 / h.a) * w2 * c2 * dc * integral
    }

    /// Frictional dissipation along one branch: ∫ dQ ∫ |q(x)| |∂s/∂Q(x)| dx. The x-integral runs
    /// over the current slip zone c₂ < |x| < a; that the stick zone |x| < c₂ does not slip
    /// (∂s/∂Q = 0) is asserted separately at sample points (a pure-noise integrand would defeat the
    /// adaptive stopping rule).
    fn md_branch_dissipation(h: &Hertz2D, mu: f64, e_star: f64, path: TangentialPath, q_star: f64) -> f64 {
        let inner = |qf: f64| {
            let c2 = md_stick_half_width(h, mu, path, qf);
            let g = |x: f64| md_traction(h, mu, path, qf, x).abs() * md_slip_rate(h, mu, e_star, path, qf, x).abs();
            2.0 * quad(&g, &[c2, h.a], 1e-7, 0.0)
        };
        quad(&inner, &[-q_star, q_star], 1e-7, 0.0)
    }

    #[test]
    fn md_loop_area_is_datum_independent_and_equals_dissipation() {
        // Expected: closed form W = (2μ²P²/(πE*))(1 − γ*² + 2γ* ln γ*), compared with
        // (i) the loop area ∮Q dδ = ∫(δ_unload − δ_reload) dQ by quadrature, for two datum lengths;
        // (ii) the frictional dissipation ∮∫|q||ds| with the slip rate derived from the traction
        // rate and the half-plane log kernel (independent of the δ formulas). Required ≤ 1e-6.
        let (h, mu, e) = md_setup();
        let p = h.load();
        for ratio in [0.3, 0.9] {
            let qs = ratio * mu * p;
            let w = md_cycle_dissipation(mu, p, e, qs);
            let un = TangentialPath::Unloading { q_star: qs };
            let re = TangentialPath::Reloading { q_star: qs };
            for d in [2.0 * h.a, 50.0 * h.a] {
                let loop_area = quad(
                    &|qf| md_displacement(&h, mu, e, d, un, qf) - md_displacement(&h, mu, e, d, re, qf),
                    &[-qs, qs],
                    1e-14,
                    0.0,
                );
                assert!(close(loop_area, w, 1e-10 * w), "D={d}: loop {loop_area} vs W {w}");
            }
            for path in [un, re] {
                for r in [-0.8, 0.0, 0.7] {
                    let qf = r * qs;
                    let c2 = md_stick_half_width(&h, mu, path, qf);
                    let rate_scale = 2.0 / (PI * PI * e);
                    for x in [0.0, 0.3 * c2, 0.9 * c2] {
                        let rate = md_slip_rate(&h, mu, e, path, qf, x);
                        assert!(rate.abs() < 1e-9 * rate_scale, "stick zone slips: {rate:e}");
                    }
                }
            }
            let diss = md_branch_dissipation(&h, mu, e, un, qs) + md_branch_dissipation(&h, mu, e, re, qs);
            let rel = (diss - w).abs() / w;
            eprintln!("M–D Q*/μP={ratio}: W={w:.12e}, dissipation={diss:.12e}, rel={rel:.2e}");
            assert!(rel < 1e-6, "Q*/μP={ratio}: dissipation {diss} vs W {w}, rel {rel:e}");
        }
    }

    #[test]
    fn md_dissipation_limits() {
        // Expected: small amplitude W ≈ 2Q*³/(3πE*μP) (series of the closed form); W(μP) = 2μ²P²/(πE*);
        // NaN outside 0 ≤ Q* ≤ μP.
        let (mu, p, e) = (0.5, 3.0, 2.0);
        let qs = 1e-3 * mu * p;
        let w = md_cycle_dissipation(mu, p, e, qs);
        let approx = 2.0 * qs.powi(3) / (3.0 * PI * e * mu * p);
        assert!(((w - approx) / approx).abs() < 2e-3);
        assert!(close(md_cycle_dissipation(mu, p, e, mu * p), 2.0 * (mu * p).powi(2) / (PI * e), 1e-14));
        assert!(md_cycle_dissipation(mu, p, e, 1.1 * mu * p).is_nan());
    }

    // -------------------------------------------------------------------------------------------
    // Carter
    // -------------------------------------------------------------------------------------------

    #[test]
    fn carter_resultant_and_creepage_law() {
        // Expected: ∫q = Q by quadrature; |ξ| = (μa/R)(1 − √(1 − |Q|/μP)) with sign opposite to Q
        // (module docs §4); inverse law round trip; saturation at |ξ| ≥ μa/R.
        let e = 1.0;
        let r = 1.0;
        let h = Hertz2D::from_load(1.0, r, e);
        let mu = 0.3;
        let mp = mu * h.load();
        for ratio in [-0.9, -0.4, 0.4, 0.9] {
            let qf = ratio * mp;
            let c = h.a * carter_c_over_a(ratio);
            let total = quad(&|x| carter_traction(&h, mu, qf, x), &[-h.a, h.a - 2.0 * c, h.a], 1e-13, 0.0);
            assert!(close(total, qf, 1e-11 * mp));
            let xi = carter_creepage(&h, mu, r, qf);
            assert!(xi * qf < 0.0);
            assert!(close(xi.abs(), mu * h.a / r * (1.0 - (1.0 - ratio.abs()).sqrt()), 1e-15));
            assert!(close(carter_force(&h, mu, r, xi), qf, 1e-13));
        }
        assert!(close(carter_force(&h, mu, r, 2.0 * mu * h.a / r), -mp, 1e-15));
        assert!(close(carter_force(&h, mu, r, -mu * h.a / r), mp, 1e-15));
    }

    /// Numerical slip `s = ξ + (2/(πE*)) PV∫ q/(x − t) dt` for a given traction.
    fn slip_numeric(q: &dyn Fn(f64) -> f64, xi: f64, e_star: f64, a: f64, kinks: &[f64], x: f64) -> f64 {
        xi + 2.0 / (PI * e_star) * hilbert(q, x, a, kinks)
    }

    #[test]
    fn carter_slip_from_hilbert_transform() {
        // Expected: s = 0 in the stick zone (to 1e-8 μa/R; achieved ~1e-13), s opposite to q in the
        // slip zone and equal to the closed form carter_slip. ∂u_x/∂x from the numerical Hilbert
        // transform of the Carter tractions, E* of the cylinder on a rigid flat.
        let (young, nu) = (210e9, 0.3);
        let e = contact_modulus(young, nu, f64::INFINITY, 0.0);
        let r = 0.46;
        let h = Hertz2D::from_load(1.0e5, r, e);
        let mu = 0.35;
        let mp = mu * h.load();
        let scale = mu * h.a / r;
        for ratio in [-0.95, -0.5, 0.2, 0.5, 0.95] {
            let qf = ratio * mp;
            let c = h.a * carter_c_over_a(ratio);
            let xi = carter_creepage(&h, mu, r, qf);
            let q = |t: f64| carter_traction(&h, mu, qf, t);
            let kinks = [h.a - 2.0 * c];
            let mut worst_stick: f64 = 0.0;
            for i in 0..50 {
                let x = -h.a + (i as f64 + 0.5) * 2.0 * h.a / 50.0;
                let s = slip_numeric(&q, xi, e, h.a, &kinks, x);
                if x > h.a - 2.0 * c {
                    worst_stick = worst_stick.max(s.abs() / scale);
                } else {
                    assert!(s * q(x) < 0.0, "slip must oppose friction at x={x}");
                    let sc = carter_slip(&h, mu, r, qf, x);
                    assert!(close(s, sc, 1e-9 * scale), "x={x}: {s} vs {sc}");
                }
            }
            eprintln!("Carter Q/μP={ratio}: max|s|/(μa/R) in stick = {worst_stick:.2e}");
            assert!(worst_stick < 1e-8, "ratio {ratio}: max |s|/(μa/R) in stick = {worst_stick:e}");
        }
    }

    #[test]
    fn carter_trailing_edge_stick_is_inadmissible() {
        // Expected: mirroring Carter's solution (stick zone at the trailing edge) and choosing ξ to
        // make s = 0 there gives, in the slip zone, s with the *same* sign as q — violating Coulomb.
        // This shows the leading-edge stick zone is forced by the convention s = ξ − ∂u_x/∂x.
        let e = 1.0;
        let h = Hertz2D::from_load(1.0, 1.0, e);
        let mu = 0.3;
        let qf = 0.5 * mu * h.load();
        let c = h.a * carter_c_over_a(0.5);
        let d = h.a - c;
        let q = |t: f64| mu * h.p0 / h.a * (semi(t, h.a) - semi(t + d, c));
        let kinks = [-h.a + 2.0 * c];
        let xs = -h.a + c; // centre of the mirrored stick zone
        let xi = -2.0 / (PI * e) * hilbert(&q, xs, h.a, &kinks);
        for frac in [0.05, 0.3, 0.6, 0.95] {
            let x = -h.a + 2.0 * c + frac * (2.0 * h.a - 2.0 * c);
            let s = slip_numeric(&q, xi, e, h.a, &kinks, x);
            assert!(s * q(x) > 0.0 && qf > 0.0, "expected inadmissible slip at x={x}");
        }
    }

    // -------------------------------------------------------------------------------------------
    // Spence
    // -------------------------------------------------------------------------------------------

    #[test]
    fn spence_closed_form_consistency() {
        // Expected: theta-function evaluation inverts K(k')/K(k) (AGM); singular moduli
        // k(1) = 1/√2, k(2) = 3 − 2√2 (Borwein & Borwein); k(1/b)² + k(b)² = 1; asymptotics.
        for b in [0.2, 0.3, 0.5, 0.635, 0.889, 0.999, 1.0, 1.001, 1.48, 2.0, 3.0, 6.0] {
            let k = spence_c_over_a(b);
            assert!(close(spence_beta_over_mu(k), b, 1e-12 * b.max(1.0)), "b={b}, k={k}");
            let kr = spence_c_over_a(1.0 / b);
            assert!(close(k * k + kr * kr, 1.0, 1e-14));
        }
        assert!(close(spence_c_over_a(1.0), 0.5f64.sqrt(), 1e-15));
        assert!(close(spence_c_over_a(2.0), 3.0 - 8f64.sqrt(), 1e-15));
        assert!(close(spence_c_over_a(-2.0), spence_c_over_a(2.0), 0.0));
        assert!(close(spence_c_over_a(0.0), 1.0, 0.0) && spence_c_over_a(f64::INFINITY) == 0.0);
        let b = 6.0;
        assert!(close(spence_c_over_a(b), 4.0 * (-PI * b / 2.0).exp(), 1e-6));
        let b = 0.2;
        assert!(close(1.0 - spence_c_over_a(b), 8.0 * (-PI / b).exp(), 1e-12));
        let mut last = 1.0;
        for i in 1..100 {
            let k = spence_c_over_a(0.05 * i as f64);
            assert!(k < last || k == 1.0, "not decreasing at {}", 0.05 * i as f64);
            last = k;
        }
    }

    #[test]
    fn spence_derived_equation_equals_elliptic_ratio() {
        // Expected: the stick/continuity conditions derived in the module docs give
        // β/μ = [π(1 − k') + L(k)/2 − 2M(k)]/(π K(k)); evaluated here by quadrature (L, M, K all by
        // tanh–sinh) and compared with K(k')/K(k).
        for k in [0.05f64, 0.2, 0.5, 0.7, 0.9, 0.99] {
            let kp = ((1.0 - k) * (1.0 + k)).sqrt();
            let l = 2.0
                * quad(
                    &|th: f64| {
                        let dd = (1.0 - (k * th.sin()).powi(2)).sqrt();
                        dd * 2.0 * ((dd + kp) / (k * th.cos())).ln()
                    },
                    &[0.0, FRAC_PI_2],
                    1e-14,
                    0.0,
                );
            let m = quad(
                &|th: f64| {
                    let t = k * th.sin();
                    let mm = (1.0 - t * t).sqrt();
                    t * t * (t / (1.0 + mm)).ln() / mm
                },
                &[0.0, FRAC_PI_2],
                1e-14,
                0.0,
            );
            let kk = quad(&|th: f64| 1.0 / (1.0 - (k * th.sin()).powi(2)).sqrt(), &[0.0, FRAC_PI_2], 1e-14, 0.0);
            let b = (PI * (1.0 - kp) + 0.5 * l - 2.0 * m) / (PI * kk);
            eprintln!("Spence identity k={k}: {b:.15} vs K'/K {:.15}", spence_beta_over_mu(k));
            assert!(close(b, spence_beta_over_mu(k), 1e-10 * b), "k={k}: {b} vs {}", spence_beta_over_mu(k));
        }
    }

    /// Incremental frictional half-plane solver for monotonic Hertz loading with Dundurs β
    /// (Hertzian pressure). Units 2/(πE*) = 1, μ = 1, p0 = a. Half grid of `n` elements on
    /// [0, 1] (q odd), piecewise-constant q, collocation at element centres. Relative displacement
    /// g = −[πβ ∫₀ˣ p + ∫ q ln|x − t| dt]. Each load step solves the incremental Coulomb problem by
    /// an active-set method (stick: g unchanged; slip: q = −μp sgn(Δg)). Returns (c/a, q).
    fn spence_incremental(n: usize, beta: f64, a_min: f64, ratio: f64) -> (f64, Vec<f64>) {
        let dx = 1.0 / n as f64;
        let x: Vec<f64> = (0..n).map(|i| (i as f64 + 0.5) * dx).collect();
        let anti = |u: f64| if u == 0.0 { 0.0 } else { u * u.abs().ln() - u };
        let iln = |x: f64, t0: f64, t1: f64| anti(x - t0) - anti(x - t1);
        let mut amat = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                let t0 = j as f64 * dx;
                amat[i * n + j] = -(iln(x[i], t0, t0 + dx) - iln(x[i], -t0 - dx, -t0));
            }
        }
        let pcum = |x: f64, a: f64| {
            let s = (x / a).clamp(-1.0, 1.0);
            0.5 * a * a * (s * (1.0 - s * s).sqrt() + s.asin())
        };
        let mut q = vec![0.0; n];
        let mut gold = vec![0.0; n];
        let mut stick = vec![true; n];
        let mut sgn = vec![1.0; n];
        let mut a = a_min;
        loop {
            let p: Vec<f64> =
                x.iter().map(|&xi| if xi < a { a * (1.0 - (xi / a).powi(2)).sqrt() } else { 0.0 }).collect();
            let s: Vec<f64> = x.iter().map(|&xi| -PI * beta * pcum(xi, a)).collect();
            let inc: Vec<bool> = x.iter().map(|&xi| xi < a).collect();
            let mut st: Vec<bool> = (0..n).map(|i| inc[i] && stick[i]).collect();
            let mut qn = vec![0.0; n];
            for _ in 0..200 {
                qn.iter_mut().for_each(|v| *v = 0.0);
                for i in 0..n {
                    if inc[i] && !st[i] {
                        qn[i] = sgn[i] * p[i];
                    }
                }
                let idx: Vec<usize> = (0..n).filter(|&i| st[i]).collect();
                if !idx.is_empty() {
                    let m = idx.len();
                    let mut sub = vec![0.0; m * m];
                    let mut rhs = vec![0.0; m];
                    for (r, &i) in idx.iter().enumerate() {
                        for (cc, &j) in idx.iter().enumerate() {
                            sub[r * m + cc] = amat[i * n + j];
                        }
                        let slip_part: f64 = (0..n).filter(|&j| !st[j]).map(|j| amat[i * n + j] * qn[j]).sum();
                        rhs[r] = -(s[i] - gold[i]) - slip_part;
                    }
                    let sol = cholesky_solve(&sub, m, &rhs);
                    for (r, &i) in idx.iter().enumerate() {
                        qn[i] = sol[r];
                    }
                }
                let mut changed = false;
                for i in 0..n {
                    if !inc[i] {
                        continue;
                    }
                    let dg = s[i] + (0..n).map(|j| amat[i * n + j] * qn[j]).sum::<f64>() - gold[i];
                    if st[i] && qn[i].abs() > p[i] * (1.0 + 1e-12) {
                        st[i] = false;
                        sgn[i] = qn[i].signum();
                        changed = true;
                    } else if !st[i] && sgn[i] * dg > 1e-15 {
                        st[i] = true;
                        changed = true;
                    }
                }
                if !changed {
                    break;
                }
            }
            q.clone_from(&qn);
            stick.clone_from(&st);
            for i in 0..n {
                gold[i] = s[i] + (0..n).map(|j| amat[i * n + j] * q[j]).sum::<f64>();
            }
            if a >= 1.0 {
                break;
            }
            a = (a * ratio).min(1.0);
        }
        let k = stick.iter().take_while(|&&b| b).count();
        (k as f64 * dx, q)
    }

    #[test]
    fn spence_incremental_solver_rust() {
        // Expected: spence_c_over_a within 0.02 (coarse grid: 120 elements per half contact, 0.0083a
        // resolution; the Python version of the same solver at 1000 elements agrees to ≤ 0.001,
        // see spence_high_resolution_table). Also the friction on body 1 points outwards for β > 0.
        for b in [1.0, 2.0] {
            let (c, q) = spence_incremental(120, b, 0.05, 1.01);
            let exact = spence_c_over_a(b);
            eprintln!("Spence incremental (Rust, n=120) β/μ={b}: {c:.4} vs {exact:.4}");
            assert!(close(c, exact, 0.02), "β/μ={b}: incremental {c} vs {exact}");
            assert!(q.iter().all(|&v| v >= 0.0) && q[100] > 0.0);
        }
    }

    #[test]
    fn spence_high_resolution_table() {
        // Expected: results of the independent incremental solver (Python/NumPy, same algorithm,
        // 2000 elements per half contact, load ratio 1.005 per step from a = 0.02), resolution
        // 0.0005a (1000 elements gave 0.985, 0.945, 0.792, 0.708, 0.377, 0.172, 0.036).
        let table =
            [(0.5, 0.985), (0.635, 0.945), (0.889, 0.792), (1.0, 0.7075), (1.48, 0.377), (2.0, 0.172), (3.0, 0.036)];
        for (b, c) in table {
            assert!(close(spence_c_over_a(b), c, 0.001), "β/μ={b}: {} vs {c}", spence_c_over_a(b));
        }
    }

    #[test]
    fn spence_team_reference_values_are_not_the_2d_result() {
        // Expected: the team's quoted values (±0.03) are inconsistent with the verified 2D
        // (Goodman-approximation) result; this test documents the discrepancy (each differs by more
        // than 0.06). For β/μ ≥ 0.889 they agree with the *coupled* problem at |β| = 0.5 (module docs).
        let quoted = [(0.5, 0.83), (0.635, 0.76), (0.889, 0.61), (1.0, 0.52), (1.48, 0.25), (2.0, 0.10)];
        for (b, c) in quoted {
            assert!((spence_c_over_a(b) - c).abs() > 0.06);
        }
    }

    // -------------------------------------------------------------------------------------------
    // McEwen
    // -------------------------------------------------------------------------------------------

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

    // -------------------------------------------------------------------------------------------
    // Disk
    // -------------------------------------------------------------------------------------------

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
