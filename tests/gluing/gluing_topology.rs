//! Secs. 3.2–3.4 on concrete objects of the exact backend: the usual topology on ℝ (Def. 3.2.1),
//! continuity and homeomorphisms (Def. 3.2.2), the Hausdorff requirement of Def. 3.3.4 and the
//! manifold M_G of Thm. 3.4.1.

use crate::common;
use pseudomanifold::gluing::exact1d::data::q;
use pseudomanifold::gluing::exact1d::{Exact1d, Interval, OpenSet, Q};
use pseudomanifold::gluing::file::read_gluing_file;
use pseudomanifold::gluing::relation::{classes, GridSample};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn load(name: &str) -> Exact1d {
    let p = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(format!("examples/gluing/{name}.toml"));
    read_gluing_file(&p).expect("parses").data
}

fn random_open(rng: &mut ChaCha8Rng) -> OpenSet {
    OpenSet::from_intervals((0..rng.gen_range(0..4)).filter_map(|_| {
        let lo = q(rng.gen_range(-16..16), 4);
        Interval::new(lo.clone(), lo + q(rng.gen_range(1..12), 4))
    }))
}

fn grid() -> impl Iterator<Item = Q> {
    (-80..=80).map(|t| q(t, 16))
}

#[test]
fn d3_2_1_open_sets_of_r_closed_under_finite_intersection_and_union() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let whole = OpenSet::from_interval(Interval::new(q(-100, 1), q(100, 1)).expect("non-empty"));
    for _ in 0..300 {
        let (a, b) = (random_open(&mut rng), random_open(&mut rng));
        let (i, u) = (a.intersect(&b), a.union(&b));
        // Results are again finite unions of open intervals (open), and pointwise correct.
        for x in grid() {
            assert_eq!(i.contains(&x), a.contains(&x) && b.contains(&x));
            assert_eq!(u.contains(&x), a.contains(&x) || b.contains(&x));
        }
        assert_eq!(a.intersect(&OpenSet::empty()), OpenSet::empty());
        assert_eq!(a.intersect(&whole), a);
        // Every point of an open set has a ball inside it (the "usual" topology).
        for x in grid().filter(|x| a.contains(x)) {
            let p = a
                .parts()
                .iter()
                .find(|p| p.contains(&x))
                .expect("x in a part");
            let r = (&x - &p.lo).min(&p.hi - &x);
            assert!(
                r > q(0, 1) && a.contains(&(&x + &r / q(2, 1))) && a.contains(&(&x - &r / q(2, 1)))
            );
        }
    }
    common::verdicts::record("D3.2.1", common::verdicts::Seen::Holds, 300);
}

#[test]
fn d3_2_2_affine_maps_are_continuous_and_homeomorphisms() {
    let mut rng = ChaCha8Rng::seed_from_u64(22);
    for _ in 0..300 {
        let u = random_open(&mut rng);
        let a = q(
            [1, -1, 2, -3][rng.gen_range(0..4)],
            [1, 2, 3][rng.gen_range(0..3)],
        );
        let b = q(rng.gen_range(-8..8), 2);
        // f⁻¹(U) is open and equals {x : f(x) ∈ U}; f(f⁻¹(U)) = U (bijective, inverse continuous).
        let pre = u.affine_preimage(&a, &b);
        for x in grid() {
            assert_eq!(pre.contains(&x), u.contains(&(&a * &x + &b)));
        }
        assert_eq!(pre.affine_image(&a, &b), u);
    }
    common::verdicts::record("D3.2.2", common::verdicts::Seen::Holds, 300);
}

#[test]
fn d3_3_4_hausdorff_requirement_fails_for_fork_quotient_and_holds_for_repair() {
    // App. A.2: in the fork, the images of (−2 − ε, −2 + ε) and (2 − η, 2 + η) always intersect;
    // in the repaired fork (−2 ↦ 3) they are disjoint for ε = η = 1/2.
    let fork = load("fork");
    for k in 1..40 {
        let e = q(1, 1i64 << k);
        // A point of (−2 − e, −2) ⊆ Ω_12 is identified with a point of (2 − e, 2).
        let x = q(-2, 1) - &e / q(2, 1);
        let y = fork.phi(2, 1, &x).expect("in Ω_12");
        assert!(y > q(2, 1) - &e && y < q(2, 1));
    }
    let rep = load("fork_repaired");
    for t in 1..100 {
        let x = q(-2, 1) - q(t, 200);
        if let Some(y) = rep.phi(2, 1, &x) {
            assert!(y >= q(5, 2), "{x} ↦ {y} enters the ball around 2");
        }
    }
}

#[test]
fn t3_4_1_transition_functions_of_m_g_are_the_phi() {
    // In M_G, the chart change τ_j⁻¹ ∘ τ_i on τ_i(Ω_ij) is φ_ji: every class containing x ∈ Ω_i
    // and y ∈ Ω_j (i ≠ j) has y = φ_ji(x); and τ_i is injective (one point of Ω_i per class).
    for name in ["circle2", "circle3", "line_repaired"] {
        let g = load(name);
        let mut checked = 0;
        for c in classes(&g, &GridSample::new(&g, 24)) {
            for x in &c {
                assert_eq!(
                    c.iter().filter(|p| p.0 == x.0).count(),
                    1,
                    "{name}: τ_{} not injective",
                    x.0
                );
                for y in c.iter().filter(|p| p.0 != x.0) {
                    assert_eq!(g.phi(y.0, x.0, &x.1).as_ref(), Some(&y.1), "{name}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 20, "{name}: {checked}");
    }
    common::verdicts::record("T3.4.1", common::verdicts::Seen::Holds, 3);
}
