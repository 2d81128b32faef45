//! The local re-embedding after a refinement round (seed 002, Part II, "Error and refinement":
//! S̃_T is refined locally; SPEC `AF-refine-local`): unchanged curves and maps are kept bit for
//! bit, the result passes every check a global re-embedding passes, and a kept curve whose face
//! did change is caught by an existing check.

use crate::common::verdicts::{assert_caught, assert_holds_for, record, Seen};
use pseudomanifold::fitting::base::{BaseMesh, Param};
use pseudomanifold::fitting::embed_checks::{check_disjoint, run};
use pseudomanifold::fitting::embedded::{embed, Embedded};
use pseudomanifold::fitting::geodesic::Node;
use pseudomanifold::fitting::local::{embed_local, kept_curves, unchanged, LocalStats, Previous};
use pseudomanifold::fitting::refine::{insert, RefineStats};
use pseudomanifold::fitting::{fit_surface, FitOptions};
use pseudomanifold::mesh::SimplicialSurface;
use pseudomanifold::oracle::tsv_diff::diagonal;
use std::collections::HashSet;

/// A node's bits (t compared by its bit pattern, so −0/NaN cannot pass as equal).
fn bits(n: &Node) -> (u32, u32, u64) {
    match *n {
        Node::Vertex(v) => (v, u32::MAX, 0),
        Node::Edge { a, b, t } => (a, b, t.to_bits()),
    }
}

fn param_bits(p: &Param) -> Option<(u32, [u64; 3])> {
    match *p {
        Param::Vertex => None,
        Param::Face { f, b } => Some((f, b.map(f64::to_bits))),
    }
}

/// A refinement at a vertex of S_T on a curve, and its local update.
struct Refined {
    /// The refined base mesh.
    base: BaseMesh,
    /// The local update.
    local: Embedded,
    /// What it kept.
    st: LocalStats,
    /// The base edge of the curve.
    edge: (u32, u32),
    /// The inserted vertex.
    x: u32,
}

/// The first inner vertex node x of a curve C, parametrized by the simplification in one of
/// C's two faces, whose insertion leaves C's base edge in the mesh and whose local update
/// holds every check.
fn refined_at_a_curve(k: &SimplicialSurface, base: &BaseMesh, prev: &Previous) -> Option<Refined> {
    for c in &prev.emb.emb.curves {
        let faces = [base.face_of_edge(c.a, c.b), base.face_of_edge(c.b, c.a)];
        for n in &c.nodes[1..c.nodes.len() - 1] {
            let Node::Vertex(x) = *n else { continue };
            let Param::Face { f, .. } = base.params()[x as usize] else {
                continue;
            };
            if !faces.contains(&Some(f)) {
                continue;
            }
            let mut b2 = base.clone();
            if !insert(&mut b2, x, &mut RefineStats::default())
                || b2.face_of_edge(c.a, c.b).is_none()
            {
                continue;
            }
            let Ok((e, st)) = embed_local(k, &b2, prev) else {
                continue;
            };
            if run(k, &b2, &e).iter().all(|r| !r.failed()) {
                return Some(Refined {
                    base: b2,
                    local: e,
                    st,
                    edge: (c.a, c.b),
                    x,
                });
            }
        }
    }
    None
}

/// On eight at ε = 10⁻² of the diagonal, a vertex of S_T on a curve is inserted as a refinement
/// round does (face split, Lawson flips). The local update keeps every curve whose two faces are
/// unchanged node for node, and the parameters of the vertices of S_T in every curved triangle
/// it does not map again, bit for bit; it re-embeds the rest; every check of the embedding holds
/// on all of it, as on the global re-embedding of the same base mesh. Planted: the curve through
/// the inserted vertex (its face changed) kept as it was — `AF-geodesic-disjoint` catches it (an
/// inner node is a base vertex now).
#[test]
fn af_refine_local_keeps_unchanged_curves_bit_identical_and_passes_the_global_checks() {
    let Some(dir) = crate::common::shared_path("af_refine_local", "meshes/good") else {
        return;
    };
    let k = pseudomanifold::mesh::load_surface(&dir.join("eight.off")).expect("corpus mesh loads");
    let fit =
        fit_surface(&k, &FitOptions::new(1e-2 * diagonal(&k)), |_| {}).expect("eight fits at 1e-2");
    let old = fit.embedded.clone().expect("eight is embedded");
    let prev = Previous::new(&fit.base, old.clone());
    let Refined {
        base: b2,
        local,
        st,
        edge: (a, b),
        x,
    } = refined_at_a_curve(&k, &fit.base, &prev)
        .expect("a vertex of S_T on a curve whose insertion is embedded locally");
    // What was kept: every curve whose two faces are unchanged, bit for bit.
    let same = unchanged(&b2, &prev);
    let kept = kept_curves(&b2, &prev, &same);
    assert!(
        st.kept_curves == kept.len() && !kept.is_empty() && kept.len() < local.emb.curves.len(),
        "{st:?}, {} kept of {}",
        kept.len(),
        local.emb.curves.len()
    );
    assert!(
        0 < st.kept_maps && st.kept_maps < st.maps,
        "some curved triangles keep their maps, some are mapped again: {st:?}"
    );
    for (e, c) in &kept {
        let (now, _) = local
            .emb
            .curve(e.0, e.1)
            .expect("a kept curve is in the result");
        assert_eq!(
            now.nodes.iter().map(bits).collect::<Vec<_>>(),
            c.nodes.iter().map(bits).collect::<Vec<_>>(),
            "curve {e:?} kept bit for bit"
        );
    }
    assert!(
        !kept.contains_key(&(a, b)),
        "the curve through {x} is traced again"
    );
    // A face whose previous curved triangle holds the inserted vertex counts as changed, its
    // corners unchanged or not (its kept curves would wall the new vertex in).
    let holding: Vec<u32> = prev
        .emb
        .maps
        .iter()
        .filter(|m| m.uv.contains_key(&x))
        .map(|m| m.face)
        .collect();
    assert!(!holding.is_empty(), "{x} is in a previous curved triangle");
    assert!(holding.iter().all(|f| !same.contains(f)), "{holding:?}");
    // Planted: x moved, in the previous embedding, into a curved triangle far from the
    // refinement whose corners did not change; that face now counts as changed too.
    let far = prev
        .emb
        .maps
        .iter()
        .position(|m| same.contains(&m.face) && !holding.contains(&m.face))
        .expect("a face far from the refinement");
    let mut moved = prev.clone();
    for m in &mut moved.emb.maps {
        m.uv.remove(&x);
    }
    let h = moved.emb.maps[far].face;
    moved.emb.maps[far].uv.insert(x, [0.25, 0.25]);
    assert!(same.contains(&h) && !unchanged(&b2, &moved).contains(&h));
    // The parameters of the vertices of S_T inside the curved triangles kept whole.
    let whole: HashSet<u32> = b2
        .faces()
        .filter(|(f, c)| {
            same.contains(f)
                && (0..3).all(|i| {
                    let (u, w) = (c[i], c[(i + 1) % 3]);
                    kept.contains_key(&(u.min(w), u.max(w)))
                })
        })
        .map(|(f, _)| f)
        .collect();
    let mut inside = 0;
    for (v, p) in old.params.iter().enumerate() {
        if matches!(param_bits(p), Some((f, _)) if whole.contains(&f)) {
            inside += 1;
            assert_eq!(
                param_bits(&local.params[v]),
                param_bits(p),
                "vertex {v}'s parameter kept"
            );
        }
    }
    assert!(inside > 0, "vertices of S_T in kept curved triangles");
    record("AF-refine-local", Seen::Holds, (kept.len() + inside) as u64);
    // Every check of the embedding, on the whole of both results.
    let global = embed(&k, &b2).expect("the global re-embedding exists");
    assert_eq!(global.emb.curves.len(), local.emb.curves.len());
    let (rl, rg) = (run(&k, &b2, &local), run(&k, &b2, &global));
    for (l, g) in rl.iter().zip(&rg) {
        assert_eq!(l.id, g.id);
        assert_holds_for("eight, global re-embedding", g);
        assert_holds_for("eight, local re-embedding", l);
    }
    // Planted: the curve a–b through x, whose face changed, kept as it was.
    let mut planted = local.emb.clone();
    let i = planted.index[&(a, b)];
    let (before, _) = old.emb.curve(a, b).expect("a–b was embedded");
    planted.curves[i] = before.clone();
    let r = check_disjoint(&k, &b2, &planted);
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);
}
