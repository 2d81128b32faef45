//! One test per file in tests/data/hostile/: the error variant, and that the message names
//! the file and the line or element. Every read is also timed against a generous 2 s budget
//! as a sanity guard against unbounded work.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use pseudomanifold::mesh::io::{read_mesh, read_mesh_from_bytes, Limits, ReadOptions};
use pseudomanifold::mesh::{Location, MeshError, MeshFormat, RawMesh};

fn hostile(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/hostile")
        .join(name)
}

fn read_with(name: &str, opts: &ReadOptions) -> Result<RawMesh, MeshError> {
    let t = Instant::now();
    let r = read_mesh(&hostile(name), opts);
    assert!(
        t.elapsed() < Duration::from_secs(2),
        "{name} took {:?}",
        t.elapsed()
    );
    r
}

fn read(name: &str) -> Result<RawMesh, MeshError> {
    read_with(name, &ReadOptions::default())
}

/// Reads `name`, expecting an error whose message names the file and contains `place`.
fn fails(name: &str, place: &str) -> MeshError {
    let err = match read(name) {
        Ok(m) => panic!("{name}: read {} faces, expected an error", m.faces.len()),
        Err(e) => e,
    };
    check_message(name, &err, place);
    err
}

fn check_message(name: &str, err: &MeshError, place: &str) {
    let msg = err.to_string();
    assert!(msg.contains(&hostile(name).display().to_string()), "{msg}");
    assert!(msg.contains(place), "expected '{place}' in: {msg}");
}

fn at(err: &MeshError) -> Option<&Location> {
    match err {
        MeshError::Parse { at, .. }
        | MeshError::Encoding { at, .. }
        | MeshError::Truncated { at, .. }
        | MeshError::TooLarge { at, .. }
        | MeshError::NotTriangle { at, .. }
        | MeshError::CannotTriangulate { at, .. }
        | MeshError::TooFewSides { at, .. } => Some(at),
        _ => None,
    }
}

#[test]
fn truncated_off() {
    let e = fails("truncated.off", "line 5: unexpected end of file");
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
    assert!(
        e.to_string().contains("after 2 of 4 declared vertices"),
        "{e}"
    );
}

#[test]
fn off_fewer_faces_than_declared() {
    let e = fails("off_fewer_faces.off", "line 10");
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
    assert!(e.to_string().contains("after 3 of 4 declared faces"), "{e}");
}

#[test]
fn off_extra_data_after_faces() {
    let e = fails("off_extra_data.off", "line 12");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("after the 4 declared faces"), "{e}");
}

#[test]
fn off_index_out_of_range_is_left_to_the_validator() {
    let m = read("off_index_out_of_range.off").unwrap();
    assert_eq!(m.positions.len(), 4);
    assert_eq!(m.faces.last(), Some(&[0, 1, 7]));
    assert_eq!(m.face_origin.last(), Some(&11));
}

#[test]
fn off_index_beyond_u32() {
    let e = fails("off_index_too_large.off", "line 11");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("4294967296 exceeds 2^32-1"), "{e}");
}

fn check_nan_inf(m: &RawMesh) {
    let p = &m.positions;
    assert!(p[0][0].is_nan() && p[0][1] == 0.0);
    assert_eq!(p[1][1], f64::INFINITY);
    assert_eq!(p[2][2], f64::NEG_INFINITY);
    assert!(p[3][0].is_nan() && p[3][2].is_nan());
    assert_eq!(p[3][1], f64::INFINITY);
    // Deterministic: every NaN is the canonical one (same bits, sign included).
    for v in [p[0][0], p[3][0], p[3][2]] {
        assert_eq!(v.to_bits(), f64::NAN.to_bits());
    }
    assert_eq!(m.faces.len(), 4);
}

#[test]
fn nan_inf_coordinates_are_accepted() {
    check_nan_inf(&read("nan_inf.off").unwrap());
    check_nan_inf(&read("nan_inf.obj").unwrap());
}

#[test]
fn huge_vertex_count_off() {
    let e = fails("huge_count.off", "line 2");
    assert!(
        matches!(
            e,
            MeshError::TooLarge {
                count: 1_000_000_000_000,
                what: "vertex",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn huge_vertex_count_ply_ascii() {
    let e = fails("huge_count_ascii.ply", "line 3");
    assert!(
        matches!(
            e,
            MeshError::TooLarge {
                count: 1_000_000_000_000,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn huge_vertex_count_ply_binary() {
    let e = fails("huge_count_binary.ply", "line 3");
    assert!(
        matches!(
            e,
            MeshError::TooLarge {
                count: 1_000_000_000_000,
                ..
            }
        ),
        "{e}"
    );
}

/// With the limits lifted, allocation is still capped by the file size: the reads end in
/// `Truncated` quickly instead of reserving 10^12 slots.
#[test]
fn huge_counts_without_limits_stay_bounded() {
    let opts = ReadOptions {
        triangulate: false,
        limits: Limits {
            max_vertices: u64::MAX,
            max_faces: u64::MAX,
            max_other_elements: u64::MAX,
        },
    };
    for (name, place) in [
        ("huge_count.off", "line 3"),
        ("huge_count_ascii.ply", "line 10"),
        ("huge_count_binary.ply", "vertex 1"),
    ] {
        let e = read_with(name, &opts).unwrap_err();
        assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
        check_message(name, &e, place);
    }
}

#[test]
fn non_utf8_obj() {
    let e = fails("non_utf8.obj", "line 3");
    assert!(
        matches!(
            e,
            MeshError::Encoding {
                at: Location::Line(3),
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn non_utf8_off() {
    let e = fails("non_utf8.off", "line 6");
    assert!(
        matches!(
            e,
            MeshError::Encoding {
                at: Location::Line(6),
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn empty_files() {
    for name in ["empty.off", "empty.obj", "empty.ply"] {
        let e = fails(name, "the file has no faces");
        assert!(matches!(e, MeshError::Empty { .. }), "{e}");
    }
}

#[test]
fn binary_ply_truncated_mid_face() {
    let e = fails("binary_truncated_mid_face.ply", "face 2");
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
    assert_eq!(
        at(&e),
        Some(&Location::Element {
            kind: "face",
            index: 2
        })
    );
}

#[test]
fn binary_ply_list_count_255_with_too_few_bytes() {
    let e = fails("list_count_255.ply", "face 3");
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
}

#[test]
fn binary_ply_list_count_4e9_is_bounded() {
    let e = fails("list_count_4e9.ply", "face 3");
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
}

#[test]
fn binary_ply_trailing_bytes() {
    let e = fails("binary_extra_bytes.ply", "2 bytes of unexpected data");
    let len = std::fs::metadata(hostile("binary_extra_bytes.ply"))
        .unwrap()
        .len();
    assert_eq!(at(&e), Some(&Location::Byte(len - 2)), "{e}");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
}

#[test]
fn ply_unknown_property_type() {
    let e = fails("unknown_property_type.ply", "line 5");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(
        e.to_string().contains("unknown property type 'float128'"),
        "{e}"
    );
}

#[test]
fn ply_negative_index() {
    let e = fails("ply_negative_index.ply", "line 13");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("negative vertex index -1"), "{e}");
}

#[test]
fn obj_index_zero() {
    let e = fails("obj_index_zero.obj", "line 5");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("vertex index 0"), "{e}");
}

#[test]
fn obj_too_negative_index() {
    let e = fails("obj_too_negative.obj", "line 5");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("relative vertex index -4"), "{e}");
}

#[test]
fn obj_non_integer_index() {
    let e = fails("obj_non_integer_index.obj", "line 4");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("'3.5'"), "{e}");
}

#[test]
fn quads_without_triangulate() {
    let e = fails("quads_no_triangulate.off", "line 13");
    assert!(matches!(e, MeshError::NotTriangle { sides: 4, .. }), "{e}");
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let m = read_with("quads_no_triangulate.off", &opts).unwrap();
    assert_eq!(m.faces.len(), 6);
    assert_eq!(m.triangulated_polygons, 1);
}

#[test]
fn nonconvex_pentagon_with_triangulate() {
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let e = read_with("nonconvex_pentagon.off", &opts).unwrap_err();
    check_message("nonconvex_pentagon.off", &e, "line 9");
    match &e {
        MeshError::CannotTriangulate { sides: 5, why, .. } => {
            assert!(why.contains("not convex: the turn at corner 3"), "{why}")
        }
        _ => panic!("{e}"),
    }
}

#[test]
fn face_with_two_vertices() {
    let e = fails("two_vertex_face.off", "line 7");
    assert!(matches!(e, MeshError::TooFewSides { sides: 2, .. }), "{e}");
}

#[test]
fn garbage_text_off() {
    let e = fails("garbage.off", "line 1");
    assert!(matches!(e, MeshError::Parse { .. }), "{e}");
    assert!(e.to_string().contains("expected an OFF header"), "{e}");
}

#[test]
fn garbage_bytes_unknown_format() {
    let e = fails("garbage.bin", "unknown mesh format");
    assert!(matches!(e, MeshError::UnknownFormat { .. }), "{e}");
    // The same bytes forced through each reader still give a typed, located error.
    let bytes = std::fs::read(hostile("garbage.bin")).unwrap();
    for f in [MeshFormat::Off, MeshFormat::Obj, MeshFormat::PlyAscii] {
        let e = read_mesh_from_bytes(&bytes, f, "garbage", &Default::default()).unwrap_err();
        assert!(at(&e).is_some(), "{f:?}: {e}");
        assert!(e.to_string().starts_with("garbage: "), "{e}");
    }
}

/// Every prefix of valid files in each format gives `Ok` or a typed error: never a panic.
/// Formats that declare their counts (OFF, PLY) only accept a prefix that still holds every
/// declared face (a cut inside the last text line can look complete); OBJ declares nothing, so
/// a prefix cut at a line end is a smaller valid file.
#[test]
fn every_prefix_of_valid_files_is_handled() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (name, f) in [
        ("tetrahedron.off", MeshFormat::Off),
        ("octahedron.obj", MeshFormat::Obj),
        ("icosahedron_ascii.ply", MeshFormat::PlyAscii),
        (
            "icosahedron_binary_le.ply",
            MeshFormat::PlyBinaryLittleEndian,
        ),
        ("icosahedron_binary_be.ply", MeshFormat::PlyBinaryBigEndian),
    ] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        let full = read_mesh_from_bytes(&bytes, f, name, &Default::default()).unwrap();
        for n in 0..bytes.len() {
            match read_mesh_from_bytes(&bytes[..n], f, name, &Default::default()) {
                Ok(m) if f == MeshFormat::Obj => {
                    assert!(m.faces.len() <= full.faces.len(), "{name}[..{n}]");
                }
                Ok(m) => {
                    assert!(
                        full.origin_is_line,
                        "{name}[..{n}]: truncated binary accepted"
                    );
                    assert_eq!(m.faces.len(), full.faces.len(), "{name}[..{n}]");
                }
                Err(e) => assert!(e.to_string().starts_with(name), "{e}"),
            }
        }
    }
}

/// Single-byte corruptions of valid files in each format: `Ok` or a typed error naming the
/// file, never a panic (a deterministic mini-fuzz; the fuzzers go further).
#[test]
fn single_byte_corruptions_are_handled() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut errors = 0;
    for (name, f) in [
        ("tetrahedron.off", MeshFormat::Off),
        ("octahedron.obj", MeshFormat::Obj),
        ("icosahedron_ascii.ply", MeshFormat::PlyAscii),
        (
            "icosahedron_binary_le.ply",
            MeshFormat::PlyBinaryLittleEndian,
        ),
        ("icosahedron_binary_be.ply", MeshFormat::PlyBinaryBigEndian),
    ] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        for i in 0..bytes.len() {
            for b in [0x00, 0xff, b'9', b'-', b'\n', b' ', b'#'] {
                let mut m = bytes.clone();
                m[i] = b;
                let opts = ReadOptions {
                    triangulate: i % 2 == 0,
                    ..Default::default()
                };
                if let Err(e) = read_mesh_from_bytes(&m, f, name, &opts) {
                    assert!(e.to_string().starts_with(name), "{e}");
                    errors += 1;
                }
            }
        }
    }
    assert!(errors > 1000, "only {errors} corruptions were detected");
}

#[test]
fn ascii_ply_values_must_fit_their_types() {
    let head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                property float z\nelement face 1\nproperty list uchar uchar vertex_indices\n\
                end_header\n0 0 0\n1 0 0\n0 1 0\n";
    for (face, msg) in [
        ("3 0 1 256", "vertex index 256 does not fit"),
        ("256 0 1 2", "list count 256 does not fit"),
        ("3 0 1 2 7", "more values than the declared properties"),
        ("3 0 1", "missing an item"),
    ] {
        let s = format!("{head}{face}\n");
        let e = read_mesh_from_bytes(
            s.as_bytes(),
            MeshFormat::PlyAscii,
            "t.ply",
            &Default::default(),
        )
        .unwrap_err();
        assert!(
            matches!(
                e,
                MeshError::Parse {
                    at: Location::Line(13),
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains(msg), "{face}: {e}");
    }
}

#[test]
fn utf8_bom_is_skipped() {
    let s = "\u{feff}OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    let m = read_mesh_from_bytes(
        s.as_bytes(),
        MeshFormat::Off,
        "bom.off",
        &Default::default(),
    )
    .unwrap();
    assert_eq!(m.faces, vec![[0, 1, 2]]);
}

/// A coordinate declared as a list is refused by name, at its header line (not read as an
/// unknown property and then missed).
#[test]
fn ply_coordinate_declared_as_a_list_is_refused() {
    let text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float x\n\
                property float y\nproperty float z\nelement face 1\n\
                property list uchar int vertex_indices\nend_header\n\
                1 0 0 0\n1 1 0 0\n1 0 1 0\n3 0 1 2\n";
    let e = read_mesh_from_bytes(
        text.as_bytes(),
        MeshFormat::PlyAscii,
        "x-list.ply",
        &Default::default(),
    )
    .unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("vertex property 'x' is a list"), "{msg}");
    assert!(msg.contains("line 4"), "{msg}");
}

/// A binary file that ends inside an element the reader skips says how many of its elements
/// were complete: 14 bytes of 4-byte elements are 3.
#[test]
fn binary_ply_truncated_in_a_skipped_element_names_the_last_complete_one() {
    let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n\
                  property float y\nproperty float z\nelement face 1\n\
                  property list uchar int vertex_indices\nelement extra 10\n\
                  property float a\nend_header\n"
        .to_vec();
    for v in [[0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        for c in v {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    b.push(3);
    for i in [0i32, 1, 2] {
        b.extend_from_slice(&i.to_le_bytes());
    }
    b.extend_from_slice(&[0u8; 14]);
    let e = read_mesh_from_bytes(
        &b,
        MeshFormat::PlyBinaryLittleEndian,
        "extra.ply",
        &Default::default(),
    )
    .unwrap_err();
    assert!(matches!(e, MeshError::Truncated { .. }), "{e}");
    assert!(e.to_string().contains("'extra' element 3 of 10"), "{e}");
}

/// A polygon is fan-split when every corner is at most the planarity tolerance (10⁻⁴ of the
/// box diagonal) off its mean plane, *at most* included: a saddle quad whose corners lie exactly
/// at the tolerance (h found by bisection on the reader's own f64 operations) is split, one
/// ulp further is refused as not planar.
#[test]
fn polygon_corners_exactly_at_the_planarity_tolerance_are_accepted() {
    let quad = |h: f64| {
        format!(
            "OFF\n4 1 0\n0 0 {h:?}\n1 0 {:?}\n1 1 {h:?}\n0 1 {:?}\n4 0 1 2 3\n",
            -h, -h
        )
    };
    let opts = ReadOptions {
        triangulate: true,
        ..Default::default()
    };
    let h: f64 = 0.000_141_421_359_065_736_72;
    let m = read_mesh_from_bytes(quad(h).as_bytes(), MeshFormat::Off, "tie.off", &opts)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((m.faces.len(), m.triangulated_polygons), (2, 1));
    let e = read_mesh_from_bytes(
        quad(f64::from_bits(h.to_bits() + 1)).as_bytes(),
        MeshFormat::Off,
        "tie.off",
        &opts,
    )
    .unwrap_err();
    assert!(e.to_string().contains("not planar"), "{e}");
}
