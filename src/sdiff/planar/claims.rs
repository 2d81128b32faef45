//! The injectivity claims of Mello–Velho Sec. 3, tested exactly on the reference triangle by a
//! seeded search: every sampled map is certified (det DX > 0 on the closed triangle, exact) or
//! refuted with an exact witness. A claim "holds" here when no sample refutes it; an
//! existential claim holds when a sample exhibits it.

use super::maps::SimplexMap;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::poly2::{index_of, multi_indices};
use crate::sdiff::common::positivity::{decide, Budget, Decision, Strictness};
use crate::sdiff::common::rational::{q, qr, Q};
use crate::sdiff::common::simplex_search::{unit_open, Search};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// Certify or refute det DX > 0 (with D > 0 first) for one map.
pub fn det_decision(m: &SimplexMap, budget: Budget) -> Decision {
    if m.family != super::maps::Family::Polynomial {
        let d = decide(&m.den, Strictness::Positive, budget);
        if !d.certified() {
            return d;
        }
    }
    decide(&m.jacobian_numerator(), Strictness::Positive, budget)
}

/// Runs `samples` maps from `gen` through [`det_decision`].
pub fn search(
    samples: usize,
    seed: u64,
    budget: Budget,
    mut gen: impl FnMut(&mut ChaCha8Rng) -> (String, SimplexMap),
) -> Search {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut s = Search::default();
    for _ in 0..samples {
        let (desc, m) = gen(&mut rng);
        s.record(det_decision(&m, budget), || desc);
    }
    s
}

/// A random point of the open face with support `supp` (barycentric, positive on supp).
pub(crate) fn open_face_point(rng: &mut ChaCha8Rng, supp: [bool; 3]) -> [Q; 3] {
    let mut w: [Q; 3] = [q(0), q(0), q(0)];
    let mut total = q(0);
    for c in 0..3 {
        if supp[c] {
            w[c] = unit_open(rng);
            total += &w[c];
        }
    }
    w.map(|x| x / &total)
}

/// An adjusted polynomial map of degree n with random control points (Sec. 3.2).
pub fn random_adjusted(n: usize, rng: &mut ChaCha8Rng) -> (String, SimplexMap) {
    let control: Vec<[Q; 3]> = multi_indices(n)
        .into_iter()
        .map(|i| open_face_point(rng, i.map(|k| k > 0)))
        .collect();
    (describe(&control), SimplexMap::polynomial(n, control))
}

/// Degree n + 1 = 3 with every non-solitary control point fixed and the solitary (1,1,1) point
/// random in the open triangle (Sec. 3.2, Fig. 1(b) in 2-D).
pub fn random_fixed_solitary3(rng: &mut ChaCha8Rng) -> (String, SimplexMap) {
    let mut control = SimplexMap::fixed_control(3);
    control[index_of(3, [1, 1, 1])] = open_face_point(rng, [true; 3]);
    (describe(&control), SimplexMap::polynomial(3, control))
}

/// Degree n rational map with fixed control points and random positive weights in [1/100, 100].
pub fn random_rational_fixed(n: usize, rng: &mut ChaCha8Rng) -> (String, SimplexMap) {
    let control = SimplexMap::fixed_control(n);
    let weights: Vec<Q> = control
        .iter()
        .map(|_| match rng.gen_range(0..6) {
            0 => qr(1, 100),
            1 => q(100),
            _ => qr(rng.gen_range(1..1000), 97),
        })
        .collect();
    let desc = format!(
        "n = {n}, weights {:?}",
        weights.iter().map(|w| w.to_string()).collect::<Vec<_>>()
    );
    (desc, SimplexMap::rational(n, control, weights))
}

/// Monotonic map with random g_i(t) = a t + b t² + c t³, a > 0, b, c ≥ 0 (so g' > 0 on [0, 1]).
pub fn random_monotonic(rng: &mut ChaCha8Rng) -> (String, SimplexMap) {
    let g = [(); 3].map(|_| {
        Poly1(vec![
            q(0),
            unit_open(rng) * q(10),
            unit_open(rng) * q(10),
            unit_open(rng) * q(10),
        ])
    });
    let desc = format!(
        "{:?}",
        g.iter()
            .map(|p| p.0.iter().map(|x| x.to_string()).collect::<Vec<_>>())
            .collect::<Vec<_>>()
    );
    (desc, SimplexMap::monotonic(g))
}

fn describe(control: &[[Q; 3]]) -> String {
    format!(
        "{:?}",
        control
            .iter()
            .map(|b| b.iter().map(|x| x.to_string()).collect::<Vec<_>>())
            .collect::<Vec<_>>()
    )
}

/// A universal claim as a [`CheckResult`]: holds when no sample refutes it.
pub fn universal(id: &str, name: &str, s: &Search, samples: usize, seed: u64) -> CheckResult {
    let mut r = CheckResult::new(id, name);
    r.seed = Some(seed);
    r.examined = samples as u64;
    for (desc, d) in &s.refuted {
        if let Decision::Refuted {
            point_f64,
            value_f64,
            point,
            value,
        } = d
        {
            r.offend(|| {
                Witness::new(
                    format!("det DX = {value_f64:.3e} ≤ 0 at w = {point_f64:?} for control {desc}"),
                    json!({"w": point, "value": value, "map": desc}),
                )
            });
        }
    }
    if s.unresolved > 0 && !r.failed() {
        r.skip(format!("{} samples unresolved", s.unresolved));
    }
    r.note = format!(
        "{} certified exactly, {} refuted, {} unresolved",
        s.certified,
        s.refuted.len(),
        s.unresolved
    );
    r
}

/// An existential claim: holds when some sample exhibits det < 0 at an interior point, which
/// with det > 0 elsewhere and a boundary homeomorphism forces two more preimages (degree
/// theory), i.e. non-injectivity.
pub fn existential(id: &str, name: &str, s: &Search, samples: usize, seed: u64) -> CheckResult {
    let mut r = CheckResult::new(id, name);
    r.seed = Some(seed);
    r.examined = samples as u64;
    let hit = s
        .refuted
        .iter()
        .find(|(_, d)| matches!(d, Decision::Refuted { value_f64, .. } if *value_f64 < 0.0));
    match hit {
        Some((
            desc,
            Decision::Refuted {
                point,
                point_f64,
                value_f64,
                ..
            },
        )) => {
            r.witnesses.push(Witness::new(
                format!(
                    "adjusted map with det DX = {value_f64:.3e} < 0 at w = {point_f64:?}: {desc}"
                ),
                json!({"w": point, "map": desc}),
            ));
        }
        _ => {
            r.skip(format!(
                "no example among {samples} samples (the search is not a proof of absence)"
            ));
        }
    }
    r.note = format!(
        "{} certified, {} with det ≤ 0 somewhere",
        s.certified,
        s.refuted.len()
    );
    r
}
