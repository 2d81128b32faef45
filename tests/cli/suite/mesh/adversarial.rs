//! The tests of `tests/mesh/adversarial.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use pseudomanifold::mesh::generate::{bipyramid, octahedron};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::output::sample_surface;
use pseudomanifold::surface::*;

fn ppm(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(args)
        .output()
        .expect("run ppm")
}

fn ppm_stdin(args: &[&str], input: &[u8]) -> std::process::Output {
    use std::io::Write;
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("spawn ppm");
    let mut stdin = child.stdin.take().expect("stdin");
    let data = input.to_vec();
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(&data);
    });
    let out = child.wait_with_output().expect("wait ppm");
    let _ = writer.join();
    out
}

/// The (σ,v) patches support degrees 1..=15 (SPEC SV-D11): a degree outside is refused at the
/// command line, not rounded into the range.
#[test]
fn sv_d11_patch_degree_outside_the_supported_range_is_refused() {
    let out_ply = std::env::temp_dir().join(format!("sv_d11_{}.ply", std::process::id()));
    let out_ply = out_ply.to_string_lossy().into_owned();
    for d in ["0", "16"] {
        for args in [
            &["check", "--spec", "--patch-degree", d, OCTAHEDRON][..],
            &[
                "sample",
                OCTAHEDRON,
                "--level",
                "0",
                "-o",
                &out_ply,
                "--construction",
                "sigma-v",
                "--patch-degree",
                d,
            ][..],
        ] {
            let out = ppm(args);
            assert_eq!(out.status.code(), Some(2), "{args:?} accepted");
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(err.contains("1..=15"), "{args:?}: {err}");
        }
    }
    assert!(!std::path::Path::new(&out_ply).exists());
}

/// Coordinates near the f64 range: a tetrahedron scaled to 1e308 was sampled to all-NaN
/// coordinates with exit 0 (and condition (C) "held" with tolerance 0); at 1e±77 the normals
/// vanished. Such meshes are refused with a typed error; inside the accepted range the sampled
/// normals are unit vectors and the positions scale.
#[test]
fn x_adv_03_coordinates_near_f64_range_r_scale_range() {
    use pseudomanifold::mesh::generate::tetrahedron;
    let scaled = |s: f64| {
        let mut raw = tetrahedron();
        for p in &mut raw.positions {
            for c in p.iter_mut() {
                *c *= s;
            }
        }
        raw
    };
    for s in [1e308, 1e77, 1e61] {
        let k = surface(&scaled(s));
        assert!(
            matches!(
                Pps::try_build(&k, &PnTriangles::new(&k), PpsOptions::default()),
                Err(SurfaceError::CoordinateOutOfRange { .. })
            ),
            "scale {s:e} accepted"
        );
    }
    for s in [1e-77, 1e-61] {
        let k = surface(&scaled(s));
        assert!(
            matches!(
                Pps::try_build(&k, &PnTriangles::new(&k), PpsOptions::default()),
                Err(SurfaceError::ExtentTooSmall { .. })
            ),
            "scale {s:e} accepted"
        );
    }
    let unit = sample_surface(&build(&surface(&scaled(1.0))), 1, None).expect("sample");
    for s in [1e50, 1e-50] {
        let k = surface(&scaled(s));
        let pps =
            Pps::try_build(&k, &PnTriangles::new(&k), PpsOptions::default()).expect("in range");
        let m = sample_surface(&pps, 1, None).expect("sample");
        for (i, (p, q)) in m.positions.iter().zip(&unit.positions).enumerate() {
            for d in 0..3 {
                assert!(
                    (p[d] / s - q[d]).abs() <= 1e-9 * (1.0 + q[d].abs()),
                    "scale {s:e}, vertex {i}: {p:?} vs {q:?}"
                );
            }
            let n = m.normals[i];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!(
                (len - 1.0).abs() < 1e-9,
                "scale {s:e}, vertex {i}: normal {n:?}"
            );
        }
    }
    let path = tmp("x_adv_03.off");
    std::fs::write(
        &path,
        "OFF\n4 4 0\n1e308 1e308 1e308\n1e308 -1e308 -1e308\n-1e308 1e308 -1e308\n-1e308 -1e308 1e308\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    )
    .expect("write");
    let out_file = tmp("x_adv_03_out.off");
    let _ = std::fs::remove_file(&out_file);
    let out = ppm(&[
        "sample",
        path.to_str().expect("utf-8"),
        "-o",
        out_file.to_str().expect("utf-8"),
        "--quiet",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!out_file.exists(), "NaN output written");
    crate::common::verdicts::record("R-scale-range", crate::common::verdicts::Seen::Holds, 1);
}

/// `ppm diff --surface` passed a surface that is missing (3 vertices against a 66-point
/// reference: the reverse distances were printed, then ignored), a level-2 file checked as
/// level 3, and an empty table; `load`/`set_precision` lines inside a table silently changed
/// the reference for the lines after them.
#[test]
fn x_adv_04_diff_surface_missing_points_r_diff_two_sided() {
    use pseudomanifold::oracle::diff::diff_table;
    use pseudomanifold::oracle::surface_diff::{diff_surface, SurfaceDiffOptions};
    use pseudomanifold::oracle::Session;
    let k = surface(&octahedron());
    let pps = build(&k);
    let l2 = sample_surface(&pps, 2, None).expect("level 2").positions;
    let opts = |level| SurfaceDiffOptions {
        level,
        spot_checks: 2,
        worst: 2,
        ..SurfaceDiffOptions::default()
    };
    let full = diff_surface(&pps, &l2, None, &opts(None)).expect("diff");
    assert!(full.within_tolerance, "our own level-2 sampling must pass");
    let three = diff_surface(&pps, &l2[..3], None, &opts(Some(2))).expect("diff");
    assert!(three.stats.max <= three.tolerance, "the 3 points are on M");
    assert!(!three.within_tolerance, "3 of {} points passed", l2.len());
    assert!(three.reference_missing.unwrap_or(0) > 0);
    let wrong_level = diff_surface(&pps, &l2, None, &opts(Some(3))).expect("diff");
    assert!(!wrong_level.within_tolerance, "level 2 checked as level 3");
    assert_eq!(wrong_level.count_matches_level, Some(2));

    let mut s = Session::with_surface(k.clone());
    let r = diff_table(&mut s, "", 1e-12, 5);
    assert!(
        !r.within_tolerance && r.stats.count == 0,
        "empty table passed"
    );
    let phi = r#"{"op":"h","p":[0.25,0.5],"value":[0.75,-0.5]}"#;
    let r = diff_table(&mut s, phi, 1e-12, 5);
    assert!(r.within_tolerance, "{:?}", r.problems);
    for op in [
        r#"{"op":"load","path":"/nonexistent.off"}"#,
        r#"{"op":"set_precision","bits":2}"#,
        r#"{"op":"set_profile","profile":"authors-code"}"#,
    ] {
        let r = diff_table(&mut s, &format!("{op}\n{phi}\n"), 1e-12, 5);
        assert!(!r.within_tolerance, "{op} accepted");
        assert_eq!(r.problems.len(), 1);
        assert_eq!(r.problems[0].line, 1);
        assert_eq!(r.stats.count, 1, "the later line is still compared");
        assert_eq!(s.bits(), 256, "{op} changed the session");
    }
    let out = ppm(&["diff", "--mesh", OCTAHEDRON, "/dev/null"]);
    assert_eq!(out.status.code(), Some(1), "empty table");
    assert!(String::from_utf8_lossy(&out.stdout).contains("NOTHING COMPARED"));
    crate::common::verdicts::record("R-diff-two-sided", crate::common::verdicts::Seen::Holds, 1);
}

/// `check --spec --samples 1..3` reported "UNEXPECTED failures: P4.1.3, P4.2.1" on valid
/// meshes (no sample landed in a lens, taken as proof that it is empty), and `--max-configs 0`
/// passed with nothing examined.
#[test]
fn x_adv_06_too_few_samples_is_not_a_failure_r_few_samples() {
    use pseudomanifold::conditions::chapter4::{run_chapter4, Ch4Options};
    use pseudomanifold::report::Verdict;
    let k = surface(&octahedron());
    for samples in 1..=3 {
        let r = run_chapter4(
            &k,
            &Ch4Options {
                samples,
                ..Ch4Options::default()
            },
        );
        assert!(
            r.unexpected_failures.is_empty(),
            "--samples {samples}: {:?}",
            r.unexpected_failures
        );
        assert!(r.inconclusive.is_none());
        for id in ["P4.1.3", "P4.2.1"] {
            let c = r.checks.iter().find(|c| c.id == id).expect(id);
            // Too few samples: inconclusive (skipped) or holding on what was sampled, never
            // a failure (R-few-samples).
            assert!(
                c.holds_with_evidence() || matches!(c.verdict(), Verdict::Skipped { .. }),
                "{id} at --samples {samples}: {:?}",
                c.verdict()
            );
        }
        let c = r.checks.iter().find(|c| c.id == "P4.1.3").expect("P4.1.3");
        if samples == 1 {
            assert!(
                matches!(c.verdict(), Verdict::Skipped { .. }),
                "{:?}",
                c.verdict()
            );
        }
    }
    let r = run_chapter4(
        &k,
        &Ch4Options {
            max_edge_configs: Some(0),
            max_triangle_configs: Some(0),
            max_star_configs: Some(0),
            ..Ch4Options::default()
        },
    );
    assert!(r.inconclusive.is_some(), "nothing examined passed");
    for args in [
        &[
            "check",
            "--spec",
            "--no-surface",
            "--max-configs",
            "0",
            OCTAHEDRON,
        ][..],
        &["check", "--spec", "--samples", "0", OCTAHEDRON][..],
    ] {
        let out = ppm(args);
        assert_ne!(out.status.code(), Some(0), "{args:?} passed");
    }
    crate::common::verdicts::record("R-few-samples", crate::common::verdicts::Seen::Holds, 1);
}

/// High-degree vertices: the paper profile's l = max(m + 1, 7) makes the fit grow like m⁴ in
/// memory and m⁶ in time (degree 128: past 60 s, degree 200: out of memory, and an oracle
/// session died on `eval`). The size is estimated before building and refused with a typed
/// error naming the vertex, degree and memory; the oracle answers a JSON error and keeps the
/// session.
#[test]
fn x_adv_08_high_degree_fit_refused_r_fit_budget() {
    use pseudomanifold::surface::admissible::{check_fit_size, fit_bytes, FIT_MEMORY_LIMIT};
    let k = surface(&bipyramid(128));
    match Pps::try_build(&k, &PnTriangles::new(&k), PpsOptions::default()) {
        Err(e @ SurfaceError::FitTooLarge { .. }) => {
            let SurfaceError::FitTooLarge {
                v,
                degree,
                l,
                bytes,
                limit,
                ..
            } = &e
            else {
                unreachable!()
            };
            assert_eq!((*degree, *l), (128, 129));
            assert!(v.0 < 2, "an apex is named");
            assert!(*bytes > *limit && *limit == FIT_MEMORY_LIMIT);
            let msg = e.to_string();
            assert!(
                msg.contains("authors-code") && msg.contains("degree 128"),
                "{msg}"
            );
        }
        other => panic!("degree 128 accepted: {:?}", other.map(|_| ())),
    }
    // The estimate is monotone and admits the degrees the paper profile handles in seconds.
    assert!(fit_bytes(70, Profile::Paper).1 < fit_bytes(71, Profile::Paper).1);
    assert!(check_fit_size(&surface(&bipyramid(60)), Profile::Paper).is_ok());
    assert!(check_fit_size(&k, Profile::AuthorsCode).expect("authors-code") < 1 << 24);
    let path = tmp("x_adv_08.off");
    let raw = bipyramid(200);
    let mut off = format!("OFF\n{} {} 0\n", raw.positions.len(), raw.faces.len());
    for p in &raw.positions {
        off.push_str(&format!("{} {} {}\n", p[0], p[1], p[2]));
    }
    for f in &raw.faces {
        off.push_str(&format!("3 {} {} {}\n", f[0], f[1], f[2]));
    }
    std::fs::write(&path, off).expect("write");
    let p = path.to_str().expect("utf-8 path");
    let out = ppm_stdin(
        &["oracle", "--mesh", p],
        b"{\"op\":\"eval\",\"face\":0,\"bary\":[0.2,0.3,0.5]}\n{\"op\":\"degree\",\"v\":0}\n",
    );
    let r = replies(&out);
    assert_eq!(r.len(), 2, "{r:?}");
    assert_eq!(r[0]["error"]["kind"], "refused", "{}", r[0]);
    assert_eq!(r[1]["value"], 200);
    let out = ppm(&["eval", p, "0", "0.2", "0.3", "0.5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("degree 200"));
    crate::common::verdicts::record("R-fit-budget", crate::common::verdicts::Seen::Holds, 1);
}

/// `ppm oracle` buffered the rest of an over-long line without bound (a 4 GB line aborted the
/// process) and a 2 MiB line got a garbled reply: the line is now skipped chunk by chunk and
/// answered "line longer than 1 MiB", and the session goes on.
#[test]
fn x_adv_11_oracle_over_long_line() {
    let mut input = vec![b'x'; 2 << 20];
    input.push(b'\n');
    input.extend_from_slice(b"{\"op\":\"degree\",\"v\":0}\n");
    input.extend(std::iter::repeat_n(b' ', 3 << 20));
    let out = ppm_stdin(&["oracle", "--mesh", OCTAHEDRON], &input);
    let r = replies(&out);
    assert_eq!(r.len(), 3, "{r:?}");
    for i in [0, 2] {
        assert!(
            r[i]["error"]["message"]
                .as_str()
                .is_some_and(|m| m.contains("line longer than 1 MiB")),
            "{}",
            r[i]
        );
    }
    assert_eq!(r[1]["value"], 4);
}

/// `sample --level` above 12 was silently clamped to 12 (and level 12 then aborted on
/// allocation): now the output size is estimated and a level beyond the budget is refused.
#[test]
fn x_adv_12_sample_level_clamped_silently() {
    use pseudomanifold::surface::output::{sample_estimate, sample_pattern, SAMPLE_MEMORY_LIMIT};
    let k = surface(&octahedron());
    let pps = build(&k);
    for level in [13, 14, 31, u32::MAX] {
        match sample_pattern(&pps, level) {
            Err(SurfaceError::LevelTooLarge {
                level: l, bytes, ..
            }) => {
                assert_eq!(l, level);
                assert!(bytes > SAMPLE_MEMORY_LIMIT || level > 30);
            }
            other => panic!(
                "level {level}: expected LevelTooLarge, got {:?}",
                other.map(|p| p.points.len())
            ),
        }
    }
    let p = sample_pattern(&pps, 3).expect("level 3");
    assert_eq!(
        p.points.len(),
        8 * 64 / 2 + 2,
        "octahedron level 3: 4^3·F/2 + 2 points"
    );
    assert!(sample_estimate(8, 3).0 >= p.points.len() as u128);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["figure", "--degrees", "4294967295,5", "-o"])
        .arg(std::env::temp_dir().join("x_adv_12.svg"))
        .output()
        .expect("run ppm");
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `ppm eval` accepted NaN, ±∞ and out-of-simplex barycentrics (printing NaN into JSON);
/// `eval-map --bits 0|1` was accepted.
#[test]
fn x_adv_13_eval_accepts_nan_barycentrics() {
    let k = surface(&octahedron());
    let pps = build(&k);
    let cj = pps.consts::<Jet<f64>>(53);
    for b in [
        [f64::NAN, 0.5, 0.5],
        [f64::INFINITY, 0.0, 0.0],
        [-0.5, 1.5, 0.0],
        [2.0, 2.0, 2.0],
    ] {
        assert!(
            matches!(
                pps.eval_geometry(FaceId(1), b, &cj),
                Err(SurfaceError::BadBarycentric(_))
            ),
            "{b:?} accepted"
        );
    }
    let bin = env!("CARGO_BIN_EXE_ppm");
    let mesh = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/octahedron.obj");
    let out = std::process::Command::new(bin)
        .args(["eval", mesh, "1", "NaN", "0.5", "0.5"])
        .output()
        .expect("run ppm");
    assert_eq!(out.status.code(), Some(1));
    assert!(
        out.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    for bits in ["0", "1"] {
        let out = std::process::Command::new(bin)
            .args(["eval-map", mesh, "0", "1", "0.3", "0.1", "--bits", bits])
            .output()
            .expect("run ppm");
        assert_eq!(out.status.code(), Some(2), "--bits {bits} accepted");
    }
}

/// `check --precision` accepted up to 10⁶ bits while the oracle stopped at 65536 and the scalar
/// type rounded silently into its own range: one limit (`numeric::PREC_BITS`) now holds
/// at every boundary, and one bit past it is refused.
#[test]
fn x_adv_13_precision_above_the_one_limit_refused_at_every_boundary() {
    let past = (pseudomanifold::numeric::PREC_BITS.end() + 1).to_string();
    let mp = format!("mp:{past}");
    for args in [
        &[
            "eval-map", OCTAHEDRON, "0", "1", "0.3", "0.1", "--bits", &past,
        ][..],
        &["oracle", "--mesh", OCTAHEDRON, "--bits", &past][..],
        &["diff", "--mesh", OCTAHEDRON, "/dev/null", "--bits", &past][..],
        &["check", "--spec", "--precision", &mp, OCTAHEDRON][..],
    ] {
        let out = ppm(args);
        assert_eq!(out.status.code(), Some(2), "{args:?} accepted");
    }
    let out = ppm_stdin(
        &["oracle", "--mesh", OCTAHEDRON],
        format!("{{\"op\":\"set_precision\",\"bits\":{past}}}\n").as_bytes(),
    );
    for r in replies(&out) {
        assert_eq!(r["error"]["kind"], "bad_precision", "{r}");
    }
}

/// The multi-precision type clamps a precision of 0 or 1 bits silently: every boundary where
/// a user gives a precision refuses it instead (eval-map, oracle, diff, check --precision).
#[test]
fn x_adv_13_precision_below_2_refused_at_every_boundary() {
    for args in [
        &[
            "eval-map", OCTAHEDRON, "0", "1", "0.3", "0.1", "--bits", "1",
        ][..],
        &["oracle", "--mesh", OCTAHEDRON, "--bits", "1"][..],
        &["diff", "--mesh", OCTAHEDRON, "/dev/null", "--bits", "0"][..],
        &["check", "--spec", "--precision", "mp:1", OCTAHEDRON][..],
    ] {
        let out = ppm(args);
        assert_eq!(out.status.code(), Some(2), "{args:?} accepted");
    }
    let out = ppm_stdin(
        &["oracle", "--mesh", OCTAHEDRON],
        b"{\"op\":\"set_precision\",\"bits\":1}\n{\"op\":\"set_precision\",\"bits\":0}\n",
    );
    for r in replies(&out) {
        assert_eq!(r["error"]["kind"], "bad_precision", "{r}");
    }
}

/// Oracle replies broke the documented shape (`"f64": [null, null]` and `"difference": null`
/// without `f64_failed`); a non-UTF-8 line got "expected ident"; after a failed `load`, later
/// queries silently used the previous mesh.
#[test]
fn x_adv_17_oracle_reply_shape_r_oracle_shape() {
    let mut input = b"{\"op\":\"g\",\"v\":0,\"p\":[1e300,1e300]}\n\xff\xfe\n".to_vec();
    input.extend_from_slice(b"{\"op\":\"load\",\"path\":\"/nonexistent.off\"}\n");
    input.extend_from_slice(b"{\"op\":\"degree\",\"v\":0}\n");
    let out = ppm_stdin(&["oracle", "--mesh", OCTAHEDRON], &input);
    let r = replies(&out);
    assert_eq!(r.len(), 4, "{r:?}");
    assert_eq!(r[0]["ok"], true);
    assert!(r[0].get("f64").is_none(), "{}", r[0]);
    assert!(r[0].get("difference").is_none(), "{}", r[0]);
    assert!(r[0]["info"]["f64_failed"].is_string(), "{}", r[0]);
    assert!(
        r[1]["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("UTF-8")),
        "{}",
        r[1]
    );
    assert_eq!(r[2]["error"]["kind"], "load_failed");
    assert_eq!(r[3]["error"]["kind"], "no_mesh", "{}", r[3]);
    crate::common::verdicts::record("R-oracle-shape", crate::common::verdicts::Seen::Holds, 1);
}

/// `diff` printed a 2.5e296 deviation as `inf`, did not name a NaN vertex, gave no line number
/// for a non-UTF-8 table, and silently ignored the options of the other mode.
#[test]
fn x_adv_18_diff_hygiene() {
    use pseudomanifold::oracle::diff::diff_table;
    use pseudomanifold::oracle::surface_diff::{diff_surface, SurfaceDiffOptions};
    use pseudomanifold::oracle::Session;
    let k = surface(&octahedron());
    let mut s = Session::with_surface(k.clone());
    let r = diff_table(
        &mut s,
        r#"{"op":"h","p":[0.25,0.5],"value":[2.5e296,-0.5]}"#,
        1e-12,
        5,
    );
    assert!(
        r.stats.max.is_finite() && (r.stats.max / 2.5e296 - 1.0).abs() < 1e-12,
        "deviation {}",
        r.stats.max
    );
    let pps = build(&k);
    let mut pts = sample_surface(&pps, 1, None).expect("level 1").positions;
    pts[5][1] = f64::NAN;
    let d = diff_surface(
        &pps,
        &pts,
        None,
        &SurfaceDiffOptions {
            spot_checks: 1,
            ..SurfaceDiffOptions::default()
        },
    )
    .expect("diff");
    assert!(!d.within_tolerance);
    assert_eq!(d.non_finite_vertices, vec![5]);
    assert!(pseudomanifold::oracle::surface_diff::render_surface(&d).contains("vertex 5"));

    let table = tmp("x_adv_18.jsonl");
    std::fs::write(
        &table,
        b"{\"op\":\"h\",\"p\":[0.25,0.5],\"value\":[0.75,-0.5]}\n{\"op\":\"h\xff\"}\n",
    )
    .expect("write");
    let t = table.to_str().expect("utf-8 path");
    let out = ppm(&["diff", "--mesh", OCTAHEDRON, t]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("line 2"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for args in [
        &["diff", "--mesh", OCTAHEDRON, "/dev/null", "--level", "2"][..],
        &[
            "diff",
            "--mesh",
            OCTAHEDRON,
            "/dev/null",
            "--match",
            "nearest",
        ][..],
        &["check", OCTAHEDRON, "--certificates", "/dev/null"][..],
        &["check", OCTAHEDRON, "--max-configs", "3"][..],
    ] {
        let out = ppm(args);
        assert_eq!(out.status.code(), Some(2), "{args:?} not refused");
    }
}

const OCTAHEDRON: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/octahedron.obj");

fn build(k: &SimplicialSurface) -> Pps {
    Pps::build(k, &PnTriangles::new(k), PpsOptions::default())
}

fn replies(out: &std::process::Output) -> Vec<serde_json::Value> {
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON reply per line"))
        .collect()
}

fn surface(raw: &pseudomanifold::mesh::RawMesh) -> SimplicialSurface {
    validate(raw).surface.expect("valid fixture")
}

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("x_adv_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    dir.join(name)
}
