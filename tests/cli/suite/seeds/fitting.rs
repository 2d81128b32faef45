//! The tests of `tests/seeds/fitting.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use crate::common::verdicts::{record, Seen};
use pseudomanifold::fitting::{fit_surface, FitOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{generate, SimplicialSurface};
use pseudomanifold::oracle::tsv_diff::diagonal;

/// SPEC `AF-memory`: a fit whose estimated memory exceeds the limit is refused before anything
/// is allocated, with a typed error naming the estimate and the limit; `ppm fit --max-memory`
/// sets the limit and exits 1 with the same message. The estimate grows with S_T (koala-sized
/// inputs fit under the default; 10⁶ vertices, ~2·10⁶ faces, too).
#[test]
fn af_memory_over_the_limit_is_refused_with_the_estimate() {
    use pseudomanifold::fitting::{memory_estimate, FitError, DEFAULT_MEMORY_LIMIT};
    let k = torus();
    let estimate = memory_estimate(&k);
    let mut o = FitOptions::new(1e-2 * diagonal(&k));
    o.memory_limit = estimate - 1;
    match fit_surface(&k, &o, |_| {}) {
        Err(e @ FitError::TooLarge { .. }) => {
            let m = e.to_string();
            assert!(
                m.contains(&estimate.to_string()) && m.contains(&(estimate - 1).to_string()),
                "{m}"
            );
        }
        other => panic!(
            "refused for memory, got {:?}",
            other.map(|f| f.rounds.len())
        ),
    }
    assert!(estimate < DEFAULT_MEMORY_LIMIT);
    let faces_of_a_million_vertices = 2_000_000u64;
    assert!(
        pseudomanifold::fitting::FIXED_BYTES
            + pseudomanifold::fitting::BYTES_PER_FACE * faces_of_a_million_vertices
            <= DEFAULT_MEMORY_LIMIT
    );
    let (_, path) = crate::common::temp_off("ppm-af-mem", "torus.off", &generate::torus(24, 12));
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args([
            "fit",
            "--epsilon",
            "1e-2",
            "--relative",
            "--quiet",
            "--max-memory",
            "1e-6",
        ])
        .arg(&path)
        .output()
        .expect("ppm runs");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("is estimated at") && err.contains("over the limit of 1073 bytes"),
        "{err}"
    );
    record("AF-memory", Seen::Holds, 2);
}

/// The generated 24 × 12 torus, the fitting tests' small closed mesh.
pub(super) fn torus() -> SimplicialSurface {
    validate(&generate::torus(24, 12))
        .surface
        .expect("the generated torus is a simplicial surface")
}
