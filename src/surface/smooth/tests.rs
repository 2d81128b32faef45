//! The three constructions through the one interface: every method either answers or says,
//! typed, that it does not apply; what the trait returns is what each type's own API returns.

use super::{SmoothError, SmoothSurface};
use crate::gluing::data::GluingData;
use crate::gluing::sampled::{domains::check_1, SampleConfig};
use crate::mesh::validate::validate;
use crate::mesh::{generate, FaceId, SimplicialSurface};
use crate::msplines::pipeline::spline;
use crate::msplines::smooth::SplineSurface;
use crate::numeric::Scalar;
use crate::surface::output::Attributes;
use crate::surface::sigma_v::SigmaVPps;
use crate::surface::{PnTriangles, Pps, PpsOptions};

fn torus() -> SimplicialSurface {
    validate(&generate::torus(6, 4))
        .surface
        .expect("generated torus is a simplicial surface")
}

/// The same point, bound, MPFR value, geometry and sampling as the types' own methods.
fn agrees(s: &dyn SmoothSurface, k: &SimplicialSurface) {
    let (f, b) = (FaceId(3), [0.2, 0.3, 0.5]);
    let p = s.eval_f64(f, b).expect("eval");
    let (q, _) = s.eval_bounded(f, b).expect("eval bounded");
    assert_eq!(p, q, "{}", s.name());
    let mp = s.mp_eval(256).expect("mp eval")(f, b).expect("mp point");
    for (x, y) in p.iter().zip(&mp) {
        assert!((x - y.to_f64()).abs() < 1e-12, "{}", s.name());
    }
    let g = s.eval_geometry(f, b).expect("geometry");
    assert!(g.point.iter().zip(&p).all(|(a, b)| (a - b).abs() < 1e-12));
    assert!((g.normal.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-12);
    let m = s.sample(1, Attributes::Curvature, None).expect("sample");
    assert_eq!(m.positions.len(), m.normals.len());
    assert_eq!(m.faces.len(), 4 * k.num_faces());
    assert_eq!(s.face_corners().expect("faces").len(), k.num_faces());
    let view = s.gluing_view(k, vec![0, 1, 2]).expect("view");
    assert_eq!(view.indices(), vec![0, 1, 2]);
    let r = check_1(&view, &SampleConfig { seed: 1, n: 16 });
    assert!(!r.failed(), "{}: {r:?}", s.name());
}

#[test]
fn the_vertex_pps_through_the_trait() {
    let k = torus();
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let (f, b) = (FaceId(3), [0.2, 0.3, 0.5]);
    assert_eq!(
        SmoothSurface::eval_f64(&pps, f, b).ok(),
        pps.eval_f64(f, b).ok()
    );
    agrees(&pps, &k);
    let other = validate(&generate::octahedron())
        .surface
        .expect("octahedron");
    assert!(matches!(
        pps.gluing_view(&other, vec![0]),
        Err(SmoothError::Unsupported { .. })
    ));
}

#[test]
fn the_sigma_v_pps_through_the_trait() {
    let k = torus();
    let pps = SigmaVPps::build(&k, &PnTriangles::new(&k), 0.25, 5).expect("build");
    agrees(&pps, &k);
}

/// The spline answers eval, sampling of positions and its atlas' gluing data; MPFR, jets
/// and sampled normals are typed refusals (Sec. 5.6 evaluates F's value only).
#[test]
fn the_manifold_spline_through_the_trait() {
    let k = torus();
    let (at, sp) = spline(&k, 0, 3, 2, 0x5eed).expect("spline");
    let s = SplineSurface {
        k: &k,
        atlas: &at,
        spline: &sp,
    };
    let f: &dyn SmoothSurface = &s;
    let p = f.eval_f64(FaceId(3), [0.2, 0.3, 0.5]).expect("eval");
    assert!(p.iter().all(|x| x.is_finite()));
    assert!(f
        .eval_bounded(FaceId(3), [0.2, 0.3, 0.5])
        .expect("eval")
        .1
        .is_none());
    let m = f.sample(1, Attributes::Positions, None).expect("sample");
    assert_eq!(m.faces.len(), 4 * k.num_faces());
    assert!(m.normals.is_empty());
    for e in [
        f.mp_eval(256).err(),
        f.eval_geometry(FaceId(3), [0.2, 0.3, 0.5]).err(),
        f.sample(1, Attributes::Normals, None).err(),
    ] {
        assert!(matches!(e, Some(SmoothError::Unsupported { .. })), "{e:?}");
    }
    assert!(matches!(
        f.eval_f64(FaceId(9999), [1.0, 0.0, 0.0]),
        Err(SmoothError::Vertex(_))
    ));
    let view = f.gluing_view(&k, vec![0, 1]).expect("view");
    assert_eq!(view.indices(), vec![0, 1]);
}
