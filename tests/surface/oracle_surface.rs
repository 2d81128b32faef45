//! Chapter 5 part of the oracle: the surface oracle ops of `ppm oracle`, and `ppm diff --surface`
//! with its self-test — this crate's own f64 sampled surface (written as `ppm sample` writes
//! it) diffed against the reference, within the printed bound; planted faults (a sign flip in
//! one rotation of the surface model, a perturbed vertex, a shuffled vertex order) caught or
//! handled as the report says.

use crate::common;

use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface, VertexId};
use pseudomanifold::oracle::diff::diff_table;
use pseudomanifold::oracle::surface_diff::{sample_count, sample_points, F64_BOUND_ULPS};
use pseudomanifold::oracle::Session;
use pseudomanifold::report::dev_max;
use pseudomanifold::surface::output::{sample_surface, write_mesh_with_attributes, SampledMesh};
use pseudomanifold::surface::{Fault, Membership, PnTriangles, Pps, PpsOptions};
use serde_json::Value;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn ico() -> PathBuf {
    data("icosahedron_binary_le.ply")
}

fn load(path: &Path) -> SimplicialSurface {
    let raw = read_mesh(path, &ReadOptions::default()).expect("readable");
    validate(&raw).surface.expect("valid")
}

fn pps(k: &SimplicialSurface) -> Pps {
    Pps::build(k, &PnTriangles::new(k), PpsOptions::default())
}

fn tmp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ppm-oracle-surface-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    dir.join(name)
}

fn diff(mesh: &Path, surface: &Path, extra: &[&str]) -> (Output, Value) {
    let out = Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["diff", "--json", "--mesh"])
        .arg(mesh)
        .arg("--surface")
        .arg(surface)
        .args(extra)
        .output()
        .expect("run ppm diff --surface");
    let v = serde_json::from_slice(&out.stdout).unwrap_or(Value::Null);
    (out, v)
}

fn f(v: &Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or_else(|| panic!("{k} in {v}"))
}

#[test]
fn sample_points_reproduce_the_order_of_sample_surface() {
    for name in ["icosahedron_binary_le.ply", "torus_4x4.off"] {
        let k = load(&data(name));
        let p = pps(&k);
        let level = 2;
        let s = sample_surface(&p, level, None).expect("sample");
        let pat = sample_points(&p, level).expect("pattern");
        assert_eq!(pat.points.len(), s.positions.len());
        assert_eq!(pat.faces, s.faces, "{name}: same triangles");
        assert_eq!(
            sample_count(
                k.num_vertices() as u64,
                k.num_edges() as u64,
                k.num_faces() as u64,
                level
            ),
            s.positions.len() as u64
        );
        for (sp, q) in pat.points.iter().zip(&s.positions) {
            let e = p.eval_f64(sp.face, sp.bary).expect("eval");
            let d = (0..3).map(|i| (e[i] - q[i]).abs()).fold(0.0, dev_max);
            assert!(d < 1e-13, "{name}: {sp:?} {d}");
        }
    }
}

/// The self-test: the crate's own f64 surface, written as `ppm sample` writes it, is within
/// the bound the report prints; the report's MPFR spot checks are too.
#[test]
fn diff_surface_self_test_within_printed_bound() {
    let mut meshes: Vec<PathBuf> = [
        "icosahedron_binary_le.ply",
        "torus_4x4.off",
        "octahedron.obj",
    ]
    .iter()
    .map(|n| data(n))
    .collect();
    meshes.extend(
        common::corpus("diff_surface_self_test_within_printed_bound")
            .into_iter()
            .filter(|m| m.good && m.faces <= 200)
            .take(3)
            .map(|m| m.path),
    );
    for (n, mesh) in meshes.iter().enumerate() {
        let k = load(mesh);
        let m = sample_surface(&pps(&k), 2, None).expect("sample");
        let out = tmp(&format!("self{n}.{}", ["off", "ply", "obj"][n % 3]));
        write_mesh_with_attributes(&out, &m).expect("write");
        let (o, r) = diff(mesh, &out, &[]);
        eprintln!(
            "{}: {} vertices, max deviation {:.3e}, reference error (MPFR) {:.3e}, printed f64 bound {:.3e}, tolerance {:.3e}",
            mesh.display(),
            r["their_vertices"],
            f(&r["stats"], "max"),
            f(&r, "reference_error_max"),
            f(&r, "f64_bound"),
            f(&r, "tolerance")
        );
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert_eq!(r["within_tolerance"], true);
        assert_eq!(r["matching"], "order");
        assert_eq!(r["level"], 2);
        assert_eq!(r["level_inferred"], true);
        assert_eq!(r["faces_identical"], true);
        assert_eq!(r["their_vertices"], m.positions.len());
        let bound = f(&r, "f64_bound");
        let maps = f(&r, "f64_bound_maps");
        assert!(
            maps > 0.0
                && maps == F64_BOUND_ULPS * f64::EPSILON * f(&r, "scale").max(1.0)
                && bound >= maps
                && bound <= (maps + f(&r, "f64_bound_patch_max")) * 1.000001
        );
        assert!(f(&r["stats"], "max") <= 2.0 * bound);
        // R-diff-f64-bound: the default tolerance is 2 × the largest printed bound (both f64
        // evaluations are within it of the exact value), and the text names no non-finite
        // vertex when there is none.
        assert_eq!(f(&r, "tolerance"), 2.0 * bound);
        let text = Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(["diff", "--mesh"])
            .arg(mesh)
            .arg("--surface")
            .arg(&out)
            .output()
            .expect("run ppm diff --surface");
        let text = String::from_utf8_lossy(&text.stdout);
        assert!(text.contains("tolerance"), "{text}");
        assert!(!text.contains("non-finite coordinates"), "{text}");
        assert!(f(&r, "reference_error_max") <= bound);
        assert!(f(&r, "mp_deviation_max") <= 2.0 * bound);
        assert_eq!(r["bound_violations"], 0);
        assert_eq!(r["outside"], 0);
        assert!(f(&r, "spot_checks") >= 30.0);
        assert_eq!(r["worst"].as_array().map(Vec::len), Some(10));
        assert!(r["worst"][0]["mp"]["reference_error"].is_number());
    }
}

/// The surface of `good` with the planted sign flip described below, on the first edge
/// [0, u] where the flip changes something (j = s_u(0) with 2j ≢ 0 mod m_u).
fn sign_flip(good: &Pps) -> (VertexId, VertexId, u32, Pps) {
    let v = VertexId(0);
    let (u, j) = (0..good.degree(v))
        .map(|i| good.link(v, i))
        .map(|u| (u, good.label(u, v).expect("label")))
        .find(|&(u, j)| (2 * j) % good.degree(u) != 0)
        .expect("an edge with a non-trivial flip");
    let angle = -4.0 * std::f64::consts::PI * f64::from(j) / f64::from(good.degree(u));
    let bad = good.clone().with_options(
        Membership::Literal,
        Some(Fault::Transition {
            from: v,
            to: u,
            angle,
        }),
    );
    (v, u, j, bad)
}

/// A "faster implementation" of the surface with a planted bug: in θ_v, the transition map
/// φ_uv of one edge ends with R_(u,v)⁻¹ rotating the wrong way (by −2πj/m_u instead of
/// +2πj/m_u, j = s_u(v)), i.e. followed by a rotation by −4πj/m_u.
#[test]
fn diff_surface_catches_a_sign_flip_in_one_rotation() {
    let mesh = ico();
    let k = load(&mesh);
    let good = pps(&k);
    let (v, u, j, bad) = sign_flip(&good);
    let m = sample_surface(&bad, 2, None).expect("sample");
    let out = tmp("flip.off");
    write_mesh_with_attributes(&out, &m).expect("write");
    let (o, r) = diff(&mesh, &out, &["--level", "2"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert_eq!(r["within_tolerance"], false);
    let max = f(&r["stats"], "max");
    eprintln!("sign flip on [{v}, {u}] (j = {j}): max deviation {max:.3e}");
    assert!(max > 1e-3, "{max}");
    // The worst vertex is evaluated in a triangle of v, in the chart of v.
    let w = &r["worst"][0];
    let face = w["face"].as_u64().expect("face") as u32;
    assert!(good.face(FaceId(face)).expect("face").contains(&v), "{w}");
    assert!(f(&w["mp"], "deviation") > 1e-3);
    assert!(f(&w["mp"], "reference_error") < 1e-13);
    // The unaffected vertices are still exact: most deviations are at rounding level.
    assert!(f(&r["stats"], "p50") < 1e-12, "{}", r["stats"]);
}

fn write_off(path: &Path, m: &SampledMesh) {
    write_mesh_with_attributes(path, m).expect("write");
}

#[test]
fn diff_surface_catches_one_perturbed_vertex_and_names_it() {
    let mesh = ico();
    let mut m = sample_surface(&pps(&load(&mesh)), 2, None).expect("sample");
    let victim = 77;
    m.positions[victim][1] += 1e-9;
    let out = tmp("perturbed.ply");
    write_off(&out, &m);
    let (o, r) = diff(&mesh, &out, &["--tolerance", "1e-10"]);
    assert_eq!(o.status.code(), Some(1));
    let w = &r["worst"][0];
    assert_eq!(w["vertex"], victim);
    assert_eq!(w["reference_vertex"], victim);
    let d = f(w, "deviation");
    assert!((d - 1e-9).abs() < 1e-12, "{d}");
    assert!(f(&r["worst"][1], "deviation") < 1e-13);
    let bary: Vec<f64> = w["bary"]
        .as_array()
        .expect("bary")
        .iter()
        .filter_map(Value::as_f64)
        .collect();
    assert!((bary.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    // The same file passes at a tolerance above the perturbation.
    let (o, _) = diff(&mesh, &out, &["--tolerance", "1e-8"]);
    assert_eq!(o.status.code(), Some(0));
}

#[test]
fn diff_surface_unknown_order_is_matched_by_nearest_neighbour() {
    let mesh = ico();
    let m = sample_surface(&pps(&load(&mesh)), 2, None).expect("sample");
    // Reverse the vertex order (a different implementation's numbering).
    let n = m.positions.len();
    let mut s = m.clone();
    s.positions.reverse();
    s.normals.reverse();
    s.gaussian.reverse();
    s.mean.reverse();
    for t in &mut s.faces {
        *t = t.map(|i| (n - 1) as u32 - i);
    }
    let out = tmp("reversed.off");
    write_off(&out, &s);
    // In eval order the counts agree, so the positions are compared as given: caught.
    let (o, r) = diff(&mesh, &out, &[]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(r["faces_identical"], false);
    // With --match nearest it is the same surface.
    let (o, r) = diff(&mesh, &out, &["--match", "nearest"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert_eq!(r["matching"], "nearest");
    assert!(r["matching_note"]
        .as_str()
        .unwrap_or("")
        .contains("NEAREST"));
    assert_eq!(r["reference_matched_twice"], 0);
    assert!(f(&r["reverse"], "max") < 1e-13);
    // A coarser sampling against a finer level: counts differ, nearest matching is used and
    // said; level-1 points are level-2 points, so the forward deviations are at rounding level
    // while the reverse distances show the missing points, which fail the verdict (SPEC
    // R-diff-two-sided) and the level mismatch is named.
    let coarse = sample_surface(&pps(&load(&mesh)), 1, None).expect("sample");
    let out = tmp("coarse.off");
    write_off(&out, &coarse);
    let (o, r) = diff(&mesh, &out, &["--level", "2"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(f(&r["stats"], "max") < 1e-13);
    assert_eq!(r["count_matches_level"], 1);
    assert!(r["reference_missing"].as_u64().unwrap_or(0) > 0);
    assert_eq!(r["matching"], "nearest");
    assert!(r["matching_note"]
        .as_str()
        .unwrap_or("")
        .contains("vertex counts differ (theirs 42, reference 162 at level 2)"));
    assert!(f(&r["reverse"], "max") > 0.1);
    // Text report says so too.
    let t = Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["diff", "--mesh"])
        .arg(&mesh)
        .arg("--surface")
        .arg(&out)
        .args(["--level", "2"])
        .output()
        .expect("run");
    let text = String::from_utf8_lossy(&t.stdout);
    assert!(
        text.contains("matched each vertex to the NEAREST reference point"),
        "{text}"
    );
    assert!(text.contains("verdict: OUTSIDE tolerance"), "{text}");
    assert!(text.contains("level mismatch"), "{text}");
}

#[test]
fn diff_surface_usage_errors_exit_2() {
    let mesh = ico();
    let junk = tmp("junk.off");
    std::fs::write(&junk, "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n").expect("write");
    let (o, _) = diff(&mesh, &junk, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("give --level"));
    let (o, _) = diff(&mesh, &junk, &["--level", "1", "--match", "sideways"]);
    assert_eq!(o.status.code(), Some(2));
    let (o, _) = diff(&mesh, &tmp("missing.off"), &["--level", "1"]);
    assert_eq!(o.status.code(), Some(2));
    let (o, _) = diff(&mesh, &junk, &["--level", "13"]);
    assert_eq!(o.status.code(), Some(2));
    // 4 finite points vs level 1: nearest matching, far from the surface: verdict 1.
    let (o, r) = diff(&mesh, &junk, &["--level", "1"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(r["matching"], "nearest");
}

#[test]
fn oracle_chapter5_ops_from_a_child_process() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["oracle", "--bits", "160", "--mesh"])
        .arg(ico())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("spawn ppm oracle");
    let mut stdin = child.stdin.take().expect("stdin");
    let requests = [
        r#"{"op":"eval","face":3,"bary":[0.25,0.25,0.5]}"#,
        r#"{"op":"gamma","v":0,"p":[0.5,0.1]}"#,
        r#"{"op":"psi","v":0,"p":[0.3,0.1]}"#,
        r#"{"op":"psi","v":0,"p":[3.0,0.1]}"#,
        r#"{"op":"psi_control","v":0}"#,
        r#"{"op":"theta","v":0,"p":[0.3,0.1]}"#,
        r#"{"op":"theta_derivatives","v":0,"p":[0.3,0.1],"order":1}"#,
        r#"{"op":"theta_derivatives","v":0,"p":[0.3,0.1]}"#,
        r#"{"op":"theta_derivatives","v":0,"p":[0.3,0.1],"order":4}"#,
        r#"{"op":"theta","v":0,"p":[0.9,0.1]}"#,
        r#"{"op":"theta","v":99,"p":[0.3,0.1]}"#,
        r#"{"op":"eval","face":3,"bary":[0.5,0.25,0.5]}"#,
        r#"{"op":"eval","face":20,"bary":[0.25,0.25,0.5]}"#,
        r#"{"op":"set_profile","profile":"nope"}"#,
        r#"{"op":"set_profile","profile":"authors-code"}"#,
        r#"{"op":"eval","face":3,"bary":[0.25,0.25,0.5]}"#,
        r#"{"op":"theta","v":0,"p":[0.3,1e400]}"#,
        r#"{"op":"theta","v":0,"p":[0.3,0.1],"extra":1}"#,
        r#"{"op":"theta","v":-1,"p":[0.3,0.1]}"#,
    ];
    for r in &requests {
        writeln!(stdin, "{r}").expect("write");
    }
    drop(stdin);
    let lines: Vec<Value> = BufReader::new(child.stdout.take().expect("stdout"))
        .lines()
        .map(|l| serde_json::from_str(&l.expect("line")).expect("JSON"))
        .collect();
    assert!(child.wait().expect("exit").success());
    assert_eq!(lines.len(), requests.len());
    let kind = |i: usize| {
        lines[i]["error"]["kind"]
            .as_str()
            .unwrap_or("ok")
            .to_string()
    };
    let diff = |i: usize| lines[i]["difference"].as_f64().unwrap_or(f64::NAN);
    let f64s = |i: usize| -> Vec<f64> {
        lines[i]["f64"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    // eval: point, chart, vertex, q.
    assert_eq!(lines[0]["info"]["chart"], "U");
    assert_eq!(lines[0]["info"]["vertex"], 0);
    assert_eq!(lines[0]["mp_bits"], 160);
    assert!(diff(0) > 0.0 && diff(0) < 1e-14, "{}", diff(0));
    assert_eq!(f64s(0).len(), 3);
    for (i, expect) in [(1, 1), (2, 3), (5, 3)] {
        assert_eq!(f64s(i).len(), expect, "{}", lines[i]);
        assert!(diff(i) < 1e-14, "{}", lines[i]);
    }
    assert!((f64s(1)[0] - 0.49005632457749604).abs() < 1e-15);
    assert_eq!(kind(3), "not_in_domain");
    assert_eq!(lines[4]["info"]["l"], 7);
    assert_eq!(lines[4]["value"].as_array().map(Vec::len), Some(64));
    assert!(lines[4]["info"]["f64_only"].is_string());
    // Derivatives: 3 partials × 3 coordinates at order 1, 10 × 3 at order 3; the value part is θ.
    assert_eq!(f64s(6).len(), 9);
    assert_eq!(
        lines[6]["info"]["partials"],
        serde_json::json!([[0, 0], [1, 0], [0, 1]])
    );
    assert_eq!(f64s(7).len(), 30);
    assert!(diff(7) < 1e-12, "{}", lines[7]);
    for d in 0..3 {
        assert!((f64s(7)[d] - f64s(5)[d]).abs() < 1e-14);
    }
    assert_eq!(kind(8), "malformed_request");
    assert_eq!(kind(9), "not_in_domain");
    assert_eq!(kind(10), "no_such_element");
    assert_eq!(kind(11), "not_in_domain");
    assert_eq!(kind(12), "no_such_element");
    assert_eq!(kind(13), "malformed_request");
    assert_eq!(lines[14]["value"]["profile"], "authors-code");
    assert_eq!(kind(15), "ok");
    assert_eq!(lines[15]["info"]["chart"], "X");
    assert!((f64s(15)[0] - f64s(0)[0]).abs() > 1e-6, "profiles differ");
    assert_eq!(kind(16), "malformed_request"); // 1e400 is not an f64
    assert_eq!(kind(17), "malformed_request");
    assert_eq!(kind(18), "malformed_request");
}

#[test]
fn theta_derivatives_agree_with_finite_differences_and_eval_with_theta() {
    let mut s = Session::with_surface(load(&ico()));
    let p = [0.3, 0.1];
    let h = 1e-6;
    let get = |s: &mut Session, line: String| -> Vec<f64> {
        let r = s.handle_line(&line);
        assert!(r.ok, "{line}: {:?}", r.error);
        r.f64
            .and_then(|v| v.as_array().cloned())
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    let jet = get(
        &mut s,
        format!(r#"{{"op":"theta_derivatives","v":0,"p":{p:?},"order":2}}"#),
    );
    let th = |s: &mut Session, x: f64, y: f64| {
        get(s, format!(r#"{{"op":"theta","v":0,"p":[{x:?},{y:?}]}}"#))
    };
    let (xp, xm) = (th(&mut s, p[0] + h, p[1]), th(&mut s, p[0] - h, p[1]));
    let (yp, ym) = (th(&mut s, p[0], p[1] + h), th(&mut s, p[0], p[1] - h));
    for d in 0..3 {
        let dx = (xp[d] - xm[d]) / (2.0 * h);
        let dy = (yp[d] - ym[d]) / (2.0 * h);
        assert!(
            (jet[3 + d] - dx).abs() < 1e-7,
            "∂x θ_{d}: {} vs {dx}",
            jet[3 + d]
        );
        assert!(
            (jet[6 + d] - dy).abs() < 1e-7,
            "∂y θ_{d}: {} vs {dy}",
            jet[6 + d]
        );
    }
    // eval(σ, λ, μ, ν) = θ_vertex(q).
    let r = s.handle_line(r#"{"op":"eval","face":7,"bary":[0.6,0.3,0.1]}"#);
    let info = r.info.expect("info");
    let v = info["vertex"].as_u64().expect("vertex");
    let q = &info["q_f64"];
    let point: Vec<f64> = r
        .f64
        .and_then(|x| x.as_array().cloned())
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default();
    let t = get(&mut s, format!(r#"{{"op":"theta","v":{v},"p":{q}}}"#));
    for d in 0..3 {
        assert!((point[d] - t[d]).abs() < 1e-15);
    }
}

/// `ppm diff` tables work for the Chapter 5 ops too: θ from the f64 path is within the bound,
/// θ from a surface with a planted sign flip is caught.
#[test]
fn diff_table_of_theta_catches_planted_sign_flip() {
    let k = load(&ico());
    let good = pps(&k);
    let (v, _, _, bad) = sign_flip(&good);
    assert_eq!(v, VertexId(0));
    let table = |m: &Pps| {
        let mut t = String::new();
        for a in 0..12 {
            for r in [0.1, 0.3, 0.5, 0.7] {
                let ang = f64::from(a) * std::f64::consts::PI / 6.0 + 0.05;
                let p = [r * ang.cos(), r * ang.sin()];
                let val = m.theta_f64(v, p).expect("θ");
                t.push_str(&format!(
                    "{{\"op\":\"theta\",\"v\":0,\"p\":{p:?},\"value\":{val:?}}}\n"
                ));
            }
        }
        t
    };
    let mut s = Session::with_surface(k.clone());
    let tol = F64_BOUND_ULPS * f64::EPSILON * good.scale();
    let r = diff_table(&mut s, &table(&good), tol, 3);
    assert_eq!(r.stats.count, 48);
    assert!(
        r.within_tolerance,
        "{}",
        pseudomanifold::oracle::diff::render(&r)
    );
    assert!(r.stats.max < 1e-14, "{}", r.stats.max);
    let r = diff_table(&mut s, &table(&bad), tol, 3);
    assert!(!r.within_tolerance);
    assert!(r.stats.max > 1e-3, "{}", r.stats.max);
    assert_eq!(r.worst[0].request["op"], "theta");
}

fn ok(s: &mut Session, line: &str) -> pseudomanifold::oracle::Response {
    let r = s.handle_line(line);
    assert!(r.ok, "{line}: {r:?}");
    r
}

/// R-oracle-shape: the session state follows the requests — the precision it reports is the
/// one set, S′ answers at a corner with the mesh vertex (Sec. 5.1) (barycentric 0 is inside
/// the simplex), a point outside the simplex is `not_in_domain`.
#[test]
fn r_oracle_shape_precision_and_sprime_at_corners() {
    let k = load(&ico());
    let mut s = Session::with_surface(k.clone());
    ok(&mut s, r#"{"op":"set_precision","bits":200}"#);
    assert_eq!(s.bits(), 200);
    for (face, corner) in [(0u32, 0usize), (7, 1), (19, 2)] {
        let mut bary = [0.0; 3];
        bary[corner] = 1.0;
        let r = ok(
            &mut s,
            &format!(r#"{{"op":"sprime","face":{face},"bary":{bary:?}}}"#),
        );
        let got: Vec<f64> = serde_json::from_value(r.f64.clone().expect("f64")).expect("f64");
        let v = k.face(FaceId(face))[corner];
        assert_eq!(got, k.position(v).to_vec(), "face {face} corner {corner}");
        assert_eq!(r.mp_bits, Some(200));
    }
    let r = s.handle_line(r#"{"op":"sprime","face":0,"bary":[-0.5,0.5,1.0]}"#);
    assert_eq!(r.error.expect("error")["kind"], "not_in_domain");
}

/// SV-D3 and SV-diff in the oracle: κ must lie in the open interval (0, 1); the (σ, v)
/// surface and its MPFR constants are rebuilt when the mesh or the precision changes (the
/// answer equals a fresh session's).
#[test]
fn sv_d3_oracle_kappa_open_interval_and_state_follows_mesh_and_precision() {
    let set = r#"{"op":"set_construction","construction":"sigma-v","kappa":0.3}"#;
    for bad in ["0", "1", "1.0", "-0.1"] {
        let mut s = Session::new();
        let r = s.handle_line(&format!(
            r#"{{"op":"set_construction","construction":"sigma-v","kappa":{bad}}}"#
        ));
        assert!(!r.ok, "kappa {bad} accepted");
        assert_eq!(r.error.expect("error")["kind"], "malformed_request");
    }
    let q = r#"{"op":"eval","face":2,"bary":[0.2,0.3,0.5]}"#;
    let load_line = |p: &Path| format!(r#"{{"op":"load","path":{:?}}}"#, p.display().to_string());
    let fresh = |mesh: &Path, bits: u32| {
        let mut s = Session::new();
        ok(&mut s, &load_line(mesh));
        ok(&mut s, set);
        ok(
            &mut s,
            &format!(r#"{{"op":"set_precision","bits":{bits}}}"#),
        );
        ok(&mut s, q)
    };
    let mut s = Session::new();
    ok(&mut s, &load_line(&ico()));
    ok(&mut s, set);
    ok(&mut s, r#"{"op":"set_precision","bits":64}"#);
    let low = ok(&mut s, q);
    assert_eq!(low.value, fresh(&ico(), 64).value);
    ok(&mut s, r#"{"op":"set_precision","bits":256}"#);
    let high = ok(&mut s, q);
    assert_eq!(
        high.value,
        fresh(&ico(), 256).value,
        "stale 64-bit constants"
    );
    assert_ne!(high.value, low.value);
    let oct = data("octahedron.obj");
    ok(&mut s, &load_line(&oct));
    let other = ok(&mut s, q);
    let want = fresh(&oct, 256);
    assert_eq!(
        other.value, want.value,
        "stale surface of the previous mesh"
    );
    assert_eq!(other.f64, want.f64);
}
