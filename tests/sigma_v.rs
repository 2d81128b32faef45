//! The tutorial's (σ, v)-indexed construction (seed 002, Parts IV–V): SPEC rows `SV-…`, each
//! with its planted faults. Fast fixtures by default; the good corpus when ../shared exists.

mod common;

use pseudomanifold::construction::maps::{in_omega_uw, EdgeConfig, P2};
use pseudomanifold::construction::sigma_v::checks::*;
use pseudomanifold::construction::sigma_v::gluing::g_uw_on_domain;
use pseudomanifold::construction::sigma_v::wedge::WedgeTable;
use pseudomanifold::construction::sigma_v::*;
use pseudomanifold::gluing::data::GluingData;
use pseudomanifold::gluing::sampled::{check_1, check_all, SampleConfig};
use pseudomanifold::mesh::generate::{icosahedron, octahedron, torus};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, RawMesh, SimplicialSurface, VertexId};
use pseudomanifold::report::CheckResult;
use pseudomanifold::surface::PnTriangles;

fn surface(raw: &RawMesh) -> SimplicialSurface {
    validate(raw).surface.expect("valid fixture")
}

/// Bipyramid over an n-gon: apexes of degree n, equator of degree 4.
fn bipyramid(n: u32) -> SimplicialSurface {
    let mut pos = vec![[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
    for i in 0..n {
        let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
        pos.push([a.cos(), a.sin(), 0.0]);
    }
    let mut faces = vec![];
    for i in 0..n {
        let (a, b) = (2 + i, 2 + (i + 1) % n);
        faces.push([0, a, b]);
        faces.push([1, b, a]);
    }
    surface(&RawMesh::from_arrays(pos, faces))
}

fn build(k: &SimplicialSurface) -> SigmaVPps {
    SigmaVPps::build(k, &PnTriangles::new(k), DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE).expect("κ valid")
}

fn holds(r: &CheckResult) {
    assert!(!r.failed(), "{} fails: {:?}", r.id, r.witnesses.first());
    assert!(r.examined > 0, "{}: nothing examined", r.id);
    eprintln!("{} holds: examined {}, worst {:?}, tol {:?}", r.id, r.examined, r.worst_deviation, r.tolerance);
}

fn fails(r: &CheckResult) {
    assert!(r.failed(), "{} should fail", r.id);
    assert!(!r.witnesses.is_empty());
    eprintln!("{} fails as expected: {}", r.id, r.witnesses[0].text);
}

const CFG: SampleConfig = SampleConfig { seed: 7, n: 16 };

#[test]
fn sv_count_three_n_t() {
    for k in [surface(&octahedron()), surface(&icosahedron()), bipyramid(7)] {
        let g = SigmaV::new(&k, DEFAULT_KAPPA).unwrap();
        assert_eq!(g.len(), 3 * k.num_faces());
        holds(&check_count(&g));
    }
}

#[test]
fn sv_d3_kappa_out_of_range_is_a_typed_error() {
    let k = surface(&octahedron());
    for kappa in [0.0, 1.0, -0.1, f64::NAN, 2.0] {
        assert!(matches!(SigmaV::new(&k, kappa), Err(SigmaVError::BadKappa(_))));
    }
}

#[test]
fn sv_first_attempt_fails_def_3_4_1_1_with_witness() {
    let k = surface(&icosahedron());
    let g = SigmaV::new(&k, DEFAULT_KAPPA).unwrap();
    let r = check_first_attempt(&g, VertexId(0), &CFG);
    fails(&r);
    // And across vertices: all P-polygons at the origin in the first attempt.
    let view = SigmaVView::at_vertices(&g, &[VertexId(0), VertexId(1)], Version::FirstAttempt);
    fails(&check_1(&view, &CFG));
}

#[test]
fn sv_1_fixed_version_satisfies_def_3_4_1() {
    for k in [surface(&octahedron()), bipyramid(7)] {
        let g = SigmaV::new(&k, DEFAULT_KAPPA).unwrap();
        let f = k.face(FaceId(0));
        let view = SigmaVView::at_vertices(&g, &f, Version::Fixed);
        for r in check_all(&view, &CFG) {
            holds(&r);
        }
    }
}
