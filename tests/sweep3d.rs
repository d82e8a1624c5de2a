//! Sweeps of 3D half-space scenes (issue 32): the reference specs `reference/sweeps/hertz3d-convergence.toml` and
//! `cattaneo3d-load.toml` run through `rollbem sweep`; their rows agree with single runs of the same cases built by
//! another path (the base scene's document edited in memory and solved by `pipeline::run_space_scene`, as
//! `rollbem run` does), with Hertz's ellipse (Johnson §4.2(b), figures of the base scene's description) within the
//! convergence `pipeline::space_checks` documents, and with Cattaneo–Mindlin (Johnson §7.2, computed here). Resume
//! (after a SIGKILL, a torn journal, a cancellation), shards and merge give the uninterrupted CSV; a resume from a
//! CSV of another kind or spec is refused; bad keys are refused naming them, with nothing written.

#[path = "common/sweep_cli.rs"]
mod common;

use common::{bin, kill_at, masked, partial, run, write};
use rollbem::pipeline::run_space_scene;
use rollbem::scene::{SpaceScene, SpaceStatus};
use rollbem::sweep::{Kind, Plan, RowStatus, SweepOptions, SweepRow};
use std::path::{Path, PathBuf};

fn reference(p: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference").join(p)
}

/// Run a sweep spec to `out` and read its rows back.
fn sweep(spec: &Path, out: &Path) -> Vec<SweepRow> {
    run(bin().arg("sweep").arg(spec).arg("--out").arg(out));
    let (header, rows) = SweepRow::read_csv(out).unwrap();
    assert_eq!(header.kind, Kind::Space);
    rows
}

/// |a − b| ≤ rel·|b|.
fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// The largest of a row's four Hertz errors (semi-axes, peak pressure of the fit, approach).
fn hertz_err(r: &SweepRow) -> f64 {
    [r.space.hertz_a_x_err, r.space.hertz_a_y_err, r.metrics.hertz_p0_err, r.space.hertz_approach_err]
        .into_iter()
        .map(|e| e.expect("Hertz applies"))
        .fold(0.0, f64::max)
}

#[test]
fn hertz_convergence_rows_agree_with_single_runs_and_with_hertz() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sweep(&reference("sweeps/hertz3d-convergence.toml"), &dir.path().join("h.csv"));
    let grids = [(24, 12), (48, 24), (96, 48), (192, 96)];
    assert_eq!(rows.len(), grids.len(), "one row per case");
    let base = SpaceScene::from_file(&reference("scenes/half-space/hertz-ellipse.toml")).unwrap();
    for (r, &(mx, my)) in rows.iter().zip(&grids) {
        assert_eq!((r.solver.as_str(), r.status), ("half_space", RowStatus::Space(SpaceStatus::Solved)), "{r:?}");
        assert_eq!((r.space.mx, r.space.my), (Some(mx), Some(my)));
        assert_eq!(r.param("mesh.mx"), Some(mx.to_string().as_str()));
        // The same case by another path: the document edited in memory, solved once.
        let scene = base
            .edit(|d| {
                d.mesh.mx = mx;
                d.mesh.my = my;
            })
            .unwrap();
        let single = run_space_scene(&scene).unwrap();
        let s = single.steps.last().unwrap();
        assert_eq!(s.status, SpaceStatus::Solved);
        assert!(close(r.normal_load.unwrap(), s.load, 1e-12) && close(r.approach.unwrap(), s.approach, 1e-12));
        assert_eq!(
            (r.space.contact_count, r.space.stick_count, r.space.slip_count),
            (Some(s.contact), Some(0), Some(s.slip))
        );
        let peak = s.elements.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        assert!(close(r.space.peak_pressure.unwrap(), peak, 1e-12));
        assert_eq!(r.space.iterations_normal, Some(s.iterations_normal));
        // Where the run's own Hertz checks apply (from 20 elements across the minor axis), the row's errors are
        // theirs.
        for (what, err) in [
            ("semi-axis a_x", r.space.hertz_a_x_err),
            ("semi-axis a_y", r.space.hertz_a_y_err),
            ("peak pressure p0", r.metrics.hertz_p0_err),
            ("approach", r.space.hertz_approach_err),
        ] {
            if let Some(c) = single.checks.iter().find(|c| c.name.contains(&format!("Hertz {what}"))) {
                assert!(close(err.unwrap(), c.error, 1e-9), "{what}: {err:?} against the run's {}", c.error);
            }
        }
        // Hertz's ellipse of the base scene's description (Johnson §4.2(b)): a_x = 0.5930, a_y = 0.2967 mm,
        // p0 = 271.3 MPa at P = 100 N, to those digits.
        let h = (r.space.hertz_a_x.unwrap(), r.space.hertz_a_y.unwrap(), r.hertz_p0.unwrap());
        assert!((h.0 - 0.5930).abs() < 6e-5 && (h.1 - 0.2967).abs() < 6e-5 && (h.2 - 271.3).abs() < 0.06, "{h:?}");
        // The grid covers 1.2 times the ellipse: MY/1.2 elements across the minor axis.
        assert!(close(r.space.elements_across.unwrap(), my as f64 / 1.2, 1e-3));
    }
    // Convergence as `pipeline::space_checks` documents it: the largest of the four errors 0.17 % at 20 and
    // 0.018 % at 40 elements across (bounds 0.2 % and 0.02 % here), within the check's 1.5 % from 20 on, and
    // falling with every refinement, 10 → 80.
    let errs: Vec<f64> = rows.iter().map(hertz_err).collect();
    assert!(errs[1] <= 2e-3 && errs[2] <= 2e-4, "{errs:?}");
    assert!(errs[1..].iter().all(|&e| e <= rollbem::tolerances::HERTZ_CONSTANT), "{errs:?}");
    assert!(errs.windows(2).all(|w| w[1] < w[0]), "not converging: {errs:?}");
}

#[test]
fn cattaneo_load_rows_agree_with_single_runs_and_with_cattaneo_mindlin() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sweep(&reference("sweeps/cattaneo3d-load.toml"), &dir.path().join("c.csv"));
    assert_eq!(rows.len(), 10);
    let base = SpaceScene::from_file(&reference("sweeps/bases/cattaneo3d-load.toml")).unwrap();
    // Johnson §3.4 and §7.2 for two identical half-spaces with ν = 0 (G = E/2), h = 0.01 (x² + y²): R = 50 mm,
    // E* = E/2, a = (3PR/(4E*))^(1/3); δ(Q) = 3μP/(16a) · 2(2 − ν)/G · [1 − (1 − Q/μP)^(2/3)].
    let (e, p, mu) = (210000.0_f64, 10000.0_f64, 0.3_f64);
    let a = (3.0 * p * 50.0 / (4.0 * e / 2.0)).cbrt();
    let slide = 3.0 * mu * p / (16.0 * a) * 2.0 * 2.0 / (e / 2.0);
    let mut seen = 0;
    for r in &rows {
        assert_eq!(r.status, RowStatus::Space(SpaceStatus::Solved), "{r:?}");
        let q = r.param("steps[1].tangential_load").unwrap();
        let q: f64 = q.trim_matches(['[', ']']).split(',').next().unwrap().trim().parse().unwrap();
        let ratio = q / (mu * p);
        // The force on body 1 is the swept one; body 1 moves by −δ along it.
        assert!(close(r.space.force_x.unwrap(), q, 1e-9), "{r:?}");
        assert!(close(-r.space.shift_x.unwrap(), slide * (1.0 - (1.0 - ratio).powf(2.0 / 3.0)), 0.01), "{q}");
        assert!(close(r.metrics.cm_c_over_a_exact.unwrap(), (1.0 - ratio).cbrt(), 1e-3), "{q}");
        // The stick radius from the stick area, within one element of c = a (1 − Q/μP)^(1/3).
        let (dx, dy) = (r.space.dx.unwrap(), r.space.dy.unwrap());
        let c = (r.space.stick_count.unwrap() as f64 * dx * dy / std::f64::consts::PI).sqrt();
        assert!((c - a * (1.0 - ratio).cbrt()).abs() <= dx.max(dy), "{q}: c = {c}");
        assert!(r.metrics.cm_c_err_elements.unwrap() <= 1.0 && r.space.cm_transfer_err.unwrap() <= 0.01, "{r:?}");
        // The same case by another path.
        let (mx, my) = (r.space.mx.unwrap(), r.space.my.unwrap());
        let scene = base
            .edit(|d| {
                d.mesh.mx = mx;
                d.mesh.my = my;
                d.steps[1].tangential_load = Some([q, 0.0]);
            })
            .unwrap();
        let single = run_space_scene(&scene).unwrap();
        let s = single.steps.last().unwrap();
        assert_eq!((r.space.stick_count, r.space.slip_count), (Some(s.stick), Some(s.slip)), "{q}");
        assert!(close(r.space.shift_x.unwrap(), s.shift.unwrap()[0], 1e-9), "{q}");
        assert_eq!(r.space.steps, Some(single.steps.len()));
        seen += 1;
    }
    assert_eq!(seen, 10);
}

/// A 3D spec of eight cases (two grids, four forces) on the Cattaneo base, by absolute path.
fn cattaneo_spec(dir: &Path, name: &str) -> PathBuf {
    write(
        dir,
        &format!("{name}.toml"),
        &format!(
            "name = \"{name}\"\nbase = '{}'\n[[grid]]\n\"mesh.mx & mesh.my\" = [[30, 30], [44, 44]]\n\
             \"steps[1].tangential_load\" = [[600.0, 0.0], [1200.0, 0.0], [1800.0, 0.0], [2400.0, 0.0]]\n",
            reference("sweeps/bases/cattaneo3d-load.toml").display()
        ),
    )
}

#[test]
fn a_3d_sweep_resumes_shards_and_merges_to_the_uninterrupted_csv() {
    let dir = tempfile::tempdir().unwrap();
    let spec = cattaneo_spec(dir.path(), "c3");
    let whole = dir.path().join("whole.csv");
    run(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole));
    let reference = masked(&whole);
    assert_eq!(reference.1.len(), 8);

    // SIGKILLed once three cases or more are in the journal (a case's row is about 700 bytes), the journal then torn
    // inside its last line, resumed: the cut line dropped, the last complete case run again, the others kept.
    let out = dir.path().join("killed.csv");
    let head = {
        let probe = dir.path().join("probe.csv");
        kill_at(bin().arg("sweep").arg(&spec).arg("--out").arg(&probe), &probe, 1, 0);
        let text = std::fs::read_to_string(partial(&probe)).unwrap();
        text.split_inclusive('\n').take(3).map(str::len).sum::<usize>() as u64
    };
    assert!(
        kill_at(bin().arg("sweep").arg(&spec).arg("--out").arg(&out), &out, head + 2200, 0),
        "finished before the kill"
    );
    let journal = std::fs::read(partial(&out)).unwrap();
    let cut = journal.len() - 5;
    std::fs::write(partial(&out), &journal[..cut]).unwrap();
    let said = run(bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume"));
    let ran: usize = said.split(" cases run now").next().unwrap().rsplit('(').next().unwrap().parse().unwrap();
    assert!((1..8).contains(&ran), "{said}");
    assert_eq!(masked(&out), reference);
    assert!(!partial(&out).exists());

    // Cancelled before its first case (the library's token): the journal stays, holding no case; a resume ends it.
    let cancelled = dir.path().join("cancelled.csv");
    let cancel = rollbem::cancel::Cancel::new();
    cancel.cancel();
    let options = SweepOptions { cancel, ..SweepOptions::default() };
    let e = Plan::new(&spec, &cancelled, &options).unwrap().run().unwrap_err();
    assert!(matches!(e, rollbem::Error::Cancelled), "{e}");
    assert!(partial(&cancelled).exists() && !cancelled.exists());
    let options = SweepOptions { resume: true, ..SweepOptions::default() };
    let outcome = Plan::new(&spec, &cancelled, &options).unwrap().run().unwrap();
    assert_eq!((outcome.rows, outcome.ran), (8, 8));
    assert_eq!(masked(&cancelled), reference);

    // Two shards, merged with --spec.
    let shards: Vec<PathBuf> = (1..=2).map(|k| dir.path().join(format!("s{k}.csv"))).collect();
    for (k, s) in shards.iter().enumerate() {
        run(bin().arg("sweep").arg(&spec).arg("--shard").arg(format!("{}/2", k + 1)).arg("--out").arg(s));
    }
    let merged = dir.path().join("merged.csv");
    run(bin().arg("sweep-merge").arg(&merged).args(&shards).arg("--spec").arg(&spec));
    assert_eq!(masked(&merged), reference);
}

/// Run `rollbem sweep` expecting bad input: exit 2, nothing written; returns standard error.
fn refused(args: &[&std::ffi::OsStr], out: &Path) -> String {
    let o = bin().arg("sweep").args(args).arg("--out").arg(out).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{err}");
    err
}

#[test]
fn a_3d_resume_refuses_a_csv_of_another_kind_or_spec() {
    let dir = tempfile::tempdir().unwrap();
    let spec = cattaneo_spec(dir.path(), "c3");
    // A finished 2D sweep's CSV where the 3D sweep's output goes.
    let plane = write(
        dir.path(),
        "p.toml",
        &format!(
            "name = \"p\"\nbase = '{}'\n[[grid]]\n\"drive.normal_load\" = [1000.0]\n\"solvers.use\" = [[\"lemke\"]]\n",
            reference("scenes/half-plane-hertz.toml").display()
        ),
    );
    let out = dir.path().join("out.csv");
    run(bin().arg("sweep").arg(&plane).arg("--out").arg(&out));
    let before = std::fs::read(&out).unwrap();
    let err = refused(&[spec.as_os_str(), "--resume".as_ref()], &out);
    assert!(err.contains("2D scenes") && err.contains("3D half-space scenes"), "{err}");
    assert_eq!(std::fs::read(&out).unwrap(), before, "the CSV is left as it was");
    // And the other way: a finished 3D CSV resumed by the 2D spec.
    let out3 = dir.path().join("out3.csv");
    run(bin().arg("sweep").arg(&spec).arg("--out").arg(&out3));
    let err = refused(&[plane.as_os_str(), "--resume".as_ref()], &out3);
    assert!(err.contains("3D half-space scenes") && err.contains("2D scenes"), "{err}");
    // A 3D journal of another spec (same cases, another name): refused naming the name.
    let killed = dir.path().join("k.csv");
    kill_at(bin().arg("sweep").arg(&spec).arg("--out").arg(&killed), &killed, 1, 0);
    assert!(partial(&killed).exists());
    let renamed = write(dir.path(), "c4.toml", &std::fs::read_to_string(&spec).unwrap().replace("\"c3\"", "\"c4\""));
    let err = refused(&[renamed.as_os_str(), "--resume".as_ref()], &killed);
    assert!(err.contains("the spec's name was `c3`, it is `c4` now"), "{err}");
}

#[test]
fn bad_keys_of_a_3d_sweep_are_refused_by_name_with_nothing_written() {
    let dir = tempfile::tempdir().unwrap();
    let hertz = reference("scenes/half-space/hertz-ellipse.toml");
    let cattaneo = reference("sweeps/bases/cattaneo3d-load.toml");
    let plane = reference("scenes/half-plane-hertz.toml");
    let cases: Vec<(String, &str, &str)> = vec![
        // A 2D key in a 3D scene.
        (
            format!("base = '{}'\n[[grid]]\n\"mesh.contact_elements\" = [10]\n", hertz.display()),
            "mesh.contact_elements",
            "2D",
        ),
        // A key no scene has.
        (format!("base = '{}'\n[[grid]]\n\"mesh.nx\" = [10]\n", hertz.display()), "mesh.nx", "unknown key"),
        // A value out of range.
        (format!("base = '{}'\n[[grid]]\n\"mesh.mx\" = [10, 0]\n", hertz.display()), "mesh.mx", "case 1"),
        // A step the base scene does not have.
        (
            format!("base = '{}'\n[[grid]]\n\"steps[2].normal_load\" = [1.0]\n", cattaneo.display()),
            "steps[2].normal_load",
            "2 entries",
        ),
        // Cases of both kinds in one sweep.
        (
            format!(
                "base = '{}'\n[[grid]]\n\"mesh.mx\" = [20]\n[[grid]]\nbase = '{}'\n\"drive.normal_load\" = [1000.0]\n",
                hertz.display(),
                plane.display()
            ),
            "wheel.model",
            "all 2D or all 3D",
        ),
        // An analysis of 2D sweeps (its own check of the grid passes: it sweeps a key named like the one it needs).
        (
            format!(
                "analysis = \"creep_curve\"\nbase = '{}'\n[[grid]]\n\"drive.tangential_load\" = [[1.0, 0.0]]\n",
                hertz.display()
            ),
            "analysis",
            "2D sweeps",
        ),
    ];
    for (k, (body, key, why)) in cases.iter().enumerate() {
        let spec = write(dir.path(), &format!("bad{k}.toml"), &format!("name = \"bad{k}\"\n{body}"));
        let out = dir.path().join(format!("bad{k}.csv"));
        let err = refused(&[spec.as_os_str()], &out);
        assert!(err.contains(key) && err.contains(why), "{key}: {err}");
        assert!(!out.exists() && !partial(&out).exists(), "{key}: something was written");
    }
}
