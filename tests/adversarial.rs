//! Regressions for the adversarial sweep of the release binary: each test is named after the
//! misbehaviour it pins (`x_adv_NN_…`), fails on the code before the fix, and asserts either the
//! corrected answer or a typed refusal.

use pseudomanifold::construction::{Mp, Scalar};
use pseudomanifold::mesh::generate::octahedron;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::output::sample_surface;
use pseudomanifold::surface::weights::{xi, XiConsts};
use pseudomanifold::surface::*;

fn surface(raw: &pseudomanifold::mesh::RawMesh) -> SimplicialSurface {
    validate(raw).surface.expect("valid fixture")
}

fn build(k: &SimplicialSurface) -> Pps {
    Pps::build(k, &PnTriangles::new(k), PpsOptions::default())
}

/// Def. 5.3.1: near H₂ the literal 1/(1 + e^{2s}) overflows (e^{2s} = ∞) and the derivative
/// jets become ∞/∞; the logistic form keeps ξ and all its derivatives finite, in f64 and Mp.
#[test]
fn x_adv_01_nan_normals_at_edge_midpoints_r_xi_finite() {
    let k = XiConsts::<Jet<f64>>::for_degree(4, 53);
    let h2 = k.h2.value().to_owned();
    for d in [1e-3, 1e-4, 1e-6, 1e-9, 1e-12, 1e-15] {
        let t = h2 * (1.0 - d);
        let (x, _) = Jet::variables(t, 0.0);
        let j = xi(&k, &x);
        assert!(
            j.c.iter().all(|c| c.is_finite()),
            "ξ jet at H₂(1 − {d:e}) not finite: {j:?}"
        );
    }
    let km = XiConsts::<Jet<Mp>>::for_degree(4, 256);
    let t = km.h2.value().mul(&Mp::from_f64(1.0 - 1e-60, 256));
    let (x, _) = Jet::variables(t, Mp::from_i64(0, 256));
    let j = xi(&km, &x);
    assert!(
        j.c.iter().all(|c| c.to_f64().is_finite()),
        "Mp ξ jet: {j:?}"
    );

    // The sampled octahedron: every normal a unit vector, every curvature finite.
    let k = surface(&octahedron());
    let pps = build(&k);
    let m = sample_surface(&pps, 1, false).expect("sample");
    for (i, n) in m.normals.iter().enumerate() {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-9, "vertex {i}: normal {n:?}");
        assert!(
            m.gaussian[i].is_finite() && m.mean[i].is_finite(),
            "vertex {i}"
        );
    }
    let cj = pps.consts::<Jet<f64>>(53);
    let (_, _, g) = pps
        .eval_geometry(FaceId(1), [0.5, 0.5, 0.0], &cj)
        .expect("eval");
    assert!(g.gaussian.is_finite() && g.area_element > 0.0, "{g:?}");
}

/// The unit roundoff 2^-bits in f64 is 0 from 1024 bits on (2^bits overflows): tolerances
/// became 0 and the literal membership of Def. 4.1.9 answered "outside" for interior points of
/// Ω_uw. The decision now takes its tolerance in the scalar type: the answers agree at every
/// precision.
#[test]
fn x_adv_02_precision_1024_breaks_membership_r_unit_roundoff() {
    use pseudomanifold::construction::{in_omega_uw, EdgeConfig, Trit, P2};
    assert_eq!(
        Mp::from_i64(1, 1024).epsilon(),
        0.5f64.powi(1000) * 0.5f64.powi(24)
    );
    assert!(Mp::from_i64(1, 1024).epsilon() > 0.0);
    let one = Mp::from_i64(1, 4000);
    // The backend may round the precision up (astro-float: to a multiple of 64 bits).
    let p = one.precision_bits() as i32;
    assert!(p >= 4000);
    let mut u = one.unit_roundoff();
    assert!(u.to_f64() == 0.0 && u.sign() == Some(std::cmp::Ordering::Greater));
    for _ in 0..62 {
        u = u.mul(&Mp::from_f64(2f64.powi(64), 4000));
    }
    assert_eq!(
        u.to_f64(),
        2f64.powi(64 * 62 - p),
        "unit roundoff at {p} bits is 2^-{p}"
    );
    for (mu, mw) in [(6, 6), (5, 7), (9, 4)] {
        let e = EdgeConfig::new(mu, 0, mw, 0).expect("config");
        let mut inside = 0;
        for a in 0..12 {
            for r in 1..6 {
                let th = (a as f64 - 5.5) * 0.05;
                let rad = 0.15 * r as f64;
                let (x, y) = (rad * th.cos(), rad * th.sin());
                let at = |bits: u32| {
                    in_omega_uw(&e, &P2::new(Mp::from_f64(x, bits), Mp::from_f64(y, bits)))
                };
                let base = at(256);
                if base == Trit::True {
                    inside += 1;
                }
                for bits in [1023, 1024, 1100, 4096] {
                    assert_eq!(
                        at(bits),
                        base,
                        "({x}, {y}) at {bits} bits, m = ({mu}, {mw})"
                    );
                }
            }
        }
        assert!(inside > 0, "no interior point sampled for ({mu}, {mw})");
    }
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

/// A failed write left a truncated output file: the file is now written under a temporary
/// name and renamed, so the previous content survives a failure.
#[test]
fn x_adv_14_failed_write_leaves_truncated_file() {
    use pseudomanifold::surface::output::{write_mesh_with_attributes, SampledMesh};
    let dir = std::env::temp_dir().join(format!("x_adv_14_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let target = dir.join("out.off");
    std::fs::write(&target, "previous").expect("write");
    // A directory where the temporary file would go makes the write fail.
    let blocker = dir.join(format!("out.off.{}.partial", std::process::id()));
    std::fs::create_dir_all(&blocker).expect("blocker");
    let m = SampledMesh {
        positions: vec![[0.0; 3]],
        normals: vec![[0.0, 0.0, 1.0]],
        gaussian: vec![0.0],
        mean: vec![0.0],
        faces: vec![],
    };
    assert!(write_mesh_with_attributes(&target, &m).is_err());
    assert_eq!(std::fs::read_to_string(&target).expect("read"), "previous");
    std::fs::remove_dir(&blocker).expect("rm");
    write_mesh_with_attributes(&target, &m).expect("write");
    assert!(std::fs::read_to_string(&target)
        .expect("read")
        .starts_with("NOFF"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Unknown output extensions (`.stl`, none) were silently written as PLY.
#[test]
fn x_adv_15_unknown_extension_written_as_ply() {
    use pseudomanifold::surface::output::{write_mesh_with_attributes, SampledMesh};
    let dir = std::env::temp_dir();
    for name in ["x_adv_15.stl", "x_adv_15"] {
        let p = dir.join(name);
        let _ = std::fs::remove_file(&p);
        let e = write_mesh_with_attributes(&p, &SampledMesh::default()).expect_err(name);
        assert_eq!(e.kind(), std::io::ErrorKind::InvalidInput);
        assert!(!p.exists(), "{name} was written");
    }
}
