//! Write then read: bit-identical positions and identical faces in every format.

use std::path::PathBuf;

use pseudomanifold::mesh::io::{read_mesh, write_mesh, write_mesh_to, ReadOptions};
use pseudomanifold::mesh::{MeshError, MeshFormat};
use rand::{Rng, SeedableRng};

const FORMATS: [(MeshFormat, &str); 5] = [
    (MeshFormat::Off, "off"),
    (MeshFormat::Obj, "obj"),
    (MeshFormat::PlyAscii, "ply"),
    (MeshFormat::PlyBinaryLittleEndian, "ply"),
    (MeshFormat::PlyBinaryBigEndian, "ply"),
];

fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ppm-io-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Awkward doubles: subnormals, extremes, negative zero, values with 17 significant digits.
fn awkward_positions() -> Vec<[f64; 3]> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let mut v = vec![
        [0.1, 0.2, 0.30000000000000004],
        [-0.0, f64::MIN_POSITIVE, 5e-324],
        [f64::MAX, f64::MIN, f64::EPSILON],
        [1e300, -1e-300, 123456789.12345679],
        [std::f64::consts::PI, std::f64::consts::E, 1.0 / 3.0],
    ];
    for _ in 0..200 {
        v.push([0; 3].map(|_| {
            f64::from_bits(rng.gen::<u64>() & !(0x7ff << 52) | (rng.gen_range(1u64..0x7fe) << 52))
        }));
    }
    v
}

fn faces_for(n: u32) -> Vec<[u32; 3]> {
    (0..n).map(|i| [i, (i + 1) % n, (i + 2) % n]).collect()
}

#[test]
fn roundtrip_every_format_bit_identical() {
    let dir = tmpdir("rt");
    let positions = awkward_positions();
    let faces = faces_for(positions.len() as u32);
    for (k, (format, ext)) in FORMATS.iter().enumerate() {
        let path = dir.join(format!("m{k}.{ext}"));
        write_mesh(&path, &positions, &faces, *format).unwrap();
        let m = read_mesh(&path, &ReadOptions::default()).unwrap();
        assert_eq!(m.format, Some(*format));
        assert_eq!(m.faces, faces, "{format:?}");
        assert_eq!(m.positions.len(), positions.len());
        for (a, b) in m.positions.iter().zip(&positions) {
            assert_eq!(
                a.map(f64::to_bits),
                b.map(f64::to_bits),
                "{format:?}: {a:?} vs {b:?}"
            );
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn roundtrip_non_finite_and_large_indices() {
    let positions = vec![
        [f64::NAN, f64::INFINITY, f64::NEG_INFINITY],
        [0.0, 1.0, 2.0],
        [3.0, 4.0, 5.0],
    ];
    // Out-of-range indices are written and read back unchanged (the validator reports them).
    let faces = vec![[0, 1, 2], [u32::MAX, 0, 1]];
    let dir = tmpdir("rt-nonfinite");
    for (k, (format, ext)) in FORMATS.iter().enumerate() {
        let path = dir.join(format!("n{k}.{ext}"));
        write_mesh(&path, &positions, &faces, *format).unwrap();
        let m = read_mesh(&path, &ReadOptions::default()).unwrap();
        assert_eq!(m.faces, faces, "{format:?}");
        assert!(m.positions[0][0].is_nan(), "{format:?}");
        assert_eq!(m.positions[0][1], f64::INFINITY, "{format:?}");
        assert_eq!(m.positions[0][2], f64::NEG_INFINITY, "{format:?}");
        assert_eq!(&m.positions[1..], &positions[1..], "{format:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn write_to_memory_is_the_file_content() {
    let positions = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.5, 0.0]];
    let faces = vec![[0, 1, 2]];
    let mut off = Vec::new();
    write_mesh_to(&mut off, &positions, &faces, MeshFormat::Off).unwrap();
    assert_eq!(
        String::from_utf8(off).unwrap(),
        "OFF\n3 1 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.5 0.0\n3 0 1 2\n"
    );
    let mut obj = Vec::new();
    write_mesh_to(&mut obj, &positions, &faces, MeshFormat::Obj).unwrap();
    assert_eq!(
        String::from_utf8(obj).unwrap(),
        "v 0.0 0.0 0.0\nv 1.0 0.0 0.0\nv 0.0 1.5 0.0\nf 1 2 3\n"
    );
    let mut ply = Vec::new();
    write_mesh_to(
        &mut ply,
        &positions,
        &faces,
        MeshFormat::PlyBinaryLittleEndian,
    )
    .unwrap();
    let header_end = b"end_header\n";
    let at = ply
        .windows(header_end.len())
        .position(|w| w == header_end)
        .unwrap();
    assert_eq!(ply.len() - at - header_end.len(), 3 * 3 * 8 + 1 + 3 * 4);
}

#[test]
fn write_failure_is_typed() {
    let dir = tmpdir("rt-fail");
    let path = dir.join("no-such-dir").join("m.off");
    let err = write_mesh(&path, &[[0.0; 3]], &[[0, 0, 0]], MeshFormat::Off).unwrap_err();
    assert!(matches!(err, MeshError::Write { .. }), "{err}");
    assert!(err.to_string().contains("no-such-dir"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
