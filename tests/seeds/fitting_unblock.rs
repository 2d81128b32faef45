//! The AC·CB rule (seed 002, Part II, "Discrete Geodesics", Adaptive Fitting): where a base
//! edge AB has no curve, it is split at a vertex C of S_T and embedded as the concatenation of
//! the curves of AC and CB (`fitting::unblock`; SPEC `AF-embedding`).

use super::fitting::fit;
use crate::common::verdicts::{assert_caught, assert_holds, assert_holds_for, record, Seen};
use pseudomanifold::fitting::base::BaseMesh;
use pseudomanifold::fitting::base::RemovalLimits;
use pseudomanifold::fitting::checks::run_fit_checks;
use pseudomanifold::fitting::embed_checks::{check_disjoint, check_on_surface, run};
use pseudomanifold::fitting::embedded::embed;
use pseudomanifold::fitting::geodesic::{Curve, Embedding, Node};
use pseudomanifold::fitting::unblock::{Change, Walk};
use pseudomanifold::fitting::Fit;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{generate, SimplicialSurface};

/// The generated 24 × 12 torus, its fit at 10⁻² of the diagonal, and the walk's removal limits
/// for it.
fn torus_fit() -> (SimplicialSurface, Fit, RemovalLimits) {
    let k = validate(&generate::torus(24, 12))
        .surface
        .expect("the generated torus is a simplicial surface");
    let f = fit(&k, 1e-2);
    let lim = RemovalLimits {
        max_deviation: f.epsilon,
        min_normal_cos: 0.5,
        min_quality: 0.1,
        max_degree: 12,
    };
    (k, f, lim)
}

/// The curve of base edge u–w as it runs from u to w.
fn oriented(e: &Embedding, u: u32, w: u32) -> Vec<Node> {
    let (c, forward) = e.curve(u, w).expect("the base edge has a curve");
    let mut n = c.nodes.clone();
    if !forward {
        n.reverse();
    }
    n
}

/// The concatenation AC·CB as one curve from min(A, B) to max(A, B).
fn concatenation(e: &Embedding, a: u32, c: u32, b: u32) -> Curve {
    let (a, b) = (a.min(b), a.max(b));
    let mut nodes = oriented(e, a, c);
    nodes.extend(oriented(e, c, b).into_iter().skip(1));
    Curve { a, b, nodes }
}

/// The rule on one base edge of the generated torus's fit at 10⁻²: the edge a–b is split at
/// the vertex C of S_T the rule names (a new base vertex; a–b gives way to a–C and C–b), the
/// base mesh is embedded again with every check holding, and the concatenation of the curves
/// of a–C and C–b joins a and b on |S_T| (AF-geodesic-on-surface). A wrong concatenation is
/// refused: through a C off the surface (AF-geodesic-on-surface), and kept beside the curves
/// it is made of (AF-geodesic-disjoint: it runs along them and through the base vertex C).
#[test]
fn af_embedding_ac_cb_split_concatenation_holds_and_wrong_concatenations_are_caught() {
    let (k, f, lim) = torus_fit();
    let mut base: BaseMesh = f.base.clone();
    // The first base edge (in face order) with a vertex of S_T in one of its two faces.
    let (a, b) = base
        .faces()
        .flat_map(|(_, c)| (0..3).map(move |i| (c[i], c[(i + 1) % 3])))
        .find(|&(a, b)| {
            [(a, b), (b, a)]
                .iter()
                .filter_map(|&(u, w)| base.face_of_edge(u, w))
                .any(|g| !base.members(g).is_empty())
        })
        .expect("a base edge with a vertex of S_T in its faces");
    // A flipped base mesh (same face count) counts as tried, so the rule splits.
    let faces = base.num_faces();
    let mut walk = Walk::default();
    let ch = walk
        .change(&mut base, a, b, &lim, |m| m.num_faces() == faces)
        .expect("the rule changes the base mesh");
    let Change::Split { c, edge_split } = ch else {
        panic!("the rule split a-b, got {ch:?}");
    };
    assert!(edge_split, "a-b gave way to a-C and C-b");
    assert!(base.is_base(c), "C is a base vertex");
    assert!(base.face_of_edge(a, b).is_none() && base.face_of_edge(b, a).is_none());
    for (u, w) in [(a, c), (c, b)] {
        assert!(
            base.face_of_edge(u, w).is_some() && base.face_of_edge(w, u).is_some(),
            "{u}-{w} is a base edge"
        );
    }
    assert_eq!(walk.changes, 1);
    assert_eq!(walk.log, vec![((a, b), ch)]);
    let e = embed(&k, &base).expect("the split base mesh is embedded");
    for r in run(&k, &base, &e) {
        assert_holds_for("the torus split at C", &r);
    }
    let ab = concatenation(&e.emb, a, c, b);
    assert!(ab.nodes.contains(&Node::Vertex(c)));
    let only = |curve: Curve| Embedding {
        curves: vec![curve],
        index: Default::default(),
        stats: Default::default(),
    };
    let r = check_on_surface(&k, &only(ab.clone()));
    assert_holds(&r);
    record("AF-embedding", Seen::Holds, r.examined);
    // C off the surface: a vertex id past the last vertex of S_T.
    let mut off = ab.clone();
    let off_c = Node::Vertex(k.vertex_slots() as u32 + 7);
    for n in off.nodes.iter_mut().filter(|n| **n == Node::Vertex(c)) {
        *n = off_c;
    }
    let r = check_on_surface(&k, &only(off));
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);
    // The concatenation kept as a curve beside those of a–C and C–b.
    let mut beside = e.emb.clone();
    beside.curves.push(ab);
    let r = check_disjoint(&k, &base, &beside);
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);
}

/// A walled-off edge on the corpus: bunny at ε = 10⁻² of the diagonal. The first base mesh has
/// base edges with no curve (20 in one tracing); the walk changes it there, the repair of the
/// changed base mesh does not reach a valid surface, and the fit simplifies again with half the
/// deviation allowance (`fit_surface`'s retry); that base mesh is embedded at once. So this is
/// where the walk leads on bunny, not the concatenation itself (asserted on the torus above):
/// Floater's parameters are used and every check `ppm fit` runs holds.
#[test]
fn af_embedding_holds_on_bunny_at_1e_2() {
    let Some(dir) = crate::common::shared_path("af_embedding_bunny_1e_2", "meshes/good") else {
        return;
    };
    let k = pseudomanifold::mesh::load_surface(&dir.join("bunny.off")).expect("corpus mesh loads");
    let f = fit(&k, 1e-2);
    assert!(f.floater_params, "bunny at 1e-2: Floater's parameters used");
    let e = f.embedded.as_ref().expect("bunny at 1e-2 is embedded");
    for r in run(&k, &f.base, e) {
        assert_holds_for("bunny at 1e-2", &r);
    }
    for r in run_fit_checks(&k, &f, 1) {
        assert_holds_for("bunny at 1e-2", &r);
    }
}

/// All blocked edges in one pass (`Walk::change_all`): a change the validator refuses is
/// undone (base mesh and walk state), the others are kept. Planted: the validator refuses the
/// first change; the first edge is still a base edge, the second one's change is kept.
#[test]
fn af_embedding_change_all_undoes_a_refused_change_and_keeps_the_others() {
    let (_, f, lim) = torus_fit();
    let mut base: BaseMesh = f.base.clone();
    let mut edges: Vec<(u32, u32)> = Vec::new();
    for (_, c) in base.faces() {
        // Edges with no end in common: neither change takes the other's edge away.
        if edges
            .iter()
            .all(|&(a, b)| !c.contains(&a) && !c.contains(&b))
        {
            edges.push((c[0], c[1]));
        }
    }
    assert!(edges.len() >= 2, "two base edges apart");
    let (first, second) = (edges[0], edges[1]);
    let calls = std::cell::Cell::new(0);
    let mut walk = Walk::default();
    let (done, gave_up) = walk.change_all(
        &mut base,
        &[first, second],
        &lim,
        |_| false,
        |_| {
            calls.set(calls.get() + 1);
            calls.get() > 1
        },
    );
    assert_eq!(calls.get(), 2, "the validator saw both changes");
    assert!(gave_up.is_none());
    assert_eq!(
        done.len(),
        1,
        "the refused change is not reported: {done:?}"
    );
    assert_eq!(done[0].0, second);
    assert!(
        base.face_of_edge(first.0, first.1).is_some(),
        "the refused change was undone"
    );
    assert_eq!(walk.changes, 1);
    assert_eq!(walk.log, done);
    // Nothing refused: both kept.
    let mut base2: BaseMesh = f.base.clone();
    let mut walk2 = Walk::default();
    let (done2, _) = walk2.change_all(&mut base2, &[first, second], &lim, |_| false, |_| true);
    assert_eq!(done2.len(), 2);
    assert_eq!(walk2.changes, 2);
    record("AF-embedding", Seen::Holds, 2);
}
