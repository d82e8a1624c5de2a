//! Creep-force tables (issue 36, item 4; `src/creeptable/`): the entries against direct calls and theory, the
//! documented layout of the CSV and the `.npz`, the readers' round trip, shards, resume and merge against the serial
//! run (byte for byte), and bad input (exit 2, nothing written). The same tables run as a SLURM job array in
//! `tests/slurm.rs`.

use rollbem::creeptable::{run_table, CreepTable, TableOptions, TableRow, TABLE_COLUMNS};
use rollbem::fastsim::{self, Contact, Creepages};
use rollbem::sweep::Shard;
use rollbem::theory::kalker::creep_coefficients;
use std::path::{Path, PathBuf};
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

fn spec(dir: &Path, name: &str, engine: &str, extra: &str, axes: &str) -> PathBuf {
    let text = format!("kind = \"creep_table\"\nname = \"{name}\"\nengine = \"{engine}\"\n{extra}\n[axes]\n{axes}\n");
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(&p, text).unwrap();
    p
}

const SMALL_AXES: &str = "nu = [0.25, 0.5]\na_over_b = [0.2, 1.0, 5.0]\nxi = [0.0, 0.1, 0.45, 1.2]\n\
                          eta = [-0.3, 0.0, 0.2]\nphi = [-0.5, 0.0, 0.4]";

fn whole() -> TableOptions {
    TableOptions::default()
}

#[test]
fn fastsim_entries_equal_direct_calls() {
    // Expected: each row is `fastsim::creep_forces` (Kalker's original FASTSIM on 100 × 100 strips, the table's
    // default engine and grid) called here on the physical case, which this test builds itself from the documented
    // normalisation (a = c√(a/b), b = c/√(a/b); ξ = −ξ'·3μN/(G c² C11), η = −η'·3μN/(G c² C22),
    // φ = −φ'·μN/(G c³ C23); Fx' = Fx/(μN), Mz' = Mz/(μN c)) with G = 80 000, μ = 0.3, N = 10 000, c = 6.
    let dir = tempfile::tempdir().unwrap();
    let extra = "[contact]\nshear_modulus = 80000.0\nfriction = 0.3\nnormal_force = 10000.0\nsize = 6.0";
    let p = spec(dir.path(), "fs", "fastsim", extra, SMALL_AXES);
    let out = dir.path().join("fs.csv");
    let o = run_table(&p, &out, &whole()).unwrap();
    assert_eq!((o.total, o.ran), (2 * 3 * 4 * 3 * 3, 216));
    let rows = TableRow::read_csv(&out).unwrap();
    let (g, mu, n, c) = (80_000.0, 0.3, 10_000.0, 6.0);
    for r in &rows {
        let (a, b) = (c * r.a_over_b.sqrt(), c / r.a_over_b.sqrt());
        let k = creep_coefficients(r.a_over_b, 1.0, r.nu).unwrap();
        let cr = Creepages {
            xi: -r.xi_n * 3.0 * mu * n / (g * c * c * k.c11),
            eta: -r.eta_n * 3.0 * mu * n / (g * c * c * k.c22),
            phi: -r.phi_n * mu * n / (g * c * c * c * k.c23),
        };
        for (got, want) in [(r.a, a), (r.b, b), (r.xi, cr.xi), (r.eta, cr.eta), (r.phi, cr.phi)] {
            assert!((got - want).abs() <= 1e-14 * want.abs().max(1e-300), "case {}: {got} vs {want}", r.case);
        }
        let contact = Contact { a: r.a, b: r.b, shear_modulus: g, nu: r.nu, mu, normal_force: n };
        let f = fastsim::creep_forces(&contact, &Creepages { xi: r.xi, eta: r.eta, phi: r.phi }).unwrap();
        assert_eq!([r.fx, r.fy, r.mz], [Some(f.fx), Some(f.fy), Some(f.mz)], "case {}", r.case);
        assert_eq!(r.fx_n, Some(f.fx / (mu * n)));
        assert_eq!(r.mz_n, Some(f.mz / (mu * n * c)));
        assert!(r.status == "solved" || r.status == "gross_sliding", "{}", r.status);
    }
    // Gross sliding is every element slipping: at ξ' = 1.2 alone (beyond Kalker's saturation at ξ' = 1).
    let at = |xi: f64, eta: f64, phi: f64| {
        rows.iter().find(|r| r.nu == 0.25 && r.a_over_b == 1.0 && (r.xi_n, r.eta_n, r.phi_n) == (xi, eta, phi)).unwrap()
    };
    assert_eq!(at(1.2, 0.0, 0.0).status, "gross_sliding");
    assert_eq!(at(0.1, 0.0, 0.0).status, "solved");
}

#[test]
fn fastrip_entries_equal_direct_calls() {
    // Expected: each row is `fastsim::fastrip` (FaStrip with CONTACT's blended flexibilities, Hertz's pressure as the
    // bound, on the table's 30 × 20 strips) called here on the physical case the row states (its a, b and creepages;
    // the normalisation itself is checked by `fastsim_entries_equal_direct_calls`), to the bit.
    let dir = tempfile::tempdir().unwrap();
    let p = spec(dir.path(), "fr", "fastrip", "[grid]\nmx = 30\nmy = 20", SMALL_AXES);
    let out = dir.path().join("fr.csv");
    run_table(&p, &out, &whole()).unwrap();
    let rows = TableRow::read_csv(&out).unwrap();
    let grid = fastsim::Grid::Strips { mx: 30, my: 20 };
    let options = fastsim::Options {
        bound: fastsim::Bound::Elliptic,
        flexibility: fastsim::Flexibility::Blended,
        direction: fastsim::Direction::PlusX,
        grid,
    };
    let mut slipping = 0;
    for r in &rows {
        let contact = Contact { a: r.a, b: r.b, shear_modulus: 1.0, nu: r.nu, mu: 1.0, normal_force: 1.0 };
        let s = fastsim::fastrip(&contact, &Creepages { xi: r.xi, eta: r.eta, phi: r.phi }, &options).unwrap();
        assert_eq!([r.fx, r.fy, r.mz], [Some(s.fx), Some(s.fy), Some(s.mz)], "case {}", r.case);
        assert_eq!(r.engine, "fastrip");
        slipping += usize::from(r.status == "gross_sliding");
    }
    assert!(slipping > 0, "the grid reaches full sliding");
    // A bad option is refused naming it.
    let bad = spec(dir.path(), "bad", "fastrip", "[options]\nbound = \"parabolic\"", SMALL_AXES);
    let o = bin().arg("sweep").arg(&bad).arg("--out").arg(dir.path().join("bad.csv")).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("options.bound"), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Kalker's simplified theory with one flexibility and the parabolic bound, ξ alone, in closed form per strip: a strip
/// of half-length l = a√(1 − y²/b²) adheres from its leading edge while l + x > d, d = (9π/16) ξ' a, and carries
/// μp0/a² (2l²d − l d² + d³/6) (4l³/3 where d ≥ 2l: all slip), p0 = 2N/(πab); Fx' is the integral over y divided by
/// μN (Simpson on 200 000 intervals; the integrand is continuous).
fn simplified_theory_fx(xi_n: f64) -> f64 {
    let (a, b, mu_p0) = (1.0f64, 1.0f64, 1.0f64);
    let d = 9.0 * std::f64::consts::PI * xi_n / 16.0 * a;
    let f = |y: f64| {
        let l = a * (1.0 - (y / b).powi(2)).max(0.0).sqrt();
        let s = if 2.0 * l > d { 2.0 * l * l * d - l * d * d + d.powi(3) / 6.0 } else { 4.0 * l.powi(3) / 3.0 };
        s * mu_p0 / (a * a)
    };
    let m = 200_000;
    let h = 2.0 * b / m as f64;
    let sum: f64 = (0..=m)
        .map(|i| {
            f(-b + i as f64 * h)
                * if i == 0 || i == m {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                }
        })
        .sum();
    sum * h / 3.0 / (mu_p0 * std::f64::consts::PI * a * b / 2.0)
}

#[test]
fn fastsim_table_follows_the_simplified_theory_for_xi_alone() {
    // Expected: the closed form above (independent of FASTSIM's marching), within 5e-4 of μN on 100 × 100 strips:
    // Fx' = 0.26994 at ξ' = 0.1 (the linear theory's 3ξ' = 0.3; FASTSIM measured 0.26997), saturating towards 1.
    let dir = tempfile::tempdir().unwrap();
    let axes = "nu = [0.28]\na_over_b = [1.0]\nxi = [0.05, 0.1, 0.3, 0.6, 0.9, 1.5]\neta = [0.0]\nphi = [0.0]";
    let p = spec(dir.path(), "sat", "fastsim", "", axes);
    let out = dir.path().join("sat.csv");
    run_table(&p, &out, &whole()).unwrap();
    for r in TableRow::read_csv(&out).unwrap() {
        let want = simplified_theory_fx(r.xi_n);
        let got = r.fx_n.unwrap();
        assert!((got - want).abs() < 5e-4, "xi' = {}: {got} vs {want}", r.xi_n);
        assert!(r.fy_n.unwrap().abs() < 1e-12);
    }
    assert!((simplified_theory_fx(0.1) - 0.26994).abs() < 1e-5);
}

#[test]
fn kalker_linear_entries_equal_coefficients_times_creepages() {
    // Expected: Kalker's linear theory, Fx = −G c² C11 ξ, Fy = −G c² (C22 η + c C23 φ), Mz = G c³ C23 η (φ = 0),
    // with C_ij read from Table E.3 here: a/b = 1, ν = 1/4: 4.12, 3.67, 1.47; a/b = 5: 7.78, 8.14, 6.63; a/b = 0.2:
    // 3.37, 2.63, 0.603. In normalised form Fx' = 3ξ', Fy' = 3η' + φ', Mz' = −3η' C23/C22; no Mz with spin (C33
    // is not in the table): an empty cell, not a number.
    let dir = tempfile::tempdir().unwrap();
    let extra = "[contact]\nshear_modulus = 2.0\nfriction = 0.5\nnormal_force = 3.0\nsize = 1.5";
    let axes = "nu = [0.25]\na_over_b = [0.2, 1.0, 5.0]\nxi = [-0.2, 0.0, 0.3]\neta = [0.0, 0.25]\nphi = [-0.1, 0.0]";
    let p = spec(dir.path(), "lin", "kalker_linear", extra, axes);
    let out = dir.path().join("lin.csv");
    run_table(&p, &out, &whole()).unwrap();
    let table_e3 = |r: f64| {
        if r == 1.0 {
            [4.12, 3.67, 1.47]
        } else if r == 5.0 {
            [7.78, 8.14, 6.63]
        } else {
            [3.37, 2.63, 0.603]
        }
    };
    let (g, c) = (2.0, 1.5);
    let rows = TableRow::read_csv(&out).unwrap();
    assert_eq!(rows.len(), 36);
    for r in &rows {
        let [c11, c22, c23] = table_e3(r.a_over_b);
        for (got, want) in [(r.c11, c11), (r.c22, c22), (r.c23, c23)] {
            // The table's nodes up to the round-off of its interpolation in ν.
            assert!((got - want).abs() < 1e-14 * want, "case {}: the CSV's coefficient {got} vs {want}", r.case);
        }
        let close = |got: Option<f64>, want: f64| {
            let got = got.unwrap();
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "case {}: {got} vs {want}", r.case);
        };
        close(r.fx, -g * c * c * c11 * r.xi);
        close(r.fy, -g * c * c * (c22 * r.eta + c * c23 * r.phi));
        close(r.fx_n, 3.0 * r.xi_n);
        close(r.fy_n, 3.0 * r.eta_n + r.phi_n);
        if r.phi_n == 0.0 {
            close(r.mz, g * c * c * c * c23 * r.eta);
            close(r.mz_n, -3.0 * r.eta_n * c23 / c22);
        } else {
            assert_eq!((r.mz, r.mz_n), (None, None), "case {}", r.case);
        }
        assert_eq!(r.status, "solved");
    }
    let line = std::fs::read_to_string(&out).unwrap().lines().nth(1).unwrap().to_string();
    assert!(line.contains(",solved,") && line.contains(",,"), "the empty Mz cell: {line}");
}

#[test]
fn layout_is_the_documented_one_and_the_readers_round_trip() {
    // Expected: the README's layout ("Creep-force tables"): these columns in this order; cases numbered with φ'
    // fastest, then η', ξ', a/b, ν; the .npz holds forces (nν, n_ab, nξ, nη, nφ, 3), status, the axes and the
    // coefficients; the CSV and the .npz read back to the same table, bit for bit, and the .npz written again is the
    // same bytes.
    let documented = "case,nu,a_over_b,xi_n,eta_n,phi_n,status,fx_n,fy_n,mz_n,engine,a,b,c11,c22,c23,xi,eta,phi,\
                      fx,fy,mz,residual,contact_elements,slip_elements,case_digest,message";
    assert_eq!(TABLE_COLUMNS.join(","), documented);
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    assert!(
        readme.replace(['\n', ' '], "").contains(&format!("`{}`", documented.replace(',', "`,`"))),
        "README documents the columns"
    );
    let dir = tempfile::tempdir().unwrap();
    let p = spec(dir.path(), "lay", "fastsim", "[grid]\nmx = 30\nmy = 20", SMALL_AXES);
    let out = dir.path().join("lay.csv");
    run_table(&p, &out, &whole()).unwrap();
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text.lines().next().unwrap(), documented);
    let rows = TableRow::read_csv(&out).unwrap();
    let (nu, ab, xi, eta, phi) =
        ([0.25, 0.5], [0.2, 1.0, 5.0], [0.0, 0.1, 0.45, 1.2], [-0.3, 0.0, 0.2], [-0.5, 0.0, 0.4]);
    let mut i = 0;
    for &n in &nu {
        for &r in &ab {
            for &x in &xi {
                for &e in &eta {
                    for &f in &phi {
                        let row = &rows[i];
                        assert_eq!(
                            (row.case, row.nu, row.a_over_b, row.xi_n, row.eta_n, row.phi_n),
                            (i, n, r, x, e, f)
                        );
                        i += 1;
                    }
                }
            }
        }
    }
    let from_csv = CreepTable::read_csv(&out).unwrap();
    let npz = out.with_extension("npz");
    let from_npz = CreepTable::read_npz(&npz).unwrap();
    let bits = |t: &CreepTable| t.forces.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&from_csv), bits(&from_npz));
    assert_eq!(
        (&from_csv.axes, &from_csv.status, &from_csv.coefficients),
        (&from_npz.axes, &from_npz.status, &from_npz.coefficients)
    );
    assert_eq!(from_npz.axes.shape(), [2, 3, 4, 3, 3]);
    // The forces of case 0 are at [0, 0, 0, 0, 0] and of the last case at the last index.
    assert_eq!(from_npz.at([0, 0, 0, 0, 0]).unwrap()[0].to_bits(), rows[0].fx_n.unwrap().to_bits());
    assert_eq!(from_npz.at([1, 2, 3, 2, 2]).unwrap()[1].to_bits(), rows[215].fy_n.unwrap().to_bits());
    let again = dir.path().join("again.npz");
    from_csv.write_npz(&again).unwrap();
    assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(&npz).unwrap());
    // The .npy header of `forces` as NumPy's format writes it.
    let bytes = std::fs::read(&npz).unwrap();
    let header = b"{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3, 4, 3, 3, 3), }";
    assert!(bytes.windows(header.len()).any(|w| w == header));
}

#[test]
fn shards_merged_and_a_resumed_run_equal_the_serial_table_byte_for_byte() {
    // Expected: each case's row depends on nothing but the case, so three shards merged, and a run whose journal
    // was cut mid-line and resumed, write the serial run's CSV and .npz byte for byte.
    let dir = tempfile::tempdir().unwrap();
    let p = spec(dir.path(), "sh", "fastsim", "[grid]\nmx = 24\nmy = 24", SMALL_AXES);
    let serial = dir.path().join("serial.csv");
    run_table(&p, &serial, &whole()).unwrap();
    let shards: Vec<PathBuf> = (1..=3)
        .map(|k| {
            let out = dir.path().join(format!("shard-{k}-of-3.csv"));
            let o = run_table(&p, &out, &TableOptions { shard: Some(Shard { k, n: 3 }), ..whole() }).unwrap();
            assert_eq!((o.cases, o.npz), (72, None));
            out
        })
        .collect();
    let merged = dir.path().join("merged.csv");
    let code = bin().arg("sweep-merge").arg("--spec").arg(&p).arg(&merged).args(&shards).status().unwrap();
    assert!(code.success());
    assert_eq!(std::fs::read(&merged).unwrap(), std::fs::read(&serial).unwrap());
    assert_eq!(
        std::fs::read(merged.with_extension("npz")).unwrap(),
        std::fs::read(serial.with_extension("npz")).unwrap()
    );
    // A merge missing a shard, or holding one twice, is refused (exit 2) and writes nothing.
    let bad = dir.path().join("bad.csv");
    let o = bin().arg("sweep-merge").arg("--spec").arg(&p).arg(&bad).args(&shards[..2]).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("is in none of the shards"));
    let o = bin().arg("sweep-merge").arg(&bad).args([&shards[0], &shards[0]]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(!bad.exists() && !bad.with_extension("npz").exists());
    // A journal cut in the middle of a line (a killed run) resumes to the serial table.
    let out = dir.path().join("resumed.csv");
    let journal = dir.path().join("resumed.csv.partial");
    let serial_text = std::fs::read_to_string(&serial).unwrap();
    let head: String = serial_text.lines().skip(1).take(100).map(|l| format!("{l}\n")).collect();
    let first = {
        run_table(&p, &out, &whole()).unwrap();
        std::fs::remove_file(&out).unwrap();
        std::fs::remove_file(out.with_extension("npz")).unwrap();
        // The journal's identity line, as a run writes it.
        let probe = dir.path().join("probe.csv");
        let child = bin().arg("sweep").arg(&p).arg("--out").arg(&probe).arg("--dry-run").output().unwrap();
        assert!(child.status.success());
        format!(
            "# rollbem creep-table journal; version={}; spec=sh; shard=whole; digest={}\n",
            env!("CARGO_PKG_VERSION"),
            rollbem::creeptable::TableSpec::from_file(&p).unwrap().digest("flexibility=weighted bound=parabolic")
        )
    };
    let cut = &serial_text.lines().nth(101).unwrap()[..20];
    std::fs::write(&journal, format!("{first}{}{head}{cut}", serial_text.lines().next().unwrap().to_string() + "\n"))
        .unwrap();
    let o = run_table(&p, &out, &TableOptions { resume: true, ..whole() }).unwrap();
    assert_eq!((o.resumed, o.ran), (100, 116));
    assert_eq!(std::fs::read(&out).unwrap(), serial_text.as_bytes());
    assert!(!journal.exists());
    // Resumed again from the finished output: nothing runs.
    let o = run_table(&p, &out, &TableOptions { resume: true, ..whole() }).unwrap();
    assert_eq!((o.resumed, o.ran), (216, 0));
    // A journal of another table is refused, naming why.
    std::fs::write(&journal, "# rollbem creep-table journal; version=0; spec=other; shard=whole; digest=0\n").unwrap();
    let e = run_table(&p, &out, &TableOptions { resume: true, ..whole() }).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().contains("spec=other"), "{e}");
}

#[test]
fn bad_specs_exit_2_naming_the_key_and_write_nothing() {
    // Expected: README "Creep-force tables": every refusal names its key; nothing is written.
    let dir = tempfile::tempdir().unwrap();
    let good = "nu = [0.25]\na_over_b = [1.0]\nxi = [0.0]\neta = [0.0]\nphi = [0.0]";
    let cases = [
        ("fastsim", "", good.replace("a_over_b = [1.0]", "a_over_b = [1.0, 20.0]"), "axes.a_over_b[1]"),
        ("fastsim", "", good.replace("xi = [0.0]", "xi = [0.5, 0.1]"), "axes.xi[1]"),
        ("fastsim", "", good.replace("nu = [0.25]", "nu = [0.7]"), "axes.nu[0]"),
        ("fastsim", "", good.replace("phi = [0.0]", "phi = []"), "axes.phi"),
        ("fastsim", "", good.replace("eta = [0.0]\n", ""), "axes.eta"),
        ("fastsim", "[options]\nflexibility = \"two\"", good.to_string(), "options.flexibility"),
        ("fastsim", "[options]\nsmoothing = \"yes\"", good.to_string(), "options.smoothing"),
        ("kalker_linear", "[options]\nx = \"y\"", good.to_string(), "options.x"),
        ("exact_theory", "", good.to_string(), "engine"),
        ("exact", "[options]\nmargin = 0.5", good.to_string(), "options.margin"),
        ("exact", "[options]\nsmoothing = 1.0", good.to_string(), "options.smoothing"),
        ("fastsim", "[contact]\nfriction = 0.0", good.to_string(), "contact.friction"),
        ("fastsim", "[contact]\nload = 1.0", good.to_string(), "contact.load"),
        ("fastsim", "[grid]\nmx = 0", good.to_string(), "grid.mx"),
        ("fastsim", "colour = 1", good.to_string(), "colour"),
    ];
    for (i, (engine, extra, axes, key)) in cases.iter().enumerate() {
        let p = spec(dir.path(), &format!("bad{i}"), engine, extra, axes);
        let out = dir.path().join(format!("bad{i}.csv"));
        let o = bin().arg("sweep").arg(&p).arg("--out").arg(&out).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{key}: {err}");
        assert!(err.contains(&format!("`{key}`")), "{key}: {err}");
        assert!(
            !out.exists()
                && !out.with_extension("npz").exists()
                && !dir.path().join(format!("bad{i}.csv.partial")).exists()
        );
    }
}

#[test]
fn fastsim_command_prints_and_writes_the_library_answer() {
    // Expected: `rollbem fastsim --json -` holds what `fastsim::solve` returns for the same arguments (the same
    // library code: equal to the last bit through JSON's shortest round-trip numbers); bad input exits 2 naming the
    // flag.
    let args = [
        "fastsim",
        "--a",
        "6",
        "--b",
        "4",
        "--shear-modulus",
        "82000",
        "--nu",
        "0.28",
        "--mu",
        "0.3",
        "--normal-force",
        "10000",
        "--xi",
        "-2e-4",
        "--eta",
        "1e-4",
        "--phi",
        "0.001",
        "--flexibility",
        "blended",
        "--bound",
        "elliptic",
        "--mx",
        "40",
        "--my",
        "30",
        "--json",
        "-",
    ];
    let o = bin().args(args).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let contact = Contact { a: 6.0, b: 4.0, shear_modulus: 82_000.0, nu: 0.28, mu: 0.3, normal_force: 10_000.0 };
    let options = fastsim::Options {
        bound: fastsim::Bound::Elliptic,
        flexibility: fastsim::Flexibility::Blended,
        direction: fastsim::Direction::PlusX,
        grid: fastsim::Grid::Strips { mx: 40, my: 30 },
    };
    let s = fastsim::solve(&contact, &Creepages { xi: -2e-4, eta: 1e-4, phi: 0.001 }, &options).unwrap();
    assert_eq!(doc["fx"].as_f64(), Some(s.fx));
    assert_eq!(doc["fy"].as_f64(), Some(s.fy));
    assert_eq!(doc["mz"].as_f64(), Some(s.mz));
    assert_eq!(doc["n_slip"].as_u64(), Some(s.n_slip as u64));
    assert!(String::from_utf8_lossy(&o.stderr).contains("Fx = "));
    for (flag, value) in [("--b", "100"), ("--mu", "-1"), ("--bound", "flat"), ("--mx", "0"), ("--xi", "nan")] {
        let mut a: Vec<&str> = args[..args.len() - 2].to_vec();
        let at = a.iter().position(|x| *x == flag).unwrap();
        a[at + 1] = value;
        let o = bin().args(&a).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{flag}: {err}");
        assert!(err.contains(&format!("`{flag}`")) || (flag == "--b" && err.contains("`--a`")), "{flag}: {err}");
    }
}

#[test]
fn a_cancelled_table_keeps_its_journal_and_resumes() {
    // Expected: a raised cancel stops the run before its next chunk (Error::Cancelled, exit 130) with the journal
    // kept and no output; --resume then writes the table a plain run writes, byte for byte.
    let dir = tempfile::tempdir().unwrap();
    let p = spec(dir.path(), "cn", "kalker_linear", "", SMALL_AXES);
    let out = dir.path().join("cn.csv");
    let cancel = rollbem::cancel::Cancel::new();
    cancel.cancel();
    let e = rollbem::creeptable::run_table_with(&p, &out, &whole(), &cancel).unwrap_err();
    assert_eq!(e.exit_code(), 130);
    assert!(!out.exists() && dir.path().join("cn.csv.partial").exists());
    let o = run_table(&p, &out, &TableOptions { resume: true, ..whole() }).unwrap();
    assert_eq!((o.resumed, o.ran), (0, 216));
    let plain = dir.path().join("plain.csv");
    run_table(&p, &plain, &whole()).unwrap();
    assert_eq!(std::fs::read(&out).unwrap(), std::fs::read(&plain).unwrap());
}
