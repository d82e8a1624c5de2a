//! `rollbem report` on a folder that is not rollbem's own (issue 12, item 6): every sentence must be computed from
//! the inputs it describes. The folder holds one scene and one sweep whose file names differ from their `name`s; the
//! expected text is what those inputs imply (their names, the folder given on the command line, the number of CPUs
//! of this machine), and the fixed phrases of the old report must be gone.

use std::path::Path;
use std::process::Command;

const SCENE: &str = r#"name = "pad-hertz"
description = "A custom frictionless half-plane case for the report test."
units = "kN, m, kPa"

[wheel]
radius = 0.5
youngs_modulus = 2.0e8
poisson_ratio = 0.25
model = "half_plane"
profile = "parabola"

[mesh]
element = "constant"
contact_half_width = 0.001
contact_elements = 40

[contact]
friction = 0.0

[drive]
normal_load = 100.0

[solvers]
use = ["lemke", "active_set"]
"#;

const SWEEP: &str = r#"name = "pad-mesh-study"
description = "pad mesh study, two direct solvers"
analysis = "accuracy"
base = "../scenes/a-file-name.toml"

[[grid]]
"mesh.contact_elements" = [20, 40, 80]
"solvers.use" = [["lemke"], ["active_set"]]
"#;

/// `rollbem report --reference REFS --out OUT`.
fn report(refs: &Path, out: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(["report", "--reference"])
        .arg(refs)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn write(p: &Path, text: &str) {
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}

#[test]
fn report_on_a_foreign_folder_says_only_what_its_inputs_imply() {
    let tmp = tempfile::tempdir().unwrap();
    let refs = tmp.path().join("my-cases");
    write(&refs.join("scenes/a-file-name.toml"), SCENE);
    write(&refs.join("sweeps/another-file-name.toml"), SWEEP);
    let out = tmp.path().join("my-report");
    let o = report(&refs, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let front = std::fs::read_to_string(out.join("README.md")).unwrap();
    // The command line as given, not "reference/".
    assert!(front.contains(&format!("--reference {} --out {}", refs.display(), out.display())), "{front}");
    // A frictionless half-plane sweep against Hertz: the Hertz page holds it, and no other family has one.
    let md = std::fs::read_to_string(out.join("families/hertz.md")).unwrap();
    assert!(!out.join("families/cattaneo-mindlin.md").exists() && !out.join("families/load-paths.md").exists());
    // Sweeps are titled by their `name`, scenes' runs are filed by theirs.
    assert!(md.contains("### pad-mesh-study"), "{md}");
    assert!(front.contains("pad-mesh-study: "), "{front}");
    assert!(md.contains("figures/pad-mesh-study-"), "figures are named after the sweep");
    assert!(out.join("runs/pad-hertz.json").exists());
    assert!(out.join("sweeps/pad-mesh-study.csv").exists());
    // The machine's CPU count, not a fixed "2 noisy vCPUs".
    let methods = std::fs::read_to_string(out.join("methods.md")).unwrap();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    assert!(methods.contains(&format!("with {cores} logical CPUs available to the process")), "{methods}");
    // Phrases the old report printed whatever its input; none is true here, on any page.
    let mut all = String::new();
    for page in ["README.md", "methods.md", "solvers.md", "families/hertz.md", "families/half-space-3d.md"] {
        all.push_str(&std::fs::read_to_string(out.join(page)).unwrap());
    }
    assert!(!all.contains("another-file-name"), "the sweep's file name leaked into the text");
    for fixed in ["from `reference/`", "a/R ≈ 0.015", "noisy vCPUs", "seed's figures", "Load paths", "load paths"] {
        assert!(!all.contains(fixed), "fixed phrase {fixed:?} in a report about other inputs");
    }
    // The sweep's Pareto table names only this sweep's solvers and meshes.
    let start = md.find("### pad-mesh-study").unwrap();
    let sweep_part = &md[start..start + md[start..].find("\n## ").unwrap_or(md.len() - start)];
    assert!(sweep_part.contains("lemke") && sweep_part.contains("active_set"));
    assert!(!sweep_part.contains("clarabel") && !sweep_part.contains("pgs ·"));
}

#[test]
fn report_refuses_unsafe_or_duplicate_names_before_writing_anything() {
    for (scene_name, sweep_name, field_file) in
        [("../../escape", "ok-sweep", "a-file-name.toml"), ("pad-hertz", "pad/../../x", "another-file-name.toml")]
    {
        let tmp = tempfile::tempdir().unwrap();
        let refs = tmp.path().join("refs");
        write(&refs.join("scenes/a-file-name.toml"), &SCENE.replace("pad-hertz", scene_name));
        write(&refs.join("sweeps/another-file-name.toml"), &SWEEP.replace("pad-mesh-study", sweep_name));
        let out = tmp.path().join("out");
        let o = report(&refs, &out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(field_file) && err.contains("`name`"), "{err}");
        assert!(!out.exists(), "nothing may be written");
    }
    // Two scenes with one name.
    let tmp = tempfile::tempdir().unwrap();
    let refs = tmp.path().join("refs");
    write(&refs.join("scenes/one.toml"), SCENE);
    write(&refs.join("scenes/two.toml"), SCENE);
    let out = tmp.path().join("out");
    let o = report(&refs, &out);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("unique") && err.contains("one.toml"), "{err}");
    assert!(!out.exists());
}

/// Issue 10 item 6: the seed's formulation against steady rolling. In the seed's formulation a sticking node's slip
/// velocity is the creepage plus the strain difference of a static solution, not zero (the issue's observation:
/// "stick nodes reported a slip velocity equal to the creepage"), so a seed scene with sticking nodes must count
/// them as inconsistent; the steady counterpart must count none (Coulomb's law holds by construction).
#[test]
fn report_compares_the_seed_rolling_formulation_with_steady_rolling() {
    let tmp = tempfile::tempdir().unwrap();
    let refs = tmp.path().join("refs");
    let seed = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/seed-fig09-mu05.toml");
    write(&refs.join("scenes/seed-fig09-mu05.toml"), &std::fs::read_to_string(seed).unwrap());
    std::fs::create_dir_all(refs.join("sweeps")).unwrap();
    let out = tmp.path().join("out");
    let o = report(&refs, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(out.join("families/seed.md")).unwrap();
    let section = &md[md.find("## The seed's rolling formulation against steady rolling").expect("the section")..];
    let row = section.lines().find(|l| l.starts_with("| seed-fig09-mu05 |")).expect("a seed-vs-steady row");
    let cells: Vec<&str> = row.split('|').map(str::trim).collect();
    // | scene | μ | drive | Q seed | Q steady | ξ | stick seed | stick steady | incons. seed | incons. steady |
    let count = |c: &str| -> (usize, usize) {
        let (a, b) = c.split_once(" / ").unwrap();
        (a.parse().unwrap(), b.parse().unwrap())
    };
    let seed_bad = count(cells[9]);
    let steady_bad = count(cells[10]);
    assert!(seed_bad.0 > 0, "the seed's stick nodes move: {row}");
    assert_eq!(steady_bad, (0, 0), "{row}");
    assert!(out.join("figures/seed-vs-steady-0.svg").exists());
}

/// The Cattaneo–Mindlin accuracy sweep on the finite wheel (issue 19, "what it must show"): the report separates the
/// stick zone's discretisation error (against each series' own converged-mesh limit) from the model error (that
/// limit against Cattaneo–Mindlin), and the discretisation error falls with the mesh. Expected: a positive observed
/// order (least squares over the meshes, more than two standard errors above zero) — the definition of an error
/// that falls; and a model-error cell beside the limit (a number, or a bound where it is not resolved). The old
/// report fitted an order to the error against Cattaneo, which converges to the model error instead.
#[test]
fn cattaneo_sweep_reports_falling_discretisation_error_and_model_error() {
    let tmp = tempfile::tempdir().unwrap();
    let refs = tmp.path().join("refs");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = std::fs::read_to_string(root.join("reference/scenes/cattaneo-decoupled.toml")).unwrap();
    write(&refs.join("scenes/cattaneo-decoupled.toml"), &scene);
    write(
        &refs.join("sweeps/cm.toml"),
        r#"name = "cm-mesh"
description = "Cattaneo-Mindlin stick zone against the mesh"
analysis = "accuracy"
base = "../scenes/cattaneo-decoupled.toml"
[[grid]]
"mesh.contact_elements" = [15, 30, 60, 120, 240]
"solvers.use" = [["lemke"]]
"#,
    );
    let out = tmp.path().join("out");
    let o = report(&refs, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(out.join("families/cattaneo-mindlin.md")).unwrap();
    let start = md.find("### cm-mesh").expect("the sweep's section");
    let sweep = &md[start..];
    // The limits table: c/a∞ and its model error beside it.
    assert!(sweep.contains("c/a∞ (± uncertainty) | x∞ vs theory, c/a"), "{sweep}");
    let limits = sweep.find("c/a∞ (± uncertainty)").unwrap();
    let row = sweep[limits..].lines().nth(2).expect("a limits row");
    let cells: Vec<&str> = row.split('|').map(str::trim).collect();
    let model = cells[4];
    assert!(!model.is_empty() && model != "–", "model error cell: {row}");
    // The discretisation error's observed order, from its table.
    let orders = sweep.find("Observed orders (stick-zone c/a error vs its mesh limit c∞)").expect("the order table");
    let line = sweep[orders..].lines().nth(4).expect("the series' order");
    let order: Vec<f64> =
        line.split('|').nth(3).unwrap().split('±').map(|v| v.trim().parse::<f64>().unwrap()).collect();
    eprintln!("c/a discretisation error order {} ± {}; limits row {row}", order[0], order[1]);
    assert!(order[0] - 2.0 * order[1] > 0.0, "not falling: {line}");
    // No order is fitted to the error against Cattaneo (it converges to the model error).
    let against_theory = sweep.find("against the mesh: on the finite wheel it converges to the model error");
    assert!(against_theory.is_some(), "{sweep}");
}

#[test]
fn report_includes_the_peer_tables_its_folder_holds() {
    // benches/peer/contact.sh writes OUT/peer-contact.md (run separately); report includes it, and says nothing
    // of a peer whose table is absent (no peer-lcp.md here).
    let tmp = tempfile::tempdir().unwrap();
    let refs = tmp.path().join("refs");
    write(&refs.join("scenes/a-scene.toml"), SCENE);
    std::fs::create_dir_all(refs.join("sweeps")).unwrap();
    let out = tmp.path().join("out");
    write(&out.join("peer-contact.md"), "| input | elements |\n|---|---:|\n| carter2d | 55 |\n");
    let o = report(&refs, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let front = std::fs::read_to_string(out.join("README.md")).unwrap();
    assert!(front.contains("](peers/contact-2d.md)"), "the front page links the peer's page: {front}");
    assert!(!front.contains("Siconos"), "a Siconos link without its table");
    let md = std::fs::read_to_string(out.join("peers/contact-2d.md")).unwrap();
    assert!(md.contains("# Side by side with CONTACT"), "{md}");
    assert!(md.contains("benches/peer/contact.sh"), "{md}");
    assert!(md.contains("| carter2d | 55 |"), "{md}");
    assert!(!out.join("peers/siconos.md").exists(), "a Siconos page without its table");
    assert!(out.join("peer-contact.md").exists(), "the peer's table is an input the report keeps");
}
