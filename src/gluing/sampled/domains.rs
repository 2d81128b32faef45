//! Sampled checks of Def. 3.4.1(1) (p-domains) and (2) (gluing domains).

use super::sampling::SampleConfig;
use crate::gluing::data::{fmt_point, norm, point_json, GluingData, Idx, Point};
use crate::report::{Check, CheckResult, Witness};
use num_traits::Float;
use serde_json::json;

/// Openness witnessed at a sample: some h = scale·2⁻ᵏ (k = 4..=40) with all 2N axis neighbours
/// p ± h·e_m still inside. A point of the set's boundary that belongs to the set fails this.
fn open_at<S: Float, const N: usize>(
    p: &Point<S, N>,
    scale: f64,
    inside: impl Fn(&Point<S, N>) -> bool,
) -> bool {
    // Halve h from scale/16 down to the resolution of the scalar at p: samplers place points
    // within a few ulps·10^k of a boundary, so a fixed smallest h would call such a point "not
    // open". Steps that no longer move p (h below half an ulp) prove nothing and stop the
    // search, so the test never degenerates into "p is inside".
    for k in 4..=1100 {
        let h = S::from(scale * 2f64.powi(-k)).unwrap_or_else(S::zero);
        let mut all = true;
        for m in 0..N {
            let mut a = *p;
            let mut b = *p;
            a[m] = a[m] + h;
            b[m] = b[m] - h;
            if a[m] == p[m] || b[m] == p[m] {
                return false;
            }
            all &= inside(&a) && inside(&b);
        }
        if all {
            return true;
        }
    }
    false
}

/// Def. 3.4.1(1): I ≠ ∅; every Ω_i is non-empty and open; Ω_i ∩ Ω_j = ∅ for i ≠ j.
pub fn check_1<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r = Check::new("D3.4.1(1)", "p-domains non-empty, open, disjoint").with_note(
        "sampled: openness = axis neighbours at some h (down to the resolution at p) inside",
    );
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(1);
    let ids = g.indices();
    if ids.is_empty() {
        r.offend(|| {
            Witness::new(
                "the index set I is empty",
                json!({"kind": "empty_index_set"}),
            )
        });
    }
    for &i in &ids {
        let s = g.sample_p_domain(i, &mut rng, cfg.n);
        if s.is_empty() {
            r.offend(|| Witness::new(format!("Ω_{i} is empty"), json!({"kind": "empty", "i": i})));
        }
        for p in &s {
            r.examined += 1;
            if !g.in_p_domain(i, p) {
                r.offend(|| {
                    Witness::new(
                        format!("sampler of Ω_{i} returned {} ∉ Ω_{i}", fmt_point(p)),
                        json!({"kind": "sampler", "i": i, "p": point_json(p)}),
                    )
                });
            } else if !open_at(p, g.scale().max(norm(p)), |q| g.in_p_domain(i, q)) {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "Ω_{i} not open at {}: no ball around it inside",
                            fmt_point(p)
                        ),
                        json!({"kind": "not_open", "i": i, "p": point_json(p)}),
                    )
                });
            }
            for &j in &ids {
                if j != i && g.in_p_domain(j, p) {
                    r.offend(|| {
                        Witness::new(
                            format!("{} ∈ Ω_{i} ∩ Ω_{j}: p-domains not disjoint", fmt_point(p)),
                            json!({"kind": "overlap", "i": i, "j": j, "p": point_json(p)}),
                        )
                    });
                }
            }
        }
    }
    r.finish("")
}

/// Def. 3.4.1(2): Ω_ij is an open subset of Ω_i, Ω_ii = Ω_i, and Ω_ij ≠ ∅ ⇔ Ω_ji ≠ ∅.
pub fn check_2<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    let mut r =
        Check::new("D3.4.1(2)", "Ω_ij ⊆ Ω_i open, Ω_ii = Ω_i, K symmetric").with_note("sampled");
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(2);
    let ids = g.indices();
    for &i in &ids {
        // Ω_ii = Ω_i, both inclusions on samples.
        for p in g.sample_p_domain(i, &mut rng, cfg.n) {
            r.examined += 1;
            if !g.in_gluing_domain(i, i, &p) {
                r.offend(|| {
                    Witness::new(
                        format!("{} ∈ Ω_{i} but ∉ Ω_({i},{i}): Ω_ii ≠ Ω_i", fmt_point(&p)),
                        json!({"kind": "diag", "i": i, "p": point_json(&p)}),
                    )
                });
            }
        }
        for &j in &ids {
            let s = g.sample_gluing_domain(i, j, &mut rng, cfg.n);
            let back = g.sample_gluing_domain(j, i, &mut rng, 1);
            r.examined += 1;
            // A sampler can miss a sliver of a gluing domain (a few ulps wide near a lens
            // corner); a point of the other domain carried over by φ and found inside by the
            // membership test is a witness of non-emptiness too, so a miss is not reported as
            // a broken K.
            let carried = |from: &[Point<G::S, N>], a: Idx, b: Idx| {
                from.iter()
                    .any(|p| g.phi(b, a, p).is_some_and(|y| g.in_gluing_domain(b, a, &y)))
            };
            let ij = !s.is_empty() || carried(&back, j, i);
            let ji = !back.is_empty() || carried(&s, i, j);
            if ij != ji {
                let word = |e: bool| if e { "non-empty" } else { "empty" };
                r.offend(|| {
                    Witness::new(
                        format!(
                            "Ω_({i},{j}) is {} but Ω_({j},{i}) is {} (sampled, and carried over by φ)",
                            word(ij),
                            word(ji)
                        ),
                        json!({"kind": "asymmetric_k", "i": i, "j": j}),
                    )
                });
            }
            for p in &s {
                r.examined += 1;
                if !g.in_gluing_domain(i, j, p) {
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "sampler of Ω_({i},{j}) returned {} ∉ Ω_({i},{j})",
                                fmt_point(p)
                            ),
                            json!({"kind": "sampler", "i": i, "j": j, "p": point_json(p)}),
                        )
                    });
                } else if !g.in_p_domain(i, p) {
                    r.offend(|| {
                        Witness::new(
                            format!("{} ∈ Ω_({i},{j}) but ∉ Ω_{i}", fmt_point(p)),
                            json!({"kind": "not_subset", "i": i, "j": j, "p": point_json(p)}),
                        )
                    });
                } else if !open_at(p, g.scale().max(norm(p)), |q| g.in_gluing_domain(i, j, q)) {
                    r.offend(|| {
                        Witness::new(
                            format!("Ω_({i},{j}) not open at {}", fmt_point(p)),
                            json!({"kind": "not_open", "i": i, "j": j, "p": point_json(p)}),
                        )
                    });
                }
            }
        }
    }
    r.finish("")
}
