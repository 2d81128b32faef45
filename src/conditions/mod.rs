//! Conformance checkers run on whole meshes: each statement of SPEC.md that is checked on data
//! has its checker here or in the module of the concept it checks, and reports through
//! [`crate::report`].

pub mod chapter4;
pub mod errata;
pub mod spec;

use crate::report::{CheckResult, Verdict, MAX_WITNESSES};

/// Merge results of the same check run on several configurations into one result per ID:
/// counts add up, the worst deviation and the largest tolerance are kept, witnesses are
/// prefixed with the configuration they came from.
pub fn aggregate(parts: impl IntoIterator<Item = (String, CheckResult)>) -> Vec<CheckResult> {
    let mut out: Vec<CheckResult> = Vec::new();
    for (ctx, r) in parts {
        let r_verdict = r.stored_verdict().clone();
        let idx = match out.iter().position(|o| o.id == r.id) {
            Some(i) => i,
            None => {
                let mut blank = CheckResult::new(r.id.clone(), generic_name(&r.name));
                blank.adopt_verdict(r.stored_verdict().clone());
                blank.seed = r.seed;
                if !r.note.is_empty() {
                    blank.note = format!("first configuration: {}", r.note);
                }
                out.push(blank);
                out.len() - 1
            }
        };
        let slot = &mut out[idx];
        slot.examined += r.examined;
        slot.offenders += r.offenders;
        for w in r.witnesses {
            if slot.witnesses.len() < MAX_WITNESSES {
                let mut w = w;
                w.text = format!("{ctx}: {}", w.text);
                slot.witnesses.push(w);
            }
        }
        slot.worst_deviation = match (slot.worst_deviation, r.worst_deviation) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        };
        slot.tolerance = match (slot.tolerance, r.tolerance) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        };
        let merged = combine(slot.stored_verdict(), &r_verdict);
        slot.adopt_verdict(merged);
    }
    out
}

/// A check's name without the configuration it was run on (which the witnesses carry).
fn generic_name(name: &str) -> String {
    let cut = [
        " (EdgeConfig",
        " (TriangleConfig",
        " (m_x =",
        " (m_v =",
        " (m_u =",
    ]
    .iter()
    .filter_map(|pat| name.find(pat))
    .min();
    match cut {
        Some(i) => name[..i].to_string(),
        None => name.to_string(),
    }
}

/// The worse of two verdicts: fails > skipped-only … > restricted > holds.
fn combine(a: &Verdict, b: &Verdict) -> Verdict {
    use Verdict::*;
    match (a, b) {
        (Fails, _) | (_, Fails) => Fails,
        (HoldsRestricted { domain }, _) | (_, HoldsRestricted { domain }) => HoldsRestricted {
            domain: domain.clone(),
        },
        (Warning, _) | (_, Warning) => Warning,
        (Holds, _) | (_, Holds) => Holds,
        (Skipped { reason }, Skipped { .. }) => Skipped {
            reason: reason.clone(),
        },
    }
}
