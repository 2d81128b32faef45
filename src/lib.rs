//! # pseudomanifold
//!
//! A formal-verification-oriented reference implementation of the *parametric pseudo-manifold*
//! (PPM) construction of Siqueira, Xu and Gallier ("A New Construction of Smooth Surfaces from
//! Triangle Meshes Using Parametric Pseudo-Manifolds", tech report).
//!
//! The module layout mirrors the paper, and data flows one way:
//! mesh (Sec. 3.1) → gluing data (Secs. 3.4–3.5 abstract, Ch. 4 concrete) → parametrizations
//! (Ch. 5, Sec. 6.1.4) → reports.
//!
//! ## The five entry points
//!
//! 1. **Read and validate a mesh** (Sec. 3.1): [`mesh::io::read_mesh`] gives a `RawMesh`;
//!    [`mesh::validate::validate`] checks Defs. 3.1.1–3.1.7 and, when they hold, returns the
//!    [`mesh::SimplicialSurface`] every later stage takes (only the validator makes one).
//! 2. **Check Chapter 4 on it**: [`conditions::chapter4::run_chapter4`] (or, per configuration,
//!    [`construction::checks::run_edge_checks`] and [`construction::checks::run_triangle_checks`]).
//! 3. **Build and evaluate the surface** (Ch. 5, Sec. 6.1.4): [`surface::Pps::build`], then
//!    `Pps::eval` at a face and barycentric coordinates; [`surface::checks::run_surface_checks`]
//!    checks condition (C) and the Chapter 5 claims.
//! 4. **Certify** every degree configuration up to a bound with interval branch and bound:
//!    [`certify::run`].
//! 5. **Serve as an oracle** (f64 and multi-precision side by side):
//!    [`oracle::protocol::Session`].
//!
//! The five in one compiling example, on the bundled icosahedron:
//!
//! ```
//! use pseudomanifold::conditions::chapter4::{run_chapter4, Ch4Options};
//! use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
//! use pseudomanifold::mesh::validate::validate;
//! use pseudomanifold::mesh::FaceId;
//! use pseudomanifold::oracle::protocol::{Request, Session};
//! use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions};
//! use std::path::Path;
//!
//! let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/icosahedron_binary_le.ply");
//! // 1. Read and validate (Sec. 3.1): bad input is a typed error; a surface only when valid.
//! let raw = read_mesh(&path, &ReadOptions::default())?;
//! let k = validate(&raw).surface.ok_or("not a simplicial surface")?;
//! // 2. Build the PPS (Ch. 5) over the PN-triangle S′ (Sec. 6.2) ...
//! let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
//! // 3. ... and evaluate it: eval(σ, λ, μ, ν) of Sec. 6.1.4 at the centre of face 0.
//! let third = 1.0 / 3.0;
//! let p = pps.eval(FaceId(0), &[third; 3], pps.consts_f64())?;
//! assert!(p.point.iter().all(|x| x.is_finite()));
//! // 4. The Chapter 4 spec checks (a small budget here; `ppm check --spec` runs them all).
//! let opts = Ch4Options {
//!     samples: 4,
//!     max_edge_configs: Some(1),
//!     max_triangle_configs: Some(1),
//!     max_star_configs: Some(1),
//!     ..Ch4Options::default()
//! };
//! let report = run_chapter4(&k, &opts);
//! assert!(report.unexpected_failures.is_empty(), "{:?}", report.unexpected_failures);
//! // 5. The oracle session (docs/oracle.md): one JSON request per line, one JSON response.
//! let mut oracle = Session::new();
//! oracle.handle(&Request::Load { path })?;
//! assert!(oracle.handle_line(r#"{"op":"degree","v":0}"#).ok);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Every checker returns [`report::CheckResult`]s recorded through one harness,
//! [`report::Check`] (a NaN is an offence, evaluation errors are counted, nothing examined is
//! skipped); only [`cli`] prints and sets exit codes.
//!
//! ## Ids: one policy (SPEC `API-ids`)
//!
//! Vertices, faces and half-edges are typed ids ([`mesh::VertexId`], [`mesh::FaceId`],
//! [`mesh::HalfedgeId`]). Where an id may come from outside (a file, a request, a caller), it
//! meets a `Result`; where it was minted by the structure itself, it is trusted:
//!
//! * **Border queries answer a foreign id with a typed error**, never a panic or a made-up value:
//!   [`construction::PpmGluing`] (`degree`, `edge_config`, the transition maps) gives
//!   `NoSuchVertex`; [`surface::Pps`] (`face`, `eval`, `theta`, `gamma`, ...) gives
//!   `NoSuchVertex`/`NoSuchFace`; the (σ, v) gluing gives its `SigmaVError`; the oracle turns
//!   each into an error response.
//! * **Counting queries are total** (`contains`, `degree`, `outgoing`, `faces_around`,
//!   `halfedge`, `s`, `link_vertex` of [`mesh::SimplicialSurface`], and `contains`/`degree` of
//!   `Pps` and the (σ, v) gluing): an id that is not a vertex of K has the empty star (degree 0,
//!   no half-edges, `None`), which is the mathematics of an unreferenced vertex slot, so guards
//!   can be written with them.
//! * **Element accessors index** (`position`, `face`, `twin`, `label`, `origin`, `dest`, `next`,
//!   `prev`, `face_of`): they take ids minted by the same surface (its iterators, or a counting
//!   query above) and, like slice indexing, panic on a foreign id — a programming error, which
//!   input cannot reach because every input path goes through a border query first.
//!
//! ## Modules
//!
//! * [`mesh`] — Sec. 3.1: reading triangle meshes, validating them as simplicial surfaces
//!   (Defs. 3.1.1–3.1.7), and the half-edge structure of Sec. 6.1.1 with the labelling s_v of
//!   Sec. 6.1.2 / Def. 4.1.4.
//! * [`gluing`] — Secs. 3.2–3.5: abstract sets of gluing data and their checkers.
//! * [`construction`] — Ch. 4: the PPM gluing data built from a simplicial surface.
//! * [`surface`] — Ch. 5 and Sec. 6.1.4: shape functions, weights, parametrizations.
//! * [`conditions`] — the conformance checkers and their reports.
//! * [`cli`] — the `ppm` command line.

#![warn(missing_docs)]
// Items no user outside the crate can reach are `pub(crate)` (docs/architecture.md, "The public API").
#![deny(unreachable_pub)]
// The check harness's rule 1 (report::harness): a deviation is compared as `!(d <= tol)`, which
// is true for NaN, so a NaN is an offence; `partial_cmp` would hide exactly that case.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod certify;
pub mod cli;
pub mod conditions;
pub mod construction;
pub mod exact;
pub mod fitting;
pub mod gluing;
pub mod mesh;
pub mod msplines;
pub mod numeric;
pub mod oracle;
pub mod render;
pub mod report;
pub mod sdiff;
pub mod surface;
