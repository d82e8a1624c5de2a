//! A scalar field sampled on a regular grid in a vertical section ([`Field`]) and its geometry: contour lines by
//! marching squares and the part of a cell above a level (the fill of a colour band).

use std::collections::BTreeMap;

/// A scalar field sampled at the nodes of a regular grid in a vertical section: x horizontal, depth downward.
///
/// Node `(ix, iz)` is at `x = x_range.0 + ix·(x_range.1 − x_range.0)/(nx − 1)` and
/// `depth = depth_range.0 + iz·(depth_range.1 − depth_range.0)/(nz − 1)`; its value is `values[iz * nx + ix]`
/// (row-major, one row per depth, row 0 the shallowest). Non-finite values mark missing data.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Number of nodes along x (at least 2).
    pub nx: usize,
    /// Number of nodes along depth (at least 2).
    pub nz: usize,
    /// `nx · nz` values, row-major: `values[iz * nx + ix]`.
    pub values: Vec<f64>,
    /// x of the first and last node column (first < last).
    pub x_range: (f64, f64),
    /// Depth of the first and last node row (first < last; depth grows downward on the map).
    pub depth_range: (f64, f64),
}

impl Field {
    /// A field from its values (row-major, `values[iz * nx + ix]`); checked when drawn.
    pub fn new(nx: usize, nz: usize, values: Vec<f64>, x_range: (f64, f64), depth_range: (f64, f64)) -> Field {
        Field { nx, nz, values, x_range, depth_range }
    }

    /// A field sampling `f(x, depth)` at the nodes.
    pub fn from_fn(
        nx: usize,
        nz: usize,
        x_range: (f64, f64),
        depth_range: (f64, f64),
        f: impl Fn(f64, f64) -> f64,
    ) -> Field {
        let mut field = Field::new(nx, nz, Vec::with_capacity(nx.saturating_mul(nz)), x_range, depth_range);
        for iz in 0..nz {
            for ix in 0..nx {
                let v = f(field.x(ix), field.depth(iz));
                field.values.push(v);
            }
        }
        field
    }

    /// x of node column `ix`.
    pub fn x(&self, ix: usize) -> f64 {
        lerp_node(self.x_range, ix, self.nx)
    }

    /// Depth of node row `iz`.
    pub fn depth(&self, iz: usize) -> f64 {
        lerp_node(self.depth_range, iz, self.nz)
    }

    /// Value at node `(ix, iz)`; `None` for a node the grid does not have.
    pub fn value(&self, ix: usize, iz: usize) -> Option<f64> {
        if ix >= self.nx || iz >= self.nz {
            return None;
        }
        self.values.get(iz.checked_mul(self.nx)?.checked_add(ix)?).copied()
    }

    /// Value at node `(ix, iz)` of a checked field ([`Field::check`]), inside it.
    fn at(&self, ix: usize, iz: usize) -> f64 {
        self.values[iz * self.nx + ix]
    }

    /// Values at the corners of cell `(ix, iz)` of a checked field, clockwise on the map from its top left: nodes
    /// `(ix, iz)`, `(ix + 1, iz)`, `(ix + 1, iz + 1)`, `(ix, iz + 1)`.
    pub(super) fn cell(&self, ix: usize, iz: usize) -> [f64; 4] {
        [self.at(ix, iz), self.at(ix + 1, iz), self.at(ix + 1, iz + 1), self.at(ix, iz + 1)]
    }

    /// Why the field cannot be drawn, if it cannot.
    pub fn check(&self) -> Result<(), String> {
        if self.nx < 2 || self.nz < 2 {
            return Err(format!("grid {}x{} has fewer than 2 nodes along an axis", self.nx, self.nz));
        }
        if self.nx.checked_mul(self.nz) != Some(self.values.len()) {
            return Err(format!("{} values for a {}x{} grid", self.values.len(), self.nx, self.nz));
        }
        for (name, (a, b)) in [("x", self.x_range), ("depth", self.depth_range)] {
            if !(a.is_finite() && b.is_finite() && a < b && (b - a).is_finite()) {
                return Err(format!("{name} range {a}..{b} is not finite and increasing"));
            }
        }
        Ok(())
    }

    /// The largest finite node value and where it is: `(x, depth, value)`; the first in row-major order on ties.
    pub fn max(&self) -> Option<(f64, f64, f64)> {
        let mut best: Option<(usize, f64)> = None;
        for (i, &v) in self.values.iter().enumerate() {
            if v.is_finite() && best.is_none_or(|(_, b)| v > b) {
                best = Some((i, v));
            }
        }
        let (i, v) = best?;
        let nx = self.nx.max(1);
        Some((self.x(i % nx), self.depth(i / nx), v))
    }

    /// Contour lines of `level` by marching squares, as polylines of `(x, depth)` points (closed loops end where
    /// they start). Along a cell edge the crossing is interpolated linearly; a cell with a non-finite corner has no
    /// line; a saddle cell is resolved by the mean of its corners. A node equal to the level counts as above it.
    /// An unusable field (see [`Field::check`]) has no lines.
    pub fn contour_lines(&self, level: f64) -> Vec<Vec<(f64, f64)>> {
        if self.check().is_err() || !level.is_finite() {
            return Vec::new();
        }
        let (nx, nz) = (self.nx, self.nz);
        // Edge ids: horizontal edges (ix, iz)–(ix+1, iz) first, then vertical edges (ix, iz)–(ix, iz+1).
        let h_edges = (nx - 1) * nz;
        let h = |ix: usize, iz: usize| iz * (nx - 1) + ix;
        let v = |ix: usize, iz: usize| h_edges + iz * nx + ix;
        let mut segments: Vec<(usize, usize)> = Vec::new();
        for iz in 0..nz - 1 {
            for ix in 0..nx - 1 {
                let c = self.cell(ix, iz);
                if c.iter().any(|x| !x.is_finite()) {
                    continue;
                }
                let inside = c.map(|x| x >= level);
                // Edges: top (c0–c1), right (c1–c2), bottom (c3–c2), left (c0–c3).
                let e = [h(ix, iz), v(ix + 1, iz), h(ix, iz + 1), v(ix, iz)];
                let crossed =
                    [inside[0] != inside[1], inside[1] != inside[2], inside[2] != inside[3], inside[3] != inside[0]];
                let n = crossed.iter().filter(|&&b| b).count();
                if n == 2 {
                    let mut it = (0..4).filter(|&k| crossed[k]);
                    if let (Some(a), Some(b)) = (it.next(), it.next()) {
                        segments.push((e[a], e[b]));
                    }
                } else if n == 4 {
                    let centre_inside = (c[0] + c[1] + c[2] + c[3]) / 4.0 >= level;
                    if centre_inside == inside[0] {
                        // c0 and c2 joined through the centre: cut off c1 (top, right) and c3 (bottom, left).
                        segments.push((e[0], e[1]));
                        segments.push((e[2], e[3]));
                    } else {
                        // c1 and c3 joined: cut off c0 (left, top) and c2 (right, bottom).
                        segments.push((e[3], e[0]));
                        segments.push((e[1], e[2]));
                    }
                }
            }
        }
        let point = |id: usize| -> (f64, f64) {
            let (a, b) = if id < h_edges {
                let (iz, ix) = (id / (nx - 1), id % (nx - 1));
                ((ix, iz), (ix + 1, iz))
            } else {
                let (iz, ix) = ((id - h_edges) / nx, (id - h_edges) % nx);
                ((ix, iz), (ix, iz + 1))
            };
            let (va, vb) = (self.at(a.0, a.1), self.at(b.0, b.1));
            let t = ((level - va) / (vb - va)).clamp(0.0, 1.0);
            let (pa, pb) = ((self.x(a.0), self.depth(a.1)), (self.x(b.0), self.depth(b.1)));
            (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1))
        };
        chain(&segments).into_iter().map(|ids| ids.into_iter().map(point).collect()).collect()
    }
}

fn lerp_node((a, b): (f64, f64), i: usize, n: usize) -> f64 {
    if n < 2 {
        return a;
    }
    if i + 1 == n {
        return b;
    }
    a + (b - a) * (i as f64 / (n - 1) as f64)
}

/// Join segments (pairs of edge ids) that share an edge into polylines of edge ids, deterministically.
fn chain(segments: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let mut at: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (i, &(a, b)) in segments.iter().enumerate() {
        at.entry(a).or_default().push(i);
        at.entry(b).or_default().push(i);
    }
    let mut used = vec![false; segments.len()];
    let mut out = Vec::new();
    for start in 0..segments.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let mut line = std::collections::VecDeque::from([segments[start].0, segments[start].1]);
        for forward in [true, false] {
            loop {
                let end = if forward { line.back() } else { line.front() };
                // The line starts with a segment's two ends and only grows.
                let Some(&end) = end else { break };
                let next = at[&end].iter().copied().find(|&s| !used[s]);
                let Some(s) = next else { break };
                used[s] = true;
                let (a, b) = segments[s];
                let other = if a == end { b } else { a };
                if forward {
                    line.push_back(other);
                } else {
                    line.push_front(other);
                }
            }
        }
        out.push(line.into_iter().collect());
    }
    out
}

/// All four corner values are finite.
pub(super) fn all_finite(c: &[f64; 4]) -> bool {
    c.iter().all(|v| v.is_finite())
}

/// The part of cell `(ix, iz)` where the field is ≥ `level`, as polygons of `(x, depth)` points, bounded by the
/// same straight pieces as [`Field::contour_lines`] draws (crossings interpolated linearly along the edges, saddles
/// resolved by the corners' mean): the cell's boundary is walked keeping the corners above the level and the
/// crossings. A saddle whose centre is below the level gives two pieces, one round each corner above it.
pub(super) fn cell_superlevel(f: &Field, ix: usize, iz: usize, c: &[f64; 4], level: f64) -> Vec<Vec<(f64, f64)>> {
    let nodes = [(ix, iz), (ix + 1, iz), (ix + 1, iz + 1), (ix, iz + 1)];
    let pos = |k: usize| (f.x(nodes[k].0), f.depth(nodes[k].1));
    let inside = c.map(|v| v >= level);
    // Crossing on the edge from corner k to corner k+1, interpolated from the lower-indexed node as in
    // `contour_lines`, so that the fill and the lines share their points exactly.
    let crossing = |k: usize| {
        let (a, b) = if k < 2 { (k, k + 1) } else { ((k + 1) % 4, k) };
        let t = ((level - c[a]) / (c[b] - c[a])).clamp(0.0, 1.0);
        let (pa, pb) = (pos(a), pos(b));
        (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1))
    };
    let crossed: Vec<usize> = (0..4).filter(|&k| inside[k] != inside[(k + 1) % 4]).collect();
    let centre_inside = (c[0] + c[1] + c[2] + c[3]) / 4.0 >= level;
    if crossed.len() == 4 && centre_inside != inside[0] {
        // Two separate pieces round the two corners above the level.
        return (0..4).filter(|&k| inside[k]).map(|k| vec![crossing((k + 3) % 4), pos(k), crossing(k)]).collect();
    }
    let mut poly = Vec::with_capacity(6);
    for k in 0..4 {
        if inside[k] {
            poly.push(pos(k));
        }
        if inside[k] != inside[(k + 1) % 4] {
            poly.push(crossing(k));
        }
    }
    if poly.len() >= 3 {
        vec![poly]
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::axis::min_max;

    #[test]
    fn field_layout_is_row_major_with_depth_rows() {
        let f = Field::from_fn(3, 2, (0.0, 2.0), (0.0, 10.0), |x, z| x + 100.0 * z);
        assert_eq!(f.values, vec![0.0, 1.0, 2.0, 1000.0, 1001.0, 1002.0]);
        assert_eq!((f.x(2), f.depth(1), f.value(1, 1)), (2.0, 10.0, Some(1001.0)));
        assert_eq!((f.value(3, 0), f.value(0, 9)), (None, None), "nodes the grid does not have");
        assert_eq!(f.max(), Some((2.0, 10.0, 1002.0)));
        assert!(Field::new(3, 2, vec![0.0; 5], (0.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(1, 2, vec![0.0; 2], (0.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(2, 2, vec![0.0; 4], (1.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(2, 2, vec![0.0; 4], (0.0, 1.0), (0.0, f64::NAN)).check().is_err());
        assert_eq!(Field::new(2, 2, vec![f64::NAN; 4], (0.0, 1.0), (0.0, 1.0)).max(), None);
    }

    #[test]
    fn marching_squares_places_levels_on_a_linear_ramp() {
        // v = 3x on x in [0, 1] (10 cells): the level L contour is the vertical line x = L/3 exactly.
        let f = Field::from_fn(11, 6, (0.0, 1.0), (0.0, 0.5), |x, _| 3.0 * x);
        for level in [0.05, 0.37 * 3.0, 1.5, 2.999] {
            let lines = f.contour_lines(level);
            assert_eq!(lines.len(), 1, "level {level}: one line");
            let line = &lines[0];
            // One point per crossed horizontal edge: all 6 depth rows.
            assert_eq!(line.len(), 6);
            for &(x, _) in line {
                assert!((x - level / 3.0).abs() < 1e-12, "level {level}: x = {x}");
            }
            let (d0, d1) = min_max(line.iter().map(|p| p.1));
            assert_eq!((d0, d1), (0.0, 0.5));
        }
        // A ramp along depth: horizontal lines at the predicted depth.
        let g = Field::from_fn(5, 9, (0.0, 1.0), (0.0, 4.0), |_, z| 10.0 - z);
        let lines = g.contour_lines(7.25);
        assert_eq!(lines.len(), 1);
        assert!(lines[0].iter().all(|p| (p.1 - 2.75).abs() < 1e-12));
        // Levels outside the range, or NaN, have no line.
        assert!(f.contour_lines(-1.0).is_empty() && f.contour_lines(4.0).is_empty());
        assert!(f.contour_lines(f64::NAN).is_empty());
    }

    #[test]
    fn marching_squares_closes_loops_around_a_maximum() {
        // v = -(x² + z²) centred in the grid: the level -r² contour is a closed loop of radius r, to within a
        // fraction of a cell (linear interpolation of a quadratic).
        let h = 0.1;
        let f = Field::from_fn(41, 41, (-2.0, 2.0), (-2.0, 2.0), |x, z| -(x * x + z * z));
        let r: f64 = 1.23;
        let lines = f.contour_lines(-r * r);
        assert_eq!(lines.len(), 1);
        let line = &lines[0];
        assert_eq!(line.first(), line.last(), "closed");
        for &(x, z) in line {
            assert!((x.hypot(z) - r).abs() < 0.1 * h, "radius {}", x.hypot(z));
        }
        // NaN cells break lines but never panic.
        let mut g = f.clone();
        g.values[20 * 41 + 32] = f64::NAN;
        let lines = g.contour_lines(-r * r);
        assert!(!lines.is_empty() && lines.iter().all(|l| l.len() >= 2));
    }

    #[test]
    fn superlevel_pieces_cover_the_right_area() {
        // Linear ramp in a unit cell: the part with v ≥ 0.3 of v = x is 0.7 of the cell.
        let f = Field::from_fn(2, 2, (0.0, 1.0), (0.0, 1.0), |x, _| x);
        let c = [0.0, 1.0, 1.0, 0.0];
        let area: f64 = cell_superlevel(&f, 0, 0, &c, 0.3)
            .iter()
            .map(|p| {
                let n = p.len();
                (0..n).map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1).sum::<f64>().abs() / 2.0
            })
            .sum();
        assert!((area - 0.7).abs() < 1e-12, "{area}");
    }
}
