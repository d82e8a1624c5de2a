//! Interior stresses by the Somigliana identity ([`rollbem::bem::stress`]) against closed-form elasticity.
//!
//! Expected values: Lamé's thick cylinder (σ_rr = C1 − C2/r², σ_θθ = C1 + C2/r² with C1 = (p_i r_i² − p_o r_o²) /
//! (r_o² − r_i²), C2 = (p_i − p_o) r_i² r_o² / (r_o² − r_i²), so σ_rr(r_i) = −p_i and σ_rr(r_o) = −p_o: pressures
//! positive, stresses tension-positive), a constant-stress patch (σ itself), Hondros' disk under two opposite
//! radial pressures (closed forms along the two diameters, checked here against boundary values, equilibrium and
//! the two-point-load limit), and brute-force composite Gauss integration of the same discrete integrals (for the
//! quadrature alone). Run with `--nocapture` to see every error figure and the timings.

#[path = "common/paired.rs"]
mod paired;
use faer::linalg::solvers::Solve;
use faer::Mat;
use paired::paired;
use rollbem::bem::kelvin::Kelvin;
use rollbem::bem::quadratic::{shape, ArcElement, XI_NODES};
use rollbem::bem::quadrature::gauss_legendre;
use rollbem::bem::stress::{boundary_stress, interior_stress, somigliana_kernels, InteriorStress, StressError};
use rollbem::bem::{assemble_full, FullSystem};
use rollbem::mesh::MeshSpec;
use rollbem::mesh::{Bc, Element, Mesh, Node, Shape};
use rollbem::scene::{ElementKind, Support};
use std::f64::consts::PI;
use std::time::Instant;

type V2 = [f64; 2];

/// Wheel mesh of `n` elements on the outer circle (radius 1), n/12 of them on the 30° contact arc.
fn wheel(n: usize, kind: ElementKind, support: Support) -> Mesh {
    let spec = MeshSpec::arc(kind, 30.0, n / 12, n - n / 12);
    Mesh::wheel(1.0, support, &spec).unwrap()
}

/// Cartesian stress [σxx, σyy, σxy] from polar components at the polar angle of `x`.
fn polar_to_xy(x: V2, srr: f64, stt: f64, srt: f64) -> [f64; 3] {
    let th = x[1].atan2(x[0]);
    let (s, c) = th.sin_cos();
    [
        srr * c * c + stt * s * s - 2.0 * srt * s * c,
        srr * s * s + stt * c * c + 2.0 * srt * s * c,
        (srr - stt) * s * c + srt * (c * c - s * s),
    ]
}

/// Lamé's thick cylinder r_i < r < r_o, pressures p_i (inside) and p_o (outside), plane strain.
#[derive(Clone, Copy)]
struct Lame {
    nu: f64,
    g: f64,
    c1: f64,
    c2: f64,
    ri: f64,
}

impl Lame {
    fn new(k: &Kelvin, ri: f64, ro: f64, pi: f64, po: f64) -> Lame {
        let d = ro * ro - ri * ri;
        Lame {
            nu: k.nu,
            g: k.shear_modulus,
            c1: (pi * ri * ri - po * ro * ro) / d,
            c2: (pi - po) * ri * ri * ro * ro / d,
            ri,
        }
    }
    fn srr(&self, r: f64) -> f64 {
        self.c1 - self.c2 / (r * r)
    }
    fn stt(&self, r: f64) -> f64 {
        self.c1 + self.c2 / (r * r)
    }
    /// u_r = [(1 − 2ν) C1 r + C2/r] / (2G) (plane strain; ε_rr + ε_θθ = (1 − 2ν)(σ_rr + σ_θθ)/(2G)).
    fn u(&self, x: V2) -> V2 {
        let r = x[0].hypot(x[1]);
        let ur = ((1.0 - 2.0 * self.nu) * self.c1 * r + self.c2 / r) / (2.0 * self.g);
        [ur * x[0] / r, ur * x[1] / r]
    }
    fn sigma(&self, x: V2) -> [f64; 3] {
        let r = x[0].hypot(x[1]);
        polar_to_xy(x, self.srr(r), self.stt(r), 0.0)
    }
    /// t = σ·n (σ is exactly radial/hoop, so any n works).
    fn t(&self, x: V2, n: V2) -> V2 {
        let s = self.sigma(x);
        [s[0] * n[0] + s[2] * n[1], s[2] * n[0] + s[1] * n[1]]
    }
    /// Largest |stress| in the annulus (at the hole): the stress scale of the relative errors.
    fn scale(&self) -> f64 {
        self.srr(self.ri).abs().max(self.stt(self.ri).abs())
    }
}

/// Exact nodal data of a field.
fn exact_data(m: &Mesh, u: impl Fn(V2) -> V2, t: impl Fn(V2, V2) -> V2) -> (Vec<V2>, Vec<V2>) {
    (m.nodes.iter().map(|n| u(n.pos)).collect(), m.nodes.iter().map(|n| t(n.pos, n.normal)).collect())
}

/// Numbers in short scientific notation.
fn es(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| format!("{x:.2e}")).collect();
    format!("[{}]", parts.join(", "))
}

fn max_err(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
}

fn observed_order(e_coarse: f64, e_fine: f64, refinement: f64) -> f64 {
    (e_coarse / e_fine).ln() / refinement.ln()
}

/// Mixed BEM solve as in tests/bem.rs: displacement prescribed on Support nodes, traction on the others.
fn solve_mixed(m: &Mesh, k: &Kelvin, u_of: &dyn Fn(V2) -> V2, t_of: &dyn Fn(V2, V2) -> V2) -> (Vec<V2>, Vec<V2>) {
    let sys = assemble_full(m, k).unwrap();
    let nd = 2 * m.n_nodes();
    let mut a = Mat::<f64>::zeros(nd, nd);
    let mut b = Mat::<f64>::zeros(nd, 1);
    for (j, node) in m.nodes.iter().enumerate() {
        let dirichlet = node.bc == Bc::Support;
        let (uk, tk) = (u_of(node.pos), t_of(node.pos, node.normal));
        for c in 0..2 {
            let col = 2 * j + c;
            for i in 0..nd {
                if dirichlet {
                    a[(i, col)] = -sys.g[(i, col)];
                    b[(i, 0)] -= sys.h[(i, col)] * uk[c];
                } else {
                    a[(i, col)] = sys.h[(i, col)];
                    b[(i, 0)] += sys.g[(i, col)] * tk[c];
                }
            }
        }
    }
    let x = a.partial_piv_lu().solve(&b);
    let mut u = Vec::new();
    let mut t = Vec::new();
    for (j, node) in m.nodes.iter().enumerate() {
        let xj = [x[(2 * j, 0)], x[(2 * j + 1, 0)]];
        if node.bc == Bc::Support {
            u.push(u_of(node.pos));
            t.push(xj);
        } else {
            u.push(xj);
            t.push(t_of(node.pos, node.normal));
        }
    }
    (u, t)
}

/// Geometry and interpolated data of element `e` at ξ: (x, n, ds/dξ, u, t).
fn element_at(m: &Mesh, e: usize, u: &[V2], t: &[V2], xi: f64) -> (V2, V2, f64, V2, V2) {
    let el = &m.elements[e];
    match el.shape {
        Shape::Straight { a, b } => {
            let len = (b[0] - a[0]).hypot(b[1] - a[1]);
            let s = 0.5 * (xi + 1.0);
            let x = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
            let n = [(b[1] - a[1]) / len, -(b[0] - a[0]) / len];
            (x, n, 0.5 * len, u[el.first_node], t[el.first_node])
        }
        Shape::Arc(arc) => {
            let nn = shape(xi);
            let mut ui = [0.0; 2];
            let mut ti = [0.0; 2];
            for j in 0..3 {
                for c in 0..2 {
                    ui[c] += nn[j] * u[el.first_node + j][c];
                    ti[c] += nn[j] * t[el.first_node + j][c];
                }
            }
            (arc.position(xi), arc.normal(xi), arc.jacobian(), ui, ti)
        }
    }
}

fn element_length(m: &Mesh, e: usize) -> f64 {
    match m.elements[e].shape {
        Shape::Straight { a, b } => (b[0] - a[0]).hypot(b[1] - a[1]),
        Shape::Arc(arc) => arc.length(),
    }
}

/// Brute-force reference of the same discrete integrals: per element, uniform composite 16-point Gauss with
/// pieces no longer than a quarter of the distance from `p` to the element (so every piece's nearest kernel
/// singularity has Bernstein parameter ≳ 16: converged to round-off), kernels from `somigliana_kernels` (the
/// unfused textbook form), no rigid-translation subtraction.
fn brute_stress(m: &Mesh, k: &Kelvin, u: &[V2], t: &[V2], p: V2) -> [f64; 3] {
    let rule = gauss_legendre(16).unwrap();
    let mut acc = [0.0; 3];
    for e in 0..m.elements.len() {
        let len = element_length(m, e);
        let dist = (0..=400)
            .map(|q| {
                let (x, ..) = element_at(m, e, u, t, -1.0 + q as f64 / 200.0);
                (x[0] - p[0]).hypot(x[1] - p[1])
            })
            .fold(f64::INFINITY, f64::min);
        let pieces = ((4.0 * len / dist).ceil() as usize).clamp(4, 40_000);
        let h = 2.0 / pieces as f64;
        for piece in 0..pieces {
            let a = -1.0 + piece as f64 * h;
            for (z, w) in rule.iter() {
                let xi = a + 0.5 * h * (z + 1.0);
                let (x, n, jac, ui, ti) = element_at(m, e, u, t, xi);
                let (d, s) = somigliana_kernels(k, x, n, p);
                let wq = 0.5 * h * w * jac;
                for (q, (i, j)) in [(0, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                    for kk in 0..2 {
                        acc[q] += wq * (d[kk][i][j] * ti[kk] - s[kk][i][j] * ui[kk]);
                    }
                }
            }
        }
    }
    acc
}

/// Interior test points of the annulus r_i = 0.4 < r < 1: three radii × seven angles (one under the contact arc).
fn annulus_points() -> Vec<V2> {
    let mut pts = Vec::new();
    for r in [0.5, 0.7, 0.88] {
        for th in [-PI / 2.0, -1.2, -0.3, 0.5, 1.4, 2.3, 3.0] {
            pts.push([r * f64::cos(th), r * f64::sin(th)]);
        }
    }
    pts
}

/// Max error of interior stresses over `points` relative to the stress scale.
fn field_error(
    m: &Mesh,
    k: &Kelvin,
    u: &[V2],
    t: &[V2],
    points: &[V2],
    exact: impl Fn(V2) -> [f64; 3],
    scale: f64,
) -> f64 {
    let s = interior_stress(m, k, u, t, points).unwrap();
    paired(points, &s).map(|(p, s)| max_err(s.as_ref().expect("interior point"), &exact(*p))).fold(0.0, f64::max)
        / scale
}

/// Point at `delta` element lengths inside the body from the boundary point at ξ of element `e` (moved along the
/// inward radial direction, which is the inward normal of arcs and of the chord at its midpoint).
fn offset_point(m: &Mesh, e: usize, xi: f64, delta: f64) -> V2 {
    let len = element_length(m, e);
    let (x, ..) = element_at(m, e, &vec![[0.0; 2]; m.n_nodes()], &vec![[0.0; 2]; m.n_nodes()], xi);
    let r = x[0].hypot(x[1]);
    let inward = if r > 0.7 { -1.0 } else { 1.0 }; // outer circle: towards the centre; hub: away from it
    [x[0] * (1.0 + inward * delta * len / r), x[1] * (1.0 + inward * delta * len / r)]
}

#[test]
fn lame_exact_data_converges_in_the_interior() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    let pts = annulus_points();
    let err = |n: usize, kind: ElementKind| {
        let m = wheel(n, kind, Support::Hub { radius: 0.4 });
        let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
        field_error(&m, &k, &u, &t, &pts, |x| lame.sigma(x), lame.scale())
    };
    let c: Vec<f64> = [48, 96, 192, 384].iter().map(|&n| err(n, ElementKind::Constant)).collect();
    let q: Vec<f64> = [24, 48, 96, 192].iter().map(|&n| err(n, ElementKind::Quadratic)).collect();
    let oc = observed_order(c[2], c[3], 2.0);
    let oq = observed_order(q[2], q[3], 2.0);
    eprintln!(
        "Lamé exact data, interior max rel err: constant {} order {oc:.2}; quadratic {} order {oq:.2}",
        es(&c),
        es(&q)
    );
    assert!(oc > 1.7, "constant order {oc}");
    assert!(oq > 2.7, "quadratic order {oq}");
    assert!(c[3] < 2e-3 && q[3] < 1e-5, "{c:?} {q:?}");
}

/// Near-boundary points: quadrature error (against `brute_stress`) and total error (against Lamé) at 1e-1, 1e-2,
/// 1e-3 element lengths from element midpoints, from a node and from element ends, on the contact arc, the free
/// outer boundary and the hub.
#[test]
fn lame_near_boundary_quadrature_and_total_error() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    for (kind, n) in [(ElementKind::Quadratic, 48), (ElementKind::Constant, 96)] {
        let m = wheel(n, kind, Support::Hub { radius: 0.4 });
        let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
        let ev = InteriorStress::new(&m, &k, &u, &t).unwrap();
        let contact = m.elements.iter().position(|e| e.bc == Bc::Contact).unwrap() + 1;
        let free = m.elements.iter().position(|e| e.bc == Bc::Free).unwrap() + 5;
        let hub = m.elements.iter().position(|e| e.bc == Bc::Support).unwrap() + 2;
        let mut worst_quad: f64 = 0.0;
        for (name, e) in [("contact", contact), ("free", free), ("hub", hub)] {
            for (where_, xi) in [("mid", 0.0), ("node 2/3", XI_NODES[2]), ("end", 1.0)] {
                let mut line = String::new();
                for delta in [1e-1, 1e-2, 1e-3] {
                    let p = offset_point(&m, e, xi, delta);
                    let s = ev.at(p).expect("interior");
                    let b = brute_stress(&m, &k, &u, &t, p);
                    let eq = max_err(&s, &b) / lame.scale();
                    let et = max_err(&s, &lame.sigma(p)) / lame.scale();
                    worst_quad = worst_quad.max(eq);
                    line += &format!("  δ={delta:.0e}: quad {eq:.1e} total {et:.1e}");
                    if kind == ElementKind::Quadratic && where_ != "end" {
                        // Away from the element ends the interpolant is smooth: the total error stays small.
                        assert!(et < 2e-3, "{kind:?} {name} {where_} δ={delta}: total {et:e}");
                    }
                }
                eprintln!("{kind:?} n={n} {name:8} {where_:9}{line}");
            }
        }
        eprintln!("{kind:?}: worst quadrature error {worst_quad:.2e} of the stress scale");
        assert!(worst_quad < 1e-6, "{kind:?}: quadrature error {worst_quad:e}");
    }
}

/// Quadrature alone over a grid under the contact (points 0.3–60 contact-element lengths from the boundary), with
/// exact Lamé data on a hub mesh: `InteriorStress` against `brute_stress`.
#[test]
fn quadrature_matches_brute_force_on_a_grid() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    for kind in [ElementKind::Quadratic, ElementKind::Constant] {
        let m = wheel(96, kind, Support::Hub { radius: 0.4 });
        let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
        let ev = InteriorStress::new(&m, &k, &u, &t).unwrap();
        let mut worst: f64 = 0.0;
        for i in 0..7 {
            for j in 0..6 {
                let p = [-0.15 + 0.05 * i as f64, -0.985 + 0.06 * j as f64];
                let s = ev.at(p).expect("interior");
                worst = worst.max(max_err(&s, &brute_stress(&m, &k, &u, &t, p)) / lame.scale());
            }
        }
        eprintln!("{kind:?} grid: worst quadrature error {worst:.2e} of the stress scale");
        assert!(worst < 1e-8, "{kind:?}: {worst:e}");
    }
}

/// Boundary stress recovery at the nodes, against Lamé (σ_rr = −p on each circle, σ_θθ from the closed form).
#[test]
fn lame_boundary_stress_recovery() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    for (kind, ns) in [(ElementKind::Quadratic, [24, 48, 96]), (ElementKind::Constant, [48, 96, 192])] {
        let mut errs = Vec::new();
        for n in ns {
            let m = wheel(n, kind, Support::Hub { radius: 0.4 });
            let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
            let mut worst: f64 = 0.0;
            for (i, node) in m.nodes.iter().enumerate() {
                let e = node.element;
                let xi = XI_NODES[i - m.elements[e].first_node];
                let s = boundary_stress(&m, &k, &u, &t, e, xi).unwrap().expect("closed mesh");
                worst = worst.max(max_err(&s, &lame.sigma(node.pos)) / lame.scale());
            }
            errs.push(worst);
        }
        let o = observed_order(errs[1], errs[2], 2.0);
        eprintln!("boundary stress recovery {kind:?}: max rel err at nodes {}, order {o:.2}", es(&errs));
        assert!(o > 1.5 && errs[2] < 5e-3, "{kind:?}: {errs:?}");
    }
}

/// Constant-stress patch on a disk: u = ε·x, t = σ·n at the nodes; the interior stress must be σ up to the
/// interpolation error of the nodal data (neither element family interpolates u = ε·x exactly on the circle).
#[test]
fn constant_stress_patch() {
    let nu = 0.25;
    let k = Kelvin::new(1.0, nu);
    let g = k.shear_modulus;
    let sig = [1.0, -0.4, 0.3];
    let tr = sig[0] + sig[1];
    let eps =
        [[(sig[0] - nu * tr) / (2.0 * g), sig[2] / (2.0 * g)], [sig[2] / (2.0 * g), (sig[1] - nu * tr) / (2.0 * g)]];
    let u_of = |x: V2| [eps[0][0] * x[0] + eps[0][1] * x[1], eps[1][0] * x[0] + eps[1][1] * x[1]];
    let t_of = |_: V2, n: V2| [sig[0] * n[0] + sig[2] * n[1], sig[2] * n[0] + sig[1] * n[1]];
    let mut pts = vec![[0.0, 0.0]];
    for r in [0.3, 0.6, 0.85] {
        for th in [-PI / 2.0, 0.4, 2.0, 3.5] {
            pts.push([r * f64::cos(th), r * f64::sin(th)]);
        }
    }
    let err = |n: usize, kind: ElementKind| {
        let m = wheel(n, kind, Support::TopArc { angle_deg: 30.0 });
        let (u, t) = exact_data(&m, u_of, t_of);
        field_error(&m, &k, &u, &t, &pts, |_| sig, 1.0)
    };
    let c: Vec<f64> = [48, 96, 192].iter().map(|&n| err(n, ElementKind::Constant)).collect();
    let q: Vec<f64> = [24, 48, 96].iter().map(|&n| err(n, ElementKind::Quadratic)).collect();
    let (oc, oq) = (observed_order(c[1], c[2], 2.0), observed_order(q[1], q[2], 2.0));
    eprintln!("patch, exact nodal data: constant {} order {oc:.2}; quadratic {} order {oq:.2}", es(&c), es(&q));
    assert!(oc > 1.7 && oq > 2.7, "orders {oc} {oq}");
    assert!(c[2] < 2e-3 && q[2] < 1e-5, "{c:?} {q:?}");
}

#[test]
fn lame_solved_by_bem_then_interior_stress() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    let pts = annulus_points();
    let err = |n: usize, kind: ElementKind| {
        let m = wheel(n, kind, Support::Hub { radius: 0.4 });
        let (u, t) = solve_mixed(&m, &k, &|x| lame.u(x), &|x, n| lame.t(x, n));
        field_error(&m, &k, &u, &t, &pts, |x| lame.sigma(x), lame.scale())
    };
    let c: Vec<f64> = [48, 96, 192].iter().map(|&n| err(n, ElementKind::Constant)).collect();
    let q: Vec<f64> = [24, 48, 96].iter().map(|&n| err(n, ElementKind::Quadratic)).collect();
    let (oc, oq) = (observed_order(c[1], c[2], 2.0), observed_order(q[1], q[2], 2.0));
    eprintln!(
        "Lamé solved by the BEM, interior max rel err: constant {} order {oc:.2}; quadratic {} order {oq:.2}",
        es(&c),
        es(&q)
    );
    assert!(oc > 0.8 && oq > oc + 0.8, "orders {oc} {oq}");
    assert!(c[2] < 2e-2 && q[2] < 1e-3, "{c:?} {q:?}");
}

/// Full circle of radius `radius` in `n` equal elements, the first starting at angle `start` (CCW).
fn circle_mesh(n: usize, kind: ElementKind, radius: f64, start: f64) -> Mesh {
    let mut m = Mesh { kind, radius, elements: Vec::new(), nodes: Vec::new(), contact_nodes: Vec::new() };
    let d = 2.0 * PI / n as f64;
    for e in 0..n {
        let (t0, t1) = (start + d * e as f64, start + d * (e + 1) as f64);
        let first = m.nodes.len();
        match kind {
            ElementKind::Constant => {
                let a = [radius * t0.cos(), radius * t0.sin()];
                let b = [radius * t1.cos(), radius * t1.sin()];
                let len = (b[0] - a[0]).hypot(b[1] - a[1]);
                let tan = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
                m.nodes.push(Node {
                    pos: [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])],
                    normal: [tan[1], -tan[0]],
                    weight: len,
                    element: e,
                    bc: Bc::Free,
                    gap: 0.5 * (a[1] + b[1]) + radius,
                });
                m.elements.push(Element {
                    shape: Shape::Straight { a, b },
                    bc: Bc::Free,
                    first_node: first,
                    n_nodes: 1,
                });
            }
            ElementKind::Quadratic => {
                let arc = ArcElement { centre: [0.0, 0.0], radius, theta0: t0, theta1: t1 };
                let w = arc.node_weights();
                for (j, &xi) in XI_NODES.iter().enumerate() {
                    m.nodes.push(Node {
                        pos: arc.position(xi),
                        normal: arc.normal(xi),
                        weight: w[j],
                        element: e,
                        bc: Bc::Free,
                        gap: arc.position(xi)[1] + radius,
                    });
                }
                m.elements.push(Element { shape: Shape::Arc(arc), bc: Bc::Free, first_node: first, n_nodes: 3 });
            }
            other => panic!("an element kind this test cannot mesh: {other:?}"),
        }
    }
    m
}

/// Pure traction problem H u = G t with the rigid modes removed by Lagrange multipliers: the bordered system
/// [H R; Rᵀ 0] [u; λ] = [G t; 0], R = the three rigid modes (translations, rotation about the origin) at the
/// nodes. Returns u and the multipliers λ (they absorb the discrete inconsistency of G t; ~ discretisation error).
fn solve_traction(m: &Mesh, k: &Kelvin, t: &[V2]) -> (Vec<V2>, [f64; 3]) {
    let FullSystem { h, g, .. } = assemble_full(m, k).unwrap();
    let nd = 2 * m.n_nodes();
    let mut a = Mat::<f64>::zeros(nd + 3, nd + 3);
    let mut b = Mat::<f64>::zeros(nd + 3, 1);
    for i in 0..nd {
        for j in 0..nd {
            a[(i, j)] = h[(i, j)];
            b[(i, 0)] += g[(i, j)] * t[j / 2][j % 2];
        }
    }
    for (j, node) in m.nodes.iter().enumerate() {
        let modes = [[1.0, 0.0], [0.0, 1.0], [-node.pos[1], node.pos[0]]];
        for (q, mode) in modes.iter().enumerate() {
            for c in 0..2 {
                a[(2 * j + c, nd + q)] = mode[c];
                a[(nd + q, 2 * j + c)] = mode[c];
            }
        }
    }
    let x = a.partial_piv_lu().solve(&b);
    let u = (0..m.n_nodes()).map(|j| [x[(2 * j, 0)], x[(2 * j + 1, 0)]]).collect();
    (u, [x[(nd, 0)], x[(nd + 1, 0)], x[(nd + 2, 0)]])
}

/// Hondros (1959): disk of radius R, uniform radial pressure p on the arcs |θ ∓ π/2| < α (load along y).
/// Along the loaded diameter (x = 0, |y| = r): σ_yy = −(2p/π)(A + B), σ_xx = (2p/π)(A − B) with
/// q = r²/R², A = (1 − q) sin 2α / (1 − 2q cos 2α + q²), B = atan((1 + q)/(1 − q) tan α).
/// Along the unloaded diameter (y = 0, |x| = r): σ_xx = (2p/π)(A' − B'), σ_yy = −(2p/π)(A' + B') with
/// A' = (1 − q) sin 2α / (1 + 2q cos 2α + q²), B' = atan((1 − q)/(1 + q) tan α). Shear vanishes on both.
struct Hondros {
    p: f64,
    r: f64,
    alpha: f64,
}

impl Hondros {
    fn loaded(&self, r: f64) -> [f64; 3] {
        let (q, a) = ((r / self.r).powi(2), self.alpha);
        let aa = (1.0 - q) * (2.0 * a).sin() / (1.0 - 2.0 * q * (2.0 * a).cos() + q * q);
        let bb = ((1.0 + q) / (1.0 - q) * a.tan()).atan();
        let f = 2.0 * self.p / PI;
        [f * (aa - bb), -f * (aa + bb), 0.0]
    }
    fn unloaded(&self, r: f64) -> [f64; 3] {
        let (q, a) = ((r / self.r).powi(2), self.alpha);
        let aa = (1.0 - q) * (2.0 * a).sin() / (1.0 + 2.0 * q * (2.0 * a).cos() + q * q);
        let bb = ((1.0 - q) / (1.0 + q) * a.tan()).atan();
        let f = 2.0 * self.p / PI;
        [f * (aa - bb), -f * (aa + bb), 0.0]
    }
}

/// Checks of the Hondros formulas themselves: boundary values (σ_rr = −p under the load, 0 on the free
/// boundary), equilibrium of the half disks (∫σ_yy dx over the unloaded diameter = −P = −2pR sin α; ∫σ_xx dy
/// over the loaded one = −2pR(1 − cos α), the horizontal components of the pressure on a half disk), and the
/// two-point-load limit at the centre (Timoshenko–Goodier: 2P/(πD), −6P/(πD)).
#[test]
fn hondros_reference_is_self_consistent() {
    let h = Hondros { p: 1.0, r: 1.0, alpha: 0.1 };
    let near = 1.0 - 1e-9;
    assert!((h.loaded(near)[1] + 1.0).abs() < 1e-6 && h.unloaded(near)[0].abs() < 1e-6);
    let rule = gauss_legendre(40).unwrap();
    let (mut fy, mut fx) = (0.0, 0.0);
    let pieces = 400;
    for k in 0..pieces {
        let a = -1.0 + 2.0 * k as f64 / pieces as f64;
        for (z, w) in rule.iter() {
            let s = a + (z + 1.0) / pieces as f64;
            fy += w / pieces as f64 * h.unloaded(s.abs())[1];
            fx += w / pieces as f64 * h.loaded(s.abs())[0];
        }
    }
    let (p, a) = (h.p, h.alpha);
    assert!((fy + 2.0 * p * a.sin()).abs() < 1e-8, "{fy}");
    assert!((fx + 2.0 * p * (1.0 - a.cos())).abs() < 1e-6, "{fx}");
    let small = Hondros { p: 1.0, r: 1.0, alpha: 1e-4 };
    let pl = 2.0 * small.p * small.alpha.sin();
    let c = small.loaded(0.0);
    assert!(
        (c[0] / (2.0 * pl / (PI * 2.0)) - 1.0).abs() < 1e-3 && (c[1] / (-6.0 * pl / (PI * 2.0)) - 1.0).abs() < 1e-3
    );
}

/// Hondros' disk solved by the BEM with traction conditions everywhere (rigid modes removed by the bordered
/// system), then interior stresses at the centre and along both diameters (r ≤ 0.8R on the loaded one, away from
/// the arcs), against the closed form.
#[test]
fn hondros_disk_by_bem() {
    let k = Kelvin::new(1.0, 0.3);
    let (alpha, p) = (6f64.to_radians(), 1.0);
    let hd = Hondros { p, r: 1.0, alpha };
    let scale = hd.loaded(0.0)[1].abs();
    let pl = 2.0 * p * alpha.sin();
    eprintln!(
        "Hondros α=6°: centre σxx {:.5} σyy {:.5}; two-point limit 2P/(πD) {:.5}, −6P/(πD) {:.5}",
        hd.loaded(0.0)[0],
        hd.loaded(0.0)[1],
        2.0 * pl / (2.0 * PI),
        -6.0 * pl / (2.0 * PI)
    );
    let mut pts: Vec<(V2, [f64; 3])> = Vec::new();
    for r in [0.0, 0.2, 0.4, 0.6, 0.8] {
        pts.push(([0.0, r], hd.loaded(r)));
        pts.push(([0.0, -r], hd.loaded(r)));
    }
    for r in [0.2, 0.4, 0.6, 0.8, 0.9] {
        pts.push(([r, 0.0], hd.unloaded(r)));
        pts.push(([-r, 0.0], hd.unloaded(r)));
    }
    let points: Vec<V2> = pts.iter().map(|p| p.0).collect();
    for (kind, per_arc) in [(ElementKind::Constant, [2, 4, 8]), (ElementKind::Quadratic, [1, 2, 4])] {
        let mut errs = Vec::new();
        for m_arc in per_arc {
            // Elements of angle 2α/m_arc, the loaded arcs [π/2 − α, π/2 + α] and its opposite made of whole elements.
            let n = (PI / alpha).round() as usize * m_arc;
            let mesh = circle_mesh(n, kind, 1.0, PI / 2.0 - alpha);
            let t: Vec<V2> = mesh
                .nodes
                .iter()
                .map(|nd| {
                    let th = nd.pos[1].atan2(nd.pos[0]);
                    let loaded = (th - PI / 2.0).abs() < alpha || (th + PI / 2.0).abs() < alpha;
                    if loaded {
                        [-p * nd.normal[0], -p * nd.normal[1]]
                    } else {
                        [0.0, 0.0]
                    }
                })
                .collect();
            let (u, lam) = solve_traction(&mesh, &k, &t);
            let s = interior_stress(&mesh, &k, &u, &t, &points).unwrap();
            let mut worst: f64 = 0.0;
            let mut worst_at = [0.0; 2];
            let mut centre = [0.0; 3];
            for ((x, want), got) in paired(&pts, &s) {
                let got = got.expect("interior");
                if *x == [0.0, 0.0] {
                    centre = got;
                }
                let e = max_err(&got, want) / scale;
                if e > worst {
                    worst = e;
                    worst_at = *x;
                }
            }
            let ec = max_err(&centre, &hd.loaded(0.0)) / scale;
            eprintln!(
                "Hondros {kind:?} n={n}: centre σ = [{:.5}, {:.5}, {:.1e}] (rel err {ec:.2e}), worst on the diameters {worst:.2e} at {worst_at:?}, multipliers {}",
                centre[0],
                centre[1],
                centre[2],
                es(&lam)
            );
            errs.push(worst);
        }
        let o = observed_order(errs[1], errs[2], 2.0);
        eprintln!("Hondros {kind:?}: errors {}, order {o:.2}", es(&errs));
        assert!(o > 0.8, "{kind:?} order {o}");
        assert!(errs[2] < if kind == ElementKind::Constant { 3e-2 } else { 1e-3 }, "{kind:?} {errs:?}");
    }
}

/// Outside, in the hole, on nodes, vertices and arcs, non-finite: the documented errors, never NaN, never a panic.
#[test]
fn points_outside_on_boundary_and_in_the_hole() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    for kind in [ElementKind::Quadratic, ElementKind::Constant] {
        let m = wheel(48, kind, Support::Hub { radius: 0.4 });
        let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
        let ev = InteriorStress::new(&m, &k, &u, &t).unwrap();
        for p in [[2.0, 0.0], [0.0, -1.5], [1.0, 1.0], [-0.8, 0.8]] {
            assert_eq!(ev.at(p), Err(StressError::OutsideBody), "{kind:?} {p:?}");
        }
        for p in [[0.0, 0.0], [0.1, -0.2], [0.0, 0.399], [-0.39, 0.0]] {
            assert_eq!(ev.at(p), Err(StressError::OutsideBody), "{kind:?} hole {p:?}");
        }
        for i in [0, 7, m.contact_nodes[3], m.n_nodes() - 1, m.n_nodes() / 2] {
            let e = m.nodes[i].element;
            assert_eq!(
                ev.at(m.nodes[i].pos),
                Err(StressError::OnBoundary { element: e, node: Some(i) }),
                "{kind:?} node {i}"
            );
        }
        // Element vertices and points on the element between nodes: on the boundary, not at a node.
        for e in [0, 5, m.elements.len() - 1] {
            for xi in [-1.0, 0.3, 1.0] {
                let (x, ..) = element_at(&m, e, &u, &t, xi);
                match ev.at(x) {
                    Err(StressError::OnBoundary { node: None, element }) => {
                        // This element, or (at a vertex) the neighbour sharing it.
                        let shares = [-1.0, 1.0].iter().any(|&end| {
                            let (y, ..) = element_at(&m, element, &u, &t, end);
                            (y[0] - x[0]).hypot(y[1] - x[1]) < 1e-12
                        });
                        assert!(element == e || (xi.abs() == 1.0 && shares), "{kind:?} {e} {xi}: {element}");
                    }
                    other => panic!("{kind:?} element {e} ξ={xi}: {other:?}"),
                }
            }
        }
        assert_eq!(ev.at([f64::NAN, 0.5]), Err(StressError::NotFinite));
        assert_eq!(ev.at([0.5, f64::INFINITY]), Err(StressError::NotFinite));
        // Just inside: 1e-10 element lengths is on the boundary (tolerance 1e-9), 1e-8 is evaluated, and finite.
        let e = m.elements.iter().position(|e| e.bc == Bc::Contact).unwrap() + 2;
        assert!(matches!(ev.at(offset_point(&m, e, 0.0, 1e-10)), Err(StressError::OnBoundary { .. })));
        let s = ev.at(offset_point(&m, e, 0.0, 1e-8)).expect("inside");
        assert!(s.iter().all(|v| v.is_finite()));
        // A dense grid over and around the wheel, also grazing the boundaries: no NaN, no panic.
        let n_hub = m.elements.iter().filter(|e| e.bc == Bc::Support).count();
        let mut n_ok = 0;
        for i in 0..=120 {
            for j in 0..=120 {
                let p = [-1.2 + 0.02 * i as f64, -1.2 + 0.02 * j as f64];
                if let Ok(s) = ev.at(p) {
                    assert!(s.iter().all(|v| v.is_finite()), "{p:?}");
                    let r = p[0].hypot(p[1]);
                    // Quadratic: the exact circles. Constant: inscribed polygons, whose hole is smaller than the
                    // hub circle by up to its sagitta.
                    let r_hole = if kind == ElementKind::Quadratic { 0.4 } else { 0.4 * (PI / n_hub as f64).cos() };
                    assert!(r > r_hole && r < 1.0, "{kind:?} {p:?} accepted");
                    n_ok += 1;
                }
            }
        }
        // Every grid point strictly inside the annulus (away from the boundary by more than the tolerance) is evaluated.
        let inside = (0..=120)
            .flat_map(|i| (0..=120).map(move |j| (-1.2 + 0.02 * i as f64).hypot(-1.2 + 0.02 * j as f64)))
            .filter(|r| *r > 0.4 + 1e-6 && *r < 1.0 - 0.02)
            .count();
        assert!(n_ok >= inside, "{n_ok} of {inside}");
    }
}

/// Time this thread has spent on a CPU, in seconds (Linux `/proc/thread-self/schedstat`; None elsewhere): with
/// other processes competing for the two cores, wall time overstates the cost.
fn thread_cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(s.split_whitespace().next()?.parse::<f64>().ok()? * 1e-9)
}

/// A 100 × 50 grid under a 100-element contact on a 300-element hub mesh (plus the hub's elements), exact Lamé data:
/// the worst error converges at least at the order the element family promises (the times are printed for
/// information only: timing belongs in the benches, `benches/stresses.rs`).
#[test]
fn grid_100_by_50_converges_under_the_contact() {
    let k = Kelvin::new(1.0, 0.3);
    let lame = Lame::new(&k, 0.4, 1.0, 0.5, 1.0);
    let pts: Vec<V2> = (0..50)
        .flat_map(|j| (0..100).map(move |i| [-0.12 + 0.24 * i as f64 / 99.0, -0.99 + 0.29 * j as f64 / 49.0]))
        .collect();
    let worst_error = |s: &[Result<[f64; 3], StressError>]| {
        paired(&pts, s).map(|(p, s)| max_err(s.as_ref().unwrap(), &lame.sigma(*p))).fold(0.0, f64::max) / lame.scale()
    };
    for kind in [ElementKind::Constant, ElementKind::Quadratic] {
        let spec = MeshSpec::arc(kind, 30.0, 100, 200);
        let m = Mesh::wheel(1.0, Support::Hub { radius: 0.4 }, &spec).unwrap();
        let (u, t) = exact_data(&m, |x| lame.u(x), |x, n| lame.t(x, n));
        let t0 = Instant::now();
        let ev = InteriorStress::new(&m, &k, &u, &t).unwrap();
        let t_new = t0.elapsed().as_secs_f64();
        let (t1, c1) = (Instant::now(), thread_cpu_seconds());
        let s = ev.evaluate(&pts);
        let t_seq = t1.elapsed().as_secs_f64();
        let cpu_seq = thread_cpu_seconds().zip(c1).map(|(b, a)| b - a).unwrap_or(f64::NAN);
        let t2 = Instant::now();
        let sp = ev.evaluate_par(&pts);
        let t_par = t2.elapsed().as_secs_f64();
        assert_eq!(s, sp);
        let worst = worst_error(&s);
        // The same grid on the mesh twice as coarse (50 + 100 elements).
        let coarse = Mesh::wheel(1.0, Support::Hub { radius: 0.4 }, &MeshSpec::arc(kind, 30.0, 50, 100)).unwrap();
        let (uc, tc) = exact_data(&coarse, |x| lame.u(x), |x, n| lame.t(x, n));
        let worst_coarse = worst_error(&InteriorStress::new(&coarse, &k, &uc, &tc).unwrap().evaluate_par(&pts));
        eprintln!(
            "timing {kind:?}: {} elements, {} points: setup {:.1} ms, sequential {:.0} ms (on-CPU {:.0} ms), rayon {:.0} ms; max rel err vs Lamé {:.1e}",
            m.elements.len(),
            pts.len(),
            1e3 * t_new,
            1e3 * t_seq,
            1e3 * cpu_seq,
            1e3 * t_par,
            worst
        );
        // Expected: halving the mesh divides the error by at least 2^p, p = 1 for constant elements (first order
        // at worst, near the boundary) and p = 3 for quadratic ones (the O(h³) interpolation of the nodal data).
        // Measured on this grid (relative to the stress scale; the worst point is 0.5 contact-element lengths
        // under the contact arc, at (0.12, −0.99)) for 25 + 50, 50 + 100, 100 + 200, 200 + 400 elements:
        // constant 1.9e-1, 7.5e-2, 2.9e-2, 1.9e-3 (order 1.4 at this mesh); quadratic 8.4e-7, 5.3e-8, 1.5e-9,
        // 3.6e-11 (order 5.1 at this mesh).
        let p = if kind == ElementKind::Constant { 1 } else { 3 };
        let bound = worst_coarse / 2f64.powi(p);
        assert!(worst <= bound, "{kind:?}: worst error {worst:.2e} > {worst_coarse:.2e} / 2^{p} of the coarser mesh");
    }
}
