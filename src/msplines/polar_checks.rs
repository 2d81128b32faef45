//! Exact checks of Sec. 3.1 and Lemma 1.1 on random rational data (seeded): Defs. 1–2,
//! Prop. 3, recurrence (4), the B-patch properties of Sec. 3.1.3 and Lemma 1.1 (1)–(2).

use super::polar::{barycentric, multi_indices, q, q2, Affine, KnotClouds, ProductPoly, Q, Q2};
use crate::report::{CheckResult, Witness};
use num_traits::{One, Signed, Zero};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

fn rq(rng: &mut ChaCha8Rng) -> Q {
    q(rng.gen_range(-40..=40), rng.gen_range(1..=12))
}
fn rq2(rng: &mut ChaCha8Rng) -> Q2 {
    [rq(rng), rq(rng)]
}
fn qs(x: &Q) -> String {
    x.to_string()
}
fn q2s(p: &Q2) -> String {
    format!("({}, {})", p[0], p[1])
}

/// A random degree-k polynomial: two products of k random affine factors.
pub fn random_poly(rng: &mut ChaCha8Rng, k: usize) -> ProductPoly {
    let terms = (0..2)
        .map(|_| {
            (
                rq(rng),
                (0..k)
                    .map(|_| Affine {
                        abc: [rq(rng), rq(rng), rq(rng)],
                    })
                    .collect(),
            )
        })
        .collect();
    ProductPoly {
        k,
        terms,
        unsymmetrised: false,
    }
}

/// Random knot clouds of degree k around the triangle (0,0), (1,0), (0,1): t_{i,0} the
/// vertex, t_{i,l} at distance ≤ 1/8 (the "generic rational offsets" of Sec. 5.5).
pub fn random_clouds(rng: &mut ChaCha8Rng, k: usize) -> KnotClouds {
    let base = [q2((0, 1), (0, 1)), q2((1, 1), (0, 1)), q2((0, 1), (1, 1))];
    let clouds = base.map(|v| {
        let mut c = vec![v.clone()];
        for _ in 0..k {
            c.push([
                &v[0] + q(rng.gen_range(-12..=12), 97),
                &v[1] + q(rng.gen_range(-12..=12), 97),
            ]);
        }
        c
    });
    KnotClouds { k, clouds }
}

/// A random point of the triangle (0,0), (1,0), (0,1) (strictly inside).
fn point_in_unit_triangle(rng: &mut ChaCha8Rng) -> Q2 {
    let (a, b) = (rng.gen_range(1..60), rng.gen_range(1..60));
    let (a, b) = if a + b >= 60 {
        (60 - a, 60 - b)
    } else {
        (a, b)
    };
    [q(a, 61), q(b, 61)]
}

/// Def. 2 and Prop. 3: the blossom is symmetric, multi-affine, and f(u, …, u) = F(u).
pub fn check_blossom(p: &ProductPoly, seed: u64, trials: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-P3",
        "blossom symmetric, multi-affine, diagonal = F (Def. 2, Prop. 3; exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..trials {
        let us: Vec<Q2> = (0..p.k).map(|_| rq2(&mut rng)).collect();
        let f = p.blossom(&us);
        r.examined += 3;
        let mut rev = us.clone();
        rev.rotate_left(1);
        if p.blossom(&rev) != f {
            r.offend(|| {
                Witness::new(
                    format!(
                        "not symmetric: f{:?} ≠ f(rotated)",
                        us.iter().map(q2s).collect::<Vec<_>>()
                    ),
                    json!({"kind": "symmetric"}),
                )
            });
        }
        let (a, b, al) = (rq2(&mut rng), rq2(&mut rng), rq(&mut rng));
        let mix = [
            &al * &a[0] + (Q::one() - &al) * &b[0],
            &al * &a[1] + (Q::one() - &al) * &b[1],
        ];
        let at = |x: &Q2| {
            let mut v = us.clone();
            v[0] = x.clone();
            p.blossom(&v)
        };
        if at(&mix) != &al * at(&a) + (Q::one() - &al) * at(&b) {
            r.offend(|| {
                Witness::new(
                    "not affine in the first argument",
                    json!({"kind": "multi_affine"}),
                )
            });
        }
        let u = rq2(&mut rng);
        if p.blossom(&vec![u.clone(); p.k]) != p.eval(&u) {
            r.offend(|| {
                Witness::new(
                    format!("f(u,…,u) ≠ F(u) at u = {}", q2s(&u)),
                    json!({"kind": "diagonal"}),
                )
            });
        }
    }
    r
}

/// Sec. 3.1.2 / 3.1.3(3): poles f(X^β) from the blossom of F reproduce F through recurrence (4).
pub fn check_reproduction(
    p: &ProductPoly,
    kc: &KnotClouds,
    seed: u64,
    trials: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-3.1.3(3)",
        "completeness: poles f(X^β) reproduce F by recurrence (4) (exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..trials {
        let u = rq2(&mut rng);
        r.examined += 1;
        match kc.eval(&|b| p.blossom(&kc.x_beta(b)), &u) {
            Some(v) if v == p.eval(&u) => {}
            Some(v) => r.offend(|| {
                Witness::new(
                    format!(
                        "at u = {}: recurrence gives {} but F(u) = {}",
                        q2s(&u),
                        qs(&v),
                        qs(&p.eval(&u))
                    ),
                    json!({"u": q2s(&u)}),
                )
            }),
            None => r.offend(|| Witness::new("a Δ^β is degenerate", json!({}))),
        }
    }
    r
}

/// Sec. 3.1.3(2): convex hull. B_β(u) ≥ 0 and Σ_β B_β(u) = 1 hold where every λ_{β,i}(u) ≥ 0
/// (u in ∩_β Δ^β); outside, a negative B_β is the witness that the property is restricted.
pub fn check_convex_hull(kc: &KnotClouds, seed: u64, trials: usize) -> CheckResult {
    let mut r = CheckResult::new("MS-3.1.3(2)", "convex hull: B_β ≥ 0, Σ B_β = 1 (exact)");
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let betas = multi_indices(kc.k);
    let mut outside_negative = None;
    for t in 0..trials {
        let u = if t % 2 == 0 {
            point_in_unit_triangle(&mut rng)
        } else {
            rq2(&mut rng)
        };
        let inside = (0..kc.k).all(|n| {
            multi_indices(n).iter().all(|b| {
                barycentric(kc.delta(b), &u).is_some_and(|l| l.iter().all(|x| !x.is_negative()))
            })
        });
        let vals: Option<Vec<Q>> = betas.iter().map(|b| kc.basis(b, &u)).collect();
        let Some(vals) = vals else {
            r.offend(|| Witness::new("a Δ^β is degenerate", json!({})));
            continue;
        };
        r.examined += 1;
        let sum = vals.iter().fold(Q::zero(), |a, b| a + b);
        if !sum.is_one() {
            r.offend(|| {
                Witness::new(
                    format!("Σ B_β({}) = {}", q2s(&u), qs(&sum)),
                    json!({"u": q2s(&u), "kind": "partition"}),
                )
            });
        }
        if let Some(i) = vals.iter().position(|v| v.is_negative()) {
            if inside {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "B_{:?}({}) = {} < 0 inside ∩Δ^β",
                            betas[i],
                            q2s(&u),
                            qs(&vals[i])
                        ),
                        json!({"u": q2s(&u), "kind": "negative"}),
                    )
                });
            } else if outside_negative.is_none() {
                outside_negative = Some(format!(
                    "B_{:?}({}) = {} < 0",
                    betas[i],
                    q2s(&u),
                    qs(&vals[i])
                ));
            }
        }
    }
    if let (Some(w), false) = (outside_negative, r.failed()) {
        r.restrict(format!("u ∈ ∩_β Δ^β (all λ_β,i(u) ≥ 0); outside: {w}"));
    }
    r
}

/// Sec. 3.1.3(4) and Lemma 1.1(1): for a rational affine φ, knots and parameter mapped by φ
/// give the same value, for every pole set; (5): an affine map of the poles maps F alike.
pub fn check_affine_invariance(
    p: &ProductPoly,
    kc: &KnotClouds,
    seed: u64,
    trials: usize,
) -> Vec<CheckResult> {
    let mut par = CheckResult::new(
        "MS-3.1.3(4)",
        "parametric affine invariance; Lemma 1.1(1) (exact)",
    );
    let mut val = CheckResult::new(
        "MS-3.1.3(5)",
        "affine invariance of the control net (exact)",
    );
    par.seed = Some(seed);
    val.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..trials {
        let m = [[rq(&mut rng), rq(&mut rng)], [rq(&mut rng), rq(&mut rng)]];
        if (&m[0][0] * &m[1][1] - &m[0][1] * &m[1][0]).is_zero() {
            continue;
        }
        let b = rq2(&mut rng);
        let phi = |x: &Q2| {
            [
                &m[0][0] * &x[0] + &m[0][1] * &x[1] + &b[0],
                &m[1][0] * &x[0] + &m[1][1] * &x[1] + &b[1],
            ]
        };
        let mapped = kc.mapped(&phi);
        let u = rq2(&mut rng);
        let poles = |bb: &[usize; 3]| p.blossom(&kc.x_beta(bb));
        par.examined += 1;
        if kc.eval(&poles, &u) != mapped.eval(&poles, &phi(&u)) {
            par.offend(|| {
                Witness::new(
                    format!("F(u) ≠ F̃(φ(u)) at u = {}", q2s(&u)),
                    json!({"u": q2s(&u)}),
                )
            });
        }
        let (a, c) = (rq(&mut rng), rq(&mut rng));
        val.examined += 1;
        let lhs = kc.eval(&|bb| &a * poles(bb) + &c, &u);
        let rhs = kc.eval(&poles, &u).map(|v| &a * v + &c);
        if lhs != rhs {
            val.offend(|| {
                Witness::new(
                    format!("F_(aP+c)(u) ≠ a·F(u) + c at u = {}", q2s(&u)),
                    json!({"u": q2s(&u)}),
                )
            });
        }
    }
    vec![par, val]
}

/// Lemma 1.1(2), contrapositive: for a non-affine φ (here the planted φ(x, y) = (x + x²/4, y)
/// or any map given), some single-pole net and some u give F(u) ≠ F̃(φ(u)); the witness is
/// reported. The result *fails* when no witness is found (the lemma would be contradicted).
pub fn check_lemma_1_1_necessity(
    kc: &KnotClouds,
    phi: &dyn Fn(&Q2) -> Q2,
    seed: u64,
    trials: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-L1.1(2)",
        "non-affine φ breaks F = F̃∘φ for some net (witness)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mapped = kc.mapped(phi);
    let mut witness = None;
    'outer: for _ in 0..trials {
        let u = point_in_unit_triangle(&mut rng);
        for b in multi_indices(kc.k) {
            r.examined += 1;
            let (x, y) = (kc.basis(&b, &u), mapped.basis(&b, &phi(&u)));
            if x != y {
                witness = Some(format!(
                    "single pole β = {b:?}: N(u) = {} but Ñ(φ(u)) = {} at u = {}",
                    x.map(|v| v.to_string()).unwrap_or_default(),
                    y.map(|v| v.to_string()).unwrap_or_default(),
                    q2s(&u)
                ));
                break 'outer;
            }
        }
    }
    match witness {
        Some(w) => r.with_note(format!("witness: {w}")),
        None => {
            r.offend(|| Witness::new("no net distinguishes F from F̃∘φ on the samples", json!({})));
            r
        }
    }
}

/// The planted non-affine transition of Lemma 1.1(2): φ(x, y) = (x + x²/4, y).
pub fn planted_non_affine(x: &Q2) -> Q2 {
    [&x[0] + &x[0] * &x[0] / q(4, 1), x[1].clone()]
}

/// Def. 1 on a map of ℚ²: f(Σ α_i u_i) = Σ α_i f(u_i) for random affine combinations (exact).
pub fn check_def1(f: &dyn Fn(&Q2) -> Q2, seed: u64, trials: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-D1",
        "affine map preserves affine combinations (Def. 1; exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..trials {
        let us: Vec<Q2> = (0..3).map(|_| rq2(&mut rng)).collect();
        let (a0, a1) = (rq(&mut rng), rq(&mut rng));
        let al = [a0.clone(), a1.clone(), Q::one() - a0 - a1];
        let comb = |ps: &[Q2]| {
            let mut s = [Q::zero(), Q::zero()];
            for (p, a) in ps.iter().zip(&al) {
                s[0] += a * &p[0];
                s[1] += a * &p[1];
            }
            s
        };
        r.examined += 1;
        let lhs = f(&comb(&us));
        let rhs = comb(&us.iter().map(f).collect::<Vec<_>>());
        if lhs != rhs {
            r.offend(|| {
                Witness::new(
                    format!("f(Σα_i u_i) = {} ≠ Σα_i f(u_i) = {}", q2s(&lhs), q2s(&rhs)),
                    json!({}),
                )
            });
        }
    }
    r
}

/// Every Sec. 3.1 / Lemma 1.1 check on seeded random data of degree k.
pub fn check_all(k: usize, seed: u64) -> Vec<CheckResult> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let p = random_poly(&mut rng, k);
    let kc = random_clouds(&mut rng, k);
    let mut out = vec![
        check_def1(
            &|x: &Q2| [&x[0] * q(3, 2) - &x[1] + q(1, 5), &x[0] + &x[1] * q(2, 3)],
            seed,
            20,
        ),
        check_blossom(&p, seed, 12),
        check_reproduction(&p, &kc, seed, 12),
        check_convex_hull(&kc, seed, 40),
    ];
    out.extend(check_affine_invariance(&p, &kc, seed, 12));
    out.push(check_lemma_1_1_necessity(
        &kc,
        &planted_non_affine,
        seed,
        20,
    ));
    out
}
