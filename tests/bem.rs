//! BEM core alone, against closed-form elasticity solutions (REFERENCES.md "BEM-only checks").
//!
//! Each problem is solved with mixed conditions on the wheel meshes rollbem uses: displacements prescribed on the
//! support part of the boundary (the clamped top arc of a disk, or the hub circle of an annulus), tractions on the
//! rest. Expected values come from the analytic fields: rigid motions, a constant-stress patch
//! (u = ε·x, ε = (σ − ν tr σ I)/(2G), t = σ·n) and Lamé's thick cylinder.

#[path = "common/paired.rs"]
mod paired;
use faer::linalg::solvers::Solve;
use faer::Mat;
use paired::paired;
use rollbem::bem::{assemble_full, kelvin::Kelvin};
use rollbem::mesh::MeshSpec;
use rollbem::mesh::{Bc, Mesh};
use rollbem::scene::{ElementKind, Support};

/// Uniform-ish mesh of `n` elements (the contact arc gets n/12, the rest is graded from the same size).
fn mesh(n: usize, kind: ElementKind, support: Support) -> Mesh {
    let spec = MeshSpec::arc(kind, 30.0, n / 12, n - n / 12);
    Mesh::wheel(1.0, support, &spec).unwrap()
}

/// Solve the mixed problem: displacements `u_of(x)` prescribed on Support nodes, tractions `t_of(x, n)` on the rest.
/// Returns (u, t) at every node (prescribed values copied, unknowns solved).
fn solve_mixed(
    m: &Mesh,
    k: &Kelvin,
    u_of: &dyn Fn([f64; 2]) -> [f64; 2],
    t_of: &dyn Fn([f64; 2], [f64; 2]) -> [f64; 2],
) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
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

fn observed_order(e_coarse: f64, e_fine: f64, refinement: f64) -> f64 {
    (e_coarse / e_fine).ln() / refinement.ln()
}

#[test]
fn rigid_translation_gives_zero_traction_to_round_off() {
    // Expected: a rigid translation is stress-free (exact elasticity), so the support tractions vanish and the free
    // boundary moves by the same translation.
    for kind in [ElementKind::Constant, ElementKind::Quadratic] {
        for support in [Support::TopArc { angle_deg: 40.0 }, Support::Hub { radius: 0.3 }] {
            let m = mesh(48, kind, support);
            let k = Kelvin::new(1.0, 0.3);
            let c = [0.37, -1.21];
            let (u, t) = solve_mixed(&m, &k, &|_| c, &|_, _| [0.0, 0.0]);
            let tmax = t.iter().flat_map(|v| v.iter()).fold(0.0_f64, |a, v| a.max(v.abs()));
            let uerr = u.iter().fold(0.0_f64, |a, v| a.max((v[0] - c[0]).abs()).max((v[1] - c[1]).abs()));
            assert!(tmax < 1e-12, "{kind:?} {support:?}: traction {tmax:e}");
            assert!(uerr < 1e-12, "{kind:?} {support:?}: displacement error {uerr:e}");
        }
    }
}

/// Constant-stress patch: σ = [[sxx, sxy], [sxy, syy]], plane strain, E = 1.
fn patch_error(n: usize, kind: ElementKind) -> f64 {
    let nu = 0.25;
    let k = Kelvin::new(1.0, nu);
    let g = k.shear_modulus;
    let (sxx, syy, sxy) = (1.0, -0.4, 0.3);
    let tr = sxx + syy;
    let eps = [[(sxx - nu * tr) / (2.0 * g), sxy / (2.0 * g)], [sxy / (2.0 * g), (syy - nu * tr) / (2.0 * g)]];
    let u_of = move |x: [f64; 2]| [eps[0][0] * x[0] + eps[0][1] * x[1], eps[1][0] * x[0] + eps[1][1] * x[1]];
    let t_of = move |_: [f64; 2], n: [f64; 2]| [sxx * n[0] + sxy * n[1], sxy * n[0] + syy * n[1]];
    let m = mesh(n, kind, Support::TopArc { angle_deg: 60.0 });
    let (u, _t) = solve_mixed(&m, &k, &u_of, &t_of);
    // Error in the solved displacements of the traction boundary, relative to the largest exact displacement.
    let mut err = 0.0_f64;
    let mut scale = 0.0_f64;
    for (node, ui) in paired(&m.nodes, &u) {
        let ue = u_of(node.pos);
        scale = scale.max(ue[0].hypot(ue[1]));
        if node.bc != Bc::Support {
            err = err.max((ui[0] - ue[0]).hypot(ui[1] - ue[1]));
        }
    }
    err / scale
}

#[test]
fn constant_stress_patch_converges_at_the_expected_order() {
    let c: Vec<f64> = [48, 96, 192].iter().map(|&n| patch_error(n, ElementKind::Constant)).collect();
    let q: Vec<f64> = [24, 48, 96].iter().map(|&n| patch_error(n, ElementKind::Quadratic)).collect();
    let (oc, oq) = (observed_order(c[1], c[2], 2.0), observed_order(q[1], q[2], 2.0));
    eprintln!("patch: constant {c:?} order {oc:.2}; quadratic {q:?} order {oq:.2}");
    // Constant elements on an inscribed polygon: about first order (REFERENCES.md).
    assert!(oc > 0.8, "constant-element order {oc}");
    // Quadratic elements on the exact arc: clearly faster than constant ones.
    assert!(oq > oc + 0.8, "quadratic order {oq} vs constant {oc}");
    assert!(c[2] < 0.02 && q[2] < 1e-3, "errors {c:?} {q:?}");
}

/// Lamé thick cylinder, inner radius ri clamped with the exact u_r, outer radius 1 loaded by −p_o n.
fn lame_error(n: usize, kind: ElementKind) -> (f64, f64) {
    let nu = 0.3;
    let k = Kelvin::new(1.0, nu);
    let g = k.shear_modulus;
    let (ri, ro, pi, po) = (0.4_f64, 1.0_f64, 0.0_f64, 1.0_f64);
    let c1 = (pi * ri * ri - po * ro * ro) / (ro * ro - ri * ri);
    let c2 = (pi - po) * ri * ri * ro * ro / (ro * ro - ri * ri);
    // REFERENCES.md: σ_rr = C1 − C2/r², u_r = [(1 − 2ν) C1 r + C2/r] / (2G).
    let ur = move |r: f64| ((1.0 - 2.0 * nu) * c1 * r + c2 / r) / (2.0 * g);
    let srr = move |r: f64| c1 - c2 / (r * r);
    let u_of = move |x: [f64; 2]| {
        let r = x[0].hypot(x[1]);
        [ur(r) * x[0] / r, ur(r) * x[1] / r]
    };
    let t_of = move |x: [f64; 2], n: [f64; 2]| {
        let r = x[0].hypot(x[1]);
        // σ·n with σ = σ_rr e_r e_r + σ_θθ e_θ e_θ and n = ±e_r on both circles.
        let s = srr(r);
        [s * n[0], s * n[1]]
    };
    let m = mesh(n, kind, Support::Hub { radius: ri });
    let (u, t) = solve_mixed(&m, &k, &u_of, &t_of);
    let mut eu = 0.0_f64;
    let mut et = 0.0_f64;
    for ((node, ui), ti) in paired(paired(&m.nodes, &u), &t) {
        let r = node.pos[0].hypot(node.pos[1]);
        if node.bc == Bc::Support {
            // Radial traction on the hole: t = σ·n, n = −e_r.
            let tr = -(ti[0] * node.pos[0] + ti[1] * node.pos[1]) / r;
            et = et.max((tr - srr(r)).abs() / srr(ro).abs());
        } else {
            let urn = (ui[0] * node.pos[0] + ui[1] * node.pos[1]) / r;
            eu = eu.max((urn - ur(r)).abs() / ur(ro).abs());
        }
    }
    (eu, et)
}

#[test]
fn lame_thick_cylinder_converges_at_the_expected_order() {
    let c: Vec<(f64, f64)> = [48, 96, 192].iter().map(|&n| lame_error(n, ElementKind::Constant)).collect();
    let q: Vec<(f64, f64)> = [24, 48, 96].iter().map(|&n| lame_error(n, ElementKind::Quadratic)).collect();
    let ocu = observed_order(c[1].0, c[2].0, 2.0);
    let oqu = observed_order(q[1].0, q[2].0, 2.0);
    let oct = observed_order(c[1].1, c[2].1, 2.0);
    let oqt = observed_order(q[1].1, q[2].1, 2.0);
    eprintln!("Lamé: constant {c:?} orders u {ocu:.2} t {oct:.2}; quadratic {q:?} orders u {oqu:.2} t {oqt:.2}");
    assert!(ocu > 0.8 && oct > 0.8, "constant orders {ocu} {oct}");
    assert!(oqu > ocu + 0.8, "quadratic u order {oqu} vs constant {ocu}");
    assert!(c[2].0 < 0.02 && q[2].0 < 1e-3, "u_r errors {c:?} {q:?}");
}
