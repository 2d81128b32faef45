//! Is the fitted surface S embedded? (seed 002, Part II: h : S → |S_T| is a homeomorphism
//! only if S is; SPEC `AF-embedded`.) S is sampled at a stated level by the Sec. 6.2
//! midpoint pattern (`surface::output::sample_pattern_faces`, the pattern `ppm sample` writes),
//! the sample is validated by the Sec. 3.1 validator `ppm check` runs (Def. 3.1.3(ii) among its
//! checks), and every offending sample triangle is mapped to the base face it samples: the
//! pattern lists the 4^L triangles of base face σ consecutively, σ in FaceId order
//! ([`triangles_per_face`]; asserted by this module's test). A sample is evidence at its
//! level only: a finer sample of the same S may still cross.

use crate::mesh::raw::RawMesh;
use crate::mesh::validate::validate;
use crate::report::{Check, CheckResult, Witness};
use crate::surface::output::Attributes;
use crate::surface::sigma_v::SigmaVPps;
use serde_json::json;
use std::collections::BTreeMap;

/// The level of the sample, unless stated otherwise: level 2, the level the seed's done-when
/// samples at (`ppm sample X.fit --level 2`).
pub const DEFAULT_EMBED_LEVEL: u32 = 2;

/// Sample triangles per base face at `level` (the midpoint pattern: 4^L).
pub fn triangles_per_face(level: u32) -> usize {
    1usize << (2 * level.min(30))
}

/// The check's result and what it located.
#[derive(Debug, Clone)]
pub struct Embeddedness {
    /// `AF-embedded`: examined = base faces, an offender per base face whose sample offends.
    pub result: CheckResult,
    /// The sample level.
    pub level: u32,
    /// Sample triangles in all.
    pub triangles: usize,
    /// Distinct sample triangles named by a failed check of the validator.
    pub offending_triangles: usize,
    /// The base faces (FaceIds of the base surface) whose sample triangles offend, sorted.
    pub faces: Vec<u32>,
}

impl Embeddedness {
    /// The sample offends somewhere (located or not).
    pub fn crosses(&self) -> bool {
        self.result.failed()
    }
}

/// `AF-embedded` on a fitted (σ, v) PPS: its sample at `level` (positions only), validated.
/// A sampling that fails (eval refused a point) is an offence, not located.
pub fn check_embedded(pps: &SigmaVPps, level: u32) -> Embeddedness {
    match pps.sample_surface_with(level, Attributes::Positions) {
        Ok(m) => check_sample(&m.positions, &m.faces, pps.gluing.num_faces(), level),
        Err(e) => {
            let mut c = Check::new(ID, name(level));
            c.offend(|| {
                Witness::new(
                    format!("the level-{level} sample of S could not be made: {e}"),
                    json!({"level": level}),
                )
            });
            Embeddedness {
                result: c.finish("the sampling failed"),
                level,
                triangles: 0,
                offending_triangles: 0,
                faces: Vec::new(),
            }
        }
    }
}

const ID: &str = "AF-embedded";

fn name(level: u32) -> String {
    format!("the fitted surface is embedded: its level-{level} sample is a simplicial surface (Sec. 3.1)")
}

/// `AF-embedded` on a sample given as arrays: `faces` must hold [`triangles_per_face`]`(level)`
/// triangles per base face, base face by base face, for `base_faces` base faces (else an
/// offence: the triangles cannot be located). No triangle is `Skipped`.
pub fn check_sample(
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    base_faces: usize,
    level: u32,
) -> Embeddedness {
    let mut c = Check::new(ID, name(level));
    let per = triangles_per_face(level);
    let mut out = Embeddedness {
        result: CheckResult::new(ID, name(level)),
        level,
        triangles: faces.len(),
        offending_triangles: 0,
        faces: Vec::new(),
    };
    if faces.is_empty() {
        let mut r = c.finish("");
        r.skip("the sample has no triangle");
        out.result = r;
        return out;
    }
    if faces.len() != base_faces.saturating_mul(per) {
        c.offend(|| {
            Witness::new(
                format!(
                    "{} sample triangles for {base_faces} base faces at level {level} ({per} each expected): not located",
                    faces.len()
                ),
                json!({"triangles": faces.len(), "base_faces": base_faces}),
            )
        });
        out.result = c.finish("");
        return out;
    }
    c.examined(base_faces as u64);
    let raw = RawMesh::from_arrays(positions.to_vec(), faces.to_vec());
    let val = validate(&raw);
    // Offending sample triangles, with the validator's check IDs that name them.
    let mut bad: BTreeMap<u32, Vec<String>> = BTreeMap::new();
    let mut unlocated: Vec<String> = Vec::new();
    let mut incident: Option<Vec<Vec<u32>>> = None;
    for r in val.report.checks.iter().filter(|r| r.failed()) {
        let mut tris: Vec<u32> = Vec::new();
        if r.id == "D3.1.3(ii)(triangles)" {
            // Every pair the search found (the result lists only the first few).
            for &(a, b) in &val.report.crossing_pairs {
                tris.extend([a, b]);
            }
        } else {
            for w in &r.witnesses {
                let d = &w.data;
                if let Some(f) = d.get("face").and_then(|x| x.as_u64()) {
                    tris.push(f as u32);
                }
                if let Some(fs) = d.get("faces").and_then(|x| x.as_array()) {
                    tris.extend(fs.iter().filter_map(|x| x.as_u64()).map(|x| x as u32));
                }
                let mut vs: Vec<u64> = Vec::new();
                if let Some(v) = d.get("vertex").and_then(|x| x.as_u64()) {
                    vs.push(v);
                }
                if let Some(a) = d.get("vertices").and_then(|x| x.as_array()) {
                    vs.extend(a.iter().filter_map(|x| x.as_u64()));
                }
                if !vs.is_empty() {
                    let inc = incident.get_or_insert_with(|| {
                        let mut inc = vec![Vec::new(); positions.len()];
                        for (t, tri) in faces.iter().enumerate() {
                            for &v in tri {
                                if let Some(l) = inc.get_mut(v as usize) {
                                    l.push(t as u32);
                                }
                            }
                        }
                        inc
                    });
                    for v in vs {
                        if let Some(l) = inc.get(v as usize) {
                            tris.extend_from_slice(l);
                        }
                    }
                }
            }
        }
        tris.retain(|&t| (t as usize) < faces.len());
        if tris.is_empty() {
            unlocated.push(r.id.clone());
        }
        for t in tris {
            let ids = bad.entry(t).or_default();
            if !ids.contains(&r.id) {
                ids.push(r.id.clone());
            }
        }
    }
    out.offending_triangles = bad.len();
    let mut per_face: BTreeMap<u32, Vec<(u32, &Vec<String>)>> = BTreeMap::new();
    for (t, ids) in &bad {
        per_face
            .entry((*t as usize / per) as u32)
            .or_default()
            .push((*t, ids));
    }
    for (f, tris) in &per_face {
        let mut ids: Vec<&str> = tris
            .iter()
            .flat_map(|(_, ids)| ids.iter().map(|s| s.as_str()))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let ts: Vec<u32> = tris.iter().map(|(t, _)| *t).collect();
        c.offend(|| {
            Witness::new(
                format!(
                    "base face {f}: sample triangles {ts:?} fail {} (level {level})",
                    ids.join(", ")
                ),
                json!({"face": f, "triangles": ts, "checks": ids}),
            )
        });
    }
    for id in &unlocated {
        c.offend(|| {
            Witness::new(
                format!("the level-{level} sample fails {id}, at no triangle named"),
                json!({"check": id}),
            )
        });
    }
    out.faces = per_face.keys().copied().collect();
    let capped = if val.report.crossing_pairs.len()
        >= crate::mesh::validate::intersect::MAX_COUNTED_INTERSECTIONS
    {
        " (the crossing search stopped at its cap: a lower bound)"
    } else {
        ""
    };
    out.result = c.finish(format!(
        "level {level}: {} sample triangles ({per} per base face) validated as `ppm check` does; {} offending{capped} at {} base faces",
        faces.len(),
        out.offending_triangles,
        out.faces.len()
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::VertexId;
    use crate::surface::output::sample_pattern_faces;

    /// The pattern lists 4^L triangles per base face, face by face: every corner of sample
    /// triangle t lies in the closed base face t / 4^L (its nonzero weights name only that
    /// face's corners), at every level used.
    #[test]
    fn af_embedded_sample_triangles_are_listed_per_base_face() {
        let faces = [
            [VertexId(0), VertexId(1), VertexId(2)],
            [VertexId(0), VertexId(2), VertexId(3)],
            [VertexId(0), VertexId(3), VertexId(1)],
            [VertexId(1), VertexId(3), VertexId(2)],
        ];
        for level in 0..=3 {
            let pat = sample_pattern_faces(&faces, level).expect("small level");
            let per = triangles_per_face(level);
            assert_eq!(pat.faces.len(), faces.len() * per);
            for (t, tri) in pat.faces.iter().enumerate() {
                let owner = faces[t / per];
                for &p in tri {
                    let s = pat.points[p as usize];
                    let corners = faces[s.face.idx()];
                    for (i, &w) in s.bary.iter().enumerate() {
                        if w != 0.0 {
                            assert!(
                                owner.contains(&corners[i]),
                                "level {level}: triangle {t}'s point {p} has weight on {:?}, not a corner of base face {}",
                                corners[i],
                                t / per
                            );
                        }
                    }
                }
            }
        }
    }
}
