//! The tests of `tests/surface/python_layer.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use pseudomanifold::cli::check::check_report;
use pseudomanifold::cli::parse_check_spec_args;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

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
