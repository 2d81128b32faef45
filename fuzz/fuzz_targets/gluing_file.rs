//! Gluing files (`ppm gluing`): arbitrary text never panics; errors name the file; parsed
//! gluing data goes through every exact check of Def. 3.4.1.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    pseudomanifold_fuzz::gluing_file(data);
});
