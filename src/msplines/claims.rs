//! The paper's statements about the number and kind of zero points, checked on the zeros
//! located by [`super::zeros::locate`]: Thm. 4 (|Z| ≤ 2g − 2) and the index claim of its
//! proof, Cor. 1 (singular points unless torus), Sec. 3.4.3 ("2g − 2 zero points"), Cor. 2
//! (one singular point suffices: not constructive), and the discrete Gauss–Bonnet identity
//! Σ_v (w_v − 1) = 2g − 2 − F⁻ (F⁻ = faces whose image under ω is flipped), all exact.

use super::zeros::{Winding, ZeroSet};
use crate::report::{CheckResult, Witness};
use serde_json::json;

/// Sec. 5.3: every vertex's winding number is decided (ω[v, w] ≠ 0, origin off the polygon).
pub fn check_decided(z: &ZeroSet) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-5.3",
        "zero test decided at every vertex (exact winding numbers)",
    );
    r.examined = z.windings.len() as u64;
    for v in &z.undecided {
        r.offend(|| {
            Witness::new(
                format!("vertex {v}: φ(v) lies on the image polygon of its link"),
                json!({"vertex": v.0}),
            )
        });
    }
    r.with_note(format!(
        "{} zero points (w_v ≥ 2), Σ order {}",
        z.zeros.len(),
        z.zeros.iter().map(|x| x.1).sum::<i64>()
    ))
}

/// Discrete Gauss–Bonnet (our identity, exact): the image angles of a positively oriented face
/// sum to π and of a flipped one to −π, so Σ_v w_v = F/2 − F⁻ and, with F/2 − V = 2g − 2,
/// Σ_v (w_v − 1) = 2g − 2 − F⁻.
pub fn check_gauss_bonnet(z: &ZeroSet, genus: usize, faces: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-GB",
        "Σ_v (w_v − 1) = 2g − 2 − F⁻ (discrete Gauss–Bonnet, exact)",
    );
    r.examined = z.windings.len() as u64 + faces as u64;
    if !z.undecided.is_empty() || !z.ambiguous_faces.is_empty() {
        r.skip(format!(
            "{} undecided windings, {} faces with degenerate or inconsistent image",
            z.undecided.len(),
            z.ambiguous_faces.len()
        ));
        return r;
    }
    let lhs = z.total_order();
    let rhs = 2 * genus as i64 - 2 - z.flipped_faces as i64;
    if lhs != rhs {
        r.offend(|| {
            Witness::new(
                format!("Σ(w_v − 1) = {lhs} but 2g − 2 − F⁻ = {rhs}"),
                json!({"lhs": lhs, "rhs": rhs}),
            )
        });
    }
    r.with_note(format!(
        "Σ(w_v − 1) = {lhs}, g = {genus}, F⁻ = {}",
        z.flipped_faces
    ))
}

/// Proof of Thm. 4: "the singularities [of ω_x] can only have negative indices": the index of
/// ω_x at v is 1 − w_v, so every vertex must have w_v ≥ 1.
pub fn check_indices(z: &ZeroSet) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-T4(index)",
        "indices of ω_x ≤ 0: every w_v ≥ 1 (proof of Thm. 4)",
    );
    r.examined = z.windings.len() as u64;
    for &(v, w) in &z.non_positive {
        r.offend(|| {
            Witness::new(
                format!("vertex {v}: w_v = {w}, index 1 − w_v = {} > 0", 1 - w),
                json!({"vertex": v.0, "winding": w}),
            )
        });
    }
    r
}

/// Thm. 4: |Z| ≤ 2g − 2.
pub fn check_count_bound(z: &ZeroSet, genus: usize) -> CheckResult {
    let mut r = CheckResult::new("MS-T4(count)", "|Z| ≤ 2g − 2 (Thm. 4)");
    r.examined = z.windings.len() as u64;
    let bound = 2 * genus as i64 - 2;
    let n = z.zeros.len() as i64;
    if n > bound {
        r.offend(|| {
            Witness::new(
                format!("|Z| = {n} > 2g − 2 = {bound}"),
                json!({"zeros": n, "bound": bound}),
            )
        });
    }
    r.with_note(format!("|Z| = {n}, 2g − 2 = {bound}"))
}

/// Sec. 3.4.3: "a holomorphic one-form has 2g − 2 zero points in principle": counted with
/// multiplicity (Σ (w_v − 1) over zeros) and as distinct points.
pub fn check_zero_count(z: &ZeroSet, genus: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-3.4.3",
        "ω has 2g − 2 zero points (with multiplicity; distinct reported)",
    );
    let want = 2 * genus as i64 - 2;
    let with_mult: i64 = z.zeros.iter().map(|x| x.1).sum();
    let distinct = z.zeros.len() as i64;
    r.examined = z.windings.len() as u64;
    if with_mult != want {
        r.offend(|| {
            Witness::new(
                format!("Σ orders of zeros = {with_mult} ≠ 2g − 2 = {want}"),
                json!({"with_multiplicity": with_mult, "want": want}),
            )
        });
    } else if distinct != want {
        r.restrict(format!("counted with multiplicity only: {distinct} distinct zero points carry total order {want}"));
    }
    r.with_note(format!(
        "{distinct} distinct, {with_mult} with multiplicity, 2g − 2 = {want}"
    ))
}

/// Cor. 1 (and Sec. 3.3/Thm. 2 for the torus): singular points exist iff the surface is not a
/// torus; on the torus ω has no zero and every w_v = 1.
pub fn check_cor1(z: &ZeroSet, genus: usize) -> CheckResult {
    let mut r = CheckResult::new("MS-C1", "Z ≠ ∅ iff g ≠ 1 (Cor. 1); torus: every w_v = 1");
    r.examined = z.windings.len() as u64;
    if genus == 1 {
        for (v, w) in &z.windings {
            if *w != Winding::Decided(1) {
                r.offend(|| {
                    Witness::new(
                        format!("torus vertex {v}: winding {w:?} ≠ 1"),
                        json!({"vertex": v.0}),
                    )
                });
            }
        }
    } else if z.zeros.is_empty() && z.non_positive.is_empty() {
        r.offend(|| {
            Witness::new(
                format!("genus {genus} but no singular vertex"),
                json!({"genus": genus}),
            )
        });
    }
    r
}

/// Cor. 2: one singular point suffices when χ ≠ 0. The paper gives no construction for closed
/// surfaces (Fig. 9 double-covers a genus-0 surface with boundaries), so only the achieved
/// number is reported.
pub fn check_cor2(z: &ZeroSet, genus: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-C2",
        "one singular point suffices (Cor. 2): not constructive",
    );
    r.examined = z.windings.len() as u64;
    r.skip(format!("existence claim without a construction for closed surfaces; this ω (genus {genus}) has {} singular points", z.zeros.len()));
    r
}

/// `MS-T4(index)-corrected` (exact): a vertex of positive index (w_v ≤ 0) is a corner of a
/// face whose image under ω is flipped or degenerate. If every face of the star of v has a
/// positively oriented image, the image angles at φ(v) lie in (0, π) and sum to 2π·w_v, so
/// w_v ≥ 1: the proof's "only negative indices" holds wherever ω preserves orientation.
pub fn check_indices_corrected(k: &crate::mesh::SimplicialSurface, z: &ZeroSet) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-T4(index)-corrected",
        "every vertex with w_v ≤ 0 is a corner of a face with flipped or degenerate image",
    );
    r.examined = z.non_positive.len() as u64;
    let corners: std::collections::BTreeSet<_> = z
        .flipped
        .iter()
        .chain(&z.ambiguous_faces)
        .flat_map(|f| k.face(*f))
        .collect();
    for &(v, w) in &z.non_positive {
        if !corners.contains(&v) {
            r.offend(|| {
                Witness::new(
                    format!("vertex {v}: w_v = {w} but every face of its star has a positively oriented image"),
                    json!({"vertex": v.0, "winding": w}),
                )
            });
        }
    }
    if r.examined == 0 {
        r.skip("no vertex with w_v ≤ 0 (the statement as written holds)");
    }
    r.with_note(format!(
        "{} vertices with w_v ≤ 0, {} flipped and {} degenerate face images",
        z.non_positive.len(),
        z.flipped.len(),
        z.ambiguous_faces.len()
    ))
}

/// `MS-3.4.3-corrected` (exact): for the discrete ω, the zeros counted with multiplicity
/// minus the positive indices equal 2g − 2 − F⁻ (Σ over the lists of zeros and of w_v ≤ 0,
/// independently of `MS-GB`'s sum over all windings); with no flipped face this is the
/// paper's count 2g − 2.
pub fn check_zero_count_corrected(z: &ZeroSet, genus: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-3.4.3-corrected",
        "Σ orders of zeros − Σ_{w_v ≤ 0} (1 − w_v) = 2g − 2 − F⁻ (= 2g − 2 when no face flips)",
    );
    r.examined = z.windings.len() as u64;
    if !z.undecided.is_empty() || !z.ambiguous_faces.is_empty() {
        r.skip(format!(
            "{} undecided windings, {} faces with degenerate or inconsistent image",
            z.undecided.len(),
            z.ambiguous_faces.len()
        ));
        return r;
    }
    let orders: i64 = z.zeros.iter().map(|x| x.1).sum();
    let positive: i64 = z.non_positive.iter().map(|x| 1 - x.1).sum();
    let want = 2 * genus as i64 - 2 - z.flipped.len() as i64;
    if orders - positive != want {
        r.offend(|| {
            Witness::new(
                format!("Σ orders {orders} − Σ positive indices {positive} ≠ 2g − 2 − F⁻ = {want}"),
                json!({"orders": orders, "positive": positive, "want": want}),
            )
        });
    }
    r.with_note(format!(
        "Σ orders {orders}, Σ positive indices {positive}, F⁻ = {}, 2g − 2 = {}",
        z.flipped.len(),
        2 * genus as i64 - 2
    ))
}
