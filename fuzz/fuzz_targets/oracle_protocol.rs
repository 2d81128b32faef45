//! Oracle protocol (issue 9): arbitrary JSON lines against a session never panic, and every
//! line gets one well-formed JSON response.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    pseudomanifold_fuzz::oracle_lines(data);
});
