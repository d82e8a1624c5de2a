//! Half-space (3D) scenes through the scene reader, the pipeline, the result document and the command line
//! (issue 32, item 5). Expected values come from theory — Hertz's ellipse (`theory::Hertz3D`, Johnson §4.2(b)),
//! Cattaneo–Mindlin (Johnson §7.2, computed here) — or from the library's independently tested solver
//! (`halfspace::Path`, checked against CONTACT in `tests/contact3d.rs`), each test saying which.

use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::Drive;
use rollbem::halfspace::tangential::TangentialDrive;
use rollbem::halfspace::{ContactGrid, HalfSpace, Path as HalfSpacePath, PathSettings, Profile, Step};
use rollbem::pipeline::SpaceModel;
use rollbem::results::space::SpaceReport;
use rollbem::results::CheckKind;
use rollbem::scene::{AnyScene, Scene, SpaceScene, SpaceStatus};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scene(name: &str) -> PathBuf {
    root().join("reference/scenes/half-space").join(name)
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

/// A small frictionless sphere on a grid `m × m` covering ±`half`.
fn sphere(m: usize, half: f64, extra: &str) -> String {
    format!(
        "name = \"sphere\"\n[wheel]\nmodel = \"half_space\"\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         [counter_body]\nkind = \"half_space\"\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         [mesh]\nmx = {m}\nmy = {m}\ncontact_x = [-{half}, {half}]\ncontact_y = [-{half}, {half}]\n\
         [profile]\ncurvatures = [0.01, 0.01]\n{extra}"
    )
}

fn read(text: &str) -> rollbem::Result<SpaceScene> {
    SpaceScene::from_toml(text, Path::new("t.toml"))
}

fn field_of(e: rollbem::Error) -> String {
    match e {
        rollbem::Error::Invalid { field, .. } => field,
        other => panic!("expected Error::Invalid, got {other}"),
    }
}

/// The Hertz ellipse a/b = 2 passes its checks; the fit and the approach are within 1.5 % of Hertz3D (theory), and
/// only the normal kernel was built (frictionless: the effects the scene calls for).
#[test]
fn hertz_ellipse_scene_meets_hertz_and_builds_only_the_normal_kernel() {
    let s = SpaceScene::from_file(&scene("hertz-ellipse.toml")).unwrap();
    let model = SpaceModel::build(&s).unwrap();
    assert!(!model.influence().has_tangential() && !model.influence().has_coupling());
    let r = model.solve(&Cancel::never()).unwrap();
    assert!(!r.kernels.tangential && !r.kernels.coupling);
    assert_eq!(r.steps[0].status, SpaceStatus::Solved);
    let h = r.references.hertz.unwrap();
    assert!((h.a_x / h.a_y - 2.0).abs() < 0.01, "a/b = {}", h.a_x / h.a_y);
    let hertz: Vec<_> = r.checks.iter().filter(|c| c.name.contains("Hertz") && c.kind == CheckKind::Figure).collect();
    assert_eq!(hertz.len(), 4, "a_x, a_y, p0, approach");
    for c in hertz {
        assert!(c.pass && c.error < 0.015, "{} {}", c.name, c.error);
    }
    assert!(r.all_pass() && !r.unexpected_status());
}

/// A frictional scene of identical bodies builds the tangential kernels but not the coupling ones; a dissimilar
/// pair asked to couple builds both and alternates.
#[test]
fn kernels_follow_the_effects() {
    let c = SpaceModel::build(&SpaceScene::from_file(&scene("cattaneo-shift.toml")).unwrap()).unwrap();
    assert!(c.influence().has_tangential() && !c.influence().has_coupling() && !c.is_coupled());
    let s = SpaceModel::build(&SpaceScene::from_file(&scene("spence-compression.toml")).unwrap()).unwrap();
    assert!(s.influence().has_tangential() && s.influence().has_coupling() && s.is_coupled());
    let off = SpaceScene::from_file(&scene("spence-compression.toml")).unwrap().edit(|d| d.contact.coupling = false);
    let off = SpaceModel::build(&off.unwrap()).unwrap();
    assert!(!off.is_coupled());
}

/// Cattaneo–Mindlin on the circle, ν = 0 (exact), shift prescribed: the force for the shift and the stick radius
/// against the theory computed here (Johnson §7.2: δ_s = 3μP/(16a)·Σ(2−ν)/G, Q/μP = 1 − (1 − δ/δ_s)^(3/2),
/// c/a = (1 − δ/δ_s)^(1/2)), a from Hertz3D: Q within 1 %, c within one element.
#[test]
fn cattaneo_shift_scene_meets_cattaneo_mindlin() {
    let s = SpaceScene::from_file(&scene("cattaneo-shift.toml")).unwrap();
    let r = rollbem::pipeline::run_space_scene(&s).unwrap();
    assert!(r.all_pass(), "{:#?}", r.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
    let last = r.steps.last().unwrap();
    let (p, mu, g) = (1.0e4, 0.3, 210000.0 / 2.0);
    let a = rollbem::theory::Hertz3D::from_load(0.01, 0.01, 105000.0, p).unwrap().a_x;
    let delta_s = 3.0 * mu * p / (16.0 * a) * (2.0 * 2.0 / g);
    let x = 0.007 / delta_s;
    let q = mu * p * (1.0 - (1.0 - x).powf(1.5));
    assert!((-last.force[0] - q).abs() <= 0.01 * q, "Q {} vs {q}", -last.force[0]);
    assert!(last.force[1].abs() <= 1e-9 * q);
    let c = a * (1.0 - x).sqrt();
    let c_num = (last.stick as f64 * r.grid.dx * r.grid.dy / std::f64::consts::PI).sqrt();
    assert!((c_num - c).abs() <= r.grid.dx, "c {c_num} vs {c}");
    let rows: Vec<_> = r.checks.iter().filter(|c| c.name.contains("Cattaneo")).collect();
    assert_eq!(rows.len(), 2);
    assert!(rows.iter().all(|c| c.kind == CheckKind::Figure), "ν = 0: judged, not a model comparison");
    // With ν = 0.3 the same rows are model comparisons (the theory is not exact there).
    let nu = s
        .edit(|d| {
            d.wheel.poisson_ratio = 0.3;
            d.counter_body =
                rollbem::scene::space::SpaceCounterTable::HalfSpace { youngs_modulus: 210000.0, poisson_ratio: 0.3 };
        })
        .unwrap();
    let r = rollbem::pipeline::run_space_scene(&nu).unwrap();
    let rows: Vec<_> = r.checks.iter().filter(|c| c.name.contains("Cattaneo")).collect();
    assert!(!rows.is_empty() && rows.iter().all(|c| c.kind == CheckKind::ModelComparison));
}

/// The methods named in `[solvers.half_space]` are the ones that run, and they agree: the Cattaneo shift scene by
/// the unpreconditioned Polonsky–Keer and FISTA (independent iterations) gives the default methods' forces and
/// stick counts (the defaults tested against theory above) to 1e-7 of the force, with more iterations.
#[test]
fn the_scene_chooses_the_methods() {
    let base = SpaceScene::from_file(&scene("cattaneo-shift.toml")).unwrap();
    let text = std::fs::read_to_string(scene("cattaneo-shift.toml")).unwrap();
    let alt =
        format!("{text}\n[solvers.half_space]\nnormal_method = \"polonsky_keer\"\ntangential_method = \"fista\"\n");
    let alt = SpaceScene::from_toml(&alt, &scene("cattaneo-shift.toml")).unwrap();
    let (a, b) =
        (rollbem::pipeline::run_space_scene(&base).unwrap(), rollbem::pipeline::run_space_scene(&alt).unwrap());
    for (x, y) in a.steps.iter().zip(&b.steps) {
        let scale = x.force[0].hypot(x.force[1]).max(1e-300);
        assert!(
            (x.force[0] - y.force[0]).hypot(x.force[1] - y.force[1]) <= 1e-7 * scale,
            "{:?} {:?}",
            x.force,
            y.force
        );
        assert_eq!((x.stick, x.slip), (y.stick, y.slip));
        let its = |s: &rollbem::results::space::SpaceStepResult| (s.iterations_normal, s.iterations_tangential);
        assert!(its(y).0 >= its(x).0 && its(y).1 >= its(x).1, "{:?} {:?}", its(x), its(y));
    }
    let total =
        |r: &rollbem::results::space::SpaceReport| r.steps.iter().map(|s| s.iterations_tangential).sum::<usize>();
    assert!(total(&b) > total(&a), "FISTA {} against the CG's {}", total(&b), total(&a));
}

/// The scene's steps are the library path's steps: the substeps interpolate the load from rest (100 … 800), and
/// the coupled Spence compression solved through the scene equals `halfspace::Path` called directly (the
/// library's solver, tested against CONTACT's spence35) bit for bit, with no net tangential force.
#[test]
fn spence_scene_is_the_library_path() {
    let s = SpaceScene::from_file(&scene("spence-compression.toml")).unwrap();
    let loads: Vec<f64> = s
        .steps()
        .iter()
        .map(|st| match st.drive.normal {
            Drive::Load(p) => p,
            _ => panic!("load-driven"),
        })
        .collect();
    assert_eq!(loads, (1..=8).map(|k| 100.0 * k as f64).collect::<Vec<_>>());
    let r = rollbem::pipeline::run_space_scene(&s).unwrap();
    assert!(r.all_pass());
    let grid = ContactGrid::covering(31, 31, -1.0, 1.0, -1.0, 1.0).unwrap();
    let steps = loads.iter().map(|&p| Step::new(Drive::Load(p), TangentialDrive::Shift(0.0, 0.0))).collect();
    let (e, rigid) = (HalfSpace::new(1000.0, 0.25).unwrap(), HalfSpace::new(f64::INFINITY, 0.0).unwrap());
    let path = HalfSpacePath::new(grid, e, rigid, Profile::Quadratic { a: 0.5, b: 0.5 }, 0.2, true, steps).unwrap();
    let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
    for (o, st) in out.iter().zip(&r.steps) {
        assert_eq!(o.pressure, st.elements.pressure);
        assert_eq!(o.qx, st.elements.qx);
        assert!(st.force[0].abs().max(st.force[1].abs()) <= 1e-9 * st.load);
    }
}

/// A gap file (MY rows of MX values, row iy = 0 first) holding A x² + B y² at the element centres gives the answer
/// of the quadratic profile (the library's sampling) exactly; with A ≠ B a transposed reading would differ.
#[test]
fn a_gap_file_is_read_row_by_row() {
    let dir = tempfile::tempdir().unwrap();
    let base = sphere(16, 1.0, "[drive]\nnormal_load = 100.0\n").replace("[0.01, 0.01]", "[0.01, 0.03]");
    let quad = read(&base).unwrap();
    let grid = quad.grid();
    let rows: Vec<String> = (0..grid.my())
        .map(|iy| {
            (0..grid.mx())
                .map(|ix| {
                    let (x, y) = grid.centre(ix, iy);
                    format!("{:e}", 0.01 * x * x + 0.03 * y * y)
                })
                .collect::<Vec<_>>()
                .join(",")
        })
        .collect();
    std::fs::write(dir.path().join("gap.csv"), format!("# gaps\n{}\n", rows.join("\n"))).unwrap();
    let text = base.replace("curvatures = [0.01, 0.03]", "gap_file = \"gap.csv\"");
    let gap = SpaceScene::from_toml(&text, &dir.path().join("s.toml")).unwrap();
    let (a, b) =
        (rollbem::pipeline::run_space_scene(&quad).unwrap(), rollbem::pipeline::run_space_scene(&gap).unwrap());
    assert_eq!(a.steps[0].elements.pressure, b.steps[0].elements.pressure);
    assert!(b.references.hertz.is_none(), "no Hertz for a gap profile");
    // The wrong shape is refused, naming the key.
    std::fs::write(dir.path().join("gap.csv"), rows[..15].join("\n")).unwrap();
    let e = SpaceScene::from_toml(&text, &dir.path().join("s.toml")).unwrap_err();
    assert!(e.to_string().contains("MY = 16 rows"), "{e}");
    assert_eq!(field_of(e), "profile.gap_file");
}

/// Bad input is refused when read, naming the key: missing, unknown, NaN, a negative modulus, a grid too large, a
/// 2D key in a 3D scene and a 3D key in a 2D scene, a force without friction, a shift after a force-driven step.
#[test]
fn bad_input_names_the_key() {
    let good = sphere(8, 1.0, "[drive]\nnormal_load = 100.0\n");
    assert!(read(&good).is_ok());
    let cases: Vec<(String, &str)> = vec![
        (good.replace("mx = 8\n", ""), "mx"),
        (good.replace("[profile]", "[profile]\nsmoothing = 1"), "profile.smoothing"),
        (good.replace("normal_load = 100.0", "normal_load = nan"), "drive.normal_load"),
        (good.replace("youngs_modulus = 210000.0\npoisson_ratio = 0.3\n[counter", "youngs_modulus = -1.0\npoisson_ratio = 0.3\n[counter"), "wheel.youngs_modulus"),
        (good.replace("mx = 8", "mx = 4096").replace("my = 8", "my = 4096"), "mesh.mx"),
        (good.replace("[wheel]\n", "[wheel]\nradius = 1.0\n"), "wheel.radius"),
        (format!("{good}[rolling]\nmode = \"steady\"\ndirection = 1\n"), "rolling"),
        (good.replace("[drive]\nnormal_load = 100.0\n", "[[steps]]\nnormal_load = 1.0\n[[steps]]\nnormal_load = 2.0\nroll = 1.0\n"), "steps[1].roll"),
        (format!("{good}tangential_load = [1.0, 0.0]\n"), "drive.tangential_load"),
        (good.replace("[drive]\nnormal_load = 100.0\n", "[contact]\nfriction = 0.3\n[[steps]]\nnormal_load = 1.0\ntangential_load = [0.1, 0.0]\n[[steps]]\nnormal_load = 1.0\ntangential_shift = [0.1, 0.0]\n"), "steps[1].tangential_shift"),
        (format!("{good}[solvers]\nuse = [\"lemke\"]\n"), "solvers.use"),
        (good.replace("curvatures = [0.01, 0.01]", "curvatures = [0.01, 0.0]"), "profile.curvatures"),
        (format!("{good}[solvers.half_space]\ntangential_method = \"newton\"\n"), "tangential_method"),
    ];
    for (text, key) in cases {
        match read(&text) {
            Err(rollbem::Error::Invalid { field, message, .. }) => assert_eq!(field, key, "{message}"),
            Err(rollbem::Error::Parse { message, .. }) => assert!(message.contains(key), "{key}: {message}"),
            other => panic!("{key}: expected an error, got {other:?}"),
        }
    }
    // A 3D key in a 2D scene, and a 3D scene given to the 2D reader, name the key.
    let plane = std::fs::read_to_string(root().join("reference/scenes/half-plane-hertz.toml")).unwrap();
    let e =
        Scene::from_toml(&format!("{plane}\n[profile]\ncurvatures = [1.0, 1.0]\n"), Path::new("p.toml")).unwrap_err();
    assert_eq!(field_of(e), "profile");
    let e = Scene::from_toml(&good, Path::new("g.toml")).unwrap_err();
    assert_eq!(field_of(e), "wheel.model");
    assert!(matches!(AnyScene::from_toml(&good, Path::new("g.toml")).unwrap(), AnyScene::Space(_)));
    assert!(matches!(AnyScene::from_toml(&plane, Path::new("p.toml")).unwrap(), AnyScene::Plane(_)));
}

/// The command line: `run` writes the JSON document (read back as a `SpaceReport`, refused by the 2D reader with a
/// message), the element CSV and the path CSV; `check` passes; bad input exits 2 with nothing written; a contact
/// cut off by the grid exits 5 unless declared; gross sliding exits 5; `plot` draws the maps and sections.
#[test]
fn the_command_line_runs_checks_and_plots_3d_scenes() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("c.json");
    let (csv, path_csv) = (dir.path().join("c.csv"), dir.path().join("p.csv"));
    let out = bin()
        .args(["run", scene("cattaneo-shift.toml").to_str().unwrap(), "--json", json.to_str().unwrap()])
        .args(["--csv", csv.to_str().unwrap(), "--path-csv", path_csv.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains("grid: 30 × 30") && table.contains("kernels: normal, tangential"), "{table}");
    let r = SpaceReport::read(&json).unwrap();
    assert_eq!(r.steps.len(), 5);
    assert_eq!(r.steps[4].elements.pressure.len(), 900);
    let e = rollbem::results::Report::read(&json).unwrap_err().to_string();
    assert!(e.contains("half-space (3D) result document"), "{e}");
    let csv = std::fs::read_to_string(&csv).unwrap();
    assert!(csv.starts_with("step,substep,ix,iy,x,y,pn,px,py,state,gap\n"));
    assert_eq!(csv.lines().count(), 1 + 5 * 900);
    assert_eq!(std::fs::read_to_string(&path_csv).unwrap().lines().count(), 6);
    let check = bin().args(["check", scene("hertz-ellipse.toml").to_str().unwrap()]).output().unwrap();
    assert_eq!(check.status.code(), Some(0), "{}", String::from_utf8_lossy(&check.stdout));
    assert!(String::from_utf8_lossy(&check.stdout).starts_with("PASS hertz3d-ellipse"));
    // Bad input: exit 2, the key named, nothing written.
    let bad = dir.path().join("bad.toml");
    std::fs::write(
        &bad,
        sphere(8, 1.0, "[drive]\nnormal_load = 100.0\n").replace("[wheel]\n", "[wheel]\nradius = 1.0\n"),
    )
    .unwrap();
    let target = dir.path().join("bad.json");
    let out = bin().args(["run", bad.to_str().unwrap(), "--json", target.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("wheel.radius"));
    assert!(!target.exists());
    // Cut off by the grid: exit 5, or 0 when the scene declares it.
    let edge = dir.path().join("edge.toml");
    std::fs::write(&edge, sphere(9, 0.2, "[drive]\nnormal_load = 1.0e4\n")).unwrap();
    assert_eq!(bin().args(["run", edge.to_str().unwrap()]).output().unwrap().status.code(), Some(5));
    std::fs::write(
        &edge,
        sphere(9, 0.2, "[drive]\nnormal_load = 1.0e4\n[checks]\nstatus = \"contact_at_grid_edge\"\n"),
    )
    .unwrap();
    assert_eq!(bin().args(["run", edge.to_str().unwrap()]).output().unwrap().status.code(), Some(0));
    // Gross sliding: a force above μP.
    let slide = dir.path().join("slide.toml");
    let text = sphere(16, 2.0, "[contact]\nfriction = 0.2\n[[steps]]\nnormal_load = 1000.0\ntangential_load = [0.0, 0.0]\n[[steps]]\nnormal_load = 1000.0\ntangential_load = [300.0, 0.0]\n");
    std::fs::write(&slide, text).unwrap();
    let out = bin().args(["run", slide.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(5));
    assert!(String::from_utf8_lossy(&out.stdout).contains("gross_sliding"));
    // Sweeps take half-space scenes (tests/sweep3d.rs tests their rows): one row for the one case.
    let spec = dir.path().join("s.toml");
    let base = scene("hertz-ellipse.toml");
    std::fs::write(
        &spec,
        format!("name = \"s3\"\nbase = '{}'\n[[grid]]\n\"drive.normal_load\" = [50.0]\n", base.display()),
    )
    .unwrap();
    let out = bin()
        .args(["sweep", spec.to_str().unwrap(), "--out", dir.path().join("s.csv").to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(dir.path().join("s.csv")).unwrap().lines().count(), 2);
    // Plots.
    let out = bin().args(["plot", json.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    for f in ["pn", "pt", "state", "section_x", "section_y"] {
        let svg = dir.path().join(format!("cattaneo3d-shift.{f}.svg"));
        assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"), "{f}");
    }
}
