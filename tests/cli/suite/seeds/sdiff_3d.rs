//! The tests of `tests/seeds/sdiff_3d.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use std::path::{Path, PathBuf};

#[test]
fn sd_cli_3_d_check3_iso3_claims3_exit_codes() {
    let exe = env!("CARGO_BIN_EXE_ppm");
    let run = |args: &[&str]| {
        let out = std::process::Command::new(exe)
            .args(args)
            .output()
            .expect("ppm runs");
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).to_string(),
            String::from_utf8_lossy(&out.stderr).to_string(),
        )
    };
    let d = |n: &str| data(n).to_string_lossy().to_string();
    let (code, out, _) = run(&["sd", "check3", &d("cube6.tets"), &d("cube6_monotonic.toml")]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("SD-L101(det,3-D)"));
    let (code, out, _) = run(&[
        "sd",
        "check3",
        &d("cube6.tets"),
        &d("planted3_fold.toml"),
        "--json",
    ]);
    assert_eq!(code, Some(1), "{out}");
    assert!(serde_json::from_str::<serde_json::Value>(&out).is_ok());
    let dir = std::env::temp_dir().join(format!("ppm_sd3_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let curved = dir.join("curved.obj");
    let linear = dir.join("linear.off");
    let (code, out, err) = run(&[
        "sd",
        "iso3",
        &d("lshape.tets"),
        &d("lshape_cubic.toml"),
        "-o",
        &curved.to_string_lossy(),
        "--linear",
        &linear.to_string_lossy(),
        "--level",
        "3",
    ]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(std::fs::read_to_string(&curved).unwrap().starts_with("v "));
    assert!(std::fs::read_to_string(&linear).unwrap().starts_with("OFF"));
    // Invalid input: exit 2 with the file named.
    let bad = dir.join("bad.tets");
    std::fs::write(&bad, format!("{CORNER}t 0 2 1 3\n")).unwrap();
    let (code, _, err) = run(&[
        "sd",
        "check3",
        &bad.to_string_lossy(),
        &d("cube6_monotonic.toml"),
    ]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("bad.tets") && err.contains("SD-K(3-D)-orientation"),
        "{err}"
    );
    let (code, out, _) = run(&["sd", "claims3", "--samples", "2"]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("SD-L161(3-D)"));
    let _ = std::fs::remove_dir_all(&dir);
}

const CORNER: &str = "tets\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/sdiff")
        .join(name)
}
