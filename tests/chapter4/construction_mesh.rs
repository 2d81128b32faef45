//! Chapter 4 on meshes: the construction wired to validated surfaces, the abstract Def. 3.4.1
//! checkers run unchanged on it (Thm. 4.2.1), and the mesh-wide runner on generated, bundled
//! and corpus meshes.

use crate::common;

use pseudomanifold::conditions::chapter4::{run_chapter4, Ch4Options, Precision};
use pseudomanifold::construction::abstract_view::AbstractPpm;
use pseudomanifold::construction::{GluingError, PpmGluing, P2};
use pseudomanifold::gluing::sampled::{check_all, SampleConfig};
use pseudomanifold::mesh::generate::{bipyramid, icosahedron, octahedron, tetrahedron, torus};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{RawMesh, SimplicialSurface, VertexId};
use pseudomanifold::numeric::Trit;
use pseudomanifold::report::Verdict;

fn surface(m: &RawMesh) -> SimplicialSurface {
    validate(m).surface.expect("valid surface")
}

#[test]
fn d4_1_10_phi_on_a_mesh_round_trips_and_names_bad_input() {
    let k = surface(&icosahedron());
    let g = PpmGluing::new(&k);
    let (u, w) = k.edges().next().expect("an edge");
    // A point of Ω_uw: pull back the centre of the canonical lens.
    let e = g.edge_config(u, w).expect("config");
    use pseudomanifold::construction::{Paper, Ppm};
    let q = P2::new(0.5f64, 0.0);
    let p = Paper.r_uw_inv(&e, &Paper.g_v_inv(e.m_u, &q).expect("g_v⁻¹"));
    assert_eq!(g.in_omega_uw(u, w, &p).expect("pair"), Trit::True);
    let t = g.phi::<f64>(w, u, &p).expect("φ_wu(p)");
    assert_eq!(g.in_omega_uw(w, u, &t).expect("pair"), Trit::True);
    let back = g.phi::<f64>(u, w, &t).expect("φ_uw(φ_wu(p))");
    assert!(back.dist_f64(&p) < 1e-14);
    // Not an edge: Ω_uw = ∅, φ undefined, typed error.
    let far = k
        .vertices()
        .find(|&x| x != u && k.halfedge(u, x).is_none())
        .expect("a non-neighbour");
    assert_eq!(g.in_omega_uw(u, far, &p).expect("pair"), Trit::False);
    assert!(matches!(
        g.phi::<f64>(far, u, &p),
        Err(GluingError::Map { .. })
    ));
    assert_eq!(
        g.degree(VertexId(999)),
        Err(GluingError::NoSuchVertex(VertexId(999)))
    );
}

#[test]
fn t4_2_1_abstract_checkers_hold_on_the_ppm_of_small_meshes() {
    let cfg = SampleConfig { seed: 7, n: 24 };
    for (name, m) in [
        ("tetrahedron", tetrahedron()),
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
    ] {
        let k = surface(&m);
        let view = AbstractPpm::new(PpmGluing::new(&k), k.vertices().collect());
        let rs = check_all(&view, &cfg);
        assert!(!rs.is_empty());
        for r in &rs {
            common::assert_holds_for(name, r);
        }
        // Every condition of Def. 3.4.1 held on the PPM of this mesh (SPEC `T4.2.1`).
        common::verdicts::record("T4.2.1", common::verdicts::Seen::Holds, rs.len() as u64);
    }
}

#[test]
fn t4_2_1_abstract_checkers_on_a_degree_12_star() {
    // The star of a degree-12 apex (gluing domains of 12 neighbours): the literal Def. 4.1.9
    // keeps every condition of Def. 3.4.1.
    let k = surface(&bipyramid(12));
    let view = AbstractPpm::star_of(PpmGluing::new(&k), VertexId(0));
    for r in check_all(&view, &SampleConfig { seed: 11, n: 16 }) {
        common::assert_holds(&r);
    }
}

#[test]
fn t4_2_1_abstract_checkers_catch_a_planted_transition_fault() {
    let k = surface(&octahedron());
    let (u, w) = k.edges().next().expect("edge");
    let g = PpmGluing::new(&k);
    let view = AbstractPpm::new(g, k.vertices().collect()).with_phi_override(Box::new(
        move |to, from, p| {
            if (to, from) == (w, u) {
                let r = g.phi::<f64>(to, from, &P2::new(p[0], p[1])).ok()?.to_f64();
                Some([r[0] + 1e-6, r[1]])
            } else {
                None
            }
        },
    ));
    let results = check_all(&view, &SampleConfig { seed: 3, n: 24 });
    let b3 = results.iter().find(|r| r.id == "D3.4.1(3b)").expect("3b");
    assert_eq!(b3.verdict(), Verdict::Fails);
    assert!(!b3.witnesses.is_empty());
    let c3 = results.iter().find(|r| r.id == "D3.4.1(3c)").expect("3c");
    assert_eq!(c3.verdict(), Verdict::Fails);
}

fn quick() -> Ch4Options {
    Ch4Options {
        samples: 6,
        max_edge_configs: Some(60),
        max_triangle_configs: Some(60),
        max_star_configs: Some(30),
        ..Ch4Options::default()
    }
}

/// The coverage a Chapter 4 run reports is K's own count: every oriented edge, triangle and
/// vertex, each covered once when no configuration is left out (`quick()`'s limits exceed the
/// octahedron's and the icosahedron's configuration counts).
#[test]
fn ch4_coverage_counts_every_oriented_edge_triangle_and_vertex() {
    for (name, raw, (v, e, t)) in [
        ("octahedron", octahedron(), (6, 12, 8)),
        ("icosahedron", icosahedron(), (12, 30, 20)),
    ] {
        let c = run_chapter4(&surface(&raw), &quick()).coverage;
        assert_eq!(
            (c.vertices, c.oriented_edges, c.triangles),
            (v, 2 * e, t),
            "{name}"
        );
        assert_eq!(c.edge_configs_checked, c.edge_configs, "{name}");
        assert_eq!(c.triangle_configs_checked, c.triangle_configs, "{name}");
        assert_eq!(c.star_configs_checked, c.star_configs, "{name}");
        assert_eq!(
            (c.vertices_covered, c.edges_covered, c.triangles_covered),
            (v, 2 * e, t),
            "{name}"
        );
    }
}

/// A certificate property names the Chapter 4 check it certifies by its ID and the suffix
/// `(cert)`; other names stand for themselves.
#[test]
fn ch4_cert_property_check_id_drops_only_the_cert_suffix() {
    use pseudomanifold::conditions::chapter4::cert_property_check_id;
    assert_eq!(cert_property_check_id("L4.2.1(cert)"), "L4.2.1");
    assert_eq!(cert_property_check_id("P4.2.3(cert)"), "P4.2.3");
    assert_eq!(cert_property_check_id("D4.1.9-lens"), "D4.1.9-lens");
}

#[test]
fn c4_1_6_gv_bijective_errata_depend_on_degree_on_meshes() {
    // Every vertex of the grid torus has degree 6: the statements that fail only for m ≠ 6
    // hold there, and the errata are not reported.
    let k = surface(&torus(6, 6));
    let r = run_chapter4(&k, &quick());
    assert!(
        r.unexpected_failures.is_empty(),
        "{:?}",
        r.unexpected_failures
    );
    for id in [
        "C4.1.6-gv-bijective",
        "C4.1.6-gv-smooth",
        "P4.1.1",
        "D4.1.9-lens",
    ] {
        let c = r.checks.iter().find(|c| c.id == id).expect(id);
        assert_eq!(c.verdict(), Verdict::Holds, "{id} on an all-degree-6 torus");
    }
    // A bipyramid over a 12-gon has two degree-12 apexes: the Sec. 6.1.3 lens test errata
    // appear, and nothing else fails unexpectedly.
    let k = surface(&bipyramid(12));
    let r = run_chapter4(&k, &quick());
    assert!(
        r.unexpected_failures.is_empty(),
        "{:?}",
        r.unexpected_failures
    );
    for id in [
        "D4.1.9-lens",
        "C5.4-at-most-two[sec6.1.3]",
        "C4.1.6-gv-bijective",
    ] {
        assert!(
            r.errata_confirmed.iter().any(|e| e == id),
            "{id} not confirmed"
        );
    }
    for id in [
        "C5.4-at-most-two",
        "C4.2-nonadjacent-disjoint",
        "L4.2.2",
        "L4.2.1",
        "P4.2.3",
    ] {
        let c = r.checks.iter().find(|c| c.id == id).expect(id);
        assert_eq!(c.verdict(), Verdict::Holds, "{id}");
        common::assert_holds_for("bipyramid over a 12-gon", c);
    }
    assert_eq!(r.coverage.vertices_covered, r.coverage.vertices);
}

#[test]
fn c5_4_at_most_two_holds_on_bundled_meshes_in_f64_and_mp() {
    for path in common::bundled_good() {
        let raw = read_mesh(&path, &ReadOptions::default()).expect("fixture readable");
        let k = surface(&raw);
        for precision in [Precision::F64, Precision::Mp(128)] {
            let opts = Ch4Options {
                precision,
                samples: 4,
                max_edge_configs: Some(6),
                max_triangle_configs: Some(6),
                max_star_configs: Some(4),
                ..Ch4Options::default()
            };
            let r = run_chapter4(&k, &opts);
            assert!(
                r.unexpected_failures.is_empty(),
                "{}: {:?}",
                path.display(),
                r.unexpected_failures
            );
            let c = r
                .checks
                .iter()
                .find(|c| c.id == "C5.4-at-most-two")
                .expect("C5.4");
            assert!(c.examined > 0);
            let l = r.checks.iter().find(|c| c.id == "L4.2.2").expect("L4.2.2");
            let tol = l.tolerance.expect("tolerance printed");
            match precision {
                Precision::F64 => assert!(tol > 1e-15 && tol < 1e-8, "{tol}"),
                Precision::Mp(_) => assert!(tol < 1e-30, "{tol}"),
            }
        }
    }
}

#[test]
fn l4_2_2_chapter4_on_every_good_corpus_mesh() {
    for m in common::corpus("l4_2_2_chapter4_on_every_good_corpus_mesh")
        .iter()
        .filter(|m| m.good)
    {
        let raw = read_mesh(&m.path, &ReadOptions::default()).expect("readable");
        let k = surface(&raw);
        let r = run_chapter4(&k, &quick());
        assert!(
            r.unexpected_failures.is_empty(),
            "{}: {:?}",
            m.file,
            r.unexpected_failures
        );
        eprintln!(
            "{}: {} errata confirmed, coverage {:?}",
            m.file,
            r.errata_confirmed.len(),
            r.coverage
        );
    }
}

/// A planted fault for openness: the gluing domains of vertex 0 collapsed onto the line y = 0
/// of its copy (a set with empty interior), sampler included.
struct Collapsed<'a>(AbstractPpm<'a>);

impl Collapsed<'_> {
    /// The horizontal line through the centre of Ω_i's copy.
    fn line(&self, i: u32) -> Option<f64> {
        self.0.copy_centre(i).map(|c| c[1])
    }
}

impl pseudomanifold::gluing::data::GluingData<2> for Collapsed<'_> {
    type S = f64;
    fn indices(&self) -> Vec<u32> {
        self.0.indices()
    }
    fn in_p_domain(&self, i: u32, p: &[f64; 2]) -> bool {
        self.0.in_p_domain(i, p)
    }
    fn in_gluing_domain(&self, i: u32, j: u32, p: &[f64; 2]) -> bool {
        self.0.in_gluing_domain(i, j, p)
            && (i == j || i != self.0.indices()[0] || Some(p[1]) == self.line(i))
    }
    fn phi(&self, j: u32, i: u32, p: &[f64; 2]) -> Option<[f64; 2]> {
        self.0.phi(j, i, p)
    }
    fn sample_p_domain(
        &self,
        i: u32,
        rng: &mut rand_chacha::ChaCha8Rng,
        n: usize,
    ) -> Vec<[f64; 2]> {
        self.0.sample_p_domain(i, rng, n)
    }
    fn sample_gluing_domain(
        &self,
        i: u32,
        j: u32,
        rng: &mut rand_chacha::ChaCha8Rng,
        n: usize,
    ) -> Vec<[f64; 2]> {
        let v = self.0.sample_gluing_domain(i, j, rng, n);
        if i == j || i != self.0.indices()[0] {
            return v;
        }
        let y = self.line(i).unwrap_or(0.0);
        v.into_iter()
            .map(|p| [p[0], y])
            .filter(|p| self.in_gluing_domain(i, j, p))
            .collect()
    }
    fn gluing_boundary_points(
        &self,
        i: u32,
        j: u32,
        rng: &mut rand_chacha::ChaCha8Rng,
        n: usize,
    ) -> Vec<[f64; 2]> {
        self.0.gluing_boundary_points(i, j, rng, n)
    }
}

#[test]
fn p4_2_2_gluing_domains_are_open_and_a_collapsed_domain_is_caught() {
    use pseudomanifold::gluing::sampled::check_2;
    let k = surface(&bipyramid(12));
    let cfg = SampleConfig { seed: 5, n: 32 };
    let r = check_2(&AbstractPpm::star_of(PpmGluing::new(&k), VertexId(0)), &cfg);
    assert_eq!(r.verdict(), Verdict::Holds, "{:?}", r.witnesses.first());
    assert!(r.examined > 100);
    crate::common::verdicts::record("P4.2.2", crate::common::verdicts::Seen::Holds, r.examined);
    let bad = Collapsed(AbstractPpm::star_of(PpmGluing::new(&k), VertexId(0)));
    let r = check_2(&bad, &cfg);
    assert_eq!(r.verdict(), Verdict::Fails);
    assert!(r.witnesses.iter().any(|w| w.text.contains("not open")));
}

#[test]
fn d4_1_1_p_domain_is_the_open_disk_of_radius_cos_pi_over_m() {
    let k = surface(&bipyramid(7));
    let g = PpmGluing::new(&k);
    for v in k.vertices() {
        let m = k.degree(v);
        let r = (std::f64::consts::PI / m as f64).cos();
        let inside = P2::new(r * (1.0 - 1e-12), 0.0);
        let on = P2::new(0.0, r);
        let outside = P2::new(r * (1.0 + 1e-12), 0.0);
        assert_eq!(g.in_omega(v, &inside).expect("vertex"), Trit::True);
        assert_eq!(g.in_omega(v, &outside).expect("vertex"), Trit::False);
        assert_ne!(
            g.in_omega(v, &on).expect("vertex"),
            Trit::True,
            "open: boundary excluded"
        );
    }
}

#[test]
fn d4_1_2_omega_v_is_inscribed_in_the_p_polygon() {
    // Def. 4.1.2: v'_i = (cos 2πi/m, sin 2πi/m); the inscribed circle of P_v has radius
    // cos(π/m) = the radius of Ω_v (Def. 4.1.1), touching each side at its midpoint.
    for m in 3..=20u32 {
        let v = |i: u32| {
            let a = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(m);
            [a.cos(), a.sin()]
        };
        for i in 0..m {
            let (a, b) = (v(i), v((i + 1) % m));
            let mid = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
            let d = (mid[0] * mid[0] + mid[1] * mid[1]).sqrt();
            assert!((d - (std::f64::consts::PI / f64::from(m)).cos()).abs() < 1e-15);
        }
    }
}

#[test]
fn d4_1_6_g_v_maps_sector_a_onto_the_canonical_sector_b() {
    // Def. 4.1.6 and Fig. 4.2: the corner of sector A (angle 2π/m, radius cos π/m) goes to the
    // corner of B (angle π/3, radius cos π/6).
    use pseudomanifold::construction::maps::g_v;
    for m in 3..=20u32 {
        let a = 2.0 * std::f64::consts::PI / f64::from(m);
        let r = (std::f64::consts::PI / f64::from(m)).cos();
        let q = g_v::<f64>(m, &P2::new(r * a.cos(), r * a.sin())).expect("g_v");
        let c6 = (std::f64::consts::PI / 6.0).cos();
        let t = std::f64::consts::PI / 3.0;
        assert!(
            q.dist_f64(&P2::new(c6 * t.cos(), c6 * t.sin())) < 1e-14,
            "m = {m}"
        );
    }
}

#[test]
fn c4_2_nonadjacent_disjoint_on_mesh_stars_including_non_edge_triples() {
    // u, w both neighbours of x with [u, w] not an edge (label difference ≥ 2): Ω_xu ∩ Ω_xw = ∅.
    let k = surface(&bipyramid(9));
    let r = run_chapter4(&k, &quick());
    let c = r
        .checks
        .iter()
        .find(|c| c.id == "C4.2-nonadjacent-disjoint")
        .expect("check");
    assert_eq!(c.verdict(), Verdict::Holds);
    common::assert_holds_for("bipyramid over a 9-gon", c);
    // The apex (degree 9) has non-adjacent neighbour pairs that are not edges of K.
    let x = VertexId(0);
    let (a, b) = (
        k.link_vertex(x, 0).expect("n0"),
        k.link_vertex(x, 3).expect("n3"),
    );
    assert!(
        k.halfedge(a, b).is_none(),
        "labels 0 and 3 are not adjacent"
    );
}

/// Minimal well-formedness check of an SVG document: one root `svg` element, every element
/// closed, attribute values quoted, every coordinate a finite number.
fn svg_well_formed(s: &str) -> Result<(), String> {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = s;
    let mut roots = 0;
    while let Some(i) = rest.find('<') {
        let j = rest[i..].find('>').ok_or("unterminated tag")? + i;
        let tag = &rest[i + 1..j];
        if let Some(name) = tag.strip_prefix('/') {
            let open = stack.pop().ok_or("closing tag without opening")?;
            if open != name.trim() {
                return Err(format!("</{name}> closes <{open}>"));
            }
        } else if !tag.ends_with('/') {
            let name = tag
                .split_whitespace()
                .next()
                .ok_or("empty tag")?
                .to_string();
            if stack.is_empty() {
                roots += 1;
            }
            stack.push(name);
        }
        if tag.matches('"').count() % 2 != 0 {
            return Err(format!("unbalanced quotes in <{tag}>"));
        }
        rest = &rest[j + 1..];
    }
    if !stack.is_empty() || roots != 1 {
        return Err(format!("unclosed {stack:?} or {roots} roots"));
    }
    if s.contains("NaN") || s.contains("inf") {
        return Err("non-finite coordinate".into());
    }
    Ok(())
}

#[test]
fn d4_1_9_figure_renders_valid_svg() {
    use pseudomanifold::construction::figure::render_svg;
    for (mu, mw) in [(5, 7), (3, 12), (6, 6)] {
        let svg = render_svg(mu, mw).expect("valid degrees");
        svg_well_formed(&svg).unwrap_or_else(|e| panic!("({mu},{mw}): {e}"));
        assert!(svg.starts_with("<svg"));
        // m_u gluing domains in u's copy plus Ω_wu, and grid lines in both panels.
        assert!(svg.matches("<polygon").count() > 2 + mu as usize);
        assert!(svg.matches("<polyline").count() > 2 * (mu + mw) as usize);
    }
    assert!(render_svg(2, 5).is_err(), "degree 2 is refused");
    assert!(
        svg_well_formed("<svg><g></svg>").is_err(),
        "the checker can fail"
    );
    // The CLI writes it.
    let out = std::env::temp_dir().join(format!("ppm-fig-{}.svg", std::process::id()));
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["figure", "--degrees", "4,9", "-o"])
        .arg(&out)
        .status()
        .expect("run");
    assert!(st.success());
    let svg = std::fs::read_to_string(&out).expect("written");
    svg_well_formed(&svg).expect("well formed");
    let _ = std::fs::remove_file(out);
}

#[test]
fn c4_1_9_nonempty_iff_edge_on_the_icosahedron() {
    // Ω_uw ≠ ∅ ⇔ u = w or [u, w] is an edge: K of Def. 4.1.10 as found by the samplers of
    // the abstract view equals the diagonal plus the oriented edges of K.
    use pseudomanifold::gluing::sampled::sampled_k;
    let k = surface(&icosahedron());
    let view = AbstractPpm::new(PpmGluing::new(&k), k.vertices().collect());
    let mut found = sampled_k(&view, &SampleConfig { seed: 1, n: 8 });
    found.sort_unstable();
    let mut want: Vec<(u32, u32)> = k.vertices().map(|v| (v.0, v.0)).collect();
    for (a, b) in k.edges() {
        want.push((a.0, b.0));
        want.push((b.0, a.0));
    }
    want.sort_unstable();
    assert_eq!(found, want);
    crate::common::verdicts::record(
        "C4.1.9-nonempty-iff-edge",
        crate::common::verdicts::Seen::Holds,
        want.len() as u64,
    );
}

#[test]
fn d3_4_1_3b_transition_perturbed_by_1e_9_is_caught_on_a_mesh() {
    let k = surface(&icosahedron());
    let (u, w) = k.edges().nth(3).expect("edge");
    let g = PpmGluing::new(&k);
    let view = AbstractPpm::new(g, k.vertices().collect()).with_phi_override(Box::new(
        move |to, from, p| {
            if (to, from) == (w, u) {
                let r = g.phi::<f64>(to, from, &P2::new(p[0], p[1])).ok()?.to_f64();
                Some([r[0], r[1] + 1e-9])
            } else {
                None
            }
        },
    ));
    let r = pseudomanifold::gluing::sampled::check_3b(&view, &SampleConfig { seed: 2, n: 16 });
    assert_eq!(r.verdict(), Verdict::Fails);
    let t = r.tolerance.expect("tolerance printed");
    assert!(t < 1e-12, "tolerance {t} must be far below the 1e-9 fault");
}

/// SPEC API-ids (crate doc, *Ids*): a foreign id meets a typed error at every border query, the
/// counting queries answer the empty star, and nothing panics on the way.
#[test]
fn api_ids_foreign_ids_get_typed_errors_and_counting_queries_are_total() {
    use pseudomanifold::mesh::FaceId;
    use pseudomanifold::surface::sigma_v::{CornerId, SigmaV};
    use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, SurfaceError};
    let k = surface(&icosahedron());
    let foreign = [VertexId(12), VertexId(u32::MAX)];
    for v in foreign {
        assert!(!k.contains(v));
        assert_eq!(k.degree(v), 0);
        assert!(k.outgoing(v).is_empty() && k.faces_around(v).is_empty());
        assert_eq!(k.halfedge(v, VertexId(0)), None);
        assert_eq!(k.link_vertex(v, 0), None);
        assert!(
            matches!(PpmGluing::new(&k).degree(v), Err(GluingError::NoSuchVertex(w)) if w == v)
        );
    }
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let c = pps.consts_f64();
    let p = P2::new(0.0, 0.0);
    for v in foreign {
        assert_eq!(pps.degree(v), 0);
        assert!(matches!(pps.theta(v, &p, c), Err(SurfaceError::NoSuchVertex(w)) if w == v));
        assert!(matches!(pps.gamma(v, &p, c), Err(SurfaceError::NoSuchVertex(w)) if w == v));
    }
    assert!(pps.face(FaceId(20)).is_err());
    assert!(pps.eval(FaceId(u32::MAX), &[1.0 / 3.0; 3], c).is_err());
    let sv = SigmaV::new(&k, 0.5).expect("σ,v gluing of the icosahedron");
    assert_eq!(sv.degree(VertexId(u32::MAX)), 0);
    assert!(sv.face_corners(FaceId(20)).is_err());
    assert!(sv.corner(CornerId(60)).is_err());
    // Two foreign vertices through every query above, and the four foreign faces/corners.
    common::verdicts::record("API-ids", common::verdicts::Seen::Holds, 6);
}
