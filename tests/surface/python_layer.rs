//! The library functions the Python layer (python/, docs/python.md) calls instead of the
//! command line, held to the command line's behaviour (SPEC `PY-*`).

use pseudomanifold::certify::{all_configs, merge, run_with, shard, Certificate, Model, Settings};
use pseudomanifold::cli::check::check_report;
use pseudomanifold::cli::{main_from, parse_check_spec_args};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::FaceId;
use pseudomanifold::surface::jet::Jet2;
use pseudomanifold::surface::{Consts, PnTriangles, Pps, PpsOptions};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn without_seconds(mut v: Value) -> Value {
    if let Some(o) = v.as_object_mut() {
        o.remove("seconds");
    }
    v
}

/// `check()` of the Python layer is `cli::check::check_report` on the mesh read as `ppm
/// check` reads it, with the options parsed by the command's own parser: its serde JSON is
/// the command's `--json` output (all but the wall time), and `passes` is its exit status.
#[test]
fn py_check_report_library_equals_cli_json() {
    for (file, flags) in [
        (
            "icosahedron_binary_le.ply",
            vec!["--max-configs", "2", "--samples", "4", "--seed", "7"],
        ),
        (
            "octahedron.obj",
            vec!["--max-configs", "1", "--samples", "3", "--no-surface"],
        ),
        (
            "tetrahedron.off",
            vec!["--max-configs", "1", "--samples", "2"],
        ),
    ] {
        let path = data(file);
        let out = Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(["check", "--spec", "--json"])
            .args(&flags)
            .arg(&path)
            .output()
            .expect("run ppm");
        let cli: Value = serde_json::from_slice(&out.stdout).expect("ppm check --json is JSON");
        let raw = read_mesh(&path, &ReadOptions::default()).expect("bundled mesh reads");
        let args = parse_check_spec_args(flags.iter().copied()).expect("flags parse");
        let rep = check_report(&raw, false, Some(&args), false).expect("report");
        let lib = serde_json::to_value(&rep).expect("serialises");
        assert_eq!(without_seconds(lib), without_seconds(cli), "{file}");
        assert_eq!(rep.passes(), out.status.success(), "{file}");
    }
    // Options are validated by the command's parser and its option checks.
    assert!(parse_check_spec_args(["--no-such-flag"]).is_err());
    let raw = read_mesh(&data("tetrahedron.off"), &ReadOptions::default()).expect("reads");
    let bad = parse_check_spec_args(["--precision", "mp:1"]).expect("parses");
    assert!(check_report(&raw, false, Some(&bad), false).is_err());
    crate::common::verdicts::record("PY-check-report", crate::common::verdicts::Seen::Holds, 3);
}

/// The `ppm` console script of the Python package runs `cli::main_from`: the same commands
/// and exit statuses as the binary (2: unreadable file, 1: not a simplicial surface).
#[test]
fn py_cli_main_from_is_the_command_line() {
    let ok = main_from([
        "ppm",
        "check",
        &data("tetrahedron.off").display().to_string(),
    ]);
    assert_eq!(ok, ExitCode::SUCCESS);
    let missing = main_from(["ppm", "check", "/nonexistent/mesh.off"]);
    assert_eq!(missing, ExitCode::from(2));
    // One triangle: read fine, but it has a boundary (Def. 3.1.6).
    let open = std::env::temp_dir().join(format!("ppm_py_cli_{}.off", std::process::id()));
    std::fs::write(&open, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").expect("temp file");
    let code = main_from(["ppm", "check", &open.display().to_string()]);
    let _ = std::fs::remove_file(&open);
    assert_eq!(code, ExitCode::from(1));
    crate::common::verdicts::record("PY-cli", crate::common::verdicts::Seen::Holds, 3);
}

/// The run-dependent parts cleared: timings, thread count, and the order of the results (a
/// run lists them in proving order, `merge` sorts them by configuration and property).
fn strip(mut c: Certificate) -> Certificate {
    c.wall_millis = 0;
    c.jobs = 0;
    for r in &mut c.results {
        r.millis = 0;
        if let Some(f) = r.f64_rounding.as_mut() {
            f.millis = 0; // the f64 rounding bound's own time (CERT-f64-rounding)
        }
        if let Some(g) = r.g_chart.as_mut() {
            g.millis = 0; // the whole-chart g_v bound's own time (CERT-f64-g-chart)
        }
    }
    c.results
        .sort_by(|a, b| (a.key, &a.property).cmp(&(b.key, &b.property)));
    c
}

/// `pseudomanifold.distributed.certify` runs shard K of N (`certify::shard`) as tasks and
/// joins them with `certify::merge`: the merge equals the unsharded run of `ppm certify`
/// (timings, thread count and result order aside).
#[test]
fn py_certify_shards_merged_equal_the_unsharded_run() {
    // Small: certification costs ~50 CPU-s already at M = 5 (docs/python.md).
    let m = 4;
    let all = all_configs(m);
    let s = Settings::default();
    let whole = run_with(&all, m, &Model::paper(), &s, 2, None, None).expect("certify");
    // One split into uneven shards (22 configurations, 3 shards of 8, 7, 7): each extra N
    // costs a whole certification again.
    let n = 3;
    let parts: Vec<Certificate> = (1..=n)
        .map(|k| {
            run_with(
                &shard(&all, k, n),
                m,
                &Model::paper(),
                &s,
                1,
                Some((k, n)),
                None,
            )
            .expect("shard")
        })
        .collect();
    let merged = merge(parts).expect("merge");
    assert_eq!(merged.configs, all.len());
    assert_eq!(strip(merged), strip(whole));
    crate::common::verdicts::record(
        "PY-certify-shards",
        crate::common::verdicts::Seen::Holds,
        all.len() as u64,
    );
}

/// The Python `eval` gives positions from plain f64 eval (`attributes="positions"`) or from the
/// order-2 jets that also give normals and curvatures: both are the same eval of Sec. 6.1.4,
/// to rounding (the testing helper compares positions with the first, normals and curvatures
/// with the second).
#[test]
fn py_eval_positions_from_f64_and_jets_agree() {
    let raw =
        read_mesh(&data("icosahedron_binary_le.ply"), &ReadOptions::default()).expect("reads");
    let k = validate(&raw).surface.expect("surface");
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let cj: Consts<Jet2<f64>> = pps.consts(53);
    let mut worst = 0.0f64;
    let mut n = 0u64;
    for f in 0..pps.num_faces() as u32 {
        for (i, j) in [(0, 0), (1, 2), (3, 1), (2, 5), (7, 0), (4, 4)] {
            let a = i as f64 / 8.0;
            let b = j as f64 / 8.0;
            let bary = [1.0 - a - b, a, b];
            let p = pps.eval_f64(FaceId(f), bary).expect("eval");
            let g = pps
                .eval_geometry_of_order(FaceId(f), bary, &cj)
                .expect("jets")
                .2;
            for (a, b) in p.iter().zip(g.point) {
                // NaN-propagating: a NaN coordinate must fail the bound below.
                worst = pseudomanifold::report::dev_max(worst, (a - b).abs());
            }
            n += 1;
        }
    }
    assert!(worst <= 1e-13, "worst {worst:e}");
    crate::common::verdicts::record("PY-eval-positions", crate::common::verdicts::Seen::Holds, n);
}

/// python/ is a crate of its own (its own `[workspace]`, the root crate by path), so `cargo
/// test` at the root neither builds nor depends on PyO3.
#[test]
fn py_crate_separate_from_the_root_crate() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let top = std::fs::read_to_string(root.join("Cargo.toml")).expect("Cargo.toml");
    // The root workspace holds the crate and its benchmarks only: python/ is never a member
    // (nor fuzz/), so `cargo test` at the root does not build it.
    let members = top
        .lines()
        .find(|l| l.starts_with("members = "))
        .expect("the root workspace lists its members");
    assert_eq!(members, r#"members = [".", "benches"]"#);
    assert!(!top.contains("pyo3"));
    let benches = std::fs::read_to_string(root.join("benches/Cargo.toml")).expect("benches");
    assert!(!benches.contains("pyo3"));
    let py = std::fs::read_to_string(root.join("python/Cargo.toml")).expect("python/Cargo.toml");
    assert!(py.contains("[workspace]"));
    assert!(py.contains("path = \"..\""));
    assert!(py.contains("cdylib"));
    let pyproject = std::fs::read_to_string(root.join("python/pyproject.toml")).expect("pyproject");
    assert!(pyproject.contains("build-backend = \"maturin\""));
    crate::common::verdicts::record("PY-crate-separate", crate::common::verdicts::Seen::Holds, 1);
}
