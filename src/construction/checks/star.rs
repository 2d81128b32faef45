//! The star of a vertex: C5.4-at-most-two and C4.2-nonadjacent-disjoint (Sec. 4.2, Sec. 5.4).

use super::common::*;
use super::samples::*;
use crate::construction::maps::*;
use crate::numeric::Scalar;
use crate::report::{Check, CheckResult, Witness};
use serde_json::json;

/// The star of a vertex x for C5.4 / non-adjacent disjointness: degree m and, for each label
/// k = 0..m−1, the neighbour's degree and the label s_n(x) of x in the neighbour's star.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct StarConfig {
    /// m, the degree of x.
    pub m: u32,
    /// For label k: (degree of the k-th neighbour n, label s_n(x)).
    pub nbrs: Vec<(u32, u32)>,
}

impl StarConfig {
    /// All neighbours of degree `m_nbr`, with x at label 0 in each.
    pub fn uniform(m: u32, m_nbr: u32) -> Result<Self, ConfigError> {
        let s = StarConfig {
            m,
            nbrs: (0..m).map(|_| (m_nbr, 0)).collect(),
        };
        s.edges().map(|_| s)
    }
    /// Oriented edges x → n_k.
    pub fn edges(&self) -> Result<Vec<EdgeConfig>, ConfigError> {
        if self.nbrs.len() != self.m as usize {
            return Err(ConfigError::LabelOutOfRange {
                label: self.nbrs.len() as u32,
                m: self.m,
            });
        }
        self.nbrs
            .iter()
            .enumerate()
            .map(|(k, &(mn, j))| EdgeConfig::new(self.m, k as u32, mn, j))
            .collect()
    }
}

/// C5.4-at-most-two and C4.2-nonadjacent-disjoint: at every sampled point of Ω_x at most two
/// gluing domains Ω_xn contain it, and Ω_xa ∩ Ω_xb = ∅ when the labels of a, b differ by ≥ 2
/// (mod m_x). `use_lens` switches membership from the literal Def. 4.1.9 to the Sec. 6.1.3 test.
/// Returns [at-most-two, nonadjacent-disjoint].
pub fn check_star_overlaps<S: Scalar, M: Ppm<S>>(
    model: &M,
    star: &StarConfig,
    use_lens: bool,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let suffix = if use_lens { "[sec6.1.3]" } else { "" };
    let mut a = Check::sampled(
        format!("C5.4-at-most-two{suffix}"),
        format!(
            "at most two Ω_xn contain any point of Ω_x (m_x = {})",
            star.m
        ),
        seed,
        0.0,
    );
    let mut b = Check::sampled(
        format!("C4.2-nonadjacent-disjoint{suffix}"),
        format!("Ω_xa ∩ Ω_xb = ∅ for non-adjacent a, b (m_x = {})", star.m),
        seed,
        0.0,
    );
    let edges = match star.edges() {
        Ok(e) => e,
        Err(err) => {
            a.offend(|| Witness::new(format!("invalid star: {err}"), json!({})));
            return vec![a.finish(String::new()), b.finish(String::new())];
        }
    };
    let pts = star_samples(model, &edges, seed, n, prec);
    let mm = star.m as i64;
    for (_, p) in &pts {
        let inside: Vec<u32> = edges
            .iter()
            .filter(|e| {
                let t = if use_lens {
                    model.in_omega_uw_lens(e, p)
                } else {
                    model.in_omega_uw_literal(e, p)
                };
                t.is_true()
            })
            .map(|e| e.i)
            .collect();
        a.holds(inside.len() <= 2, || {
            Witness::new(
                format!("p = {} lies in Ω_xn for labels {inside:?}", fmt(p)),
                json!({"p": pt(p), "labels": inside}),
            )
        });
        for (ka, la) in inside.iter().enumerate() {
            for lb in &inside[ka + 1..] {
                let d = (*la as i64 - *lb as i64).rem_euclid(mm);
                let adjacent = d == 1 || d == mm - 1;
                b.holds(adjacent, || Witness::new(format!("p = {} lies in Ω_xa ∩ Ω_xb for non-adjacent labels {la}, {lb} (θ = {:.6})", fmt(p), angle_of(p).unwrap_or(0.0)), json!({"p": pt(p), "a": la, "b": lb})));
            }
        }
        if inside.len() < 2 {
            b.examined(1);
        }
    }
    let note = format!(
        "{} samples of Ω_x (disk + lens pull-backs for every neighbour); membership by {}",
        pts.len(),
        if use_lens {
            "the Sec. 6.1.3 lens test"
        } else {
            "the literal Def. 4.1.9"
        }
    );
    vec![a.finish(note.clone()), b.finish(note)]
}
