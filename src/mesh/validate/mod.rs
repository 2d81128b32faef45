//! The named checks of Sec. 3.1. Each check returns *every* offending element (the first few
//! listed, all counted) in a [`CheckResult`] carrying the SPEC.md ID it decides.
//!
//! [`validate`] runs them all and is the only constructor of
//! [`SimplicialSurface`].

pub(crate) mod affine;
pub(crate) mod basic;
mod error_class;
mod fans;
mod grid;
pub(crate) mod incidence;
pub mod intersect;
pub mod predicates;
pub mod surface;
pub(crate) mod topology;

pub use error_class::ErrorClass;
pub use incidence::Incidence;

use crate::mesh::{RawMesh, SimplicialSurface};
use crate::report::{Check, CheckResult, Witness};
use serde::Serialize;
use std::collections::BTreeMap;

/// Everything the validator found.
#[derive(Debug, Clone, Serialize)]
pub struct ValidationReport {
    /// The file the mesh was read from, if any.
    pub source: Option<String>,
    /// Number of vertex records in the file.
    pub vertices_in_file: u64,
    /// Number of triangles after reading (fan-split polygons count once per triangle).
    pub faces_in_file: u64,
    /// Polygons fan-split by `--triangulate` (the report says so).
    pub triangulated_polygons: u64,
    /// Every check run, in order, with its verdict and witnesses.
    pub checks: Vec<CheckResult>,
    /// Defect classes found (sorted, unique).
    pub error_classes: Vec<ErrorClass>,
    /// Connected components of the well-formed faces.
    pub components: Vec<topology::Component>,
    /// degree → number of vertices.
    pub degree_histogram: BTreeMap<u32, u64>,
    /// Def. 3.1.6 holds (and with it Lemma 3.1.1: |K| is a topological surface).
    pub is_simplicial_surface: bool,
    /// Every pair of triangles the Def. 3.1.3(ii) search found meeting outside a common face
    /// (up to its cap; the check lists only the first few), for callers that locate them.
    #[serde(skip)]
    pub crossing_pairs: Vec<(u32, u32)>,
}

/// Result of validation: the report, and the validated surface when every check passed.
pub struct Validation {
    /// The validator's findings.
    pub report: ValidationReport,
    /// The validated surface; `None` unless every check passed.
    pub surface: Option<SimplicialSurface>,
}

/// Run every check of Sec. 3.1 on a raw triangle list.
pub fn validate(raw: &RawMesh) -> Validation {
    let nv = raw.positions.len();
    let mut checks = Vec::new();
    let mut classes: Vec<ErrorClass> = Vec::new();

    let range = basic::indices_in_range(raw);
    let finite = basic::coordinates_finite(raw);
    let (repeated, repeated_bad) = basic::repeated_corners(raw);
    classes.extend(basic::classes_of(&range));
    classes.extend(basic::classes_of(&finite));
    classes.extend(basic::classes_of(&repeated));

    let in_range = |t: &[u32; 3]| t.iter().all(|&i| (i as usize) < nv);
    let active: Vec<bool> = raw
        .faces
        .iter()
        .enumerate()
        .map(|(f, t)| in_range(t) && !repeated_bad[f])
        .collect();
    // K is a *set* of simplices (Def. 3.1.3): a face listed twice is one triangle of K. The
    // repeats are reported by the duplicate check and take no further part.
    let first_pass = Incidence::build(raw, active.clone());
    let dup = basic::duplicate_faces(raw, &first_pass);
    classes.extend(basic::classes_of(&dup));
    let groups = first_pass.duplicate_groups();
    // Without duplicates the second pass would rebuild the same tables.
    let inc = if groups.is_empty() {
        first_pass
    } else {
        let mut active = active;
        for group in groups {
            for &g in group.iter().skip(1) {
                active[g as usize] = false;
            }
        }
        Incidence::build(raw, active)
    };
    let mut referenced = vec![false; nv];
    for t in raw.faces.iter().filter(|t| in_range(t)) {
        for &i in t {
            referenced[i as usize] = true;
        }
    }

    let unref = basic::unreferenced_vertices(raw, &referenced);

    // Geometry: only on faces whose corners are finite.
    let finite_face: Vec<bool> = raw
        .faces
        .iter()
        .enumerate()
        .map(|(f, t)| {
            inc.active[f]
                && t.iter()
                    .all(|&i| raw.positions[i as usize].iter().all(|c| c.is_finite()))
        })
        .collect();
    let (affine, nondegenerate) = affine::affinely_independent(raw, &finite_face);
    if affine.failed() {
        classes.push(ErrorClass::DegenerateFace);
    }
    let coincident = intersect::coincident_vertices(raw, &referenced);
    if coincident.failed() {
        classes.push(ErrorClass::CoincidentVertices);
    }
    // The geometric search and the combinatorial checks are independent: side by side.
    let (crossing, ((edges, c_edges), (links, c_links), (orientation, orient_check))) = rayon::join(
        || intersect::triangles_meet_properly_pairs(raw, &nondegenerate),
        || {
            (
                surface::edges_in_two_triangles(raw, &inc),
                surface::links_are_cycles(raw, &inc),
                // Holds exactly when a consistent orientation was found (topology::orient
                // offends only on an edge that cannot be oriented).
                topology::orient(raw, &inc),
            )
        },
    );
    let (crossing, crossing_pairs) = crossing;
    if crossing.failed() {
        classes.push(ErrorClass::SelfIntersection);
    }
    classes.extend(c_edges);
    classes.extend(c_links);
    if orient_check.failed() {
        classes.push(ErrorClass::NonOrientable);
    }
    let closed = !edges.failed();
    let components = topology::components(raw, &inc, orientation.orientable, closed);
    let degree_histogram = topology::degree_histogram(&inc, nv);

    let nonempty = {
        let mut r = Check::new("X-nonempty", "the mesh has at least one triangle");
        r.examined(raw.faces.len() as u64);
        if raw.faces.is_empty() {
            r.offend(|| Witness::new("no faces", serde_json::json!({})));
        }
        r.finish("")
    };

    let is_simplicial_surface = [
        &nonempty,
        &range,
        &finite,
        &repeated,
        &dup,
        &affine,
        &coincident,
        &crossing,
        &edges,
        &links,
    ]
    .iter()
    .all(|c| !c.failed());

    // Lemma 3.1.1: K simplicial surface ⇔ |K| topological surface. The checkable consequence
    // on a closed surface embedded in R³: each component is orientable with χ = 2 − 2g, g ≥ 0.
    let mut lemma = Check::new(
        "L3.1.1",
        "|K| is a topological surface (Lemma 3.1.1): orientable, χ = 2 − 2g",
    );
    if is_simplicial_surface {
        lemma.examined(components.len() as u64);
        for (i, c) in components.iter().enumerate() {
            if c.genus.is_none() {
                lemma.offend(|| {
                    Witness::new(
                        format!(
                            "component {i}: χ = {} with orientable = {} is not the Euler characteristic of a closed orientable surface",
                            c.euler_characteristic, orientation.orientable
                        ),
                        serde_json::json!({"component": i, "chi": c.euler_characteristic}),
                    )
                });
            }
        }
    } else {
        lemma.skip("K is not a simplicial surface (Def. 3.1.6), so |K| is not a surface");
    }

    checks.extend([
        nonempty,
        range,
        finite,
        repeated,
        dup,
        unref,
        affine,
        coincident,
        crossing,
        edges,
        links,
        orient_check,
        lemma.finish(""),
    ]);
    classes.sort();
    classes.dedup();

    let ok = checks.iter().all(|c| !c.failed());
    let surface = if ok {
        SimplicialSurface::from_validated(raw, &orientation.flip, &referenced)
    } else {
        None
    };
    let report = ValidationReport {
        source: raw.source.as_ref().map(|p| p.display().to_string()),
        vertices_in_file: nv as u64,
        faces_in_file: raw.faces.len() as u64,
        triangulated_polygons: raw.triangulated_polygons,
        checks,
        error_classes: classes,
        components,
        degree_histogram,
        is_simplicial_surface: ok,
        crossing_pairs,
    };
    Validation { report, surface }
}
