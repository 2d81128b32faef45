//! The conformance suite's theme: Secs. 3.2–3.5: gluing data (exact and sampled checkers), the paper's examples, planted faults, the check harness.

mod gluing_crossval;
mod gluing_file_errors;
mod gluing_generic_scalar;
mod gluing_paper_examples;
mod gluing_planted;
mod gluing_stereo_ppm;
mod gluing_topology;
mod harness_planted;
