//! The conformance suite's theme: Sec. 3.1 and the readers: mesh validation, the corpus, I/O, hostile inputs, fuzz regressions, random surfaces.

mod adversarial;
mod corpus;
mod fuzz_regressions;
mod io_corpus;
mod io_fuzz;
mod io_hostile;
mod io_read;
mod io_roundtrip;
mod mesh_validate;
mod random_surfaces;
