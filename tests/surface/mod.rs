//! The conformance suite's theme: Chapters 5–6, Loop S′, the (σ, v) construction, rendering, the oracle, the authors' tables, SPEC sync.

mod architecture;
mod authors_code;
mod docs_pictures;
mod loop_sprime;
mod one_surface;
mod oracle;
mod oracle_surface;
mod python_layer;
mod render;
mod sample_curvature;
mod sigma_v;
mod spec_sync;
mod surface_spec;
