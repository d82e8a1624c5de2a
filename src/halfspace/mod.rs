//! # The 3D body model `half_space`: two elastic half-spaces in contact on a rectangular grid
//!
//! Kalker's (and CONTACT's) three-dimensional discretisation of a concentrated contact: the potential contact area
//! is a uniform grid of `MX × MY` rectangles `DX × DY` placed where the user says; each element carries a
//! piecewise-constant pressure `p` and shear `(q_x, q_y)`, and displacements are collocated at the element centres.
//! The two bodies are elastic half-spaces (either may be rigid), so the influence of element `j` on the centre of
//! element `i` depends on the index offset `i − j` only: block-Toeplitz matrices, held as their kernels and applied
//! by 2D FFT ([`crate::toeplitz2d`]) in O(N log N) time and O(N) memory for N elements. No dense influence matrix
//! is formed above [`DENSE_LIMIT`] elements.
//!
//! The parts, each with its derivation and tests in its module docs:
//!
//! - [`kernel`]: the closed-form influence coefficients of a uniformly loaded rectangle (Boussinesq and Cerruti
//!   integrated; Love's rectangle), of one body or a pair through the pair's Dundurs-type constant, and the kernel
//!   of a uniform grid;
//! - [`ContactGrid`]: where the elements are (origin, sizes), and the element-centre coordinates;
//! - [`Influence`]: the FFT operators of a grid, built for only the effects asked for (the normal kernel alone for
//!   a frictionless problem; the tangential kernels on demand; the coupling kernels only when the pair's coupling
//!   constant is non-zero, so an identical pair never pays for them);
//! - [`normal`]: the frictionless normal problem (load or approach prescribed);
//! - [`tangential`]: a shift step of the tangential problem with memory, Coulomb's law on the disc exactly
//!   (Cattaneo–Mindlin, load paths);
//! - [`path`]: the typed 3D problem — bodies, grid, profile, friction, a path of steps — solving each step from the
//!   previous state, coupling the normal and tangential problems only for a dissimilar pair, with a status per
//!   step (a contact cut off by the grid's edge is not `Solved`);
//! - [`rolling`]: steady rolling with creepages and spin (Kalker's exact theory), the creepages or the force
//!   prescribed;
//! - [`subsurface`]: the stresses inside a half-space under the grid's tractions (closed form per element: Love's
//!   and Cerruti's rectangle), with von Mises and Tresca maxima;
//! - [`dense`]: the small-grid cross-checks with dense influence matrices: the normal problem by Lemke and by
//!   clarabel's QP, the tangential shift problem at given pressure on the Coulomb disc (clarabel, second-order
//!   cones) and on the inscribed k-facet pyramid (Lemke).
//!
//! Axes and signs are [`kernel`]'s: `z` into body 1, pressure positive in compression, displacements of body 1
//! relative to body 2 (slip along `x`, `y`; gap change along `z`, positive when the surfaces move apart). Grid
//! vectors are indexed `ix + MX·iy` (x fastest), i.e. arrays of shape `(MY, MX)` in row-major order.

pub mod dense;
pub mod kernel;
pub mod normal;
mod operator;
pub mod path;
pub mod rolling;
pub mod subsurface;
pub mod tangential;

pub use kernel::{Coefficients, Compliance, HalfSpace, KernelTable, UniformGrid};
pub use operator::{ContactGrid, Influence, Kernels, DENSE_LIMIT, PRECONDITIONER_FLOOR};
pub use path::{Path, PathSettings, PathStatus, Profile, Step, StepOutcome};
