//! Chapter 5 part of the oracle: the surface oracle ops of `ppm oracle`, and `ppm diff --surface`
//! with its self-test — this crate's own f64 sampled surface (written as `ppm sample` writes
//! it) diffed against the reference, within the printed bound; planted faults (a sign flip in
//! one rotation of the surface model, a perturbed vertex, a shuffled vertex order) caught or
//! handled as the report says.

use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface, VertexId};
use pseudomanifold::oracle::diff::diff_table;
use pseudomanifold::oracle::surface_diff::{sample_count, sample_points, F64_BOUND_ULPS};
use pseudomanifold::oracle::Session;
use pseudomanifold::report::dev_max;
use pseudomanifold::surface::output::sample_surface;
use pseudomanifold::surface::{Fault, Membership, PnTriangles, Pps, PpsOptions};
use serde_json::Value;
use std::path::{Path, PathBuf};

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
