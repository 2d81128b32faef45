//! `ppm render` (Sec. 6.2, Figs. 6.4–6.7): the pictures are checked by numbers, not by eye.
//! Silhouette area against the projected convex hull (`R-silhouette`), the curvature code
//! against the unit sphere (`R-sphere-curvature`), curvature continuity of the PPS across edges
//! of K versus PN triangles (`C6.2-curvature-continuity`), byte-for-byte determinism
//! (`R-deterministic`) and a planted sign error in the normal (`R-normal-sign`).

use pseudomanifold::gluing::stereo::{phi_north_inv, phi_south_inv};
use pseudomanifold::mesh::generate::{icosahedron, torus};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface, VertexId};
use pseudomanifold::numeric::Scalar;
use pseudomanifold::render::camera::Camera;
use pseudomanifold::render::orientation::check_orientation;
use pseudomanifold::render::source::{mesh_scene, pps_scene, sprime_scene};
use pseudomanifold::render::{render_scene, ColourBy, RenderOptions, Scene, View};
use pseudomanifold::report::dev_max;
use pseudomanifold::surface::geometry::from_jet;
use pseudomanifold::surface::target::eval_cubic;
use pseudomanifold::surface::{Jet, PnTriangles, Pps, PpsOptions, SPrime};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn surface(raw: pseudomanifold::mesh::raw::RawMesh) -> SimplicialSurface {
    validate(&raw)
        .surface
        .expect("generated mesh is a simplicial surface")
}

/// Area of the convex hull of 2-D points (Andrew's monotone chain, shoelace formula).
fn hull_area(mut p: Vec<[f64; 2]>) -> f64 {
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut h: Vec<[f64; 2]> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let it: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in it {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    let n = h.len();
    (0..n)
        .map(|i| {
            let (a, b) = (h[i], h[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

fn plain(w: u32, h: u32, view: View) -> RenderOptions {
    RenderOptions {
        width: w,
        height: h,
        view,
        colour: ColourBy::None,
        ..RenderOptions::default()
    }
}

/// Relative difference between the covered pixels and the hull of the projected vertices,
/// computed from the geometry with the same camera but without the rasteriser.
fn silhouette_error(scene: &Scene, hull_of: &Scene, view: View) -> f64 {
    let (w, h) = (400, 300);
    let (_, rep) = render_scene(scene, &plain(w, h, view)).expect("render");
    let (lo, hi) = scene.bbox().expect("bbox");
    let cam = Camera::fit(lo, hi, view, w, h, 0.05);
    let area = hull_area(
        hull_of
            .positions
            .iter()
            .map(|&p| {
                let s = cam.project(p);
                [s[0], s[1]]
            })
            .collect(),
    );
    (rep.covered_pixels as f64 - area).abs() / area
}

#[test]
fn r_silhouette_convex_mesh_covers_its_projected_hull_within_1_percent() {
    let k = surface(icosahedron());
    let scene = mesh_scene(&k);
    let mut worst: f64 = 0.0;
    for (az, el) in [(0.0, 0.0), (30.0, 20.0), (75.0, -40.0), (200.0, 60.0)] {
        let e = silhouette_error(
            &scene,
            &scene,
            View {
                azimuth: az,
                elevation: el,
            },
        );
        println!("view ({az}, {el}): |pixels − hull| / hull = {e:.2e}");
        worst = dev_max(worst, e);
    }
    println!("R-silhouette: worst relative error {worst:.2e} over 4 views (bound 1e-2)");
    assert!(worst < 0.01, "silhouette off by {worst}");
    crate::common::verdicts::record("R-silhouette", crate::common::verdicts::Seen::Holds, 4);
}

#[test]
fn r_silhouette_planted_shrunken_geometry_is_caught() {
    // The hull of the true geometry against the picture of a copy shrunk by 2 %: the area
    // differs by ~4 %, and the check must say so (the camera is fitted to the true box).
    let k = surface(icosahedron());
    let truth = mesh_scene(&k);
    let mut shrunk = truth.clone();
    for p in &mut shrunk.positions {
        *p = p.map(|x| 0.98 * x);
    }
    // Keep the camera on the true box: add the true box's corners as a degenerate triangle.
    let (lo, hi) = truth.bbox().expect("bbox");
    let base = shrunk.positions.len() as u32;
    shrunk.positions.extend([lo, hi, lo]);
    shrunk.normals.extend([[0.0; 3]; 3]);
    shrunk.faces.push([base, base + 1, base + 2]);
    let e = silhouette_error(&shrunk, &truth, View::default());
    println!("planted 2% shrink: relative error {e:.3}");
    assert!(e > 0.01, "a 2 % shrink went unnoticed ({e})");
}

/// Worst |K − 1| and ||H| − 1| over seeded points of the disk of radius 2 for a chart.
fn sphere_deviation(theta: impl Fn(&[Jet<f64>]) -> Vec<Jet<f64>>, scale: f64) -> (f64, f64, f64) {
    let mut rng = ChaCha8Rng::seed_from_u64(19);
    let (mut dk, mut dh, mut sign) = (0.0f64, 0.0f64, 0.0);
    for _ in 0..500 {
        let (r, a): (f64, f64) = (
            2.0 * rng.gen::<f64>().sqrt(),
            rng.gen_range(0.0..std::f64::consts::TAU),
        );
        let (x, y) = Jet::<f64>::variables(r * a.cos(), r * a.sin());
        let v = theta(&[x, y]);
        let j: [Jet<f64>; 3] = std::array::from_fn(|d| v[d].scale(&scale));
        let g = from_jet(&j);
        dk = dev_max(dk, (g.gaussian - 1.0).abs());
        dh = dev_max(dh, (g.mean.abs() - 1.0).abs());
        sign = g.mean.signum();
        if !(g.gaussian.is_finite() && g.mean.is_finite()) {
            return (f64::NAN, f64::NAN, f64::NAN);
        }
    }
    (dk, dh, sign)
}

#[test]
fn r_sphere_curvature_stereographic_charts_give_k_1_and_h_1() {
    for (name, chart, expect_sign) in [
        (
            "φ_N⁻¹",
            phi_north_inv::<Jet<f64>> as fn(&[Jet<f64>]) -> Vec<Jet<f64>>,
            1.0,
        ),
        ("φ_S⁻¹", phi_south_inv::<Jet<f64>>, -1.0),
    ] {
        let (dk, dh, sign) = sphere_deviation(chart, 1.0);
        println!("{name}: 500 points (seed 19), worst |K − 1| = {dk:.2e}, ||H| − 1| = {dh:.2e}, sign of H {sign}");
        assert!(dk <= 1e-9 && dh <= 1e-9, "{name}: {dk} {dh}");
        // φ_N⁻¹'s chart orientation gives the inward normal (H = +1), φ_S⁻¹'s the outward one.
        assert_eq!(sign, expect_sign, "{name}");
    }
    crate::common::verdicts::record(
        "R-sphere-curvature",
        crate::common::verdicts::Seen::Holds,
        1000,
    );
}

#[test]
fn r_sphere_curvature_planted_radius_2_is_caught() {
    let (dk, dh, _) = sphere_deviation(phi_north_inv::<Jet<f64>>, 2.0);
    println!("radius 2: |K − 1| = {dk}, ||H| − 1| = {dh}");
    assert!(
        dk > 0.7 && dh > 0.4,
        "a sphere of radius 2 passed as the unit sphere"
    );
}

fn pps_of(k: &SimplicialSurface) -> (PnTriangles, Pps) {
    let pn = PnTriangles::new(k);
    let pps = Pps::build(k, &pn, PpsOptions::default());
    (pn, pps)
}

/// Barycentric coordinates w.r.t. the corners `c` of the point (1−t)a + tb moved by ε
/// towards the third corner.
fn edge_bary(c: [VertexId; 3], a: VertexId, b: VertexId, t: f64, eps: f64) -> [f64; 3] {
    c.map(|v| {
        if v == a {
            (1.0 - t) * (1.0 - eps)
        } else if v == b {
            t * (1.0 - eps)
        } else {
            eps
        }
    })
}

fn pn_gaussian(pn: &PnTriangles, c: [VertexId; 3], bary: [f64; 3]) -> f64 {
    let (x, y) = Jet::<f64>::variables(bary[1], bary[2]);
    let one = Jet::<f64>::constant(1.0);
    let g = from_jet(&eval_cubic(&pn.net(c), [one.sub(&x).sub(&y), x, y]));
    g.gaussian
}

/// Largest jump of K across an edge of K: sample points at ε from each side of every edge
/// (t = 1/4, 1/2, 3/4), evaluated through the two faces. Returns (PPS jump, PN jump).
fn jumps(k: &SimplicialSurface, pn: &PnTriangles, pps: &Pps, eps: f64) -> (f64, f64) {
    let cj = pps.consts(53);
    let (mut jp, mut jn) = (0.0f64, 0.0f64);
    for (a, b) in k.edges() {
        let f1 = k.face_of(k.halfedge(a, b).expect("edge"));
        let f2 = k.face_of(k.halfedge(b, a).expect("edge"));
        for t in [0.25, 0.5, 0.75] {
            let side = |f: FaceId| {
                let c = pps.face(f).expect("face");
                let kp = pps
                    .eval_geometry(f, edge_bary(c, a, b, t, eps), &cj)
                    .expect("eval")
                    .2
                    .gaussian;
                let kc = k.face(f);
                (kp, pn_gaussian(pn, kc, edge_bary(kc, a, b, t, eps)))
            };
            let ((p1, n1), (p2, n2)) = (side(f1), side(f2));
            jp = dev_max(jp, (p1 - p2).abs());
            jn = dev_max(jn, (n1 - n2).abs());
            assert!(
                jp.is_finite() && jn.is_finite(),
                "NaN curvature at edge {a}-{b}"
            );
        }
    }
    (jp, jn)
}

#[test]
fn c6_2_curvature_continuity_pps_continuous_across_edges_pn_not() {
    for (name, k) in [
        ("icosahedron", surface(icosahedron())),
        ("torus 8×6", surface(torus(8, 6))),
    ] {
        let (pn, pps) = pps_of(&k);
        let (p3, n3) = jumps(&k, &pn, &pps, 1e-3);
        let (p4, n4) = jumps(&k, &pn, &pps, 1e-4);
        let (p0, n0) = jumps(&k, &pn, &pps, 0.0);
        println!(
            "{name}: max |ΔK| across edges at ε = 1e-3, 1e-4, 0: PPS {p3:.2e}, {p4:.2e}, {p0:.2e}; PN {n3:.2e}, {n4:.2e}, {n0:.2e}"
        );
        // Continuous: the jump shrinks with ε (linearly: ×1/10; asked ≤ ×1/5) and vanishes on
        // the edge up to rounding; PN's does not shrink (≥ ×1/2) and stays O(1) on the edge.
        assert!(
            p4 <= p3 / 5.0,
            "{name}: PPS jump does not shrink: {p3} → {p4}"
        );
        // PN's jump is a property of the mesh: on the icosahedron every edge is a mirror
        // symmetry of the PN surface, so K agrees across it (measured 6e-16); the claim is
        // asserted where no such symmetry holds.
        if name != "icosahedron" {
            assert!(n4 >= n3 / 2.0, "{name}: PN jump shrinks: {n3} → {n4}");
            assert!(
                n0 > 1e3 * p0,
                "{name}: PN jump on the edge {n0} not ≫ PPS {p0}"
            );
        }
    }
    crate::common::verdicts::record(
        "C6.2-curvature-continuity",
        crate::common::verdicts::Seen::Holds,
        2,
    );
}

fn lit_luminance(scene: &Scene) -> (f64, usize) {
    let (img, rep) = render_scene(scene, &plain(200, 200, View::default())).expect("render");
    let mut sum = 0.0;
    let mut n = 0;
    for px in img.data.chunks(3) {
        if px != [255, 255, 255] {
            sum += f64::from(px[0]);
            n += 1;
        }
    }
    assert_eq!(n, rep.covered_pixels);
    (sum / n as f64, rep.orientation.disagreeing)
}

#[test]
fn r_normal_sign_planted_flip_darkens_the_shading_and_is_reported() {
    let k = surface(icosahedron());
    let (_, pps) = pps_of(&k);
    let scene = pps_scene(&pps, 2, true).expect("sample");
    let (good, bad_corners) = lit_luminance(&scene);
    let ok = check_orientation(&scene);
    assert_eq!(bad_corners, 0);
    assert!(!ok.flipped());
    assert!(
        ok.checked > 0 && ok.disagreeing == 0,
        "{} of {} corners disagree",
        ok.disagreeing,
        ok.checked
    );
    crate::common::verdicts::record(
        "R-normal-sign",
        crate::common::verdicts::Seen::Holds,
        ok.checked as u64,
    );
    let mut flipped = scene.clone();
    for n in &mut flipped.normals {
        *n = n.map(|x| -x);
    }
    let (dark, _) = lit_luminance(&flipped);
    let r = check_orientation(&flipped);
    println!("mean red level of the surface: {good:.1} (normals as computed), {dark:.1} (flipped); flipped: {} of {} corners disagree, worst {:?}", r.disagreeing, r.checked, r.worst);
    assert!(
        dark < 0.5 * good,
        "flipping the normals did not darken the picture"
    );
    assert!(r.flipped() && r.disagreeing == r.checked);
    let w = r.worst.expect("witness");
    assert!(w.cosine < -0.9, "witness {w:?}");
}

#[test]
fn r_deterministic_same_scene_same_png_bytes() {
    let k = surface(torus(10, 7));
    let (pn, pps) = pps_of(&k);
    for scene in [
        sprime_scene(&k, &SPrime::Pn(pn), 2),
        pps_scene(&pps, 2, true).expect("sample"),
    ] {
        let o = RenderOptions {
            width: 160,
            height: 120,
            ..RenderOptions::default()
        };
        let a = render_scene(&scene, &o)
            .expect("render")
            .0
            .to_png()
            .expect("png");
        let b = render_scene(&scene, &o)
            .expect("render")
            .0
            .to_png()
            .expect("png");
        assert_eq!(a, b);
        assert!(a.starts_with(b"\x89PNG\r\n\x1a\n"));
    }
    crate::common::verdicts::record("R-deterministic", crate::common::verdicts::Seen::Holds, 2);
}

#[test]
fn r_bad_scene_and_arguments_are_typed_errors() {
    use pseudomanifold::render::{ColourRange, RenderError};
    let mut s = mesh_scene(&surface(icosahedron()));
    assert!(matches!(
        render_scene(&s, &RenderOptions::default()),
        Err(RenderError::NoCurvature("gaussian"))
    ));
    s.faces.push([0, 1, 9999]);
    assert!(matches!(
        render_scene(&s, &plain(100, 100, View::default())),
        Err(RenderError::IndexOutOfRange { index: 9999, .. })
    ));
    assert!(ColourRange::parse("1,2").is_err());
    assert!(ColourRange::parse("-1,nan").is_err());
    assert!(ColourRange::parse("-1,2").is_ok());
    assert!(View::parse("10,95").is_err());
    assert!(render_scene(&Scene::default(), &plain(100, 100, View::default())).is_err());
}

#[test]
fn r_sampling_attributes_agree_whatever_is_computed() {
    use pseudomanifold::surface::output::{sample_surface_with, Attributes};
    let k = surface(icosahedron());
    let (_, pps) = pps_of(&k);
    let full = sample_surface_with(&pps, 2, Attributes::Curvature, None).expect("sample");
    let nrm = sample_surface_with(&pps, 2, Attributes::Normals, None).expect("sample");
    let pos = sample_surface_with(&pps, 2, Attributes::Positions, None).expect("sample");
    assert_eq!(full.faces, pos.faces);
    assert!(pos.normals.is_empty() && pos.gaussian.is_empty() && nrm.gaussian.is_empty());
    let d = |a: [f64; 3], b: [f64; 3]| (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, dev_max);
    let (mut dp, mut dn) = (0.0f64, 0.0f64);
    for i in 0..full.positions.len() {
        dp = dev_max(dp, d(full.positions[i], pos.positions[i]));
        dp = dev_max(dp, d(full.positions[i], nrm.positions[i]));
        dn = dev_max(dn, d(full.normals[i], nrm.normals[i]));
    }
    println!(
        "{} points: max position difference {dp:e}, normal difference {dn:e}",
        full.positions.len()
    );
    // Same operations on the value and first-order parts: equal up to a few ulps.
    assert!(dp <= 1e-13 && dn <= 1e-13, "{dp} {dn}");
}

/// S′ = the Loop limit surface (Sec. 6.2, Figs. 6.6–6.7) renders with Stam's exact
/// derivatives: on the icosahedron every face has three extraordinary corners (valence 5), so
/// every sample goes through the internal subdivision step, and the corners are the points
/// where the parametrization is singular. Every normal is a finite unit vector that agrees
/// with K's orientation, and every curvature is finite; the PPS panel from the same S′ too.
#[test]
fn r_loop_sprime_scene_has_finite_normals_and_curvatures() {
    let k = surface(icosahedron());
    let l = pseudomanifold::surface::loop_subdiv::LoopSurface::new(&k).expect("Loop S′");
    let sprime = SPrime::Loop(Box::new(l));
    let scene = sprime_scene(&k, &sprime, 3);
    let not_unit = scene
        .normals
        .iter()
        .filter(|n| {
            // NaN counts as "not unit".
            let d = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0).abs();
            d.is_nan() || d >= 1e-9
        })
        .count();
    assert_eq!(not_unit, 0, "normals that are not finite unit vectors");
    let g = scene.gaussian.as_ref().expect("curvature");
    let h = scene.mean.as_ref().expect("curvature");
    assert!(g.iter().chain(h.iter()).all(|x| x.is_finite()));
    let o = check_orientation(&scene);
    assert_eq!(o.disagreeing, 0, "{o:?}");
    let pps = Pps::build(&k, sprime.as_target(), PpsOptions::default());
    let p = pps_scene(&pps, 2, true).expect("sample");
    assert_eq!(check_orientation(&p).disagreeing, 0);
    let (img, rep) = render_scene(
        &scene,
        &RenderOptions {
            width: 160,
            height: 120,
            ..RenderOptions::default()
        },
    )
    .expect("render");
    assert!(rep.covered_pixels > 0 && img.width == 160);
    crate::common::verdicts::record("R-loop-sprime", crate::common::verdicts::Seen::Holds, 1);
}
