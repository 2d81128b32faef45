//! The conformance suite's theme: Chapter 4: the maps, the mesh-wide runs, the certificate provers, the multi-precision backends.

mod cert_compact;
mod cert_docs;
mod cert_exact;
mod cert_f64_band;
mod cert_f64_props;
mod cert_f64_rounding;
mod cert_g_chart;
mod certify_provers;
mod construction_explore;
mod construction_maps;
mod construction_mesh;
mod errata_domain;
mod interval_vs_inari;
mod mp_backends;
