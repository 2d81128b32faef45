//! One interface for every smooth surface (SPEC `X-one-surface`): the oracle's `eval` and
//! `ppm eval` build their construction at one choice point (`oracle::choice`) and evaluate it
//! through `SmoothSurface` only, so both accept the vertex PPS (Ch. 4–5), the (σ, v) PPS
//! (SPEC `SV-D13`), the manifold spline (seed 003 Secs. 5.5–5.6) and a fitted-surface file
//! (docs/fit-format.md); what a construction lacks is a typed refusal, and the vertex
//! construction's answers are its own methods' to the bit.

use crate::common::verdicts::{record, Seen};
use pseudomanifold::fitting::format::{read_fit, write_fit};
use pseudomanifold::fitting::{fit_surface, FitOptions};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::oracle::tsv_diff::diagonal;
use pseudomanifold::oracle::{Response, Session};
use pseudomanifold::surface::sigma_v::{SigmaVPps, DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE};
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const FACE: u32 = 3;
const BARY: [f64; 3] = [0.2, 0.3, 0.5];
const EVAL: &str = r#"{"op":"eval","face":3,"bary":[0.2,0.3,0.5]}"#;

/// A genus-1 mesh: the manifold spline needs one (Thm. 2 of seed 003).
fn torus_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/torus_4x4.off")
}

fn torus() -> SimplicialSurface {
    let raw = read_mesh(&torus_path(), &ReadOptions::default()).expect("readable");
    validate(&raw).surface.expect("a simplicial surface")
}

/// The torus fitted at ε = 10⁻² of its diagonal and written as a fitted-surface file.
fn fit_file(name: &str) -> PathBuf {
    let k = torus();
    let f = fit_surface(&k, &FitOptions::new(1e-2 * diagonal(&k)), |_| {}).expect("fit");
    let dir = std::env::temp_dir().join(format!("ppm-one-surface-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    write_fit(&path, &f).expect("write");
    path
}

fn ok(s: &mut Session, line: &str) -> Response {
    let r = s.handle_line(line);
    assert!(r.ok, "{line}: {r:?}");
    r
}

fn f64s(v: &Value) -> Vec<f64> {
    serde_json::from_value(v.clone()).expect("numbers")
}

fn bits(p: &[f64]) -> Vec<u64> {
    p.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn x_one_surface_oracle_eval_answers_every_construction() {
    let k = torus();
    let load = format!(
        r#"{{"op":"load","path":{:?}}}"#,
        torus_path().display().to_string()
    );
    let mut s = Session::new();
    ok(&mut s, &load);
    // The vertex PPS: the chart of Sec. 6.1.4 and the point of `Pps::eval_f64`, no name added.
    let v = ok(&mut s, EVAL);
    let info = v.info.clone().expect("info");
    for key in ["chart", "vertex", "q", "q_f64"] {
        assert!(info.get(key).is_some(), "{key}: {info}");
    }
    assert!(info.get("construction").is_none(), "{info}");
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let want = pps.eval_f64(FaceId(FACE), BARY).expect("eval");
    assert_eq!(bits(&f64s(&v.f64.clone().expect("f64"))), bits(&want));
    // The (σ, v) PPS: its corner and point.
    ok(
        &mut s,
        r#"{"op":"set_construction","construction":"sigma-v"}"#,
    );
    let sv = ok(&mut s, EVAL);
    let info = sv.info.clone().expect("info");
    assert_eq!(info["construction"], "sigma-v");
    assert_eq!(info["kappa"], DEFAULT_KAPPA);
    assert!(
        info["corner"]["v"].is_u64() && info["corner"]["k"].is_u64(),
        "{info}"
    );
    let svp = SigmaVPps::build(
        &k,
        &PnTriangles::new(&k),
        DEFAULT_KAPPA,
        DEFAULT_PATCH_DEGREE,
    )
    .expect("build");
    let want = svp.eval_f64(FaceId(FACE), BARY).expect("eval");
    assert_eq!(bits(&f64s(&sv.f64.clone().expect("f64"))), bits(&want));
    assert!(sv.difference.is_some_and(|d| d < 1e-12), "{sv:?}");
    // The manifold spline: f64 data only, so eval (f64 and MPFR) is a typed refusal; its f64
    // eval answers through the session's reference.
    ok(
        &mut s,
        r#"{"op":"set_construction","construction":"manifold-spline"}"#,
    );
    let r = s.handle_line(EVAL);
    let e = r.error.expect("refused");
    assert_eq!(e["kind"], "refused", "{e}");
    assert!(
        e["message"].as_str().is_some_and(|m| m.contains("MPFR")),
        "{e}"
    );
    let spline = s.reference().expect("spline");
    let p = spline.eval_f64(FaceId(FACE), BARY).expect("spline eval");
    assert!(p.iter().all(|x| x.is_finite()));
    assert!(s
        .handle_line(r#"{"op":"set_construction","construction":"manifold-spline","kappa":0.3}"#)
        .error
        .is_some_and(|e| e["kind"] == "malformed_request"));
    // A fitted-surface file: its base mesh is loaded, eval answers for the fitted PPS.
    let path = fit_file("torus.fit");
    let l = ok(
        &mut s,
        &format!(r#"{{"op":"load","path":{:?}}}"#, path.display().to_string()),
    );
    assert_eq!(l.value.expect("value")["construction"], "fit");
    let fit = ok(&mut s, EVAL);
    let info = fit.info.clone().expect("info");
    assert_eq!(info["construction"], "fit");
    assert!(info["corner"].is_object(), "{info}");
    let back = read_fit(&path).expect("read");
    let want = back.pps.eval_f64(FaceId(FACE), BARY).expect("eval");
    assert_eq!(bits(&f64s(&fit.f64.clone().expect("f64"))), bits(&want));
    // Loading a mesh drops the fitted surface: the vertex PPS answers again, as before.
    ok(&mut s, &load);
    let again = ok(&mut s, EVAL);
    assert_eq!(again, v);
    record("X-one-surface", Seen::Holds, 4);
}

fn ppm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(args)
        .output()
        .expect("run ppm")
}

fn json(o: &Output) -> Value {
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("one JSON object")
}

#[test]
fn x_one_surface_ppm_eval_takes_every_construction() {
    let k = torus();
    let mesh = torus_path();
    let mesh = mesh.to_str().expect("utf-8 path");
    let at = ["3", "0.2", "0.3", "0.5"];
    let eval = |extra: &[&str]| {
        let mut a = vec!["eval", mesh];
        a.extend(at);
        a.extend(extra);
        ppm(&a)
    };
    // The vertex PPS: the line its own eval_geometry gives, byte for byte.
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let (chart, vx, g) = pps
        .eval_geometry(FaceId(FACE), BARY, &pps.consts(53))
        .expect("geometry");
    let line = format!(
        "{{\"face\": {FACE}, \"bary\": {BARY:?}, \"chart\": \"{chart:?}\", \"vertex\": {vx}, \"point\": {:?}, \"normal\": {:?}, \"gaussian\": {}, \"mean\": {}}}\n",
        g.point, g.normal, g.gaussian, g.mean
    );
    let o = eval(&[]);
    assert_eq!(String::from_utf8_lossy(&o.stdout), line);
    // The (σ, v) PPS: its corner, normal and curvatures.
    let sv = json(&eval(&["--construction", "sigma-v"]));
    assert!(
        sv["corner"].is_object() && sv["gaussian"].is_number(),
        "{sv}"
    );
    // The manifold spline: the point, and its missing jets a typed refusal (exit 1).
    let sp = json(&eval(&[
        "--construction",
        "manifold-spline",
        "--attributes",
        "positions",
    ]));
    let mut s = Session::with_surface(k.clone());
    ok(
        &mut s,
        r#"{"op":"set_construction","construction":"manifold-spline"}"#,
    );
    let want = s
        .reference()
        .expect("spline")
        .eval_f64(FaceId(FACE), BARY)
        .expect("eval");
    assert_eq!(bits(&f64s(&sp["point"])), bits(&want));
    let o = eval(&["--construction", "manifold-spline"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("not available") && err.contains("--attributes positions"),
        "{err}"
    );
    // A fitted-surface file: its point (positions by default) and its corner; a construction
    // option is a usage error.
    let path = fit_file("cli.fit");
    let fit = path.to_str().expect("utf-8 path");
    let mut a = vec!["eval", fit];
    a.extend(at);
    let one = json(&ppm(&a));
    let back = read_fit(&path).expect("read");
    let want = back.pps.eval_f64(FaceId(FACE), BARY).expect("eval");
    assert_eq!(bits(&f64s(&one["point"])), bits(&want));
    assert!(one["corner"].is_object(), "{one}");
    a.extend(["--construction", "sigma-v"]);
    assert_eq!(ppm(&a).status.code(), Some(2));
    record("X-one-surface", Seen::Holds, 4);
}
