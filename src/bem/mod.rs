//! The boundary element core: 2D plane-strain elastostatics with the Kelvin solution (seed eq. 13, `H u = G t`).
//!
//! Assembly visits every (source node, element) pair once and hands the 2×2 blocks of H and G to a sink (the
//! crate's `BlockSink`), so that [`assemble_full`] builds the full matrices (tests, small problems) and the
//! condensation ([`crate::source::bem_wheel`]) writes directly into its rearranged system without storing H and G.
//!
//! H's diagonal blocks come from the rigid-body condition: a rigid translation of a bounded body produces no
//! traction, so each block row of H sums to zero: `H_ii = −Σ_{j≠i} H_ij` (Brebbia & Dominguez §5). This absorbs
//! the free term c_ij and the principal value of the singular T* integral.

pub(crate) mod constant;
pub mod kelvin;
pub mod quadratic;
pub mod quadrature;
pub mod stress;

use crate::error::ArgumentError;
use crate::mesh::{Mesh, Shape};
use kelvin::Kelvin;

/// Receiver of assembled blocks: `h[l][k]` and `g[l][k]` are added to rows `2·row + l`, columns `2·col + k` of H and
/// G. The same (row, col) pair may be delivered more than once (contributions add up).
pub(crate) trait BlockSink {
    /// Add one pair of 2×2 blocks.
    fn add(&mut self, row: usize, col: usize, h: &[[f64; 2]; 2], g: &[[f64; 2]; 2]);

    /// Add a whole block column: `blocks[row]` for every source node `row` (default: one `add` per block; a sink
    /// writing into a column-major matrix can do better).
    fn add_column(&mut self, col: usize, blocks: &[Block]) {
        for (row, (h, g)) in blocks.iter().enumerate() {
            self.add(row, col, h, g);
        }
    }
}

/// A pair of 2×2 blocks (h, g).
pub(crate) type Block = ([[f64; 2]; 2], [[f64; 2]; 2]);

/// Assemble H and G of `mesh` for the material `k` (in the mesh's units), delivering blocks to `sink`. The mesh must
/// hold together ([`Mesh::check`]); the public entry points check it first.
pub(crate) fn assemble<S: BlockSink>(mesh: &Mesh, k: &Kelvin, sink: &mut S) {
    if mesh.elements.iter().all(|e| matches!(e.shape, Shape::Straight { .. })) {
        assemble_straight(mesh, k, sink);
        return;
    }
    // Elements outer, sources inner: a column-major sink receives contiguous columns.
    let zero = [[0.0; 2]; 2];
    let mut hsum = vec![[[0.0; 2]; 2]; mesh.nodes.len()];
    for (e, el) in mesh.elements.iter().enumerate() {
        for (i, src) in mesh.nodes.iter().enumerate() {
            match el.shape {
                Shape::Straight { a, b } => {
                    let own = src.element == e;
                    let (h, g) = constant::integrate(a, b, src.pos, own, k);
                    if !own {
                        acc(&mut hsum[i], &h);
                    }
                    sink.add(i, el.first_node, &h, &g);
                }
                Shape::Arc(arc) => {
                    let own = (src.element == e).then(|| i - el.first_node);
                    let (h, g) = quadratic::integrate(&arc, src.pos, own, k);
                    for (loc, (hj, gj)) in h.iter().zip(g.iter()).enumerate() {
                        let j = el.first_node + loc;
                        if j != i {
                            acc(&mut hsum[i], hj);
                        }
                        sink.add(i, j, hj, gj);
                    }
                }
            }
        }
    }
    for (i, hs) in hsum.iter().enumerate() {
        let diag = [[-hs[0][0], -hs[0][1]], [-hs[1][0], -hs[1][1]]];
        sink.add(i, i, &diag, &zero);
    }
}

/// Constant elements: the closed forms need `ln r²` at both vertices of every element; a vertex shared by two
/// consecutive elements is evaluated once per source. Elements are the outer loop so that a sink writing into a
/// column-major matrix writes contiguous columns; H's row sums are kept per source for the diagonal blocks.
fn assemble_straight<S: BlockSink>(mesh: &Mesh, k: &Kelvin, sink: &mut S) {
    let els: Vec<constant::Straight> = mesh
        .elements
        .iter()
        .map(|e| match e.shape {
            Shape::Straight { a, b } => constant::Straight::new(a, b),
            Shape::Arc(_) => unreachable!("checked by the caller"),
        })
        .collect();
    let nodes = &mesh.nodes;
    let ln_r2 = |v: [f64; 2], out: &mut Vec<f64>| {
        out.clear();
        out.extend(nodes.iter().map(|s| ((v[0] - s.pos[0]).powi(2) + (v[1] - s.pos[1]).powi(2)).ln()));
    };
    let zero = [[0.0; 2]; 2];
    let mut hsum = vec![[[0.0; 2]; 2]; nodes.len()];
    let (mut la, mut lb) = (Vec::new(), Vec::new());
    let mut col: Vec<Block> = vec![(zero, zero); nodes.len()];
    for (e, el) in els.iter().enumerate() {
        // ln r² at the start vertex: the previous element's end vertex when they coincide bit for bit.
        if e > 0 && els[e - 1].b == el.a {
            std::mem::swap(&mut la, &mut lb);
        } else {
            ln_r2(el.a, &mut la);
        }
        ln_r2(el.b, &mut lb);
        let j = mesh.elements[e].first_node;
        for (i, (src, c)) in nodes.iter().zip(col.iter_mut()).enumerate() {
            if src.element == e {
                *c = (zero, el.self_g(k));
                continue;
            }
            *c = el.integrate(src.pos, la[i], lb[i], k);
            acc(&mut hsum[i], &c.0);
        }
        sink.add_column(j, &col);
    }
    for (i, hs) in hsum.iter().enumerate() {
        let diag = [[-hs[0][0], -hs[0][1]], [-hs[1][0], -hs[1][1]]];
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

/// Full H and G matrices (2N × 2N, row-major `Vec`s are avoided: faer column-major matrices), as
/// [`assemble_full`] makes them.
#[non_exhaustive]
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

/// Assemble the full H and G (for tests and small problems; the contact pipeline uses [`crate::source::bem_wheel`]).
/// A mesh that does not hold together ([`Mesh::check`]) is refused.
pub fn assemble_full(mesh: &Mesh, k: &Kelvin) -> Result<FullSystem, ArgumentError> {
    mesh.check()?;
    let n = 2 * mesh.n_nodes();
    let mut s = FullSystem { h: faer::Mat::zeros(n, n), g: faer::Mat::zeros(n, n) };
    assemble(mesh, k, &mut s);
    Ok(s)
}
