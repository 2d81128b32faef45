//! Property tests: arbitrary input to every reader gives `Ok` or a typed error naming the
//! input, never a panic; `Ok` meshes satisfy the `RawMesh` invariants.

use proptest::prelude::*;
use pseudomanifold::mesh::io::{read_mesh_from_bytes, ReadOptions};
use pseudomanifold::mesh::MeshFormat;

const PLY_LE_HEAD: &[u8] = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\n\
property float x\nproperty float y\nproperty float z\nelement face 2\n\
property list uchar int vertex_indices\nend_header\n";

fn check(bytes: &[u8], format: MeshFormat, triangulate: bool) -> Result<(), TestCaseError> {
    let opts = ReadOptions {
        triangulate,
        ..Default::default()
    };
    match read_mesh_from_bytes(bytes, format, "fuzz", &opts) {
        Ok(m) => {
            prop_assert!(!m.faces.is_empty());
            prop_assert_eq!(m.faces.len(), m.face_origin.len());
            prop_assert_eq!(m.positions.len(), m.vertex_origin.len());
            prop_assert!(triangulate || m.triangulated_polygons == 0);
        }
        Err(e) => prop_assert!(e.to_string().starts_with("fuzz: "), "{}", e),
    }
    Ok(())
}

/// Text made of the tokens the text formats use, so the parsers get past their headers.
fn text_tokens() -> impl Strategy<Value = String> {
    let tok = prop::sample::select(vec![
        "OFF",
        "v",
        "f",
        "3",
        "4",
        "0",
        "1",
        "2",
        "-1",
        "-7",
        "1/2/3",
        "2//1",
        "nan",
        "inf",
        "1e308",
        "0.5",
        "#",
        "vt",
        "x",
        "\n",
        "\n",
        "\n",
        " ",
        "4294967296",
        "\u{e9}",
    ]);
    prop::collection::vec(tok, 0..80).prop_map(|v| v.join(" "))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_bytes(bytes in prop::collection::vec(any::<u8>(), 0..256), t in any::<bool>()) {
        for f in [MeshFormat::Off, MeshFormat::Obj, MeshFormat::PlyAscii] {
            check(&bytes, f, t)?;
        }
    }

    #[test]
    fn random_text(s in text_tokens(), t in any::<bool>()) {
        check(s.as_bytes(), MeshFormat::Off, t)?;
        check(format!("OFF\n3 2 0\n{s}").as_bytes(), MeshFormat::Off, t)?;
        check(s.as_bytes(), MeshFormat::Obj, t)?;
    }

    #[test]
    fn random_binary_ply_body(body in prop::collection::vec(any::<u8>(), 0..128), t in any::<bool>()) {
        let mut bytes = PLY_LE_HEAD.to_vec();
        bytes.extend_from_slice(&body);
        check(&bytes, MeshFormat::PlyBinaryLittleEndian, t)?;
    }
}
