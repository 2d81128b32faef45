//! The loop of every exact check of Mello–Velho Secs. 2–3, in both dimensions: one exact
//! decision per cell (or per cell and component); a refutation becomes a witness, the smallest
//! certified lower bound is kept, and unresolved decisions make the check skipped — never
//! "holds" — unless something already failed it.

use crate::report::{CheckResult, Witness};
use crate::sdiff::common::positivity::Decision;

/// A refuting point of an exact decision, for the witness.
pub(crate) struct Refutation<'a> {
    /// The point in barycentric coordinates (planar) or the chart (tetrahedra), exact.
    pub point: &'a [String; 3],
    /// The same point in f64.
    pub point_f64: [f64; 3],
    /// The decided polynomial at the point, exact.
    pub value: &'a str,
    /// The same value in f64.
    pub value_f64: f64,
}

/// What a check has decided so far.
#[derive(Debug, Default)]
pub(crate) struct Tally {
    unresolved: u64,
    worst: Option<f64>,
}

impl Tally {
    /// Records `d` in `r`: a refutation is an offender whose witness `witness` makes.
    pub(crate) fn record(
        &mut self,
        r: &mut CheckResult,
        d: &Decision,
        witness: impl FnOnce(Refutation<'_>) -> Witness,
    ) {
        match d {
            Decision::Certified { lower_bound, .. } => {
                self.worst = Some(self.worst.map_or(*lower_bound, |w| w.min(*lower_bound)));
            }
            Decision::Refuted {
                point,
                point_f64,
                value,
                value_f64,
            } => r.offend(|| {
                witness(Refutation {
                    point,
                    point_f64: *point_f64,
                    value,
                    value_f64: *value_f64,
                })
            }),
            Decision::Unresolved { .. } => self.unresolved += 1,
        }
    }

    /// Counts a decision left unresolved outside [`Tally::record`].
    pub(crate) fn unresolved(&mut self) {
        self.unresolved += 1;
    }

    /// The smallest lower bound over the certificates recorded.
    pub(crate) fn worst(&self) -> Option<f64> {
        self.worst
    }

    /// Ends the check: unresolved decisions make it skipped unless it already failed.
    pub(crate) fn finish(self, r: &mut CheckResult) {
        if self.unresolved > 0 && !r.failed() {
            r.skip(format!(
                "{} decisions unresolved within the subdivision budget",
                self.unresolved
            ));
        }
    }
}
