//! Randomized closed surfaces. From the tetrahedron, octahedron, icosahedron and tori,
//! random edge flips, edge splits and 1→3 splits (`mesh::generate::grow`, re-validated exactly
//! after each step) give closed simplicial surfaces with degrees from 3 to 20+. On them:
//! the validator accepts (Def. 3.1.6), χ is preserved, s_v is a simplicial isomorphism
//! (Def. 4.1.4), every Chapter 4 statement gets the verdict recorded in
//! `SPEC.md` (holds, or fails exactly for the degrees listed there), and
//! random corruptions are rejected with the right error class. Both proptest and quickcheck.

use proptest::prelude::*;
use pseudomanifold::construction::checks::{run_edge_checks, run_triangle_checks};
use pseudomanifold::construction::{EdgeConfig, TriangleConfig};
use pseudomanifold::mesh::generate::{self, Corruption, Expected, SurfaceOp, Surgery};
use pseudomanifold::mesh::star::check_star_isomorphism;
use pseudomanifold::mesh::validate::{validate, ErrorClass};
use pseudomanifold::mesh::{RawMesh, SimplicialSurface};
use pseudomanifold::report::{CheckResult, Verdict};

/// Samples per check (the conformance suite uses 240; 60 keeps a case under a second).
const N: usize = 60;

fn base(k: u8) -> RawMesh {
    match k % 5 {
        0 => generate::tetrahedron(),
        1 => generate::octahedron(),
        2 => generate::icosahedron(),
        3 => generate::torus(3, 4),
        _ => generate::torus(4, 5),
    }
}

fn op_strategy() -> impl Strategy<Value = SurfaceOp> {
    prop_oneof![
        any::<u16>().prop_map(|k| SurfaceOp::Flip(k as usize)),
        any::<u16>().prop_map(|k| SurfaceOp::SplitEdge(k as usize)),
        any::<u16>().prop_map(|k| SurfaceOp::SplitFace(k as usize)),
        // Raising one vertex repeatedly is how degrees of 20 and more are reached.
        (0usize..3, any::<u8>()).prop_map(|(v, k)| SurfaceOp::Raise { v, k: k as usize }),
    ]
}

fn surface(raw: &RawMesh) -> SimplicialSurface {
    let v = validate(raw);
    assert!(
        v.report.is_simplicial_surface,
        "grow must keep a simplicial surface: {:?}",
        v.report.error_classes
    );
    v.surface.expect("validated")
}

/// The verdict SPEC.md records for `id` on an edge with m_u = `m` (`None`: not a
/// degree-dependent statement of that table, or one that must simply hold).
fn predicted_fails(id: &str, m: u32) -> Option<bool> {
    Some(match id {
        "C4.1.6-gv-bijective" => m != 6,
        "C4.1.6-gv-smooth" => m % 6 != 0,
        "C4.1.8-onto-intC" => m < 6,
        "C4.1.8-guw-bijective" => m > 6,
        "P4.1.1" => m % 6 != 0,
        "P4.1.3-inverse" | "D4.1.9-lens" => m >= 11,
        "P4.1.2-proof-step" => true,
        "P4.2.4(i,ii)" => m == 3,
        "D4.1.5"
        | "C4.1.7-h-identity"
        | "C4.1.8-lens-in-Q"
        | "P4.1.2"
        | "P4.1.3"
        | "D4.1.10"
        | "P4.2.1"
        | "P4.2.3"
        | "L4.2.3"
        | "L4.2.4"
        | "L4.2.1"
        | "L4.2.2"
        | "L4.2.1-proof-equality"
        | "P4.2.4(iii,iv)" => false,
        _ => return None,
    })
}

fn assert_as_recorded(r: &CheckResult, m: u32, cfg: &str) {
    if r.id.ends_with("[restricted]") {
        assert!(
            r.holds_with_evidence(),
            "{} must hold on its restricted domain ({cfg}): {:?}, examined {}",
            r.id,
            r.verdict(),
            r.examined
        );
        return;
    }
    match predicted_fails(&r.id, m) {
        Some(true) => assert!(
            r.failed() && !r.witnesses.is_empty(),
            "{} should fail with a witness for m_u = {m} ({cfg}): {:?}",
            r.id,
            r.verdict()
        ),
        Some(false) => assert!(
            matches!(r.verdict(), Verdict::Holds),
            "{} should hold ({cfg}): {:?} {:?}",
            r.id,
            r.verdict(),
            r.witnesses.first()
        ),
        None => {}
    }
}

/// Chapter 4 on every oriented edge of one distinct configuration and on every face.
fn chapter4_as_recorded(s: &SimplicialSurface, seed: u64) -> usize {
    let mut seen_e = std::collections::BTreeSet::new();
    let mut seen_t = std::collections::BTreeSet::new();
    for (u, w) in s.edges() {
        for (a, b) in [(u, w), (w, u)] {
            let cfg = EdgeConfig::new(
                s.degree(a),
                s.s(a, b).expect("label"),
                s.degree(b),
                s.s(b, a).expect("label"),
            )
            .expect("validated surface gives a valid configuration");
            // Verdicts depend on (m_u, m_w) and labels only; one run per configuration.
            if seen_e.insert((cfg.m_u, cfg.i, cfg.m_w, cfg.j)) {
                for r in run_edge_checks::<f64>(&cfg, seed, N, 53) {
                    assert_as_recorded(&r, cfg.m_u, &format!("{cfg:?}"));
                }
            }
        }
    }
    for f in s.faces() {
        let [u, w, x] = s.face(f);
        let t = TriangleConfig::ccw(
            s.degree(u),
            s.degree(w),
            s.degree(x),
            s.s(u, w).expect("label"),
            s.s(w, x).expect("label"),
            s.s(x, u).expect("label"),
        )
        .expect("faces of a consistently oriented surface are counterclockwise fans");
        if seen_t.insert((t.m_u, t.m_w, t.m_x, t.u_w, t.w_x, t.x_u)) {
            for r in run_triangle_checks::<f64>(&t, seed, N, 53) {
                assert_as_recorded(&r, t.m_u, &format!("{t:?}"));
            }
        }
    }
    seen_e.len() + seen_t.len()
}

fn check_corruption(s: &Surgery, c: Corruption) {
    let mut bad = s.clone();
    let Some(expected) = bad.corrupt(c) else {
        return;
    };
    let v = validate(&bad.to_raw());
    match expected {
        Expected::Rejected(class) => {
            assert!(!v.report.is_simplicial_surface, "{c:?} accepted");
            assert!(
                v.report.error_classes.contains(&class),
                "{c:?}: expected {class:?} in {:?}",
                v.report.error_classes
            );
        }
        Expected::Reoriented => {
            let k = v
                .surface
                .expect("one reversed face is re-oriented, not rejected");
            let nf = k.num_faces() as u64;
            assert!(k.flipped_faces() == 1 || k.flipped_faces() == nf - 1);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Def. 3.1.6 on random surgery: accepted, χ preserved, degrees as counted combinatorially;
    /// each corruption rejected with its class (delete → boundary, duplicate → duplicate_face,
    /// glue two far vertices → nonmanifold_vertex), a reversed face re-oriented.
    #[test]
    fn d3_1_6_random_surfaces_accepted_and_corruptions_rejected(
        b in any::<u8>(),
        ops in prop::collection::vec(op_strategy(), 0..30),
        k in any::<u16>(),
    ) {
        let base = base(b);
        let chi = Surgery::new(&base).euler_characteristic();
        let (s, _) = generate::grow(&base, &ops);
        prop_assert_eq!(s.euler_characteristic(), chi);
        let k_surf = surface(&s.to_raw());
        let deg = s.degrees();
        for v in k_surf.vertices() {
            prop_assert_eq!(k_surf.degree(v), deg[v.0 as usize]);
        }
        for c in [
            Corruption::DeleteFace(k as usize),
            Corruption::DuplicateFace(k as usize),
            Corruption::GlueVertices(k as usize),
            Corruption::FlipOrientation(k as usize),
        ] {
            check_corruption(&s, c);
        }
        crate::common::verdicts::record("D3.1.6-random", crate::common::verdicts::Seen::Holds, 1);
    }

    /// Def. 4.1.4 and the Chapter 4 verdicts of SPEC.md on random surfaces.
    #[test]
    fn t4_2_1_random_surfaces_chapter4_verdicts_as_recorded(
        b in any::<u8>(),
        ops in prop::collection::vec(op_strategy(), 0..20),
        seed in any::<u64>(),
    ) {
        let (s, _) = generate::grow(&base(b), &ops);
        let k = surface(&s.to_raw());
        let iso = check_star_isomorphism(&k, |v, x| k.s(v, x));
        prop_assert!(iso.holds_with_evidence(), "{:?} {:?}", iso.verdict(), iso.witnesses.first());
        prop_assert!(chapter4_as_recorded(&k, seed) > 0);
    }
}

/// quickcheck: the same surgery from a plain list of integers (a different generator and
/// shrinker than proptest's); D4.1.4 and the validator's acceptance must hold.
#[test]
fn d4_1_4_random_surfaces_quickcheck_labels_are_star_isomorphisms() {
    fn prop(b: u8, ops: Vec<(u8, u16)>) -> bool {
        let ops: Vec<SurfaceOp> = ops
            .iter()
            .take(25)
            .map(|&(t, k)| match t % 4 {
                0 => SurfaceOp::Flip(k as usize),
                1 => SurfaceOp::SplitEdge(k as usize),
                2 => SurfaceOp::SplitFace(k as usize),
                _ => SurfaceOp::Raise {
                    v: 0,
                    k: k as usize,
                },
            })
            .collect();
        let (s, _) = generate::grow(&base(b), &ops);
        let v = validate(&s.to_raw());
        let Some(k) = v.surface else { return false };
        check_star_isomorphism(&k, |v, x| k.s(v, x)).holds_with_evidence()
            && k.vertices().all(|v| k.degree(v) >= 3)
    }
    quickcheck::QuickCheck::new()
        .tests(40)
        .quickcheck(prop as fn(u8, Vec<(u8, u16)>) -> bool);
    // quickcheck panics on a counterexample: reaching here, 40 surfaces held.
    crate::common::verdicts::record("D4.1.4-random", crate::common::verdicts::Seen::Holds, 40);
}

/// Degrees from 3 to 20+ are reached: raising vertex 0 of each base 24 times gives degree ≥ 20
/// (validated at every step), and the Chapter 4 verdicts are as recorded on that surface too.
#[test]
fn t4_2_1_random_surfaces_reach_degree_3_to_20_plus() {
    for b in 0..5u8 {
        let ops: Vec<SurfaceOp> = (0..24).map(|k| SurfaceOp::Raise { v: 0, k }).collect();
        let (s, kept) = generate::grow(&base(b), &ops);
        let deg = s.degrees();
        let max = deg.iter().copied().max().unwrap_or(0);
        let min = deg.iter().copied().filter(|&d| d > 0).min().unwrap_or(0);
        assert!(
            max >= 20,
            "base {b}: max degree {max} after {kept} of 24 steps"
        );
        assert!(min >= 3, "base {b}: min degree {min}");
        if b == 0 {
            assert_eq!(min, 3, "the 1→3 splits leave degree-3 vertices");
            let k = surface(&s.to_raw());
            let configs = chapter4_as_recorded(&k, 20240601);
            assert!(configs > 0);
            // Every Chapter 4 verdict as SPEC records it, on degrees 3 to 20+.
            crate::common::verdicts::record(
                "T4.2.1-random",
                crate::common::verdicts::Seen::Holds,
                configs as u64,
            );
        }
    }
}

/// Corruptions on a fixed torus, one by one, with the exact class.
#[test]
fn d3_1_6_random_corruptions_each_class_on_torus() {
    let s = Surgery::new(&generate::torus(4, 5));
    for (c, class) in [
        (Corruption::DeleteFace(3), ErrorClass::Boundary),
        (Corruption::DuplicateFace(7), ErrorClass::DuplicateFace),
        (Corruption::GlueVertices(0), ErrorClass::NonmanifoldVertex),
    ] {
        let mut bad = s.clone();
        assert_eq!(bad.corrupt(c), Some(Expected::Rejected(class)));
        let v = validate(&bad.to_raw());
        assert!(
            v.report.error_classes.contains(&class),
            "{c:?}: {:?}",
            v.report.error_classes
        );
    }
}
