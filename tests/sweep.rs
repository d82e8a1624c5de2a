//! Sweeps: expansion of the grids, sharding and merging, bad specs.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::scene::ElementKind;
use rollbem::sweep::{merge, run_sweep, Shard, SweepSpec, PROVENANCE_COLUMNS};
use rollbem::Error;
use std::path::{Path, PathBuf};

fn scene(name: &str) -> String {
    format!("{}/reference/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Header and rows of a CSV.
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut r = csv::Reader::from_path(path).unwrap();
    let h = r.headers().unwrap().iter().map(str::to_string).collect();
    let rows = r.records().map(|x| x.unwrap().iter().map(str::to_string).collect()).collect();
    (h, rows)
}

/// The rows with the timing columns blanked.
fn without_timing(header: &[String], rows: &[Vec<String>]) -> Vec<Vec<String>> {
    rows.iter()
        .map(|r| {
            paired(r, header)
                .map(|(c, h)| if PROVENANCE_COLUMNS.contains(&h.as_str()) { "" } else { c }.into())
                .collect()
        })
        .collect()
}

#[test]
fn expansion_order_and_params() {
    let dir = tempfile::tempdir().unwrap();
    let spec = write(
        dir.path(),
        "s.toml",
        &format!(
            r#"
name = "expansion"
description = "test"
base = '{}'

[[grid]]
"wheel.poisson_ratio" = [0.2, 0.3]
"mesh.contact_elements" = [10, 20, 30]

[[grid]]
contact.friction = [0.1, 0.2]     # unquoted dotted key: a nested table, same meaning
"solvers.pgs.tolerance" = [1e-3]  # creates the missing table (parsed later; cases() checks only this grid's scenes)
"#,
            scene("seed-fig6-constant.toml")
        ),
    );
    let s = SweepSpec::from_file(&spec).unwrap();
    assert_eq!(s.name, "expansion");
    assert_eq!(s.grid.len(), 2);
    assert_eq!(s.len(), 2 * 3 + 2);
    assert_eq!(s.keys(), ["contact.friction", "mesh.contact_elements", "solvers.pgs.tolerance", "wheel.poisson_ratio"]);

    // The second grid names a settings table this build may not know: enumerate the first grid alone too.
    let first = SweepSpec { grid: vec![s.grid[0].clone()], ..s.clone() };
    let cases = first.cases(&spec).unwrap();
    assert_eq!(cases.len(), 6);
    // Keys sorted ("mesh..." < "wheel..."), the last varying fastest.
    let expect = [("10", "0.2"), ("10", "0.3"), ("20", "0.2"), ("20", "0.3"), ("30", "0.2"), ("30", "0.3")];
    for (i, (c, (n, nu))) in paired(&cases, expect).enumerate() {
        assert_eq!(c.index, i);
        assert_eq!(
            c.params,
            vec![("mesh.contact_elements".to_string(), n.to_string()), ("wheel.poisson_ratio".into(), nu.into())]
        );
        assert_eq!(c.scene.document().mesh.contact_elements, n.parse::<usize>().unwrap());
        assert_eq!(c.scene.document().wheel.poisson_ratio, nu.parse::<f64>().unwrap());
        assert_eq!(c.scene.document().mesh.element, ElementKind::Constant);
        assert_eq!(c.scene.name(), "seed-fig6-constant");
    }

    // A grid of known keys only: cases numbered on after the first grid.
    let spec2 = write(
        dir.path(),
        "s2.toml",
        &format!(
            r#"
name = "expansion2"
base = '{}'
[[grid]]
"mesh.element" = ["quadratic"]
"mesh.contact_elements" = [4, 8]
[[grid]]
"contact.friction" = [0.1, 0.2, 0.4]
"solvers.use" = [["lemke"]]
"#,
            scene("seed-fig6-constant.toml")
        ),
    );
    let cases = SweepSpec::from_file(&spec2).unwrap().cases(&spec2).unwrap();
    assert_eq!(cases.len(), 2 + 3);
    assert_eq!(cases.iter().map(|c| c.index).collect::<Vec<_>>(), [0, 1, 2, 3, 4]);
    assert_eq!(cases[1].scene.document().mesh.element, ElementKind::Quadratic);
    assert_eq!(cases[1].scene.document().mesh.contact_elements, 8);
    assert_eq!(cases[4].scene.document().contact.friction, 0.4);
    assert_eq!(cases[4].params[1], ("solvers.use".to_string(), r#"["lemke"]"#.to_string()));
    assert_eq!(
        cases[4].scene.document().mesh.element,
        ElementKind::Constant,
        "the second grid keeps the base's element"
    );
}

/// A small sweep: frictionless and frictional cases, constant and quadratic elements and an error case (clarabel
/// named on a frictional scene: unsupported). (A solver this build does not know is the spec's error, refused before
/// anything runs: `grid_errors_are_refused_before_running`.)
fn small_spec(dir: &Path) -> PathBuf {
    write(
        dir,
        "small.toml",
        &format!(
            r#"
name = "small"
base = '{}'

[[grid]]
"mesh.element" = ["constant", "quadratic"]
"mesh.contact_elements" = [6, 12]
"solvers.use" = [["lemke", "clarabel"]]

[[grid]]
"mesh.contact_elements" = [8, 16]
"contact.friction" = [0.2, 0.5]
"solvers.use" = [["lemke"], ["pgs"]]
"#,
            scene("seed-fig6-constant.toml")
        ),
    )
}

/// The published header of the small spec's CSV, written out independently of the code that writes it (the
/// swept keys, then the documented columns; `rollbem::sweep::row`).
fn expected_header() -> Vec<&'static str> {
    let mut h = vec!["case", "contact.friction", "mesh.contact_elements", "mesh.element", "solvers.use"];
    h.extend([
        "scene",
        "scene_digest",
        "element",
        "contact_elements",
        "contact_nodes",
        "solver",
        "formulation",
        "status",
        "problem_size",
        "pivots",
        "iterations",
        "factorisations",
        "gmres",
        "sweeps",
        "outer",
        "residual",
        "normal_load",
        "tangential_load",
        "half_width_fit",
        "peak_pressure_fit",
        "peak_pressure",
        "hertz_a_err",
        "hertz_p0_err",
        "hertz_l2_err",
        "cm_c_over_a",
        "cm_c_over_a_exact",
        "cm_c_err_elements",
        "cm_centre_elements",
        "cm_shear_err",
        "cm_shear_l2_err",
        "model",
        "strip_width",
        "radius",
        "contact_radius",
        "counter_body",
        "counter_radius",
        "contact_modulus",
        "friction",
        "hertz_a",
        "hertz_p0",
        "shift",
        "approach",
        "stick_left",
        "stick_right",
        "creepage",
        "carter_q_over_mup",
        "carter_q_over_mup_exact",
        "carter_c_over_a",
        "carter_c_over_a_exact",
        "carter_c_err_elements",
        "carter_shear_rms",
        "contact_half_angle",
        "pin_bore_half_angle",
        "pin_bore_p0",
        "pin_bore_half_angle_err",
        "pin_bore_p0_err",
        "message",
        "t_assembly",
        "t_condensation",
        "t_formulation",
        "t_solve",
        "t_total",
        "t_total_min",
        "t_total_max",
        "timing_runs",
        "setup",
    ]);
    h
}

#[test]
fn the_sweep_csv_has_one_row_per_run_under_the_published_header() {
    let dir = tempfile::tempdir().unwrap();
    let spec = small_spec(dir.path());
    let whole = dir.path().join("whole.csv");
    let n_rows = run_sweep(&spec, None, &whole, false).unwrap();
    let (header, rows) = read_csv(&whole);
    assert_eq!(rows.len(), n_rows);
    assert_eq!(header, expected_header());
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    // 4 frictionless cases × (lemke, clarabel) + 8 frictional cases × 1 row.
    assert_eq!(rows.len(), 4 * 2 + 8);
    // Sorted by case, then solver.
    let keys: Vec<(usize, String)> = rows.iter().map(|r| (r[0].parse().unwrap(), r[col("solver")].clone())).collect();
    let mut sorted = keys.clone();
    sorted.sort();
    assert_eq!(keys, sorted);
    // Frictionless lemke rows solved, with Hertz figures; empty cells where a grid does not set a key.
    let r0 = &rows[1];
    assert_eq!((r0[0].as_str(), r0[col("solver")].as_str(), r0[col("status")].as_str()), ("0", "lemke", "solved"));
    assert_eq!(r0[col("contact.friction")], "");
    assert!(r0[col("hertz_l2_err")].parse::<f64>().is_ok(), "{r0:?}");
    if std::env::var_os("SWEEP_TEST_SHOW").is_some() {
        eprintln!("{}", std::fs::read_to_string(&whole).unwrap());
    }
    // Frictional lemke and pgs rows carry the swept value (in TOML syntax) and solve; no case is an error.
    for solver in ["lemke", "pgs"] {
        assert!(rows.iter().any(|r| r[col("solver")] == solver
            && r[col("contact.friction")] == "0.2"
            && r[col("status")] == "solved"));
    }
    assert!(rows.iter().all(|r| r[col("status")] != "error"));
}

/// Issue 31: a grid point whose named solver cannot take its scene (clarabel with friction) is bad input found when
/// the grid is validated, before anything runs (it used to run, and write an `error` row for that case): the error
/// names the case, `solvers.use` and why, and nothing is written.
#[test]
fn a_named_solver_that_cannot_take_a_case_refuses_the_sweep_before_it_runs() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(small_spec(dir.path())).unwrap();
    let spec =
        write(dir.path(), "clarabel.toml", &text.replace("[[\"lemke\"], [\"pgs\"]]", "[[\"lemke\"], [\"clarabel\"]]"));
    let out = dir.path().join("out.csv");
    let e = run_sweep(&spec, None, &out, false).unwrap_err();
    match &e {
        Error::Invalid { field, message, .. } => {
            assert_eq!(field, "solvers.use", "{e}");
            assert!(message.contains("case 5 (") && message.contains("clarabel does not apply"), "{e}");
            assert!(message.contains("with friction use normtang_qp"), "{e}");
        }
        other => panic!("expected Error::Invalid, got {other}"),
    }
    assert!(!out.exists() && !dir.path().join("out.csv.partial").exists());
}

#[test]
fn shards_merge_to_the_unsharded_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let spec = small_spec(dir.path());
    let whole = dir.path().join("whole.csv");
    let n_rows = run_sweep(&spec, None, &whole, false).unwrap();
    let (header, rows) = read_csv(&whole);
    // Shards 1/3, 2/3, 3/3 then merge: the same rows except for the timings.
    let mut parts = Vec::new();
    let mut total = 0;
    for k in 1..=3 {
        let p = dir.path().join(format!("shard{k}.csv"));
        total += run_sweep(&spec, Some(Shard { k, n: 3 }), &p, false).unwrap();
        let (h, shard_rows) = read_csv(&p);
        assert_eq!(h, header);
        assert!(shard_rows.iter().all(|r| r[0].parse::<usize>().unwrap() % 3 == k - 1));
        parts.push(p);
    }
    assert_eq!(total, n_rows);
    // Merge in a scrambled order.
    parts.reverse();
    let merged = dir.path().join("merged.csv");
    assert_eq!(merge(&parts, &merged).unwrap(), n_rows);
    let (mh, mrows) = read_csv(&merged);
    assert_eq!(mh, header);
    assert_eq!(without_timing(&mh, &mrows), without_timing(&header, &rows));
    // Issue 31: the results are the columns up to `message`, the provenance columns (the one documented mask) all
    // come after it. Cut there, the merged shards are the serial CSV cell for cell; the provenance did differ
    // (`setup`: a shard builds a model the serial run reused), so the cut is needed as well as sufficient.
    let m = header.iter().position(|c| c == "message").unwrap();
    assert_eq!(&header[m + 1..], PROVENANCE_COLUMNS);
    let results = |rows: &[Vec<String>]| rows.iter().map(|r| r[..=m].to_vec()).collect::<Vec<_>>();
    assert_eq!(results(&mrows), results(&rows));
    let setup = header.iter().position(|c| c == "setup").unwrap();
    assert!(mrows.iter().zip(&rows).any(|(a, b)| a[setup] != b[setup]), "no `setup` differs: a vacuous check");

    // The same shard twice is refused.
    let twice = [parts[0].clone(), parts[0].clone()];
    assert!(merge(&twice, &dir.path().join("twice.csv")).is_err());
}

#[test]
fn bad_specs_are_errors_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let base = scene("seed-fig6-constant.toml");
    let field_of = |text: &str| -> (String, String) {
        let p = write(dir.path(), "bad.toml", text);
        let e = SweepSpec::from_file(&p).and_then(|s| s.cases(&p).map(|_| ())).unwrap_err();
        match e {
            Error::Invalid { ref field, .. } => (field.clone(), e.to_string()),
            other => panic!("expected Error::Invalid, got {other}"),
        }
    };
    let (f, _) =
        field_of(&format!("name = 'x'\nbase = '{base}'\nbogus = 1\n[[grid]]\n'mesh.contact_elements' = [4]\n"));
    assert_eq!(f, "bogus");
    let (f, m) = field_of(&format!("name = 'x'\nbase = '{base}'\n[[grid]]\n'mesh.contact_elements' = 4\n"));
    assert_eq!(f, "grid.mesh.contact_elements");
    assert!(m.contains("array"), "{m}");
    let (f, _) = field_of(&format!("name = 'x'\nbase = '{base}'\n[[grid]]\n'mesh.contact_elements' = []\n"));
    assert_eq!(f, "grid.mesh.contact_elements");
    let (f, _) = field_of(&format!("name = 'x'\nbase = '{base}'\n"));
    assert_eq!(f, "grid");
    let (f, _) = field_of(&format!("name = 'x'\nbase = '{base}'\ngrid = []\n"));
    assert_eq!(f, "grid");
    let (f, _) = field_of(&format!("name = 'x'\nbase = '{base}'\n[[grid]]\n"));
    assert_eq!(f, "grid");
    // The spec says what the sweep is; an analysis that cannot apply to the grid is bad input naming `analysis`.
    let (f, m) = field_of(&format!(
        "name = 'x'\nbase = '{base}'\nanalysis = 'creep_curve'\n[[grid]]\n'mesh.contact_elements' = [4, 8]\n"
    ));
    assert_eq!(f, "analysis");
    assert!(m.contains("rolling.creepage"), "{m}");
    let (f, m) =
        field_of(&format!("name = 'x'\nbase = '{base}'\nanalysis = 'guess'\n[[grid]]\n'contact.friction' = [0.1]\n"));
    assert_eq!(f, "analysis");
    assert!(m.contains("accuracy") && m.contains("creep_curve"), "{m}");
    // Overlapping keys: a table and a key inside it, or a key given plainly and inside a zipped key.
    let (f, m) = field_of(&format!(
        "name = 'x'\nbase = '{base}'\n[[grid]]\n'drive' = [{{ normal_load = 1.0 }}]\n'drive.normal_load' = [2.0]\n"
    ));
    assert_eq!(f, "grid.drive.normal_load");
    assert!(m.contains("overlaps `drive`"), "{m}");
    let (f, _) = field_of(&format!(
        "name = 'x'\nbase = '{base}'\n[[grid]]\n'wheel.radius' = [1.0]\n'wheel.radius & mesh.contact_elements' = [[1.0, 4]]\n"
    ));
    assert_eq!(f, "grid.wheel.radius");
    let (f, m) = field_of("name = 'x'\nbase = 'no/such/scene.toml'\n[[grid]]\n'mesh.contact_elements' = [4]\n");
    assert_eq!(f, "base");
    assert!(m.contains("no/such/scene.toml"), "{m}");
    // An out-of-range value in a variant: names the spec, the case's parameters and the scene field.
    let text =
        format!("name = 'x'\nbase = '{base}'\n[[grid]]\n'wheel.radius' = [1.0, -2.0]\n'mesh.contact_elements' = [4]\n");
    let (f, m) = field_of(&text);
    assert_eq!(f, "wheel.radius");
    assert!(m.contains("bad.toml") && m.contains("case 1") && m.contains("wheel.radius = -2.0"), "{m}");
    // run_sweep refuses it before running anything.
    let p = write(dir.path(), "bad.toml", &text);
    let out = dir.path().join("out.csv");
    match run_sweep(&p, None, &out, false) {
        Err(Error::Invalid { path, field, message }) => {
            assert_eq!((path, field.as_str()), (p.clone(), "wheel.radius"));
            assert!(message.contains("case 1"), "{message}");
        }
        other => panic!("expected Error::Invalid, got {other:?}"),
    }
    assert!(!out.exists());
    // A dotted path through a value that is not a table.
    let (f, _) = field_of(&format!("name = 'x'\nbase = '{base}'\n[[grid]]\n'wheel.radius.x' = [1.0]\n"));
    assert_eq!(f, "wheel.radius.x");

    for s in ["0/3", "4/3", "x", "1/0", "1/", "/3", "-1/3", "1/3/4"] {
        assert!(s.parse::<Shard>().is_err(), "{s} should not parse");
    }
    assert_eq!("2/3".parse::<Shard>().unwrap(), Shard { k: 2, n: 3 });
    assert_eq!("1/1".parse::<Shard>().unwrap(), Shard { k: 1, n: 1 });
    let e = "4/3".parse::<Shard>().unwrap_err();
    assert!(e.contains("4/3"), "{e}");
}

#[test]
fn merge_refuses_different_headers() {
    use rollbem::sweep::row::header;
    use rollbem::sweep::{RowStatus, SweepRow};
    // Shard CSVs as `run_sweep` writes them: the header of their swept keys, one typed row per line.
    let csv = |key: &str, rows: &[(usize, &str, &str)]| {
        let keys = vec![key.to_string()];
        let mut text = header(&keys).join(",") + "\n";
        for &(case, solver, x) in rows {
            let mut r = SweepRow::new(case, solver, RowStatus::Run(rollbem::status::Status::Solved));
            r.params = vec![(key.to_string(), x.to_string())];
            text += &(r.record(&keys).join(",") + "\n");
        }
        text
    };
    let dir = tempfile::tempdir().unwrap();
    let a = write(dir.path(), "a.csv", &csv("x", &[(0, "lemke", "1")]));
    let b = write(dir.path(), "b.csv", &csv("y", &[(1, "lemke", "1")]));
    let c = write(dir.path(), "c.csv", &csv("x", &[(1, "clarabel", "2"), (1, "lemke", "2")]));
    let out = dir.path().join("out.csv");
    let e = merge(&[a.clone(), b.clone()], &out).unwrap_err();
    assert!(matches!(e, Error::Invalid { ref field, .. } if field == "header"), "{e}");
    assert!(!out.exists());
    assert_eq!(merge(&[c, a], &out).unwrap(), 3);
    let (h, rows) = read_csv(&out);
    let solver = h.iter().position(|c| c == "solver").unwrap();
    assert_eq!(
        rows.iter().map(|r| (r[0].as_str(), r[solver].as_str())).collect::<Vec<_>>(),
        [("0", "lemke"), ("1", "clarabel"), ("1", "lemke")]
    );
    assert!(merge(&[], &out).is_err());
}

/// The reference sweeps `hertz-accuracy` and `cattaneo-accuracy` (`reference/sweeps/`) run end to end: every case
/// builds and the direct solvers solve it. Slow for `cargo test` (about 50 s of CPU on two threads, 108 cases), so
/// ignored there and run by CI (`.ci/run`, after `cargo test --release`) as
/// `cargo test --release --test sweep -- --ignored --nocapture`, the command to run it by hand too. Set
/// `ROLLBEM_SWEEP_OUT=DIR` to keep the CSVs.
#[test]
#[ignore = "slow (about 50 s CPU): CI runs it, `cargo test --release --test sweep -- --ignored`"]
fn reference_sweeps_run() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = std::env::var_os("ROLLBEM_SWEEP_OUT").map(PathBuf::from).unwrap_or_else(|| dir.path().into());
    for name in ["hertz-accuracy", "cattaneo-accuracy"] {
        let spec = PathBuf::from(format!("{}/reference/sweeps/{name}.toml", env!("CARGO_MANIFEST_DIR")));
        let n_cases = SweepSpec::from_file(&spec).unwrap().len();
        let out = out_dir.join(format!("{name}.csv"));
        let t = std::time::Instant::now();
        let rows = run_sweep(&spec, None, &out, true).unwrap();
        eprintln!("{name}: {n_cases} cases, {rows} rows in {:.1} s -> {}", t.elapsed().as_secs_f64(), out.display());
        let (h, rows) = read_csv(&out);
        let col = |c: &str| h.iter().position(|x| x == c).unwrap();
        let mut statuses = std::collections::BTreeMap::new();
        for r in &rows {
            *statuses.entry((r[col("solver")].clone(), r[col("status")].clone())).or_insert(0) += 1;
        }
        eprintln!("{name}: (solver, status) counts {statuses:?}");
        // Every case builds and runs (a loose PGS tolerance may legitimately fail the residual check: that is a
        // finding of the sweep, not an error of it); the direct solvers solve everything.
        let bad: Vec<String> = rows
            .iter()
            .filter(|r| r[col("status")] == "error" || (r[col("solver")] != "pgs" && r[col("status")] != "solved"))
            .map(|r| format!("case {} {}: {} {}", r[0], r[col("solver")], r[col("status")], r[col("message")]))
            .collect();
        assert!(bad.is_empty(), "{name}: runs not solved:\n{}", bad.join("\n"));
    }
}

#[test]
fn zipped_keys_and_a_grid_base() {
    // Zipped keys set several keys together (one CSV column each); a grid's own `base` replaces the spec's.
    let dir = tempfile::tempdir().unwrap();
    let hp = write(
        dir.path(),
        "hp.toml",
        "name = \"hp\"\n[wheel]\nradius = 100.0\nyoungs_modulus = 1000.0\npoisson_ratio = 0.3\n\
         model = \"half_plane\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 1.0\ncontact_elements = 20\n\
         [contact]\nfriction = 0.0\n[drive]\nnormal_load = 1.0\n[solvers]\nuse = [\"lemke\"]\n",
    );
    let spec = write(
        dir.path(),
        "s.toml",
        &format!(
            r#"
name = "zip"
base = '{}'

[[grid]]
"drive.normal_load & mesh.contact_half_width" = [[1.0, 1.0], [4.0, 2.0]]

[[grid]]
base = '{}'
"mesh.contact_elements" = [10]
"#,
            hp.display(),
            scene("seed-fig6-constant.toml")
        ),
    );
    let s = SweepSpec::from_file(&spec).unwrap();
    assert_eq!(s.keys(), vec!["drive.normal_load", "mesh.contact_elements", "mesh.contact_half_width"]);
    let cases = s.cases(&spec).unwrap();
    assert_eq!(cases.len(), 3);
    assert_eq!(
        cases[1].params,
        vec![("drive.normal_load".into(), "4.0".into()), ("mesh.contact_half_width".into(), "2.0".into())]
    );
    assert_eq!(cases[1].scene.document().drive.normal_load, Some(4.0));
    assert_eq!(cases[1].scene.document().mesh.contact_half_width, Some(2.0));
    assert_eq!(cases[0].scene.name(), "hp");
    assert_ne!(cases[2].scene.name(), "hp", "the second grid's own base");
    // A tuple of the wrong length names the key.
    let bad = write(
        dir.path(),
        "bad.toml",
        &format!(
            "name = \"b\"\nbase = '{}'\n[[grid]]\n\"drive.normal_load & mesh.contact_half_width\" = [[1.0]]\n",
            hp.display()
        ),
    );
    match SweepSpec::from_file(&bad) {
        Err(Error::Invalid { field, message, .. }) => {
            assert!(field.contains("drive.normal_load & mesh.contact_half_width"), "{field}");
            assert!(message.contains("tuples of 2"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

/// `timing_repeats = 3`: every (fast) run is timed by three warm repeats (the cold first run is not counted), its
/// total time is the median repeat's between the fastest and slowest, and the results are those of a sweep without
/// repeats (the repeats change times, never answers).
#[test]
fn repeated_timings_change_times_not_results() {
    let dir = tempfile::tempdir().unwrap();
    let spec = small_spec(dir.path());
    let text =
        std::fs::read_to_string(&spec).unwrap().replace("name = \"small\"", "name = \"small\"\ntiming_repeats = 3");
    // The same file name in another folder: error messages name the spec's file.
    let other = dir.path().join("repeated");
    std::fs::create_dir(&other).unwrap();
    let repeated_spec = write(&other, "small.toml", &text);
    let (once, thrice) = (dir.path().join("once.csv"), dir.path().join("thrice.csv"));
    run_sweep(&spec, None, &once, false).unwrap();
    run_sweep(&repeated_spec, None, &thrice, false).unwrap();
    let (h1, r1) = read_csv(&once);
    let (h3, r3) = read_csv(&thrice);
    assert_eq!(h1, h3);
    assert_eq!(without_timing(&h1, &r1), without_timing(&h3, &r3));
    let col = |name: &str| h3.iter().position(|h| h == name).unwrap();
    let status = col("status");
    assert!(r3.iter().filter(|r| r[status] == "solved").count() >= 8);
    for row in r3.iter().filter(|r| r[status] == "solved") {
        assert_eq!(row[col("timing_runs")], "3", "{row:?}");
        let t = |name: &str| row[col(name)].parse::<f64>().unwrap();
        assert!(t("t_total_min") <= t("t_total") && t("t_total") <= t("t_total_max"), "{row:?}");
    }
    for row in r1.iter().filter(|r| r[status] == "solved") {
        assert_eq!(row[col("timing_runs")], "1", "a sweep without repeats times each run once: {row:?}");
    }
}
