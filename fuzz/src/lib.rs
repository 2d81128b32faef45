//! Shared oracles of the fuzz targets. Every function panics (= a libFuzzer crash) when an
//! invariant of the library is violated; they never panic on merely invalid input.

use pseudomanifold::construction::checks::{run_edge_checks, run_triangle_checks};
use pseudomanifold::construction::{EdgeConfig, TriangleConfig};
use pseudomanifold::mesh::io::{read_mesh_from_bytes, write_mesh_to, ReadOptions};
use pseudomanifold::mesh::star::check_star_isomorphism;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{MeshFormat, RawMesh, SimplicialSurface, VertexId};
use pseudomanifold::report::Verdict;

/// Read `data` as `format` with and without `triangulate`; check the `RawMesh` invariants and
/// that writing the mesh and reading it back gives the same mesh (bit-identical positions).
pub fn read_and_roundtrip(data: &[u8], format: MeshFormat) -> Option<RawMesh> {
    let mut first = None;
    for triangulate in [false, true] {
        let opts = ReadOptions {
            triangulate,
            ..Default::default()
        };
        match read_mesh_from_bytes(data, format, "fuzz", &opts) {
            Ok(m) => {
                assert!(!m.faces.is_empty(), "Ok mesh without faces");
                assert_eq!(m.faces.len(), m.face_origin.len());
                assert_eq!(m.positions.len(), m.vertex_origin.len());
                assert!(triangulate || m.triangulated_polygons == 0);
                roundtrip(&m, format);
                if first.is_none() {
                    first = Some(m);
                }
            }
            Err(e) => {
                let s = e.to_string();
                assert!(
                    s.starts_with("fuzz: "),
                    "error does not name the input: {s}"
                );
            }
        }
    }
    first
}

fn same_bits(a: &[[f64; 3]], b: &[[f64; 3]]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(p, q)| {
            p.iter()
                .zip(q)
                .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
        })
}

/// Write in the format family of `format` and read back.
pub fn roundtrip(m: &RawMesh, format: MeshFormat) {
    let outs: &[MeshFormat] = match format {
        MeshFormat::Off => &[MeshFormat::Off],
        MeshFormat::Obj => &[MeshFormat::Obj],
        _ => &[MeshFormat::PlyAscii, MeshFormat::PlyBinaryLittleEndian],
    };
    for &out in outs {
        let mut buf = Vec::new();
        if write_mesh_to(&mut buf, &m.positions, &m.faces, out).is_err() {
            continue; // e.g. an index the format cannot encode
        }
        match read_mesh_from_bytes(&buf, out, "fuzz", &ReadOptions::default()) {
            Ok(back) => {
                assert_eq!(back.faces, m.faces, "faces changed in a {out:?} round trip");
                assert!(
                    same_bits(&back.positions, &m.positions),
                    "positions changed in a {out:?} round trip"
                );
            }
            Err(e) => panic!("cannot read back what was written as {out:?}: {e}"),
        }
    }
}

/// Validate and check the validator's own invariants: the report agrees with itself, the
/// verdict does not depend on face order or on reversing every face, and a surface's DCEL
/// satisfies the Sec. 6.1.1–6.1.2 invariants. Returns the surface when there is one.
pub fn validate_checked(raw: &RawMesh) -> Option<SimplicialSurface> {
    let v = validate(raw);
    let r = &v.report;
    assert_eq!(r.is_simplicial_surface, v.surface.is_some());
    if r.is_simplicial_surface {
        assert!(
            r.error_classes.is_empty(),
            "surface with classes {:?}",
            r.error_classes
        );
    } else {
        assert!(
            r.checks.iter().any(|c| c.failed()),
            "rejected without a failing check"
        );
    }
    // Metamorphic: K is a set of triangles; order and orientation of the list do not matter.
    // Only on small lists: the exact self-intersection test is quadratic in the number of
    // crossing pairs, and three validations of a 500-face tangle exceed the 1 s hang limit.
    if raw.faces.len() <= 128 {
        let mut rev = raw.clone();
        rev.faces.reverse();
        rev.face_origin.reverse();
        let vr = validate(&rev);
        assert_eq!(
            vr.report.error_classes, r.error_classes,
            "face order changed classes"
        );
        let mut flipped = raw.clone();
        for t in &mut flipped.faces {
            t.swap(1, 2);
        }
        let vf = validate(&flipped);
        assert_eq!(
            vf.report.error_classes, r.error_classes,
            "reorientation changed classes"
        );
    }
    let s = v.surface?;
    check_surface(&s);
    Some(s)
}

/// DCEL and labelling invariants of a validated surface (Secs. 6.1.1–6.1.2, Def. 4.1.4).
pub fn check_surface(s: &SimplicialSurface) {
    assert_eq!(s.num_halfedges(), 3 * s.num_faces());
    let mut deg_sum = 0u64;
    for v in s.vertices() {
        let m = s.degree(v);
        assert!(m >= 3, "degree {m} < 3 at {v:?}");
        deg_sum += m as u64;
        for (i, &h) in s.outgoing(v).iter().enumerate() {
            assert_eq!(s.origin(h), v);
            assert_eq!(s.label(h), i as u32);
            assert_eq!(s.twin(s.twin(h)), h);
            assert_eq!(s.dest(s.twin(h)), v);
            let rot = s.twin(s.prev(h));
            assert_eq!(
                s.label(rot),
                (i as u32 + 1) % m,
                "labels not counterclockwise"
            );
        }
    }
    assert_eq!(deg_sum, 3 * s.num_faces() as u64);
    let iso = check_star_isomorphism(s, |v, x| s.s(v, x));
    assert!(!iso.failed(), "D4.1.4 fails: {:?}", iso.witnesses.first());
}

/// IDs of Chapter 4 statements that hold on every configuration (SPEC.md).
pub const ALWAYS_HOLD: &[&str] = &[
    "D4.1.5",
    "C4.1.7-h-identity",
    "C4.1.8-lens-in-Q",
    "P4.1.2",
    "P4.1.3",
    "D4.1.10",
    "P4.2.1",
    "P4.2.3",
    "L4.2.3",
    "L4.2.4",
    "L4.2.1",
    "L4.2.2",
    "L4.2.1-proof-equality",
    "P4.2.4(iii,iv)",
];

/// Edge configuration of the oriented edge u → w of a surface.
pub fn edge_config(s: &SimplicialSurface, u: VertexId, w: VertexId) -> Option<EdgeConfig> {
    EdgeConfig::new(s.degree(u), s.s(u, w)?, s.degree(w), s.s(w, u)?).ok()
}

/// Triangle configuration of face f (corners in the surface's orientation).
pub fn triangle_config(
    s: &SimplicialSurface,
    f: pseudomanifold::mesh::FaceId,
) -> Option<TriangleConfig> {
    let [u, w, x] = s.face(f);
    TriangleConfig::ccw(
        s.degree(u),
        s.degree(w),
        s.degree(x),
        s.s(u, w)?,
        s.s(w, x)?,
        s.s(x, u)?,
    )
    .ok()
}

/// Run the Chapter 4 edge and triangle checks at low density on a few edges and faces of `s`
/// (chosen by `pick`) and assert every statement of [`ALWAYS_HOLD`] holds.
pub fn chapter4_low_density(s: &SimplicialSurface, pick: u64, edges: usize, n: usize) {
    let all: Vec<_> = s.edges().collect();
    if all.is_empty() {
        return;
    }
    for k in 0..edges {
        let (u, w) = all[(pick as usize).wrapping_add(k * 7919) % all.len()];
        // Chapter 4 needs m ≥ 3 (guaranteed by validation); very high degrees only cost time.
        if s.degree(u) > 64 || s.degree(w) > 64 {
            continue;
        }
        let cfg = edge_config(s, u, w).expect("validated surface gives a valid edge config");
        for r in run_edge_checks::<f64>(&cfg, pick ^ k as u64, n, 53) {
            assert_verdict(&r.id, &r.verdict(), &format!("{cfg:?}"), &r);
        }
    }
    let nf = s.num_faces();
    let f = pseudomanifold::mesh::FaceId((pick as usize % nf) as u32);
    if let Some(t) = triangle_config(s, f) {
        if t.m_u.max(t.m_w).max(t.m_x) <= 64 {
            for r in run_triangle_checks::<f64>(&t, pick, n, 53) {
                assert_verdict(&r.id, &r.verdict(), &format!("{t:?}"), &r);
            }
        }
    } else {
        panic!("validated surface gives an invalid triangle config for {f:?}");
    }
}

/// Statements asserting that some sample exists (non-emptiness): at the fuzzers' density of
/// three samples they may legitimately find none, so they are only asserted by the property
/// tests at full density.
pub const EXISTENCE: &[&str] = &["P4.1.3", "P4.2.1"];

fn assert_verdict(id: &str, v: &Verdict, cfg: &str, r: &pseudomanifold::report::CheckResult) {
    // Low density: a statement that holds must not *fail*; `Skipped` (no sample fell in the
    // statement's domain) is fine.
    if ALWAYS_HOLD.contains(&id) && !EXISTENCE.contains(&id) {
        assert!(
            !v.is_failure(),
            "{id} should hold on {cfg}: {:?} {:?}",
            v,
            r.witnesses.first()
        );
    }
}

/// The bundled icosahedron the oracle target's session is opened on.
static ICOSAHEDRON: &[u8] = include_bytes!("../../tests/data/icosahedron_binary_le.ply");

/// Oracle protocol (issue 9): at most 16 lines of `data` go through one session on the
/// icosahedron. Every line must get exactly one response that serializes to one line of JSON
/// with `ok`, echoing a well-formed request's `id`; an error response must carry a message.
/// Not sent: `load` (it reads the file system) and `set_precision` above 1024 bits (the cost
/// of MPFR constants grows with the precision; the library bounds it by `MAX_BITS`).
pub fn oracle_lines(data: &[u8]) {
    use pseudomanifold::oracle::protocol::Session;
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(raw) = read_mesh_from_bytes(
        ICOSAHEDRON,
        MeshFormat::PlyBinaryLittleEndian,
        "icosahedron",
        &ReadOptions::default(),
    ) else {
        panic!("bundled icosahedron does not read");
    };
    let Some(k) = validate(&raw).surface else {
        panic!("bundled icosahedron is not a simplicial surface");
    };
    let mut session = Session::with_surface(k);
    for line in text.lines().take(16) {
        if let Ok(v) = serde_json::from_str::<serde_json::Value>(line) {
            let op = v.get("op").and_then(|o| o.as_str());
            let bits = v.get("bits").and_then(|b| b.as_u64()).unwrap_or(0);
            if op == Some("load") || (op == Some("set_precision") && bits > 1024) {
                continue;
            }
        }
        let r = session.handle_line(line);
        let out = serde_json::to_string(&r).unwrap_or_else(|e| panic!("unserializable: {e}"));
        assert!(!out.contains('\n'), "response spans lines: {out}");
        let back: serde_json::Value =
            serde_json::from_str(&out).unwrap_or_else(|e| panic!("not JSON: {e}: {out}"));
        assert!(back.get("ok").is_some_and(|o| o.is_boolean()), "{out}");
        if !r.ok {
            assert!(
                back.get("error").is_some_and(|m| !m.is_null()),
                "error without message: {out}"
            );
        }
    }
}

/// Gluing files (`ppm gluing`, Sec. 3.4 in 1-D): any text of at most 4 KiB parses to gluing
/// data or to an error naming the file; parsed data goes through every exact check of Def.
/// 3.4.1 and the relation checks, as the command runs them; a failing check has a witness.
pub fn gluing_file(data: &[u8]) {
    use pseudomanifold::gluing::exact1d::decide;
    use pseudomanifold::gluing::file::parse_gluing_str;
    use pseudomanifold::gluing::relation;
    if data.len() > 4096 {
        return;
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = std::path::Path::new("fuzz.toml");
    match parse_gluing_str(text, path) {
        Err(e) => {
            let s = e.to_string();
            assert!(s.starts_with("fuzz.toml: "), "error does not name the file: {s}");
        }
        Ok(f) => {
            let mut results = decide::check_all(&f.data);
            let sample = relation::GridSample::new(&f.data, 24);
            results.push(relation::check_equivalence(&f.data, &sample));
            results.push(relation::check_claim(&f.data, &sample));
            for r in &results {
                assert!(
                    !r.failed() || (r.offenders > 0 && !r.witnesses.is_empty()),
                    "{}: fails without a witness",
                    r.id
                );
            }
        }
    }
}
