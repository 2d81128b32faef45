//! The tests of `tests/seeds/sdiff_spec.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use crate::common;
use common::sdiff::data;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};

#[test]
fn sd_cli_normals_c1_handle_polygonize_run_and_write_their_files() {
    let bin = env!("CARGO_BIN_EXE_ppm");
    let dir = std::env::temp_dir().join(format!("sdiff_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mesh, kink) = (data("square.off"), data("kink_c1.toml"));
    let run =
        |args: &[&std::ffi::OsStr]| std::process::Command::new(bin).args(args).output().unwrap();
    let solved = dir.join("solved.toml");
    let out = run(&[
        "sd".as_ref(),
        "c1".as_ref(),
        mesh.as_os_str(),
        kink.as_os_str(),
        "-o".as_ref(),
        solved.as_os_str(),
        "--json".as_ref(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["id"] == "SD-E12" && r["verdict"] == "holds"));
    // The solved map is a diffeomorphism and 𝒪's one-sided normals agree (to the level shift).
    let out = run(&[
        "sd".as_ref(),
        "check".as_ref(),
        mesh.as_os_str(),
        solved.as_os_str(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    let out = run(&[
        "sd".as_ref(),
        "normals".as_ref(),
        mesh.as_os_str(),
        solved.as_os_str(),
        "--json".as_ref(),
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(
        v["points"][0]["curved_angle"].as_f64().unwrap() < 1e-9
            && v["points"][0]["dx_jumps"] == true
    );
    // The handle sweep fails as written (exit 1) and names its first witness.
    let out = run(&[
        "sd".as_ref(),
        "handle".as_ref(),
        mesh.as_os_str(),
        kink.as_os_str(),
        "--edge".as_ref(),
        "0,2".as_ref(),
        "--steps".as_ref(),
        "8".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("u_h = 1/8 needs λ = 61/42"));
    // Polygonization of the Fig. 4 circle writes 𝒪, O and the triangulation.
    let (c, l, m) = (dir.join("c.obj"), dir.join("l.obj"), dir.join("m.off"));
    let out = run(&[
        "sd".as_ref(),
        "polygonize".as_ref(),
        "--curve".as_ref(),
        "circle".as_ref(),
        "-o".as_ref(),
        c.as_os_str(),
        "--linear".as_ref(),
        l.as_os_str(),
        "--mesh".as_ref(),
        m.as_os_str(),
    ]);
    assert_eq!(out.status.code(), Some(1), "only the L302 erratum fails");
    assert!(String::from_utf8_lossy(&out.stdout).contains("FAILS    SD-L302"));
    for p in [&c, &l] {
        assert!(std::fs::read_to_string(p).unwrap().contains("\nl "));
    }
    let raw = read_mesh(&m, &ReadOptions::default()).unwrap();
    assert_eq!(raw.faces.len(), 186);
    let out = run(&[
        "sd".as_ref(),
        "polygonize".as_ref(),
        "--curve".as_ref(),
        "lemniscate".as_ref(),
        "-o".as_ref(),
        c.as_os_str(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}
