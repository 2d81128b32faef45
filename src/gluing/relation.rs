//! The relation ∼ of the proof of Thm. 3.4.1 on a finite sample of the disjoint union ⊔Ω_i:
//! x ∼ y iff there is (i, j) ∈ K with x ∈ Ω_ij, y ∈ Ω_ji and y = φ_ji(x) (points carry their
//! chart index, which is how the disjoint union is realised). Exact 1-D data only, so equality
//! of points is exact.

use super::exact1d::interval::{fmt_q, Q};
use super::exact1d::Exact1d;
use super::Idx;
use crate::report::{CheckResult, Witness};
use serde_json::json;
use std::collections::{BTreeMap, BTreeSet};

/// A point of the disjoint union: (chart index i, x ∈ Ω_i).
pub type Tagged = (Idx, Q);

/// Grid points (before the closure under φ) a [`GridSample`] aims at: with more interval
/// pieces than `GRID_POINT_BUDGET / m`, each piece gets fewer cells (at least 2), because every
/// sampled point's successors scan the listed pieces and a 4 KiB file can list a hundred.
/// The price: on such files the sampled relation checks see a coarser grid, and a failure of
/// ∼ confined to a gap finer than the lowered spacing can go unseen (the exact checks of Def.
/// 3.4.1 are unaffected; with all of them holding, Thm. 3.4.1 makes the relation checks hold
/// on any sample). Without the budget, 50 + 50 pieces took 2 s in the fuzz build.
pub const GRID_POINT_BUDGET: u32 = 512;

/// A finite sample of ⊔Ω_i: a rational grid in every Ω_i and every gluing domain, closed
/// under two rounds of transition functions so that chains x ∼ y ∼ z stay inside it.
#[derive(Clone, Debug)]
pub struct GridSample {
    /// The sampled points, sorted and unique.
    pub points: Vec<Tagged>,
    /// Cells per interval piece actually used (`m`, or fewer under [`GRID_POINT_BUDGET`]);
    /// 0 for [`GridSample::from_points`].
    pub cells: u32,
}

fn fmt_t(p: &Tagged) -> String {
    format!("{}∈Ω_{}", fmt_q(&p.1), p.0)
}

impl GridSample {
    /// Grid with `m` cells per interval piece (m − 1 interior points), plus images; `m` is
    /// lowered (not below 2) so that the grid has about [`GRID_POINT_BUDGET`] points.
    pub fn new(g: &Exact1d, m: u32) -> GridSample {
        let mut set: BTreeSet<Tagged> = BTreeSet::new();
        let mut sets: Vec<(Idx, super::exact1d::OpenSet)> =
            g.ids().into_iter().map(|i| (i, g.omega(i))).collect();
        sets.extend(g.k().into_iter().map(|(i, j)| (i, g.omega_ij(i, j))));
        let parts: usize = sets.iter().map(|(_, s)| s.parts().len()).sum();
        let parts = u32::try_from(parts).unwrap_or(u32::MAX).max(1);
        let m = m.min(GRID_POINT_BUDGET / parts + 1).max(2);
        for (i, set_) in &sets {
            for p in set_.parts() {
                for t in 1..m {
                    let x = &p.lo + (&p.hi - &p.lo) * Q::new(t.into(), m.into());
                    set.insert((*i, x));
                }
            }
        }
        // Two rounds; a round only needs the successors of the points the previous one added.
        let mut frontier: Vec<Tagged> = set.iter().cloned().collect();
        for _ in 0..2 {
            let mut new: Vec<Tagged> = frontier
                .iter()
                .flat_map(|p| successors(g, p))
                .filter(|p| !set.contains(p))
                .collect();
            new.sort();
            new.dedup();
            set.extend(new.iter().cloned());
            frontier = new;
        }
        GridSample {
            points: set.into_iter().collect(),
            cells: m,
        }
    }
    /// A sample of exactly the given points (not closed under transition functions).
    pub fn from_points(points: Vec<Tagged>) -> GridSample {
        GridSample { points, cells: 0 }
    }
}

/// x ∼ y, literally as defined in the proof of Thm. 3.4.1.
pub fn related(g: &Exact1d, x: &Tagged, y: &Tagged) -> bool {
    let (i, j) = (x.0, y.0);
    g.in_omega_ij(i, j, &x.1)
        && g.in_omega_ij(j, i, &y.1)
        && g.phi(j, i, &x.1).as_ref() == Some(&y.1)
}

/// All y with x ∼ y.
pub fn successors(g: &Exact1d, x: &Tagged) -> Vec<Tagged> {
    // Only j with listed pieces of φ_j(x.0) can have x ∼ (j, ·); this keeps the sample's cost
    // linear, not quadratic, in |I|.
    g.glue
        .range((x.0, Idx::MIN)..=(x.0, Idx::MAX))
        .map(|(&(_, j), _)| j)
        .filter(|j| g.domains.contains_key(j))
        .filter_map(|j| {
            let y = (j, g.phi(j, x.0, &x.1)?);
            // y = φ_j(x.0)(x) found a piece containing x, so x ∈ Ω_(x.0)j and the value
            // matches: of `related`, only y ∈ Ω_j(x.0) is left to test.
            g.in_omega_ij(j, x.0, &y.1).then_some(y)
        })
        .collect()
}

/// Thm. 3.4.1 (proof): ∼ is an equivalence relation — reflexivity, symmetry and transitivity
/// checked on every chain x ∼ y ∼ z starting in the sample. A failure lists the chain.
pub fn check_equivalence(g: &Exact1d, s: &GridSample) -> CheckResult {
    let mut r = CheckResult::new("T3.4.1(equiv)", "∼ reflexive, symmetric, transitive")
        .with_note(format!(
            "exact, on a rational grid sample ({} cells per piece, {} points) closed under two rounds of φ",
            s.cells,
            s.points.len()
        ));
    let mut memo: BTreeMap<Tagged, Vec<Tagged>> = BTreeMap::new();
    for x in &s.points {
        r.examined += 1;
        if !related(g, x, x) {
            r.offend(|| {
                Witness::new(
                    format!("not reflexive: {} ≁ itself", fmt_t(x)),
                    json!({"kind": "reflexivity", "x": [x.0, fmt_q(&x.1)]}),
                )
            });
        }
        for y in successors(g, x) {
            if !related(g, &y, x) {
                r.offend(|| {
                    Witness::new(
                        format!("not symmetric: {} ∼ {} but not conversely", fmt_t(x), fmt_t(&y)),
                        json!({"kind": "symmetry", "x": [x.0, fmt_q(&x.1)], "y": [y.0, fmt_q(&y.1)]}),
                    )
                });
            }
            let zs = memo.entry(y.clone()).or_insert_with(|| successors(g, &y));
            for z in zs.iter() {
                r.examined += 1;
                if !related(g, x, z) {
                    r.offend(|| {
                        Witness::new(
                            format!("not transitive: {} ∼ {} ∼ {} but {} ≁ {}", fmt_t(x), fmt_t(&y), fmt_t(z), fmt_q(&x.1), fmt_q(&z.1)),
                            json!({"kind": "transitivity", "x": [x.0, fmt_q(&x.1)], "y": [y.0, fmt_q(&y.1)], "z": [z.0, fmt_q(&z.1)]}),
                        )
                    });
                }
            }
        }
    }
    r
}

/// Classes of the equivalence relation *generated* by ∼ on the sample (union–find). When ∼ is
/// an equivalence (Thm. 3.4.1) these are the points of M_G met by the sample.
pub fn classes(g: &Exact1d, s: &GridSample) -> Vec<Vec<Tagged>> {
    let index: BTreeMap<&Tagged, usize> =
        s.points.iter().enumerate().map(|(n, p)| (p, n)).collect();
    let mut sets = crate::numeric::UnionFind::new(s.points.len());
    for (n, p) in s.points.iter().enumerate() {
        for q in successors(g, p) {
            if let Some(&m) = index.get(&q) {
                sets.union(n, m);
            }
        }
    }
    let mut groups: BTreeMap<usize, Vec<Tagged>> = BTreeMap::new();
    for (n, p) in s.points.iter().enumerate() {
        let root = sets.find(n);
        groups.entry(root).or_default().push(p.clone());
    }
    groups.into_values().collect()
}

/// The Claim in the proof of Thm. 3.4.1: τ_i(Ω_i) ∩ τ_j(Ω_j) ≠ ∅ iff (i, j) ∈ K, and then
/// τ_i(Ω_i) ∩ τ_j(Ω_j) = τ_i(Ω_ij) = τ_j(Ω_ji). On the sample: a class meets Ω_i and Ω_j
/// (i ≠ j) only if (i, j) ∈ K, each (i, j) ∈ K has such a class, and in such a class every
/// Ω_i-point lies in Ω_ij.
pub fn check_claim(g: &Exact1d, s: &GridSample) -> CheckResult {
    let mut r = CheckResult::new(
        "T3.4.1(claim)",
        "τ_i(Ω_i) ∩ τ_j(Ω_j) ≠ ∅ ⇔ (i,j) ∈ K, = τ_i(Ω_ij)",
    )
    .with_note(format!(
        "exact, on the classes of the equivalence generated by ∼ on a grid sample ({} cells per piece, {} points)",
        s.cells,
        s.points.len()
    ));
    let k: BTreeSet<(Idx, Idx)> = g.k().into_iter().collect();
    let mut met: BTreeSet<(Idx, Idx)> = BTreeSet::new();
    for c in classes(g, s) {
        r.examined += 1;
        let charts: BTreeSet<Idx> = c.iter().map(|p| p.0).collect();
        for &i in &charts {
            for &j in &charts {
                if i == j {
                    continue;
                }
                met.insert((i, j));
                if !k.contains(&(i, j)) {
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "τ_{i}(Ω_{i}) ∩ τ_{j}(Ω_{j}) ≠ ∅ but ({i},{j}) ∉ K: class {{{}}}",
                                c.iter().map(fmt_t).collect::<Vec<_>>().join(", ")
                            ),
                            json!({"kind": "meet_outside_k", "i": i, "j": j}),
                        )
                    });
                }
                for p in c.iter().filter(|p| p.0 == i) {
                    if !g.omega_ij(i, j).contains(&p.1) {
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "[{}] ∈ τ_{i}(Ω_{i}) ∩ τ_{j}(Ω_{j}) but {} ∉ Ω_({i},{j}): class {{{}}}",
                                    fmt_t(p), fmt_q(&p.1), c.iter().map(fmt_t).collect::<Vec<_>>().join(", ")
                                ),
                                json!({"kind": "not_in_gluing_domain", "i": i, "j": j, "x": fmt_q(&p.1)}),
                            )
                        });
                    }
                }
            }
        }
    }
    for &(i, j) in &k {
        if i != j && !met.contains(&(i, j)) {
            r.offend(|| {
                Witness::new(
                    format!("({i},{j}) ∈ K but no sampled class meets both Ω_{i} and Ω_{j}"),
                    json!({"kind": "k_not_met", "i": i, "j": j}),
                )
            });
        }
    }
    r
}
