//! The tests of `tests/surface/sigma_v.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use crate::common;
use pseudomanifold::mesh::generate::icosahedron;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, RawMesh, SimplicialSurface};
use pseudomanifold::surface::sigma_v::*;
use pseudomanifold::surface::PnTriangles;

/// SPEC `SV-diff` (surfaces): `ppm diff --surface` takes the (σ, v) construction as the
/// reference. Its own `ppm sample` passes; the vertex construction's sampling does not; one
/// vertex moved by 1e-6 is the worst item; the construction has no f64 error analysis, so a
/// tolerance must be given (a typed error otherwise, exit 2), and the spot checks report the
/// reference's own error with no bound.
#[test]
fn sv_diff_surface_takes_the_sigma_v_reference() {
    use pseudomanifold::oracle::surface_diff::{diff_surface, SurfaceDiffOptions};
    use pseudomanifold::surface::{Pps, PpsOptions};
    use std::process::Command;
    let k = surface(&icosahedron());
    let pps = build(&k);
    let ours = pps.sample_surface(2).expect("sample");
    let opts = |t: Option<f64>| SurfaceDiffOptions {
        tolerance: t,
        ..SurfaceDiffOptions::default()
    };
    let r =
        diff_surface(&pps, &ours.positions, Some(&ours.faces), &opts(Some(1e-12))).expect("diff");
    assert!(r.within_tolerance, "{r:?}");
    assert_eq!((r.level, r.faces_identical), (2, Some(true)));
    assert!(r.reference.contains("(σ, v)"), "{}", r.reference);
    assert!(r.f64_bound.is_none() && r.spot_checks > 0);
    assert!(r.reference_error_max <= 1e-13, "{}", r.reference_error_max);
    assert!(r
        .worst
        .iter()
        .all(|w| w.mp.as_ref().is_some_and(|m| m.bound.is_none())));
    // No tolerance: no analysis to derive one from.
    let e = diff_surface(&pps, &ours.positions, None, &opts(None)).unwrap_err();
    assert!(e.to_string().contains("--tolerance"), "{e}");
    // A planted fault.
    let mut moved = ours.positions.clone();
    moved[17][2] += 1e-6;
    let r = diff_surface(&pps, &moved, Some(&ours.faces), &opts(Some(1e-12))).expect("diff");
    assert!(!r.within_tolerance && r.outside == 1);
    assert_eq!(r.worst[0].vertex, 17);
    // The vertex construction's surface is another surface.
    let pn = PnTriangles::new(&k);
    let vertex = Pps::try_build(&k, &pn, PpsOptions::default()).expect("vertex PPS");
    let theirs = pseudomanifold::surface::output::sample_surface(&vertex, 2, None).expect("sample");
    let r = diff_surface(&pps, &theirs.positions, None, &opts(Some(1e-12))).expect("diff");
    assert!(!r.within_tolerance && r.stats.max > 1e-6, "{}", r.stats.max);
    // The command line.
    let dir = std::env::temp_dir().join(format!("ppm_sv_diff_surface_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mesh = dir.join("ico.off");
    write_off(&k, &mesh);
    let sampled = dir.join("sv.off");
    pseudomanifold::surface::output::write_mesh_with_attributes(&sampled, &ours).unwrap();
    let run = |extra: &[&str]| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_ppm"));
        c.args(["diff", "--mesh"])
            .arg(&mesh)
            .arg("--surface")
            .arg(&sampled);
        c.args(extra).output().expect("run ppm")
    };
    let o = run(&["--construction", "sigma-v", "--tolerance", "1e-12"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{text}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        text.contains("(σ, v)") && text.contains("bound none"),
        "{text}"
    );
    let o = run(&["--construction", "sigma-v"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--tolerance"));
    let o = run(&[
        "--construction",
        "sigma-v",
        "--tolerance",
        "1e-12",
        "--sprime",
        "loop",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["--tolerance", "1e-12"]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "the vertex reference is another surface"
    );
    common::verdicts::record(
        "SV-diff",
        common::verdicts::Seen::Holds,
        ours.positions.len() as u64,
    );
}

/// `ppm diff` takes either construction as the reference of a JSON-lines table: eval answers
/// of the (σ, v) construction pass with `--construction sigma-v` and fail against the vertex
/// construction (the two surfaces differ); a planted error fails with its line; a
/// `set_construction` line inside a table is refused (the reference is the command line's).
#[test]
fn sv_diff_takes_either_construction_as_reference() {
    use pseudomanifold::oracle::Session;
    use std::process::Command;
    let k = surface(&icosahedron());
    let mut s = Session::with_surface(k.clone());
    assert!(
        s.handle_line(r#"{"op":"set_construction","construction":"sigma-v"}"#)
            .ok
    );
    let mut table = String::new();
    for (f, b) in [
        (0u32, [0.2, 0.3, 0.5]),
        (3, [0.6, 0.2, 0.2]),
        (7, [1.0, 0.0, 0.0]),
        (11, [0.0, 0.5, 0.5]),
        (19, [0.1, 0.1, 0.8]),
    ] {
        let line = format!(
            r#"{{"op":"eval","face":{f},"bary":[{},{},{}]}}"#,
            b[0], b[1], b[2]
        );
        let r = s.handle_line(&line);
        assert!(r.ok, "{r:?}");
        let v = r.f64.expect("f64 answer");
        table.push_str(&format!("{},\"value\":{v}}}\n", line.trim_end_matches('}')));
    }
    let dir = std::env::temp_dir().join(format!("ppm_sv_diff_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mesh = dir.join("ico.off");
    write_off(&k, &mesh);
    let good = dir.join("sv.jsonl");
    std::fs::write(&good, &table).unwrap();
    let run = |t: &std::path::Path, extra: &[&str]| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_ppm"));
        c.args(["diff", "--mesh"]).arg(&mesh).arg(t).args(extra);
        c.output().expect("run ppm")
    };
    let o = run(&good, &["--construction", "sigma-v"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{text}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(text.contains("sigma-v"), "{text}");
    // The same answers against the vertex construction: outside the tolerance.
    let o = run(&good, &[]);
    assert_eq!(o.status.code(), Some(1));
    // A planted error in one answer.
    let bad = dir.join("bad.jsonl");
    let mut lines: Vec<String> = table.lines().map(String::from).collect();
    let v: serde_json::Value = serde_json::from_str(&lines[1]).unwrap();
    let mut v2 = v.clone();
    v2["value"][0] = serde_json::json!(v["value"][0].as_f64().unwrap() + 1e-6);
    lines[1] = v2.to_string();
    std::fs::write(&bad, lines.join("\n") + "\n").unwrap();
    let o = run(&bad, &["--construction", "sigma-v"]);
    assert_eq!(o.status.code(), Some(1));
    // The reference cannot be switched from inside a table.
    let sw = dir.join("switch.jsonl");
    std::fs::write(
        &sw,
        format!("{{\"op\":\"set_construction\",\"construction\":\"vertex\"}}\n{table}"),
    )
    .unwrap();
    let o = run(&sw, &["--construction", "sigma-v"]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    // A κ outside (0, 1) is a usage error.
    let o = run(&good, &["--construction", "sigma-v", "--kappa", "1.5"]);
    assert_eq!(o.status.code(), Some(2));
    common::verdicts::record("SV-diff", common::verdicts::Seen::Holds, 5);
}

fn build(k: &SimplicialSurface) -> SigmaVPps {
    SigmaVPps::build(k, &PnTriangles::new(k), DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE).expect("κ valid")
}

fn surface(raw: &RawMesh) -> SimplicialSurface {
    validate(raw).surface.expect("valid fixture")
}

/// K as an OFF file, vertices and faces in K's order (the mesh a `ppm` command reads back).
fn write_off(k: &SimplicialSurface, path: &std::path::Path) {
    let mut off = format!("OFF\n{} {} 0\n", k.num_vertices(), k.num_faces());
    for v in k.vertices() {
        let p = k.position(v);
        off.push_str(&format!("{:?} {:?} {:?}\n", p[0], p[1], p[2]));
    }
    for f in 0..k.num_faces() {
        let c = k.face(FaceId(f as u32));
        off.push_str(&format!("3 {} {} {}\n", c[0].0, c[1].0, c[2].0));
    }
    std::fs::write(path, off).expect("write the OFF fixture");
}
