//! Sampled checks of Def. 3.4.1(3): the transition functions, 3(a) identity, 3(b) inverses,
//! 3(c) the full cocycle condition (with its domain inclusion), and the weaker Grimm–Hughes
//! "proto-manifold" cocycle condition quoted in App. A.2.

use super::sampling::{sampled_k, SampleConfig};
use crate::gluing::data::{dist, fmt_point, norm, point_json, GluingData};
use crate::gluing::tolerance::tol;
use crate::report::{Check, CheckResult, OnError, Witness};
use serde_json::json;

/// φ returned `None` where the statement claims it is defined.
const UNDEFINED: &str = "φ undefined";

/// φ returned `None` on its own gluing domain, an offence of D3.4.1(3) (reported there): the
/// sample cannot be examined by the statement at hand.
const UNDEFINED_ELSEWHERE: &str = "φ_ji(x) undefined on Ω_ij (reported by D3.4.1(3))";

/// Def. 3.4.1(3), the part a sampler can refute: φ_ji is defined on Ω_ij and maps it into Ω_ji.
/// (Surjectivity onto Ω_ji and injectivity follow from 3(b), checked separately.)
pub fn check_maps_into<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r = Check::new("D3.4.1(3)", "φ_ji : Ω_ij → Ω_ji defined, into Ω_ji")
        .with_note("sampled; bijectivity via 3(b)");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(3);
    for (i, j) in sampled_k(g, cfg) {
        for x in g.sample_gluing_domain(i, j, &mut rng, cfg.n) {
            match g.phi(j, i, &x) {
                None => r.error(OnError::Offence, UNDEFINED, || {
                    Witness::new(
                        format!("φ_({j},{i})({}) undefined though the point is in Ω_({i},{j})", fmt_point(&x)),
                        json!({"kind": "undefined", "i": i, "j": j, "x": point_json(&x)}),
                    )
                }),
                Some(y) if !g.in_gluing_domain(j, i, &y) => r.holds(false, || {
                    Witness::new(
                        format!("φ_({j},{i})({}) = {} ∉ Ω_({j},{i})", fmt_point(&x), fmt_point(&y)),
                        json!({"kind": "not_into", "i": i, "j": j, "x": point_json(&x), "y": point_json(&y)}),
                    )
                }),
                Some(_) => r.examined(1),
            }
        }
    }
    r.finish("")
}

/// Def. 3.4.1(3a): φ_ii = id on Ω_i.
pub fn check_3a<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r = Check::new("D3.4.1(3a)", "φ_ii = id").with_note("sampled");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(4);
    for i in g.indices() {
        for x in g.sample_p_domain(i, &mut rng, cfg.n) {
            let t = tol::<G::S>(norm(&x)) * g.amplification();
            match g.phi(i, i, &x) {
                None => r.error(OnError::Offence, UNDEFINED, || {
                    Witness::new(
                        format!("φ_({i},{i})({}) undefined", fmt_point(&x)),
                        json!({"kind": "undefined", "i": i, "x": point_json(&x)}),
                    )
                }),
                Some(y) => {
                    let d = dist(&x, &y);
                    r.deviation_within(d, t, || {
                        Witness::new(
                            format!("φ_({i},{i})({}) = {} ≠ {}", fmt_point(&x), fmt_point(&y), fmt_point(&x)),
                            json!({"kind": "not_identity", "i": i, "x": point_json(&x), "phi": point_json(&y), "deviation": d}),
                        )
                    });
                }
            }
        }
    }
    r.finish("")
}

/// Def. 3.4.1(3b): φ_ij = φ_ji⁻¹, checked as φ_ij(φ_ji(x)) = x for sampled x ∈ Ω_ij, for every
/// (i, j) ∈ K (both orders, so both one-sided inverse laws are sampled).
pub fn check_3b<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r = Check::new("D3.4.1(3b)", "φ_ij = φ_ji⁻¹").with_note("sampled");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(5);
    for (i, j) in sampled_k(g, cfg) {
        for x in g.sample_gluing_domain(i, j, &mut rng, cfg.n) {
            let Some(y) = g.phi(j, i, &x) else {
                // The offence is D3.4.1(3)'s; here the sample cannot be examined.
                r.error(OnError::Skip, UNDEFINED_ELSEWHERE, || {
                    Witness::new(fmt_point(&x), point_json(&x))
                });
                continue;
            };
            let t = tol::<G::S>(norm(&x).max(norm(&y))) * g.amplification();
            match g.phi(i, j, &y) {
                None => r.error(OnError::Offence, UNDEFINED, || {
                    Witness::new(
                        format!(
                            "φ_({i},{j})(φ_({j},{i})({})) undefined: φ_({j},{i})(x) = {} ∉ Ω_({j},{i})",
                            fmt_point(&x),
                            fmt_point(&y)
                        ),
                        json!({"kind": "undefined", "i": i, "j": j, "x": point_json(&x)}),
                    )
                }),
                Some(z) => {
                    let d = dist(&x, &z);
                    r.deviation_within(d, t, || {
                        Witness::new(
                            format!("φ_({i},{j})(φ_({j},{i})({})) = {} ≠ x", fmt_point(&x), fmt_point(&z)),
                            json!({"kind": "not_inverse", "i": i, "j": j, "x": point_json(&x), "back": point_json(&z), "deviation": d}),
                        )
                    });
                }
            }
        }
    }
    r.finish("")
}

/// Def. 3.4.1(3c), the full cocycle condition: for all i, j, k with Ω_ji ∩ Ω_jk ≠ ∅,
/// φ_ji⁻¹(Ω_ji ∩ Ω_jk) ⊆ Ω_ik and φ_ki = φ_kj ∘ φ_ji there. Sampled as: x ∈ Ω_ij with
/// φ_ji(x) ∈ Ω_jk must lie in Ω_ik, and φ_ki(x) = φ_kj(φ_ji(x)). Points of Ω_ji ∩ Ω_jk are
/// also sampled directly and pulled back with φ_ij (relying on 3(b), checked separately), so
/// that small intersections are hit.
pub fn check_3c<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r = Check::new(
        "D3.4.1(3c)",
        "cocycle: domain inclusion and φ_ki = φ_kj∘φ_ji",
    )
    .with_note("sampled over all triples (i, j, k)");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(6);
    let ids = g.indices();
    for &i in &ids {
        for &j in &ids {
            let xs = g.sample_gluing_domain(i, j, &mut rng, cfg.n);
            if xs.is_empty() {
                continue;
            }
            // Pull back samples of Ω_ji ∩ Ω_jk.
            let ys = g.sample_gluing_domain(j, i, &mut rng, cfg.n);
            for &k in &ids {
                let mut cand = xs.clone();
                let more = g.sample_gluing_domain(j, k, &mut rng, cfg.n / 4 + 1);
                let pulled = ys
                    .iter()
                    .filter(|y| g.in_gluing_domain(j, k, y))
                    .chain(more.iter().filter(|y| g.in_gluing_domain(j, i, y)));
                for y in pulled {
                    // y ∈ Ω_ji: φ_ij(y) is claimed defined; where it is not, the offence is
                    // D3.4.1(3)'s and this candidate cannot be examined.
                    match g.phi(i, j, y) {
                        Some(x) => cand.push(x),
                        None => r.error(OnError::Skip, UNDEFINED_ELSEWHERE, || {
                            Witness::new(fmt_point(y), point_json(y))
                        }),
                    }
                }
                for x in &cand {
                    let Some(y) = g.phi(j, i, x) else {
                        r.error(OnError::Skip, UNDEFINED_ELSEWHERE, || {
                            Witness::new(fmt_point(x), point_json(x))
                        });
                        continue;
                    };
                    if !(g.in_gluing_domain(j, i, &y) && g.in_gluing_domain(j, k, &y)) {
                        continue;
                    }
                    if !g.in_gluing_domain(i, k, x) {
                        r.holds(false, || {
                            Witness::new(
                                format!(
                                    "(i,j,k)=({i},{j},{k}): x = {} ∈ φ_({j},{i})⁻¹(Ω_({j},{i}) ∩ Ω_({j},{k})) but x ∉ Ω_({i},{k}) (domain inclusion fails)",
                                    fmt_point(x)
                                ),
                                json!({"kind": "inclusion", "i": i, "j": j, "k": k, "x": point_json(x), "y": point_json(&y)}),
                            )
                        });
                        continue;
                    }
                    let (Some(z1), Some(z2)) = (g.phi(k, i, x), g.phi(k, j, &y)) else {
                        // x ∈ Ω_ik and φ_ji(x) ∈ Ω_jk: both sides are claimed defined.
                        r.error(OnError::Offence, UNDEFINED, || {
                            Witness::new(
                                format!("(i,j,k)=({i},{j},{k}): φ_({k},{i})({}) or φ_({k},{j})(φ_({j},{i})(x)) undefined", fmt_point(x)),
                                json!({"kind": "undefined", "i": i, "j": j, "k": k, "x": point_json(x)}),
                            )
                        });
                        continue;
                    };
                    let d = dist(&z1, &z2);
                    let t = tol::<G::S>(norm(&z1).max(norm(x))) * g.amplification();
                    r.deviation_within(d, t, || {
                        Witness::new(
                            format!(
                                "(i,j,k)=({i},{j},{k}): φ_({k},{i})({}) = {} ≠ φ_({k},{j})(φ_({j},{i})(x)) = {}",
                                fmt_point(x), fmt_point(&z1), fmt_point(&z2)
                            ),
                            json!({"kind": "equation", "i": i, "j": j, "k": k, "x": point_json(x), "lhs": point_json(&z1), "rhs": point_json(&z2), "deviation": d}),
                        )
                    });
                }
            }
        }
    }
    r.finish("")
}

/// App. A.2, the Grimm–Hughes proto-manifold cocycle condition: for all x ∈ Ω_ij ∩ Ω_ik,
/// φ_ki(x) = φ_kj ∘ φ_ji(x). The paper does not say what happens when φ_ji(x) ∉ Ω_jk (the
/// right side is undefined). `strict = false` reads it as an equation between partial functions
/// (required only where both sides are defined) — the reading under which App. A.2's claim "too
/// weak" is true; `strict = true` additionally requires the right side to be defined, and is
/// then equivalent to 3(c) in the presence of 3(b).
pub fn check_grimm_hughes<G: GluingData<N>, const N: usize>(
    g: &G,
    cfg: &SampleConfig,
    strict: bool,
) -> CheckResult {
    let (id, name) = if strict {
        (
            "CA.2-GH-strict",
            "Grimm–Hughes cocycle, RHS required defined",
        )
    } else {
        ("CA.2-GH", "Grimm–Hughes cocycle (where both sides defined)")
    };
    let mut r = Check::new(id, name).with_note("sampled over all triples (i, j, k)");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(if strict { 8 } else { 7 });
    let ids = g.indices();
    for &i in &ids {
        for &j in &ids {
            let xs = g.sample_gluing_domain(i, j, &mut rng, cfg.n);
            for &k in &ids {
                let mut cand = xs.clone();
                cand.extend(g.sample_gluing_domain(i, k, &mut rng, cfg.n / 4 + 1));
                for x in &cand {
                    if !(g.in_gluing_domain(i, j, x) && g.in_gluing_domain(i, k, x)) {
                        continue;
                    }
                    // x ∈ Ω_ij ∩ Ω_ik: φ_ji(x) and φ_ki(x) are claimed defined (D3.4.1(3)), and
                    // so is φ_kj(y) for y ∈ Ω_jk; an undefined one is counted, never dropped.
                    // The strict reading requires the right side defined: there an undefined
                    // φ_ji(x) or φ_kj(y) is its offence; the non-strict one cannot examine x.
                    let rhs_rule = if strict {
                        OnError::Offence
                    } else {
                        OnError::Skip
                    };
                    let Some(y) = g.phi(j, i, x) else {
                        r.error(rhs_rule, UNDEFINED, || {
                            Witness::new(
                                format!("(i,j,k)=({i},{j},{k}): φ_({j},{i})({}) undefined though x ∈ Ω_({i},{j})", fmt_point(x)),
                                json!({"kind": "undefined", "i": i, "j": j, "k": k, "x": point_json(x)}),
                            )
                        });
                        continue;
                    };
                    let rhs = g.phi(k, j, &y);
                    if rhs.is_none() && g.in_gluing_domain(j, k, &y) {
                        r.error(rhs_rule, UNDEFINED, || {
                            Witness::new(
                                format!("(i,j,k)=({i},{j},{k}): φ_({k},{j})({}) undefined though φ_({j},{i})(x) ∈ Ω_({j},{k}) (x = {})", fmt_point(&y), fmt_point(x)),
                                json!({"kind": "undefined", "i": i, "j": j, "k": k, "x": point_json(x), "y": point_json(&y)}),
                            )
                        });
                        continue;
                    }
                    match (g.phi(k, i, x), rhs) {
                        (Some(z1), Some(z2)) => {
                            let d = dist(&z1, &z2);
                            let t = tol::<G::S>(norm(&z1).max(norm(x))) * g.amplification();
                            r.deviation_within(d, t, || {
                                Witness::new(
                                    format!("(i,j,k)=({i},{j},{k}): φ_({k},{i})({}) = {} ≠ φ_({k},{j})∘φ_({j},{i})(x) = {}", fmt_point(x), fmt_point(&z1), fmt_point(&z2)),
                                    json!({"kind": "equation", "i": i, "j": j, "k": k, "x": point_json(x), "deviation": d}),
                                )
                            });
                        }
                        (_, None) if strict => r.holds(false, || {
                            Witness::new(
                                format!("(i,j,k)=({i},{j},{k}): x = {} ∈ Ω_({i},{j}) ∩ Ω_({i},{k}) but φ_({k},{j})∘φ_({j},{i})(x) undefined (φ_({j},{i})(x) ∉ Ω_({j},{k}))", fmt_point(x)),
                                json!({"kind": "rhs_undefined", "i": i, "j": j, "k": k, "x": point_json(x)}),
                            )
                        }),
                        // Where the right side is undefined the non-strict reading requires
                        // nothing; the sample still counts as examined.
                        (Some(_), None) => r.examined(1),
                        // φ_ki undefined on Ω_ik: D3.4.1(3)'s offence; x cannot be examined.
                        (None, _) => r.error(OnError::Skip, UNDEFINED_ELSEWHERE, || {
                            Witness::new(fmt_point(x), point_json(x))
                        }),
                    }
                }
            }
        }
    }
    r.finish("")
}

#[cfg(test)]
#[path = "cocycle_tests.rs"]
mod tests;
