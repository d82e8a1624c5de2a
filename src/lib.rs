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
//! [`scene`] → [`source`] (the flexibility: [`mesh`] → [`bem`] assembly → condensation, [`source::bem_wheel`]) →
//! [`flexibility`] → [`formulation`] (the contact problem: LCP / QP, slip operator) → [`solvers`] (one trait, one
//! registry) → [`post`] (residuals, resultants, states) → [`checks`] (against [`references`], [`hertz`] and between
//! solvers) → [`results`] (the JSON document); with `[stresses]`, [`stresses`] evaluates the subsurface field of each
//! solved run. [`run`] is the pipeline for one scene; [`sweep`] and [`report`] run
//! many.
//!
//! ## Conventions
//! Per unit thickness, plane strain. x horizontal, y up, wheel centre at the origin, the flat is y = −R. Tractions
//! act on the wheel: pressure p = t_y ≥ 0, shear q = t_x. The support moves rigidly by an approach d_N (towards the
//! flat), a shift d_T (+x) and a rotation φ (counter-clockwise). Units are the user's, consistent; internally every
//! length is divided by L0 = 2R and every stress by E, so results do not depend on the unit of length.
#![forbid(unsafe_code)]
#![warn(missing_docs)]
// Index loops over 2×2 blocks and matrix rows read like the formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod admissible;
pub mod bem;
pub mod checks;
pub mod condition;
pub mod diagnostics;
pub mod error;
pub mod flexibility;
pub mod formulation;
pub mod halfplane;
pub mod hertz;
pub mod history;
pub mod io;
pub mod lcp_io;
pub mod lcp_residual;
pub mod material;
pub mod mesh;
pub mod plot;
pub mod plot_result;
pub mod post;
pub mod progress;
pub mod references;
pub mod report;
pub mod results;
pub mod run;
pub mod scene;
pub mod solvers;
pub mod source;
pub mod status;
pub mod stresses;
pub mod sweep;
pub mod theory;
pub mod tolerances;
pub mod validity;

pub use error::{Error, Result};
