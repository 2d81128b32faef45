//! Conformance checkers run on whole meshes: each statement of SPEC.md that is checked on data
//! has its checker here or in the module of the concept it checks, and reports through
//! [`crate::report`].

pub mod chapter4;
pub mod errata;
pub(crate) mod spec;

use crate::report::{CheckResult, Verdict, MAX_WITNESSES};

/// Merge results of the same check run on several configurations into one result per ID:
/// counts add up, the worst deviation and the largest tolerance are kept, witnesses are
/// prefixed with the configuration they came from.
pub fn aggregate(parts: impl IntoIterator<Item = (String, CheckResult)>) -> Vec<CheckResult> {
    let mut out: Vec<CheckResult> = Vec::new();
    for (ctx, r) in parts {
        // The part's verdict as earned: an offender or a NaN worst deviation under a stored
        // "holds" is a failure (the stored verdict alone would pass it on).
        let r_verdict = match r.verdict() {
            Verdict::Fails => Verdict::Fails,
            _ => r.stored_verdict().clone(),
        };
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
            // NaN-propagating: `f64::max` would drop a NaN deviation.
            (Some(a), Some(b)) => Some(crate::report::dev_max(a, b)),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::Witness;

    fn part(dev: f64, offenders: usize) -> (String, CheckResult) {
        let mut r = CheckResult::new("X", "x (m_u = 5)");
        r.examined = 10;
        r.worst_deviation = Some(dev);
        for i in 0..offenders {
            r.offend(|| Witness::new(format!("w{i}"), serde_json::Value::Null));
        }
        ("config".into(), r)
    }

    #[test]
    fn aggregate_lists_at_most_max_witnesses_and_counts_every_offender() {
        let out = aggregate([part(0.5, MAX_WITNESSES), part(0.25, MAX_WITNESSES)]);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].witnesses.len(), MAX_WITNESSES);
        assert_eq!(out[0].offenders, 2 * MAX_WITNESSES as u64);
        assert_eq!(out[0].examined, 20);
        assert_eq!(out[0].verdict(), Verdict::Fails);
        assert_eq!(out[0].name, "x");
    }

    #[test]
    fn aggregate_passes_a_nan_deviation_on_as_a_failure() {
        for parts in [
            [part(0.5, 0), part(f64::NAN, 0)],
            [part(f64::NAN, 0), part(0.5, 0)],
        ] {
            let out = aggregate(parts);
            assert!(out[0].worst_deviation.is_some_and(f64::is_nan));
            assert_eq!(out[0].verdict(), Verdict::Fails);
            assert_eq!(out[0].stored_verdict(), &Verdict::Fails);
        }
        let ok = aggregate([part(0.5, 0), part(0.25, 0)]);
        assert_eq!(ok[0].worst_deviation, Some(0.5));
        assert_eq!(ok[0].verdict(), Verdict::Holds);
    }
}
