//! Binary PLY bodies (Sec. 3.1 input). The first byte picks one of a few well-formed binary
//! headers (little/big endian, float/double/int coordinates, uchar/int/uint list counts, an
//! extra element, an extra property); the rest of the input is the body, so the fuzzer spends
//! its time in the binary element decoder rather than in the header parser. Selector 0 feeds
//! the input unchanged (whole binary files from the seed corpus).
#![no_main]
use libfuzzer_sys::fuzz_target;
use pseudomanifold::mesh::MeshFormat;

const HEADERS: &[&str] = &[
    "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n",
    "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n",
    "ply\nformat binary_little_endian 1.0\nelement vertex 6\nproperty double x\nproperty double y\nproperty double z\nelement face 8\nproperty list uchar uint vertex_indices\nend_header\n",
    "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty int x\nproperty short y\nproperty uchar z\nproperty float nx\nelement face 1\nproperty list int int vertex_index\nend_header\n",
    "ply\nformat binary_little_endian 1.0\ncomment extra\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nelement edge 2\nproperty int vertex1\nproperty int vertex2\nelement face 4\nproperty list uchar int vertex_indices\nproperty float quality\nend_header\n",
    "ply\nformat binary_little_endian 1.0\nelement vertex 12\nproperty float x\nproperty float y\nproperty float z\nelement face 20\nproperty list ushort ushort vertex_indices\nend_header\n",
    "ply\nformat binary_big_endian 1.0\nelement face 2\nproperty list uchar int vertex_indices\nelement vertex 3\nproperty double z\nproperty double y\nproperty double x\nend_header\n",
];

fuzz_target!(|data: &[u8]| {
    let Some((&sel, body)) = data.split_first() else {
        return;
    };
    let sel = sel as usize % (HEADERS.len() + 1);
    let input = if sel == 0 {
        body.to_vec()
    } else {
        let mut v = HEADERS[sel - 1].as_bytes().to_vec();
        v.extend_from_slice(body);
        v
    };
    pseudomanifold_fuzz::read_and_roundtrip(&input, MeshFormat::PlyBinaryLittleEndian);
});
