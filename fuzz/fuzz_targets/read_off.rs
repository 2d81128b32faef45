//! OFF reader (Sec. 3.1 input): arbitrary bytes never panic; `Ok` meshes round-trip.
#![no_main]
use libfuzzer_sys::fuzz_target;
use pseudomanifold::mesh::MeshFormat;

fuzz_target!(|data: &[u8]| {
    pseudomanifold_fuzz::read_and_roundtrip(data, MeshFormat::Off);
});
