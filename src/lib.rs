//! # rollbem
//!
//! Frictional contact of an elastic wheel (a cylinder in plane strain) on a rigid flat, by the boundary element
//! method and linear complementarity, after Addi, Antes & Stavroulakis ("On solving a rolling frictional contact
//! problem using BEM and Mathematical Programming"; "the seed" in these docs).
//!
//! ## The problem
//! The wheel's boundary is discretised with constant or discontinuous quadratic elements; the Kelvin solution gives
//! `H u = G t` (seed eq. 13). Condensing everything but the potential contact nodes gives the flexibility
//! `u_c = F t_c + R ρ` (eqs. 15–24), where ρ is the rigid motion of the wheel's support. With the initial gap
//! `g₀`, the frictionless contact problem is the linear complementarity problem
//!
//! ```text
//!   g = g₀ + F_NN p + R_N ρ ≥ 0,   p ≥ 0,   pᵀ g = 0
//! ```
//!
//! (plus equilibrium rows when a load rather than a displacement drives the support), solved by Lemke's algorithm
//! or, as a QP, by the clarabel interior-point solver.
//!
//! ## Pipeline (one module per stage)
//! [`scene`] (a validated scene: [`scene::Scene`]) → [`source`] (the flexibility: [`mesh`] → [`bem`] assembly →
//! condensation, [`source::bem_wheel`]; or the half-plane's closed forms) → [`flexibility`] → [`formulation`] (the
//! contact problem: LCP / QP, slip operator) → [`solvers`] (one trait, one registry) → [`post`] (residuals,
//! resultants, states) → [`checks`] (against [`references`], which poses [`theory`], and between solvers) →
//! [`results`] (the result document, its text and CSV renderings); with `[stresses]`, [`stresses`] evaluates the
//! subsurface field of each solved run. [`pipeline`] runs these stages: a [`pipeline::Model`] is built once per
//! scene and solved for many drives; [`sweep`] and [`report`] run many scenes.
//!
//! ## Use as a library
//! ```
//! use rollbem::pipeline::Model;
//! use rollbem::scene::Scene;
//! use rollbem::status::Status;
//! let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml");
//! let scene = Scene::from_file(&path).unwrap(); // parsed and validated: bad input is an `Err` naming the key
//! let model = Model::build(&scene).unwrap(); // the flexibility, built once
//! for load in [500.0, 1000.0, 2000.0] {
//!     // Another normal load on the same bodies and mesh: solved on the same model.
//!     let at = scene.edit(|d| d.drive.normal_load = Some(load)).unwrap();
//!     let report = model.solve(&at).unwrap();
//!     for run in &report.runs {
//!         assert_eq!(run.status, Status::Solved, "{}", run.explanation());
//!         let p = run.resultants.unwrap().normal;
//!         assert!((p - load).abs() < 1e-9 * load);
//!     }
//! }
//! ```
//!
//! ## Conventions
//! Per unit thickness, plane strain. x horizontal, y up, wheel centre at the origin, the flat is y = −R. Tractions
//! act on the wheel: pressure p = t_y ≥ 0, shear q = t_x. The support moves rigidly by an approach d_N (towards the
//! flat), a shift d_T (+x) and a rotation φ (counter-clockwise). Units are the user's, consistent; internally every
//! length is divided by L0 = 2R and every stress by E, so results do not depend on the unit of length.
#![forbid(unsafe_code)]
#![warn(missing_docs)]
// No public function panics on a value a caller can give: it returns an error instead (issue 31). With
// `-D warnings` this makes clippy refuse a public function with a reachable `assert!`, `unwrap`, `expect` or
// `panic!`; documenting the panic (a `# Panics` section) is not the fix: removing it is.
#![warn(clippy::missing_panics_doc)]
// Index loops over 2×2 blocks and matrix rows read like the formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod admissible;
pub mod bem;
pub mod cancel;
pub mod checks;
pub mod cli;
pub(crate) mod condition;
pub mod creeptable;
pub(crate) mod diagnostics;
pub mod error;
pub mod exit;
pub mod fastsim;
pub mod flexibility;
pub mod formulation;
pub mod halfplane;
pub mod halfspace;
pub(crate) mod io;
pub mod lcp_io;
pub mod lcp_residual;
pub(crate) mod lu;
pub mod material;
pub mod mesh;
pub mod pipeline;
pub mod plot;
pub mod post;
pub(crate) mod progress;
pub mod references;
pub mod report;
pub mod results;
pub mod scene;
pub mod solvers;
pub mod source;
pub mod status;
pub mod stresses;
pub mod sweep;
pub mod theory;
pub mod toeplitz;
pub mod toeplitz2d;
pub mod tolerances;
pub(crate) mod validity;
pub mod veldep;
pub mod viscoelastic;

pub use error::{Error, Result};
/// `rollbem plot` on a result document (JSON) or a CSV: part of [`report`], re-exported at the root.
pub use report::{plot_csv, plot_result};
