//! The embedding and the parametrization together (seed 002, Part II, "Embed S̃_T in |S_T|"
//! then "Create S from S̃_T"): curves ([`geodesic`], [`shorten`]), curved triangles
//! ([`overlay`]), Floater's maps ([`floater`]), and the parameters of the vertices of S_T
//! they give. These parameters replace the simplification's for the fit; the
//! simplification's stay in [`BaseMesh`], where they choose and refine the base mesh.
//!
//! A failure names the base faces where it happened; the pipeline reports it (SPEC
//! `AF-embedding`) and fits with the simplification's parameters, never passing it on as
//! Floater's. Where base edges have no curve, the base mesh is changed at each by the AC·CB
//! rule ([`super::unblock`], SPEC `AF-embedding`) and embedded again ([`super::fit_surface`]);
//! refining by face splits at the failing faces and embedding again was tried: on the corpus it
//! did not converge in 60 rounds.

use super::base::{BaseMesh, Param};
use super::floater::{self, RegionMap};
use super::geodesic::{Curve, EmbedError, Embedding};
use super::overlay::{self, Overlay};
use super::route;
use super::shorten;
use crate::mesh::SimplicialSurface;
use std::collections::HashMap;

/// The embedded base mesh and its parametrization.
#[derive(Debug, Clone)]
pub struct Embedded {
    /// The curves.
    pub emb: Embedding,
    /// S_T cut along them.
    pub overlay: Overlay,
    /// Floater's map of each curved triangle.
    pub maps: Vec<RegionMap>,
    /// Parameter of every vertex of S_T (base face slot, barycentric coordinates).
    pub params: Vec<Param>,
}

/// Why the embedding failed, and where.
#[derive(Debug, Clone, Default)]
pub struct Failure {
    /// What went wrong.
    pub what: String,
    /// Base face slots to refine.
    pub faces: Vec<u32>,
    /// The base edge that has no curve, when that is the failure.
    pub edge: Option<(u32, u32)>,
    /// Every base edge with no curve (the first is `edge`).
    pub blocked: Vec<(u32, u32)>,
    /// Why the base-mesh changes at that edge stopped (`unblock`), when they did.
    pub gave_up: Option<super::unblock::GiveUp>,
}

/// Embed, cut, map (module doc).
pub fn embed(k: &SimplicialSurface, base: &BaseMesh) -> Result<Embedded, Failure> {
    embed_ticking(k, base, &mut |_, _| {})
}

/// [`embed`] with `tick` following each tracing ([`route::curves_keeping`]).
pub fn embed_ticking(
    k: &SimplicialSurface,
    base: &BaseMesh,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<Embedded, Failure> {
    embed_keeping(k, base, &HashMap::new(), |_, _, _, _| None, tick)
}

/// [`embed`] with the curves in `kept` taken as they are (neither traced nor shortened; the
/// others are traced and shortened around them) and the maps `reuse` gives for some faces
/// (`super::local`: given the face slot, its pieces, the overlay and the curves); `tick`
/// follows the tracing ([`route::curves_keeping`]).
pub fn embed_keeping(
    k: &SimplicialSurface,
    base: &BaseMesh,
    kept: &HashMap<(u32, u32), Curve>,
    mut reuse: impl FnMut(u32, &[usize], &Overlay, &Embedding) -> Option<RegionMap>,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<Embedded, Failure> {
    let mut emb = route::curves_keeping(k, base, kept, tick).map_err(|e| {
        let EmbedError::NoPath { a, b, blocked } = &e;
        let (a, b) = (*a, *b);
        Failure {
            blocked: blocked.clone(),
            what: e.to_string(),
            faces: [(a, b), (b, a)]
                .iter()
                .filter_map(|&(u, w)| base.face_of_edge(u, w))
                .collect(),
            edge: Some((a, b)),
            gave_up: None,
        }
    })?;
    let frozen: Vec<bool> = emb
        .curves
        .iter()
        .map(|c| kept.contains_key(&(c.a, c.b)))
        .collect();
    shorten::shorten_except(k, base, &mut emb, &frozen);
    let ov = overlay::build(k, base, &emb).map_err(|e| {
        let fine = match e {
            overlay::OverlayError::OffSurface { curve, .. } => {
                let c = &emb.curves[curve];
                return Failure {
                    what: e.to_string(),
                    faces: [(c.a, c.b), (c.b, c.a)]
                        .iter()
                        .filter_map(|&(u, w)| base.face_of_edge(u, w))
                        .collect(),
                    edge: None,
                    gave_up: None,
                    blocked: Vec::new(),
                };
            }
            overlay::OverlayError::Crossing(f) | overlay::OverlayError::Degenerate(f) => f,
        };
        let faces = k
            .face(crate::mesh::FaceId(fine))
            .iter()
            .filter_map(|v| match base.params().get(v.idx()) {
                Some(Param::Face { f, .. }) => Some(*f),
                _ => None,
            })
            .collect();
        Failure {
            what: e.to_string(),
            faces,
            edge: None,
            gave_up: None,
            blocked: Vec::new(),
        }
    })?;
    let bad: Vec<u32> = overlay::disk_defects(&ov, base, &emb)
        .into_iter()
        .filter(|(_, d)| !d.is_empty())
        .map(|(f, _)| f)
        .collect();
    if !bad.is_empty() {
        return Err(Failure {
            what: format!("{} curved triangles are not disks", bad.len()),
            faces: bad,
            edge: None,
            gave_up: None,
            blocked: Vec::new(),
        });
    }
    let maps = floater::map_regions_with(&ov, base, &emb, |f, pieces| reuse(f, pieces, &ov, &emb))
        .map_err(|e| {
            let floater::FloaterError::Solve { face, .. } = &e;
            Failure {
                what: e.to_string(),
                faces: vec![*face],
                edge: None,
                gave_up: None,
                blocked: Vec::new(),
            }
        })?;
    let params = floater::params(&maps, base, &emb, base.positions().len());
    Ok(Embedded {
        emb,
        overlay: ov,
        maps,
        params,
    })
}
