//! The boundary element core: 2D plane-strain elastostatics with the Kelvin solution (seed eq. 13, `H u = G t`).
//!
//! Assembly visits every (source node, element) pair once and hands the 2×2 blocks of H and G to a
//! [`BlockSink`], so a caller can build the full matrices (tests, small problems) or write directly into the
//! rearranged system of the condensation ([`crate::condense`]) without storing H and G.
//!
//! H's diagonal blocks come from the rigid-body condition: a rigid translation of a bounded body produces no
//! traction, so each block row of H sums to zero: `H_ii = −Σ_{j≠i} H_ij` (Brebbia & Dominguez §5). This absorbs
//! the free term c_ij and the principal value of the singular T* integral.

pub mod constant;
pub mod kelvin;
pub mod quadratic;
pub mod quadrature;

use crate::mesh::{Mesh, Shape};
use kelvin::Kelvin;

/// Receiver of assembled blocks: `h[l][k]` and `g[l][k]` are added to rows `2·row + l`, columns `2·col + k` of H and
/// G. The same (row, col) pair may be delivered more than once (contributions add up).
pub trait BlockSink {
    /// Add one pair of 2×2 blocks.
    fn add(&mut self, row: usize, col: usize, h: &[[f64; 2]; 2], g: &[[f64; 2]; 2]);
}

/// Assemble H and G of `mesh` for the material `k` (in the mesh's units), delivering blocks to `sink`.
pub fn assemble<S: BlockSink>(mesh: &Mesh, k: &Kelvin, sink: &mut S) {
    let zero = [[0.0; 2]; 2];
    for (i, src) in mesh.nodes.iter().enumerate() {
        let mut hsum = [[0.0; 2]; 2];
        for (e, el) in mesh.elements.iter().enumerate() {
            match el.shape {
                Shape::Straight { a, b } => {
                    let own = src.element == e;
                    let (h, g) = constant::integrate(a, b, src.pos, own, k);
                    let j = el.first_node;
                    if !own {
                        acc(&mut hsum, &h);
                    }
                    sink.add(i, j, &h, &g);
                }
                Shape::Arc(arc) => {
                    let own = (src.element == e).then(|| i - el.first_node);
                    let (h, g) = quadratic::integrate(&arc, src.pos, own, k);
                    for (loc, (hj, gj)) in h.iter().zip(g.iter()).enumerate() {
                        let j = el.first_node + loc;
                        if j != i {
                            acc(&mut hsum, hj);
                        }
                        sink.add(i, j, hj, gj);
                    }
                }
            }
        }
        let diag = [[-hsum[0][0], -hsum[0][1]], [-hsum[1][0], -hsum[1][1]]];
        sink.add(i, i, &diag, &zero);
    }
}

#[inline]
fn acc(sum: &mut [[f64; 2]; 2], h: &[[f64; 2]; 2]) {
    for l in 0..2 {
        for m in 0..2 {
            sum[l][m] += h[l][m];
        }
    }
}

/// Full H and G matrices (2N × 2N, row-major `Vec`s are avoided: faer column-major matrices).
pub struct FullSystem {
    /// H: displacement influence matrix.
    pub h: faer::Mat<f64>,
    /// G: traction influence matrix.
    pub g: faer::Mat<f64>,
}

impl BlockSink for FullSystem {
    fn add(&mut self, row: usize, col: usize, h: &[[f64; 2]; 2], g: &[[f64; 2]; 2]) {
        for l in 0..2 {
            for m in 0..2 {
                self.h[(2 * row + l, 2 * col + m)] += h[l][m];
                self.g[(2 * row + l, 2 * col + m)] += g[l][m];
            }
        }
    }
}

/// Assemble the full H and G (for tests and small problems; the contact pipeline uses [`crate::condense`]).
pub fn assemble_full(mesh: &Mesh, k: &Kelvin) -> FullSystem {
    let n = 2 * mesh.n_nodes();
    let mut s = FullSystem { h: faer::Mat::zeros(n, n), g: faer::Mat::zeros(n, n) };
    assemble(mesh, k, &mut s);
    s
}
