//! Sec. 3.1 checks on meshes built in code, each with a planted fault that the check must catch.

use crate::common;

use pseudomanifold::mesh::generate::{
    bipyramid_with_apexes, icosahedron, octahedron, tetrahedron, torus,
};
use pseudomanifold::mesh::star::{
    canonical_triangulation, check_star_isomorphism, link, star, TVertex,
};
use pseudomanifold::mesh::validate::{validate, ErrorClass, ValidationReport};
use pseudomanifold::mesh::{HalfedgeId, RawMesh, VertexId};
use pseudomanifold::report::Verdict;

fn check<'a>(rep: &'a ValidationReport, id: &str) -> &'a pseudomanifold::report::CheckResult {
    rep.checks
        .iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no check {id}"))
}

fn good_meshes() -> Vec<(&'static str, RawMesh)> {
    vec![
        ("tetrahedron", tetrahedron()),
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
        ("torus", torus(6, 5)),
    ]
}

#[test]
fn generated_meshes_are_simplicial_surfaces() {
    for (name, m) in good_meshes() {
        let v = validate(&m);
        assert!(
            v.report.is_simplicial_surface,
            "{name}: {:#?}",
            v.report.checks
        );
        assert!(v.surface.is_some(), "{name}");
        assert!(v.report.error_classes.is_empty(), "{name}");
    }
}

#[test]
fn d3_1_1_collinear_face_is_caught_exactly() {
    // Planted fault: move a vertex of the octahedron onto the segment between two others,
    // exactly (0.5 is representable), making face [0, 2, 4] ... collinear.
    let mut m = octahedron();
    m.positions[4] = [0.5, 0.5, 0.0]; // on the segment [v0, v2] = [(1,0,0), (0,1,0)]
    let v = validate(&m);
    let c = check(&v.report, "D3.1.1");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert!(
        c.witnesses[0].text.contains("face 0"),
        "{}",
        c.witnesses[0].text
    );
    assert!(v.report.error_classes.contains(&ErrorClass::DegenerateFace));
    assert!(v.surface.is_none());
}

#[test]
fn d3_1_1_nearly_collinear_is_not_degenerate() {
    // One ulp off the segment: a genuine (thin) triangle; an epsilon test would call it
    // degenerate, the exact test must not.
    let mut m = octahedron();
    m.positions[4] = [0.5, f64::from_bits(0.5f64.to_bits() + 1), 0.0];
    let v = validate(&m);
    assert_eq!(check(&v.report, "D3.1.1").verdict(), Verdict::Holds);
}

#[test]
fn d3_1_2_faces_of_a_simplex() {
    // Def. 3.1.2: the faces of a 2-simplex are its 3 vertices, 3 edges and itself; the star
    // of a vertex contains exactly the faces of its triangles.
    let k = validate(&tetrahedron()).surface.expect("valid");
    let st = star(&k, VertexId(0));
    assert_eq!(st.triangles.len(), 3);
    assert_eq!(st.edges.len(), 6); // 3 spokes + 3 link edges
    assert_eq!(st.vertices.len(), 4);
    for t in &st.triangles {
        for i in 0..3 {
            assert!(st.vertices.contains(&t[i]));
            let mut e = [t[i], t[(i + 1) % 3]];
            e.sort();
            assert!(st.edges.contains(&e), "face {e:?} of {t:?} missing");
        }
    }
}

#[test]
fn d3_1_3_i_index_out_of_range_is_caught() {
    let mut m = tetrahedron();
    m.faces[2] = [0, 2, 9];
    m.faces[3] = [7, 3, 2];
    let v = validate(&m);
    let c = check(&v.report, "D3.1.3(i)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert_eq!(c.offenders, 2, "every offending index is counted");
    assert!(c.witnesses[0].text.contains("face 2"));
    assert!(v
        .report
        .error_classes
        .contains(&ErrorClass::IndexOutOfRange));
}

#[test]
fn d3_1_3_ii_coincident_vertices_are_caught() {
    // Two octahedra far apart, then one vertex of the second moved onto a vertex of the first.
    let a = octahedron();
    let mut pos = a.positions.clone();
    let mut faces = a.faces.clone();
    for p in &a.positions {
        pos.push([p[0] + 10.0, p[1], p[2]]);
    }
    for f in &a.faces {
        faces.push([f[0] + 6, f[1] + 6, f[2] + 6]);
    }
    let clean = validate(&RawMesh::from_arrays(pos.clone(), faces.clone()));
    assert!(clean.report.is_simplicial_surface);
    assert_eq!(clean.report.components.len(), 2);
    pos[7] = pos[0]; // vertex 7 (= -x of the second) onto vertex 0 (+x of the first)
                     // keep the second octahedron a valid surface by shifting it to touch
    let v = validate(&RawMesh::from_arrays(pos, faces));
    let c = check(&v.report, "D3.1.3(ii)(vertices)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert!(v
        .report
        .error_classes
        .contains(&ErrorClass::CoincidentVertices));
}

#[test]
fn d3_1_3_ii_interpenetrating_tetrahedra_are_caught() {
    let a = tetrahedron();
    let mut pos = a.positions.clone();
    let mut faces = a.faces.clone();
    for p in &a.positions {
        pos.push([p[0] + 0.5, p[1] + 0.25, p[2] + 0.125]);
    }
    for f in &a.faces {
        faces.push([f[0] + 4, f[1] + 4, f[2] + 4]);
    }
    let v = validate(&RawMesh::from_arrays(pos, faces));
    let c = check(&v.report, "D3.1.3(ii)(triangles)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert!(c.offenders >= 2);
    assert!(v
        .report
        .error_classes
        .contains(&ErrorClass::SelfIntersection));
    // Combinatorially the two tetrahedra are fine: only the geometric check fires.
    assert_eq!(check(&v.report, "D3.1.6(edges)").verdict(), Verdict::Holds);
    assert_eq!(check(&v.report, "D3.1.6(link)").verdict(), Verdict::Holds);
    assert!(v.surface.is_none());
}

#[test]
fn d3_1_3_ii_vertex_pushed_through_the_tube_is_caught() {
    // Torus: push an outer-equator vertex through the tube into the hole; its fan now
    // crosses the inner wall.
    let mut m = torus(8, 6);
    assert!(validate(&m).report.is_simplicial_surface);
    m.positions[0] = [0.9, 0.0, 0.0];
    let v = validate(&m);
    let c = check(&v.report, "D3.1.3(ii)(triangles)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert!(v.surface.is_none());
}

#[test]
fn d3_1_3_ii_shared_face_cases_of_the_exact_test() {
    use pseudomanifold::mesh::validate::intersect::triangles_meet_improperly;
    let pos = vec![
        [0.0, 0.0, 0.0],    // 0
        [1.0, 0.0, 0.0],    // 1
        [0.0, 1.0, 0.0],    // 2
        [1.0, 1.0, 0.0],    // 3
        [0.25, 0.25, 0.0],  // 4 (inside triangle 0,1,2)
        [0.0, 0.0, 1.0],    // 5
        [0.5, 0.5, 0.0],    // 6 (on segment 1-2)
        [-1.0, -1.0, 0.0],  // 7
        [0.25, 0.25, 0.5],  // 8
        [0.75, 0.25, 0.5],  // 9
        [0.25, 0.25, 0.1],  // 10
        [0.75, -0.25, 0.0], // 11
        [0.75, 0.75, 0.0],  // 12
        [-2.0, -1.0, 0.0],  // 13
        [-1.0, -2.0, 0.0],  // 14
    ];
    // Shared edge [1,2], coplanar, opposite corners on opposite sides: proper.
    assert!(!triangles_meet_improperly(&pos, [0, 1, 2], [1, 3, 2]));
    // Shared edge, coplanar, same side: overlap.
    assert!(triangles_meet_improperly(&pos, [0, 1, 2], [1, 4, 2]));
    // Shared edge, not coplanar: proper.
    assert!(!triangles_meet_improperly(&pos, [0, 1, 2], [1, 5, 2]));
    // Shared vertex 0, coplanar, second triangle inside the first's corner: overlap.
    assert!(triangles_meet_improperly(&pos, [0, 1, 2], [0, 4, 6]));
    // Shared vertex 0, coplanar, pointing away: proper.
    assert!(!triangles_meet_improperly(&pos, [0, 1, 2], [0, 7, 5]));
    // No shared vertex, a vertex in the interior of the other's edge: improper.
    assert!(triangles_meet_improperly(&pos, [0, 1, 2], [6, 3, 5]));
    // No shared vertex, disjoint (the second one above the first's plane).
    assert!(!triangles_meet_improperly(&pos, [0, 1, 2], [10, 8, 9]));
    // No shared vertex, one vertex touching the first's interior: improper.
    assert!(triangles_meet_improperly(&pos, [0, 1, 2], [4, 8, 9]));
    // No shared vertex, coplanar and overlapping: improper; coplanar and apart: proper.
    assert!(triangles_meet_improperly(&pos, [0, 1, 2], [4, 11, 12]));
    assert!(!triangles_meet_improperly(&pos, [0, 1, 2], [7, 13, 14]));
    // The same configurations scaled by 2^700 (exact): outside the range of the floating
    // predicates, decided by the exact integer determinants instead, with the same answers.
    let big: Vec<[f64; 3]> = pos.iter().map(|p| p.map(|x| x * 2f64.powi(700))).collect();
    for (t1, t2, improper) in [
        ([0, 1, 2], [1, 3, 2], false),
        ([0, 1, 2], [1, 4, 2], true),
        ([0, 1, 2], [0, 4, 6], true),
        ([0, 1, 2], [0, 7, 5], false),
        ([0, 1, 2], [4, 11, 12], true),
        ([0, 1, 2], [7, 13, 14], false),
        ([0, 1, 2], [4, 8, 9], true),
        ([0, 1, 2], [10, 8, 9], false),
    ] {
        assert_eq!(
            triangles_meet_improperly(&big, t1, t2),
            improper,
            "{t1:?} {t2:?} at 2^700"
        );
    }
}

#[test]
fn d3_1_4_skeleta_counts() {
    // Def. 3.1.4: K^(0), K^(1), K^(2) of the icosahedron have 12, 30, 20 simplices.
    let k = validate(&icosahedron()).surface.expect("valid");
    assert_eq!(k.num_vertices(), 12);
    assert_eq!(k.num_edges(), 30);
    assert_eq!(k.edges().count(), 30);
    assert_eq!(k.num_faces(), 20);
}

#[test]
fn d3_1_5_star_and_link_by_definition() {
    let k = validate(&torus(5, 4)).surface.expect("valid");
    for v in k.vertices() {
        let lk = link(&k, v);
        let st = star(&k, v);
        assert_eq!(lk.vertices.len() as u32, k.degree(v));
        assert_eq!(lk.edges.len() as u32, k.degree(v));
        assert!(!lk.vertices.contains(&v));
        assert!(lk.edges.iter().all(|e| !e.contains(&v)));
        assert!(lk.edges.iter().all(|e| st.edges.contains(e)));
    }
}

#[test]
fn d3_1_6_boundary_edge_is_caught() {
    let mut m = icosahedron();
    m.faces.remove(7);
    m.face_origin.remove(7);
    let v = validate(&m);
    let c = check(&v.report, "D3.1.6(edges)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert_eq!(c.offenders, 3, "all three edges of the hole");
    assert!(v.report.error_classes.contains(&ErrorClass::Boundary));
    assert_eq!(check(&v.report, "D3.1.6(link)").offenders, 3);
}

#[test]
fn d3_1_6_nonmanifold_vertex_is_caught() {
    // Two tetrahedra sharing only a vertex (the paper's Fig. 3.3 situation): every edge is in
    // two triangles, but the link of the shared vertex is two cycles.
    let a = tetrahedron();
    let mut pos = a.positions.clone();
    let mut faces = a.faces.clone();
    for p in &a.positions[1..] {
        pos.push([2.0 - p[0], 2.0 - p[1], 2.0 - p[2]]); // point reflection through v0
    }
    let map = |i: u32| if i == 0 { 0 } else { i + 3 };
    for f in &a.faces {
        faces.push([map(f[0]), map(f[2]), map(f[1])]);
    }
    let v = validate(&RawMesh::from_arrays(pos, faces));
    assert_eq!(check(&v.report, "D3.1.6(edges)").verdict(), Verdict::Holds);
    let c = check(&v.report, "D3.1.6(link)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert_eq!(c.offenders, 1);
    assert!(c.witnesses[0].text.contains("vertex 0"));
    assert_eq!(v.report.error_classes, vec![ErrorClass::NonmanifoldVertex]);
}

#[test]
fn d3_1_6_duplicate_face_is_one_simplex_of_k() {
    // K is a set (Def. 3.1.3): a face listed twice is reported as a duplicate, and counted once
    // for the edge condition of Def. 3.1.6.
    let mut m = tetrahedron();
    m.faces.push([0, 2, 1]); // same triangle, opposite orientation
    m.face_origin.push(4);
    let v = validate(&m);
    assert_eq!(check(&v.report, "X-duplicate-face").offenders, 1);
    assert_eq!(v.report.error_classes, vec![ErrorClass::DuplicateFace]);
    assert!(v.surface.is_none());
}

#[test]
fn d3_1_6_nonmanifold_edge_is_caught() {
    // A fin: a third triangle on edge [0, 1] of the tetrahedron.
    let mut m = tetrahedron();
    m.positions.push([3.0, 0.0, 0.0]);
    m.faces.push([0, 1, 4]);
    m.face_origin.push(4);
    let v = validate(&m);
    let c = check(&v.report, "D3.1.6(edges)");
    assert_eq!(c.verdict(), Verdict::Fails);
    assert!(c
        .witnesses
        .iter()
        .any(|w| w.text.contains("edge [0, 1] is in 3")));
    assert!(v
        .report
        .error_classes
        .contains(&ErrorClass::NonmanifoldEdge));
    assert!(v.report.error_classes.contains(&ErrorClass::Boundary)); // the fin's free edges
}

#[test]
fn d3_1_7_simplicial_map_of_tetrahedron() {
    // Def. 3.1.7: on a tetrahedron every vertex bijection is a simplicial isomorphism; the
    // labelling of each star by the half-edges is one.
    let k = validate(&tetrahedron()).surface.expect("valid");
    for v in k.vertices() {
        let t = canonical_triangulation(k.degree(v));
        assert_eq!(t.triangles.len(), 3);
        assert!(t.vertices.contains(&TVertex::Centre));
    }
    assert_eq!(
        check_star_isomorphism(&k, |v, x| k.s(v, x)).verdict(),
        Verdict::Holds
    );
}

#[test]
fn d4_1_4_s_v_is_a_simplicial_isomorphism_on_generated_meshes() {
    for (name, m) in good_meshes() {
        let k = validate(&m).surface.expect("valid");
        let r = check_star_isomorphism(&k, |v, x| k.s(v, x));
        assert_eq!(r.verdict(), Verdict::Holds, "{name}: {:?}", r.witnesses);
        assert_eq!(r.examined as usize, k.num_vertices());
    }
}

#[test]
fn d4_1_4_planted_wrong_labels_are_caught() {
    // Swap the labels of two non-adjacent link vertices of vertex 0 of the icosahedron: still
    // a bijection on vertices, but spokes' neighbours no longer map to polygon sides.
    let k = validate(&icosahedron()).surface.expect("valid");
    let v0 = VertexId(0);
    let a = k.link_vertex(v0, 0).expect("label 0");
    let b = k.link_vertex(v0, 2).expect("label 2");
    let r = check_star_isomorphism(&k, |v, x| {
        let l = k.s(v, x)?;
        if v == v0 && x == a {
            Some(2)
        } else if v == v0 && x == b {
            Some(0)
        } else {
            Some(l)
        }
    });
    assert_eq!(r.verdict(), Verdict::Fails);
    assert_eq!(r.offenders, 1);
    assert!(r.witnesses[0].text.contains("vertex 0"));
}

#[test]
fn l3_1_1_surface_invariants() {
    let v = validate(&torus(7, 4));
    let c = check(&v.report, "L3.1.1");
    assert_eq!(c.verdict(), Verdict::Holds);
    common::assert_holds(c);
    assert_eq!(v.report.components[0].genus, Some(1));
    let v = validate(&icosahedron());
    assert_eq!(v.report.components[0].genus, Some(0));
    // Not a simplicial surface: the lemma's conclusion is not claimed.
    let mut m = icosahedron();
    m.faces.pop();
    m.face_origin.pop();
    let v = validate(&m);
    assert!(matches!(
        check(&v.report, "L3.1.1").verdict(),
        Verdict::Skipped { .. }
    ));
}

#[test]
fn c6_1_2_labelling_dcel_invariants_hold_on_generated_meshes() {
    for (name, m) in good_meshes() {
        let k = validate(&m).surface.expect("valid");
        for h in (0..k.num_halfedges() as u32).map(HalfedgeId) {
            assert_eq!(k.twin(k.twin(h)), h, "{name}");
            assert_ne!(k.twin(h), h);
            assert_eq!(k.next(k.next(k.next(h))), h);
            assert_eq!(k.origin(k.twin(h)), k.dest(h));
            assert_eq!(k.dest(k.twin(h)), k.origin(h));
            assert_eq!(k.origin(k.next(h)), k.dest(h));
            // Labels advance by one around the origin (counterclockwise rotation).
            let rot = k.twin(k.prev(h));
            let m_v = k.degree(k.origin(h));
            assert_eq!(k.label(rot), (k.label(h) + 1) % m_v, "{name}");
        }
    }
    common::verdicts::record(
        "C6.1.2-labelling",
        common::verdicts::Seen::Holds,
        good_meshes().len() as u64,
    );
}

#[test]
fn inconsistent_orientation_is_repaired_and_reported() {
    let mut m = icosahedron();
    m.faces[3] = [m.faces[3][0], m.faces[3][2], m.faces[3][1]];
    let v = validate(&m);
    assert!(v.report.is_simplicial_surface);
    let k = v.surface.expect("valid");
    assert_eq!(k.flipped_faces(), 1);
}

#[test]
fn c4_1_degree_ge_3_follows_from_link_cycle() {
    use pseudomanifold::mesh::validate::surface::{link_shape, LinkShape};
    // A 2-cycle link (vertex of degree 2) is not a simple cycle.
    assert_eq!(link_shape(0, &[(1, 2), (2, 1)]), LinkShape::Other);
    assert_eq!(link_shape(0, &[(1, 2), (2, 3), (3, 1)]), LinkShape::Cycle);
    assert_eq!(link_shape(0, &[(1, 2), (2, 3)]), LinkShape::Path);
    for (_, m) in good_meshes() {
        let k = validate(&m).surface.expect("valid");
        assert!(k.vertices().all(|v| k.degree(v) >= 3));
    }
    common::verdicts::record(
        "C4.1-degree-ge-3",
        common::verdicts::Seen::Holds,
        good_meshes().len() as u64,
    );
}

#[test]
fn d4_1_3_canonical_triangulation_counts() {
    for m in 3..=12u32 {
        let t = canonical_triangulation(m);
        assert_eq!(t.vertices.len() as u32, m + 1);
        assert_eq!(t.edges.len() as u32, 2 * m);
        assert_eq!(t.triangles.len() as u32, m);
    }
}

#[test]
fn x_input_sanity_checks_catch_planted_faults() {
    let mut m = octahedron();
    m.positions[1][2] = f64::NAN;
    m.faces[5] = [1, 1, 5];
    m.positions.push([9.0, 9.0, 9.0]); // unreferenced
    m.vertex_origin.push(6);
    let v = validate(&m);
    assert_eq!(check(&v.report, "X-finite").verdict(), Verdict::Fails);
    assert_eq!(check(&v.report, "X-repeated-corner").offenders, 1);
    assert_eq!(
        check(&v.report, "X-unreferenced").verdict(),
        Verdict::Warning
    );
    assert_eq!(check(&v.report, "X-unreferenced").offenders, 1);
    assert!(v.report.error_classes.contains(&ErrorClass::NonFinite));
    let empty = validate(&RawMesh::from_arrays(vec![], vec![]));
    assert_eq!(check(&empty.report, "X-nonempty").verdict(), Verdict::Fails);
    assert!(!empty.report.is_simplicial_surface);
    // Non-finite, repeated corner, unreferenced (warning), empty: four planted faults caught.
    common::verdicts::record("X-input", common::verdicts::Seen::Caught, 4);
}

/// The error classes' names are the corpus manifest's spellings (manifest.tsv, `ppm check`'s
/// text report), the same as their JSON form.
#[test]
fn d3_1_6_error_class_names_are_the_manifest_spellings() {
    use ErrorClass::*;
    let all = [
        (Boundary, "boundary"),
        (NonmanifoldEdge, "nonmanifold_edge"),
        (NonmanifoldVertex, "nonmanifold_vertex"),
        (DuplicateFace, "duplicate_face"),
        (DegenerateFace, "degenerate_face"),
        (SelfIntersection, "self_intersection"),
        (CoincidentVertices, "coincident_vertices"),
        (NonOrientable, "non_orientable"),
        (IndexOutOfRange, "index_out_of_range"),
        (NonFinite, "non_finite"),
    ];
    for (c, name) in all {
        assert_eq!(c.name(), name);
        assert_eq!(serde_json::to_value(c).ok(), Some(serde_json::json!(name)));
    }
}

use pseudomanifold::mesh::validate::intersect::{
    triangles_meet_improperly, MAX_COUNTED_INTERSECTIONS,
};

/// Every improperly meeting pair of distinct triangles, by testing all pairs.
fn improper_pairs_by_brute_force(raw: &RawMesh) -> u64 {
    let fs = &raw.faces;
    let mut n = 0;
    for f in 0..fs.len() {
        for g in f + 1..fs.len() {
            let (mut a, mut b) = (fs[f], fs[g]);
            a.sort_unstable();
            b.sort_unstable();
            if a != b && triangles_meet_improperly(&raw.positions, fs[f], fs[g]) {
                n += 1;
            }
        }
    }
    n
}

/// Def. 3.1.3(ii) around vertices of degree ≥ 16 (the star search and the trimmed boxes of
/// the general search): the validator finds exactly the improper pairs that testing every pair
/// finds — none on a clean 40-gon bipyramid, the folds of two swapped rim vertices inside both
/// stars, and the crossings of two stars whose apexes were moved through each other's cone.
#[test]
fn d3_1_3_ii_high_degree_stars_find_what_all_pairs_find() {
    let (t, b) = ([0.0, 0.0, 1.0], [0.0, 0.0, -1.0]);
    let clean = bipyramid_with_apexes(40, t, b);
    let mut folded = bipyramid_with_apexes(40, t, b);
    folded.positions.swap(7, 8);
    let crossed = bipyramid_with_apexes(40, t, [1.2, 0.1, 0.8]);
    // The top star flat (coplanar triangles: the exact 2-D predicates decide its pairs).
    let flat = bipyramid_with_apexes(40, [0.0; 3], b);
    let mut flat_folded = bipyramid_with_apexes(40, [0.0; 3], b);
    flat_folded.positions.swap(7, 8);
    // A small triangle (its own component) piercing one star triangle 0.1 from the apex: the
    // nearest non-incident box is that triangle's, so the apex's trimming radius is about
    // 0.045 and the piercing lies outside the trimmed corner (the general search must find it).
    let mut pierced = bipyramid_with_apexes(40, t, b);
    let (a0, b0) = (pierced.positions[2], pierced.positions[3]);
    let sub = |x: [f64; 3], y: [f64; 3]| [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
    let (ea, eb) = (sub(a0, t), sub(b0, t));
    let n = [
        ea[1] * eb[2] - ea[2] * eb[1],
        ea[2] * eb[0] - ea[0] * eb[2],
        ea[0] * eb[1] - ea[1] * eb[0],
    ];
    let nl = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let m = [
        (ea[0] + eb[0]) / 2.0,
        (ea[1] + eb[1]) / 2.0,
        (ea[2] + eb[2]) / 2.0,
    ];
    let ml = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
    let at = |r: f64, h: f64| -> [f64; 3] {
        std::array::from_fn(|d| t[d] + r * m[d] / ml + h * n[d] / nl)
    };
    let base = pierced.positions.len() as u32;
    pierced
        .positions
        .extend([at(0.1, 0.01), at(0.095, -0.01), at(0.105, -0.01)]);
    pierced.faces.push([base, base + 1, base + 2]);
    // The same, stretched 100× along one axis: edge lengths are then dominated by one
    // coordinate, and the trimmed box must still be cut at r_v/2 along the edge, not farther.
    let stretched = |axis: usize| {
        let mut m = pierced.clone();
        for p in &mut m.positions {
            p[axis] *= 100.0;
        }
        m
    };
    let (sx, sy, sz) = (stretched(0), stretched(1), stretched(2));
    // Two triangles added at the top apex, above its star: one with a corner of 160° at the apex
    // (its arc of directions bulges along +y beyond both edge directions), one crossing it near
    // the direction +y. Their arc boxes overlap only through that bulge, so the box of a wide
    // arc must reach the meeting point of its tangents.
    let mut obtuse = bipyramid_with_apexes(40, t, b);
    let (c80, s80) = (80f64.to_radians().cos(), 80f64.to_radians().sin());
    let n2 = (1.0f64 + 0.05 * 0.05).sqrt();
    let at2 = |d: [f64; 3]| -> [f64; 3] { std::array::from_fn(|k| t[k] + 0.5 * d[k]) };
    let base = obtuse.positions.len() as u32;
    obtuse.positions.extend([
        at2([s80, c80, 0.0]),
        at2([-s80, c80, 0.0]),
        at2([0.0, 1.0 / n2, -0.05 / n2]),
        at2([0.0, 0.3, 0.954]),
    ]);
    obtuse.faces.push([0, base, base + 1]);
    obtuse.faces.push([0, base + 2, base + 3]);
    for (name, raw, expect_some) in [
        ("clean", clean, false),
        ("pierced near the apex", pierced, true),
        ("pierced near the apex, stretched along x", sx, true),
        ("pierced near the apex, stretched along y", sy, true),
        ("pierced near the apex, stretched along z", sz, true),
        ("obtuse corner crossed through its bulge", obtuse, true),
        ("folded", folded, true),
        ("crossed", crossed, true),
        ("flat", flat, false),
        ("flat folded", flat_folded, true),
    ] {
        let brute = improper_pairs_by_brute_force(&raw);
        assert_eq!(
            brute > 0,
            expect_some,
            "{name}: {brute} pairs by brute force"
        );
        let v = validate(&raw);
        let c = check(&v.report, "D3.1.3(ii)(triangles)");
        let counted = brute.min(MAX_COUNTED_INTERSECTIONS as u64);
        assert_eq!(c.offenders, counted, "{name}: validator against all pairs");
        if expect_some {
            assert!(c.failed(), "{name}");
        } else {
            common::assert_holds_for(name, c);
        }
    }
}

/// Lemma 3.1.1's genus g = (2 − χ)/2 is claimed for closed orientable surfaces only: an open
/// band (χ = 0, like the torus) has none.
#[test]
fn l3_1_1_open_band_has_no_genus() {
    let n = 4u32;
    let mut pos = Vec::new();
    for z in [0.0, 1.0] {
        for i in 0..n {
            let a = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(n);
            pos.push([a.cos(), a.sin(), z]);
        }
    }
    let mut faces = Vec::new();
    for i in 0..n {
        let j = (i + 1) % n;
        faces.push([i, j, n + j]);
        faces.push([i, n + j, n + i]);
    }
    let v = validate(&RawMesh::from_arrays(pos, faces));
    let c = &v.report.components;
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].euler_characteristic, 0);
    assert_eq!(c[0].genus, None);
    assert!(v.surface.is_none());
}

/// Def. 3.1.3(ii) around high-degree vertices, differentially: 120 seeded random bipyramids
/// (rim of 16–40 vertices with jittered radius, height and angle; in half the cases one rim
/// vertex is moved 1–2.5 steps around, folding both stars by varying amounts) give the
/// validator exactly the all-pairs count.
#[test]
fn d3_1_3_ii_random_high_degree_stars_agree_with_all_pairs() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x3113);
    let mut with_pairs = 0;
    for case in 0..120 {
        let n: u32 = rng.gen_range(16..=40);
        let top = [
            rng.gen_range(-0.2..0.2),
            rng.gen_range(-0.2..0.2),
            rng.gen_range(0.3..1.5),
        ];
        let bottom = [
            rng.gen_range(-0.2..0.2),
            rng.gen_range(-0.2..0.2),
            rng.gen_range(-1.5..-0.3),
        ];
        let mut raw = bipyramid_with_apexes(n, top, bottom);
        let step = 2.0 * std::f64::consts::PI / f64::from(n);
        // Half the cases move one rim vertex past or onto a neighbour's angle.
        let odd = rng.gen_bool(0.5).then(|| rng.gen_range(0..n));
        for i in 0..n {
            let jitter = if odd == Some(i) {
                rng.gen_range(1.0..2.5) * if rng.gen_bool(0.5) { 1.0 } else { -1.0 }
            } else {
                rng.gen_range(-0.2..0.2)
            };
            let a = step * (f64::from(i) + jitter);
            let r = rng.gen_range(0.8..1.2);
            raw.positions[2 + i as usize] = [r * a.cos(), r * a.sin(), rng.gen_range(-0.05..0.05)];
        }
        let brute = improper_pairs_by_brute_force(&raw);
        with_pairs += usize::from(brute > 0);
        let v = validate(&raw);
        let c = check(&v.report, "D3.1.3(ii)(triangles)");
        let counted = brute.min(MAX_COUNTED_INTERSECTIONS as u64);
        assert_eq!(
            c.offenders, counted,
            "case {case} (n = {n}): validator against all pairs"
        );
    }
    // The sample must exercise both outcomes to mean anything.
    assert!(
        (20..100).contains(&with_pairs),
        "{with_pairs} of 120 cases have improper pairs"
    );
}

/// Def. 3.1.3(ii), the general search's trimmed box of a triangle with two high-degree corners
/// (both ends of a long edge): it must be cut at r_v/2 along each edge, measured in the edge's
/// length. T = (P, Q, X) is 100 long and 1 wide; P and Q carry fans of 16 triangles (cones
/// opening away from T); a small triangle crosses T 0.5 from P, outside P's trimmed corner
/// (r_P ≈ 0.245). The same scene is laid along x, y and z (one coordinate of T's edges
/// dominates their length in each).
#[test]
fn d3_1_3_ii_trimmed_box_of_a_long_triangle_with_two_high_degree_corners() {
    for axis in 0..3 {
        let rot = |p: [f64; 3]| -> [f64; 3] { std::array::from_fn(|k| p[(k + 3 - axis) % 3]) };
        let mut pos = vec![[0.0, 0.0, 0.0], [100.0, 0.0, 0.0], [100.0, 1.0, 0.0]];
        let mut faces = vec![[0u32, 1, 2]];
        for (apex, dx) in [(0u32, -1.0), (1u32, 1.0)] {
            let c = pos[apex as usize];
            let first = pos.len() as u32;
            for i in 0..16 {
                let a = std::f64::consts::TAU * f64::from(i) / 16.0;
                pos.push([c[0] + dx, c[1] + a.cos(), c[2] + a.sin()]);
            }
            for i in 0..16 {
                faces.push([apex, first + i, first + (i + 1) % 16]);
            }
        }
        let base = pos.len() as u32;
        pos.extend([
            [0.5, 0.0025, 0.01],
            [0.49, 0.0025, -0.01],
            [0.51, 0.0025, -0.01],
        ]);
        faces.push([base, base + 1, base + 2]);
        let raw = RawMesh::from_arrays(pos.into_iter().map(rot).collect(), faces);
        assert_eq!(improper_pairs_by_brute_force(&raw), 1, "axis {axis}");
        let v = validate(&raw);
        let c = check(&v.report, "D3.1.3(ii)(triangles)");
        assert_eq!(c.offenders, 1, "axis {axis}: {:?}", c.witnesses);
    }
}
