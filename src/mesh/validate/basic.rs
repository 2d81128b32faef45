//! Sanity checks that precede the paper's definitions: indices in range, finite coordinates,
//! repeated corners, duplicate faces, unreferenced vertices.

use super::error_class::ErrorClass;
use super::incidence::Incidence;
use crate::mesh::RawMesh;
use crate::report::{Check, CheckResult, Witness};
use serde_json::json;

/// Def. 3.1.3(i) as it applies to a triangle list: K is the closure of the listed triangles,
/// so "every face of a simplex of K is in K" fails exactly when a triangle names a vertex
/// that does not exist (an index out of range).
pub(crate) fn indices_in_range(raw: &RawMesh) -> CheckResult {
    let n = raw.positions.len() as u64;
    let mut r = Check::new("D3.1.3(i)", "faces of faces present (indices in range)");
    r.examined(raw.faces.len() as u64);
    for (f, tri) in raw.faces.iter().enumerate() {
        for &i in tri {
            if u64::from(i) >= n {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "{}: vertex index {} out of range ({} vertices): its 0-face is missing",
                            raw.describe_face(f),
                            i,
                            n
                        ),
                        json!({"face": f, "index": i, "vertices": n}),
                    )
                });
            }
        }
    }
    r.finish("")
}

/// Coordinates must be finite real numbers (a NaN or infinite coordinate is not a point of R³).
pub(crate) fn coordinates_finite(raw: &RawMesh) -> CheckResult {
    let mut r = Check::new("X-finite", "coordinates finite");
    r.examined(raw.positions.len() as u64);
    for (v, p) in raw.positions.iter().enumerate() {
        if !p.iter().all(|c| c.is_finite()) {
            r.offend(|| {
                Witness::new(
                    format!("{}: coordinates {:?} not finite", raw.describe_vertex(v), p),
                    json!({"vertex": v, "position": format!("{p:?}")}),
                )
            });
        }
    }
    r.finish("")
}

/// A triangle whose corner list repeats a vertex spans fewer than 3 points (Def. 3.1.1).
pub(crate) fn repeated_corners(raw: &RawMesh) -> (CheckResult, Vec<bool>) {
    let mut r = Check::new("X-repeated-corner", "no face repeats a vertex");
    r.examined(raw.faces.len() as u64);
    let mut bad = vec![false; raw.faces.len()];
    for (f, t) in raw.faces.iter().enumerate() {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            bad[f] = true;
            r.offend(|| {
                Witness::new(
                    format!("{}: corners {:?} repeat a vertex", raw.describe_face(f), t),
                    json!({"face": f, "corners": t}),
                )
            });
        }
    }
    (r.finish(""), bad)
}

/// Two faces with the same vertex set (in any order or orientation) are one simplex listed
/// twice; Def. 3.1.3 describes a *set* of simplices.
pub(crate) fn duplicate_faces(raw: &RawMesh, inc: &Incidence) -> CheckResult {
    let mut r = Check::new("X-duplicate-face", "no duplicate faces");
    r.examined(raw.faces.len() as u64);
    for group in inc.duplicate_groups() {
        let (first, rest) = match group.split_first() {
            Some(x) => x,
            None => continue,
        };
        for &g in rest {
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} duplicates {} (vertices {:?})",
                        raw.describe_face(g as usize),
                        raw.describe_face(*first as usize),
                        raw.faces.get(g as usize)
                    ),
                    json!({"face": g, "duplicate_of": first}),
                )
            });
        }
    }
    r.finish("")
}

/// Vertices that no face uses are not in K (K is the closure of the triangles). Not an error,
/// but reported: a user's vertex ids stay file indices, so these ids are not in I.
pub(crate) fn unreferenced_vertices(raw: &RawMesh, referenced: &[bool]) -> CheckResult {
    let mut r = Check::new("X-unreferenced", "every vertex is used by a face");
    r.examined(raw.positions.len() as u64);
    for (v, &used) in referenced.iter().enumerate() {
        if !used {
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} is used by no face (not a vertex of K)",
                        raw.describe_vertex(v)
                    ),
                    json!({"vertex": v}),
                )
            });
        }
    }
    // Not a statement of the paper: unreferenced vertices are a warning, not a failure.
    r.finish_as_warning("")
}

pub(super) fn classes_of(r: &CheckResult) -> Vec<ErrorClass> {
    if !r.failed() {
        return vec![];
    }
    match r.id.as_str() {
        "X-duplicate-face" => vec![ErrorClass::DuplicateFace],
        "X-repeated-corner" => vec![ErrorClass::DegenerateFace],
        "D3.1.3(i)" => vec![ErrorClass::IndexOutOfRange],
        "X-finite" => vec![ErrorClass::NonFinite],
        _ => vec![],
    }
}
