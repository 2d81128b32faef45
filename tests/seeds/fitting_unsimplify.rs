//! The fallback of the embedding (`fitting::unsimplify`, SPEC `AF-unsimplify`): where a base
//! edge has no curve and the AC·CB walk cannot finish, S_T's own triangles are kept around it
//! (the simplification run again from S_T with those vertices never removed), growing to S_T
//! itself, the limit of refinement where every base edge is an edge of S_T.

use crate::common::verdicts::{assert_caught, assert_holds_for, record, Seen};
use pseudomanifold::fitting::base::{BaseMesh, RemovalLimits};
use pseudomanifold::fitting::embed_checks::{check_curved_disk, run};
use pseudomanifold::fitting::embedded::embed;
use pseudomanifold::fitting::geodesic::Node;
use pseudomanifold::fitting::overlay;
use pseudomanifold::fitting::unsimplify::{
    check_restored, restore, strip, Restore, Site, MAX_RING,
};
use pseudomanifold::fitting::{fit_surface, FitOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{generate, SimplicialSurface};
use pseudomanifold::oracle::tsv_diff::diagonal;
use std::collections::HashSet;

fn torus(n: u32, m: u32) -> SimplicialSurface {
    validate(&generate::torus(n, m))
        .surface
        .expect("the generated torus is a simplicial surface")
}

/// The edges of S_T as sorted pairs.
fn edges_of(k: &SimplicialSurface) -> HashSet<(u32, u32)> {
    k.faces()
        .flat_map(|f| {
            let c = k.face(f).map(|v| v.0);
            (0..3).map(move |i| (c[i].min(c[(i + 1) % 3]), c[i].max(c[(i + 1) % 3])))
        })
        .collect()
}

/// Every base edge of `base` that is an edge of S_T has that edge as its curve (two vertex
/// nodes); returns how many there are.
fn edges_embedded_as_themselves(
    k: &SimplicialSurface,
    base: &BaseMesh,
    e: &pseudomanifold::fitting::embedded::Embedded,
) -> usize {
    let st = edges_of(k);
    let mut n = 0;
    for (_, c) in base.faces() {
        for i in 0..3 {
            let (u, w) = (c[i], c[(i + 1) % 3]);
            if u < w && st.contains(&(u, w)) {
                let (curve, _) = e.emb.curve(u, w).expect("the base edge has a curve");
                assert_eq!(curve.nodes.len(), 2, "{u}-{w}: the edge of S_T itself");
                assert!(
                    curve.nodes.contains(&Node::Vertex(u))
                        && curve.nodes.contains(&Node::Vertex(w))
                );
                n += 1;
            }
        }
    }
    n
}

/// The first base edge a–b (in face order) that is not an edge of S_T (`st`, [`edges_of`]) and
/// has vertices of S_T parametrized in its faces: the edge a forced fallback round takes as
/// blocked.
fn edge_off_s_t(st: &HashSet<(u32, u32)>, base: &BaseMesh) -> (u32, u32) {
    base.faces()
        .flat_map(|(_, c)| (0..3).map(move |i| (c[i], c[(i + 1) % 3])))
        .find(|&(a, b)| {
            !st.contains(&(a.min(b), a.max(b)))
                && [(a, b), (b, a)]
                    .iter()
                    .filter_map(|&(u, w)| base.face_of_edge(u, w))
                    .any(|g| !base.members(g).is_empty())
        })
        .expect("a base edge off S_T with vertices of S_T in its faces")
}

/// One round forced on the generated torus's fit at 10⁻² (which needs none): the base edge
/// a–b (the first not an edge of S_T with vertices of S_T in its faces) is taken as blocked.
/// The returned base mesh keeps a, b and the strip (ring 0: their triangles of S_T and those
/// a–b crosses) as base vertices,
/// the triangles of S_T with three kept corners are base faces with nothing in them
/// (`AF-unsimplify`), their base edges are embedded as themselves, and every check of the
/// embedding holds. Planted: a kept vertex removed again (caught by `AF-unsimplify`), and the
/// curve of a restored base edge left out (caught by `AF-curved-disk`: two curved triangles
/// merge).
#[test]
fn af_unsimplify_restores_s_t_around_a_blocked_edge_and_planted_stitches_are_caught() {
    let k = torus(24, 12);
    let opts = FitOptions::new(1e-2 * diagonal(&k));
    let f = fit_surface(&k, &opts, |_| {}).expect("the fit succeeds");
    assert!(!f.restore.active(), "the torus needs no fallback");
    let st = edges_of(&k);
    let (a, b) = edge_off_s_t(&st, &f.base);
    let members: Vec<u32> = [(a, b), (b, a)]
        .iter()
        .filter_map(|&(u, w)| f.base.face_of_edge(u, w))
        .flat_map(|g| f.base.members(g).to_vec())
        .collect();
    // Ring 0: a, b, their triangles of S_T and those a-b crosses (corners in both faces).
    let region = strip(&k, &f.base, a, b);
    assert!(
        region.contains(&a) && region.contains(&b) && region.iter().any(|x| members.contains(x)),
        "strip {region:?}, {members:?} in a-b's faces"
    );
    let mut state = Restore::default();
    let (m, _) = restore(
        &k,
        &f.base,
        &[Site::Edge(a, b)],
        &opts.simplify_options(),
        &mut state,
        |_| false,
    )
    .expect("one round of the fallback");
    assert_eq!(state.rings, vec![0]);
    for &x in region.iter().chain([a, b].iter()) {
        assert!(m.is_base(x), "vertex {x} of a-b's strip is a base vertex");
    }
    let r = check_restored(&k, &m, state.keep());
    assert_holds_for("the torus restored around a-b", &r);
    let e = embed(&k, &m).expect("the restored base mesh is embedded");
    for r in run(&k, &m, &e) {
        assert_holds_for("the torus restored around a-b", &r);
    }
    assert!(edges_embedded_as_themselves(&k, &m, &e) > 0);

    // A kept vertex removed again: its triangles of S_T are no base faces any more.
    let loose = RemovalLimits {
        max_deviation: f64::INFINITY,
        min_normal_cos: -1.0,
        min_quality: 0.0,
        max_degree: 64,
    };
    let mut removed = m.clone();
    let x = region
        .iter()
        .copied()
        .find(|&x| removed.clone().remove_vertex(x, &loose).is_ok())
        .expect("a kept vertex that can be removed");
    removed
        .remove_vertex(x, &loose)
        .expect("the kept vertex is removed");
    let r = check_restored(&k, &removed, state.keep());
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);

    // The curve of a restored base edge (an edge of S_T between kept vertices) left out.
    let mut emb = e.emb.clone();
    let i = emb
        .curves
        .iter()
        .position(|c| {
            c.nodes.len() == 2
                && state.keep()[c.a as usize]
                && state.keep()[c.b as usize]
                && st.contains(&(c.a.min(c.b), c.a.max(c.b)))
        })
        .expect("a restored base edge");
    emb.curves.remove(i);
    emb.index = emb
        .curves
        .iter()
        .enumerate()
        .map(|(j, c)| ((c.a.min(c.b), c.a.max(c.b)), j))
        .collect();
    let r = match overlay::build(&k, &m, &emb) {
        Ok(ov) => check_curved_disk(&ov, &m, &emb),
        Err(err) => panic!("the overlay without one curve is built: {err}"),
    };
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);
}

/// The fallback ends: on a small torus, with every base mesh short of S_T counted as tried,
/// the rounds grow the kept set ring by ring (the strip, the edge's two faces, then the faces
/// around its ends grown by rings of S_T, which cover the 12 × 6 torus before `MAX_RING`) until
/// every vertex is kept, and the base mesh is
/// then S_T itself, every base edge embedded as itself and every check holding.
#[test]
fn af_unsimplify_ends_at_s_t_itself_with_every_check_holding() {
    let k = torus(12, 6);
    let opts = FitOptions::new(1e-2 * diagonal(&k));
    let mut base = BaseMesh::new(&k);
    pseudomanifold::fitting::simplify::simplify(&mut base, &k, &opts.simplify_options(), |_, _| {});
    let (a, b) = base
        .faces()
        .map(|(_, c)| (c[0], c[1]))
        .next()
        .expect("a base edge");
    let mut state = Restore::default();
    let (m, _) = restore(
        &k,
        &base,
        &[Site::Edge(a, b)],
        &opts.simplify_options(),
        &mut state,
        |m| m.num_faces() < k.num_faces(),
    )
    .expect("S_T itself is the last round");
    // Each round tried grows the ring (at most to every vertex kept, past MAX_RING).
    assert!(
        state.rings.windows(2).all(|w| w[0] < w[1]),
        "{:?}",
        state.rings
    );
    assert!(state.rings.last().is_some_and(|&r| r <= MAX_RING + 1));
    assert_eq!(state.kept, k.num_vertices());
    let mut faces: Vec<[u32; 3]> = m.faces().map(|(_, c)| c).collect();
    let mut want: Vec<[u32; 3]> = k.faces().map(|f| k.face(f).map(|v| v.0)).collect();
    faces.sort_unstable();
    want.sort_unstable();
    assert_eq!(faces, want, "the base mesh is S_T");
    let r = check_restored(&k, &m, state.keep());
    assert_holds_for("S_T itself", &r);
    let e = embed(&k, &m).expect("S_T is embedded in itself");
    for r in run(&k, &m, &e) {
        if r.id == "AF-geodesic-shortest" {
            // Every curve is an edge of S_T: no inner node to move, nothing examined.
            assert_eq!(r.examined, 0, "no inner node on S_T itself");
            continue;
        }
        assert_holds_for("S_T itself", &r);
    }
    assert_eq!(edges_embedded_as_themselves(&k, &m, &e), edges_of(&k).len());
    // Every vertex kept and S_T tried: nothing is left to do.
    assert!(restore(
        &k,
        &m,
        &[Site::Edge(a, b)],
        &opts.simplify_options(),
        &mut state,
        |_| true
    )
    .is_none());
}

/// A round after refinement (`Restore::keep_base`): on the generated torus's fit at 10⁻², a few
/// vertices of S_T are inserted as a refinement round does, and a round is forced at a base
/// edge. Every base vertex of the refined base mesh stays a base vertex (`AF-unsimplify`: they
/// are kept), the previous embedding re-slotted to the new base mesh keeps the curves of the
/// faces that did not change, and every check of the embedding holds on the local update.
/// Planted: the round without the current base vertices kept (as before `keep_base`) loses some
/// of them, caught by `AF-unsimplify` against the kept set that names them.
#[test]
fn af_unsimplify_after_refinement_keeps_every_base_vertex_and_updates_locally() {
    use pseudomanifold::fitting::local::{embed_local, Previous};
    use pseudomanifold::fitting::refine::{insert, RefineStats};
    let k = torus(24, 12);
    let opts = FitOptions::new(1e-2 * diagonal(&k));
    let f = fit_surface(&k, &opts, |_| {}).expect("the fit succeeds");
    let prev = Previous::new(&f.base, f.embedded.clone().expect("the torus is embedded"));
    // The refinement: the first vertex of S_T in every eighth base face.
    let mut base = f.base.clone();
    let xs: Vec<u32> = f
        .base
        .faces()
        .step_by(8)
        .filter_map(|(g, _)| f.base.members(g).first().copied())
        .collect();
    let mut refined = Vec::new();
    for x in xs {
        if insert(&mut base, x, &mut RefineStats::default()) {
            refined.push(x);
        }
    }
    assert!(!refined.is_empty(), "vertices of S_T inserted");
    let (a, b) = edge_off_s_t(&edges_of(&k), &base);
    let n = base.positions().len();
    let round = |keep_base: bool| {
        let mut state = Restore::default();
        state.add(n, refined.iter().copied());
        if keep_base {
            assert!(state.keep_base(&base) > 0, "base vertices not kept before");
        }
        let (m, _) = restore(
            &k,
            &base,
            &[Site::Edge(a, b)],
            &opts.simplify_options(),
            &mut state,
            |_| false,
        )
        .expect("one round of the fallback");
        (m, state)
    };
    let (m, state) = round(true);
    for v in base.base_vertices() {
        assert!(m.is_base(v), "base vertex {v} of the refined mesh kept");
    }
    let r = check_restored(&k, &m, state.keep());
    assert_holds_for("the refined torus restored around a-b", &r);
    let prev = prev.reslot(&m);
    assert!(
        !prev.faces.is_empty() && prev.faces.iter().all(|(&g, &c)| m.face(g) == Some(c)),
        "the re-slotted faces are faces of the new base mesh, corners in order"
    );
    let (e, ls) = embed_local(&k, &m, &prev).expect("the local update after the round");
    assert!(
        0 < ls.kept_curves && ls.kept_curves < ls.curves && ls.kept_maps > 0,
        "{ls:?}"
    );
    for r in run(&k, &m, &e) {
        assert_holds_for("the local update after the round", &r);
    }

    // Planted: the round without the current base vertices kept.
    let (m_old, _) = round(false);
    let r = check_restored(&k, &m_old, state.keep());
    assert_caught(&r);
    record("AF-planted", Seen::Caught, r.examined);
}
