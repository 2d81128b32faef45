//! The tests of `tests/seeds/msplines.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use crate::common;
use pseudomanifold::mesh::generate;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;

/// The CLI: `ppm msplines sample` writes a closed mesh of the torus's spline surface and
/// reports its edge counts; on an open mesh it exits 1 naming the boundary (Thm. 3 row).
#[test]
fn ms_sample_ms_t3_cli_sample_torus_and_refuse_open_mesh() {
    let dir = std::env::temp_dir().join(format!("ms_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    // The sampling part needs the corpus torus; the refusal below runs without ../shared.
    if let Some(torus_path) = corpus_torus_path("ms_sample_ms_t3_cli_sample_torus") {
        let out = dir.join("spline.obj");
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(["msplines", "sample"])
            .arg(&torus_path)
            .arg("--out")
            .arg(&out)
            .args(["--level", "1"])
            .output()
            .expect("ppm runs");
        let err = String::from_utf8_lossy(&o.stderr);
        println!("{err}");
        assert!(o.status.success(), "{err}");
        assert!(err.contains("0 otherwise"), "{err}");
        let back = read_mesh(&out, &ReadOptions::default()).expect("reads back");
        assert!(validate(&back).surface.is_some(), "closed surface");
    }
    let open = dir.join("open.off");
    std::fs::write(
        &open,
        "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n3 0 3 1\n",
    )
    .expect("write");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["msplines", "check"])
        .arg(&open)
        .output()
        .expect("ppm runs");
    let err = String::from_utf8_lossy(&o.stderr);
    println!("{err}");
    assert_eq!(o.status.code(), Some(1), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `ppm sample --construction manifold-spline` (the spline as a run-time choice of surface)
/// samples the same spline as `ppm msplines sample` (the same defaults: form 0, degree 2, the
/// same seed, 3-ring charts): the same points, and not none.
#[test]
fn ms_sample_ms_t3_ppm_sample_manifold_spline_equals_msplines_sample() {
    let raw = generate::torus(12, 8);
    let (dir, mesh) = common::temp_off("ms_choice", "torus.off", &raw);
    let run = |args: &[&str]| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(args)
            .output()
            .expect("ppm runs");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    let (a, b) = (dir.join("choice.obj"), dir.join("msplines.obj"));
    let m = mesh.to_str().expect("utf-8 path");
    let (sa, sb) = (a.to_str().expect("utf-8"), b.to_str().expect("utf-8"));
    run(&[
        "sample",
        m,
        "--construction",
        "manifold-spline",
        "--level",
        "1",
        "--attributes",
        "positions",
        "-o",
        sa,
        "--quiet",
    ]);
    run(&[
        "msplines", "sample", m, "--level", "1", "--out", sb, "--quiet",
    ]);
    let ra = read_mesh(&a, &ReadOptions::default()).expect("reads back");
    let rb = read_mesh(&b, &ReadOptions::default()).expect("reads back");
    // Level 1: every face of the 12 × 8 torus split in four.
    assert_eq!(ra.faces.len(), 4 * raw.faces.len());
    assert_eq!(ra.faces, rb.faces);
    assert_eq!(ra.positions, rb.positions);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `../shared/meshes/good/torus.obj`, or None (skip recorded for `test`) without ../shared.
fn corpus_torus_path(test: &str) -> Option<std::path::PathBuf> {
    common::shared_path(test, "meshes/good/torus.obj")
}
