//! Reading the fixtures in tests/data/: counts, exact values, origins, closedness.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use pseudomanifold::mesh::io::{read_mesh, read_mesh_from_bytes, ReadOptions};
use pseudomanifold::mesh::{MeshError, MeshFormat, RawMesh};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn read(name: &str) -> RawMesh {
    match read_mesh(&data(name), &ReadOptions::default()) {
        Ok(m) => m,
        Err(e) => panic!("{name}: {e}"),
    }
}

/// Euler characteristic, asserting every directed edge occurs once and its reverse once
/// (closed, consistently oriented).
fn closed_oriented_euler(m: &RawMesh) -> i64 {
    let mut directed: HashMap<(u32, u32), u32> = HashMap::new();
    for f in &m.faces {
        for k in 0..3 {
            *directed.entry((f[k], f[(k + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "directed edge {a}->{b} occurs {n} times");
        assert_eq!(directed.get(&(b, a)), Some(&1), "edge {a}->{b} has no twin");
    }
    m.positions.len() as i64 - (directed.len() / 2) as i64 + m.faces.len() as i64
}

#[test]
fn tetrahedron_off_exact() {
    let m = read("tetrahedron.off");
    assert_eq!(
        m.positions,
        vec![
            [1.0, 1.0, 1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, 1.0]
        ]
    );
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
    assert_eq!(m.vertex_origin, vec![4, 5, 6, 7]);
    assert_eq!(m.face_origin, vec![8, 9, 10, 11]);
    assert!(m.origin_is_line);
    assert_eq!(m.format, Some(MeshFormat::Off));
    assert_eq!(m.source.as_deref(), Some(data("tetrahedron.off").as_path()));
    assert_eq!(m.triangulated_polygons, 0);
    assert_eq!(closed_oriented_euler(&m), 2);
    assert_eq!(m.describe_face(1), "face 1 (line 9)");
}

#[test]
fn octahedron_obj_all_corner_forms() {
    let m = read("octahedron.obj");
    assert_eq!(m.positions.len(), 6);
    assert_eq!(m.faces.len(), 8);
    assert_eq!(m.format, Some(MeshFormat::Obj));
    // Line 17 is `f 1 3 5`; line 21 is `f -5 -2 -4` = vertices 2, 5, 3 (1-based).
    assert_eq!(m.faces[0], [0, 2, 4]);
    assert_eq!(m.face_origin[0], 17);
    assert_eq!(m.faces[4], [1, 4, 2]);
    assert_eq!(m.face_origin[4], 21);
    assert_eq!(m.vertex_origin, vec![4, 5, 6, 7, 8, 9]);
    assert_eq!(closed_oriented_euler(&m), 2);
}

fn icosahedron_checks(m: &RawMesh) {
    assert_eq!((m.positions.len(), m.faces.len()), (12, 20));
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let r = (1.0 + phi * phi).sqrt();
    for p in &m.positions {
        let n = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        assert!(
            (n - r).abs() < 1e-6,
            "vertex {p:?} not on the sphere of radius {r}"
        );
    }
    assert_eq!(closed_oriented_euler(m), 2);
}

#[test]
fn icosahedron_three_ply_encodings_agree() {
    let a = read("icosahedron_ascii.ply");
    let le = read("icosahedron_binary_le.ply");
    let be = read("icosahedron_binary_be.ply");
    for m in [&a, &le, &be] {
        icosahedron_checks(m);
    }
    assert_eq!(a.format, Some(MeshFormat::PlyAscii));
    assert_eq!(le.format, Some(MeshFormat::PlyBinaryLittleEndian));
    assert_eq!(be.format, Some(MeshFormat::PlyBinaryBigEndian));
    // ascii holds the f32 values in decimal, binary LE the f32 bits: identical f64s.
    assert_eq!(a.positions, le.positions);
    assert_eq!(a.faces, le.faces);
    assert_eq!(a.faces, be.faces);
    assert!(a.origin_is_line && !le.origin_is_line && !be.origin_is_line);
    assert_eq!(a.vertex_origin[0], 11);
    assert_eq!(a.face_origin[0], 23);
    assert_eq!(le.vertex_origin, (0..12).collect::<Vec<u64>>());
    assert_eq!(le.face_origin, (0..20).collect::<Vec<u64>>());
    // BE stores the exact doubles: within f32 rounding of the LE values.
    for (p, q) in be.positions.iter().zip(&le.positions) {
        for k in 0..3 {
            assert!((p[k] - q[k]).abs() < 1e-6);
        }
    }
}

#[test]
fn torus_4x4_exact_coordinates() {
    let m = read("torus_4x4.off");
    assert_eq!((m.positions.len(), m.faces.len()), (16, 32));
    assert_eq!(closed_oriented_euler(&m), 0);
    assert_eq!(m.positions[0], [3.0, 0.0, 0.0]);
    assert_eq!(m.positions[6], [0.0, 1.0, 0.0]);
}

#[test]
fn cube_quads_need_triangulate() {
    let err = read_mesh(&data("cube_quads.off"), &ReadOptions::default()).unwrap_err();
    assert!(
        matches!(err, MeshError::NotTriangle { sides: 4, .. }),
        "{err}"
    );
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let m = read_mesh(&data("cube_quads.off"), &opts).unwrap();
    assert_eq!(m.triangulated_polygons, 6);
    assert_eq!(m.faces.len(), 12);
    assert_eq!(&m.faces[..2], &[[0, 1, 3], [0, 3, 2]]);
    assert_eq!(&m.face_origin[..4], &[12, 12, 13, 13]);
    assert_eq!(closed_oriented_euler(&m), 2);
}

#[test]
fn triangulated_polygons_keep_file_order_between_triangles() {
    let off = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n3 0 1 4\n4 0 3 2 1\n3 1 2 4\n";
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let m = read_mesh_from_bytes(off.as_bytes(), MeshFormat::Off, "mem.off", &opts).unwrap();
    assert_eq!(m.faces, vec![[0, 1, 4], [0, 3, 2], [0, 2, 1], [1, 2, 4]]);
    assert_eq!(m.face_origin, vec![8, 9, 9, 10]);
    assert_eq!(m.triangulated_polygons, 1);
}

#[test]
fn triangulate_refuses_bad_polygons() {
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let cases = [
        // collinear corner
        ("4 0 1 2 3", "0 0 0\n1 0 0\n2 0 0\n1 1 0\n", "reflex or straight"),
        // self-overlapping pentagram (all turns the same sign, winds twice)
        (
            "5 0 2 4 1 3",
            "1 0 0\n0.309017 0.951057 0\n-0.809017 0.587785 0\n-0.809017 -0.587785 0\n0.309017 -0.951057 0\n",
            "winds more than once",
        ),
        // non-planar quad
        ("4 0 1 2 3", "0 0 0\n1 0 0\n1 1 0.5\n0 1 0\n", "not planar"),
        // repeated index
        ("4 0 1 0 2", "0 0 0\n1 0 0\n1 1 0\n", "repeated"),
        // out of range
        ("4 0 1 2 9", "0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "out of range"),
    ];
    for (face, verts, why) in cases {
        let nv = verts.lines().count();
        let off = format!("OFF\n{nv} 1 0\n{verts}{face}\n");
        let err =
            read_mesh_from_bytes(off.as_bytes(), MeshFormat::Off, "p.off", &opts).unwrap_err();
        let line = 3 + nv as u64;
        match &err {
            MeshError::CannotTriangulate { at, why: w, .. } => {
                assert_eq!(at.to_string(), format!("line {line}"));
                assert!(w.contains(why), "{face}: expected '{why}', got '{w}'");
            }
            _ => panic!("{face}: {err}"),
        }
    }
}

#[test]
fn binary_ply_triangulates_with_element_location() {
    let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\nelement face 1\nproperty list uchar ushort vertex_index\nend_header\n".to_vec();
    for p in [[0.0f64, 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]] {
        for c in p {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    b.push(4);
    for i in [0u16, 1, 2, 3] {
        b.extend_from_slice(&i.to_le_bytes());
    }
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let m = read_mesh_from_bytes(&b, MeshFormat::PlyAscii, "q.ply", &opts).unwrap();
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.face_origin, vec![0, 0]);
    assert_eq!(m.format, Some(MeshFormat::PlyBinaryLittleEndian));
    let err = read_mesh_from_bytes(&b, MeshFormat::PlyAscii, "q.ply", &ReadOptions::default())
        .unwrap_err();
    assert_eq!(err.to_string(), "q.ply: face 0: polygon with 4 sides; only triangles are accepted (use --triangulate to fan-split convex polygons)");
}

#[test]
fn off_header_variants() {
    let body = "3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2 255 0 0\n";
    for kw in ["OFF", "COFF", "NOFF", "CNOFF", "STCNOFF"] {
        let s = format!("{kw}\n{body}");
        let m = read_mesh_from_bytes(s.as_bytes(), MeshFormat::Off, "v.off", &Default::default())
            .unwrap_or_else(|e| panic!("{kw}: {e}"));
        assert_eq!(m.positions[1], [1.0, 0.0, 0.0]);
        assert_eq!(m.faces, vec![[0, 1, 2]]);
    }
    let inline = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    let m = read_mesh_from_bytes(
        inline.as_bytes(),
        MeshFormat::Off,
        "i.off",
        &Default::default(),
    )
    .unwrap();
    assert_eq!(m.face_origin, vec![5]);
    for (bad, msg) in [
        ("4OFF", "unsupported OFF variant"),
        ("OFF BINARY", "binary OFF"),
    ] {
        let s = format!("{bad}\n{body}");
        let err = read_mesh_from_bytes(s.as_bytes(), MeshFormat::Off, "b.off", &Default::default())
            .unwrap_err();
        assert!(
            matches!(err, MeshError::Parse { .. }) && err.to_string().contains(msg),
            "{err}"
        );
    }
}

#[test]
fn crlf_line_ends_and_comments() {
    let s = "# c\r\nOFF\r\n3 1 0 # counts\r\n0 0 0\r\n\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    let m =
        read_mesh_from_bytes(s.as_bytes(), MeshFormat::Off, "c.off", &Default::default()).unwrap();
    assert_eq!(m.vertex_origin, vec![4, 6, 7]);
    assert_eq!(m.face_origin, vec![8]);
}

#[test]
fn format_detection_by_magic_then_extension() {
    let ply = std::fs::read(data("icosahedron_binary_le.ply")).unwrap();
    // Magic wins over a misleading extension.
    let dir = std::env::temp_dir().join(format!("ppm-io-detect-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("really_a_ply.obj");
    std::fs::write(&p, &ply).unwrap();
    let m = read_mesh(&p, &Default::default()).unwrap();
    assert_eq!(m.format, Some(MeshFormat::PlyBinaryLittleEndian));
    let p = dir.join("OFF_without_ext");
    std::fs::copy(data("tetrahedron.off"), &p).unwrap();
    assert_eq!(read_mesh(&p, &Default::default()).unwrap().faces.len(), 4);
    let p = dir.join("upper.OBJ");
    std::fs::copy(data("octahedron.obj"), &p).unwrap();
    assert_eq!(
        read_mesh(&p, &Default::default()).unwrap().format,
        Some(MeshFormat::Obj)
    );
    std::fs::remove_dir_all(&dir).unwrap();
    let err = read_mesh(&data("does-not-exist.off"), &Default::default()).unwrap_err();
    assert!(matches!(err, MeshError::Io { .. }), "{err}");
}

#[test]
fn obj_polygon_before_its_vertices_is_triangulated_at_the_end() {
    let s = "f 1 2 3 4\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nfo -4 -2 -1\n";
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let m = read_mesh_from_bytes(s.as_bytes(), MeshFormat::Obj, "fwd.obj", &opts).unwrap();
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3], [0, 2, 3]]);
    assert_eq!(m.face_origin, vec![1, 1, 6]);
    assert_eq!(m.triangulated_polygons, 1);
}

#[test]
fn ply_ascii_blank_lines_in_the_body_are_skipped() {
    let header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    let tight = format!("{header}0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    let loose = format!("{header}\n0 0 0\n   \n1 0 0\n\n0 1 0\n\n3 0 1 2\n\n");
    let read = |s: &str| {
        read_mesh_from_bytes(
            s.as_bytes(),
            MeshFormat::PlyAscii,
            "t.ply",
            &ReadOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{e}"))
    };
    let (a, b) = (read(&tight), read(&loose));
    assert_eq!(a.positions, b.positions);
    assert_eq!(a.faces, b.faces);
    assert_eq!(b.faces, vec![[0, 1, 2]]);
    // The face's origin is the line it is on, blank lines counted.
    assert_eq!(b.face_origin, vec![17]);
}
