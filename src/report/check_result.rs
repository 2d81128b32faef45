//! The result of one check: its verdict (earned, never stored as a pass it did not earn), its
//! witnesses and counts.

use serde::Serialize;

/// How many offending elements a check lists in full; the total is always counted.
pub const MAX_WITNESSES: usize = 8;

/// The verdict vocabulary of SPEC.md.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The statement holds on the input (decided, certified or on every sample).
    Holds,
    /// The statement holds on the stated restricted domain only.
    HoldsRestricted {
        /// The restricted domain on which it holds.
        domain: String,
    },
    /// The statement fails; witnesses are attached.
    Fails,
    /// Not a statement of the paper: an informational finding (e.g. unreferenced vertices).
    Warning,
    /// The check could not run because a precondition failed (named).
    Skipped {
        /// The failed precondition.
        reason: String,
    },
}

impl Verdict {
    /// Only `Fails` is a failure.
    pub fn is_failure(&self) -> bool {
        matches!(self, Verdict::Fails)
    }
    /// Short label for text reports.
    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::HoldsRestricted { .. } => "holds (restricted)",
            Verdict::Fails => "FAILS",
            Verdict::Warning => "warning",
            Verdict::Skipped { .. } => "skipped",
        }
    }
}

/// One concrete offending element or counterexample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Witness {
    /// Human-readable description, e.g. "face 12 (line 40): vertices 3, 7, 9 are collinear".
    pub text: String,
    /// Machine-readable form of the same witness.
    pub data: serde_json::Value,
}

impl Witness {
    /// A witness from its description and machine-readable form.
    pub fn new(text: impl Into<String>, data: serde_json::Value) -> Self {
        Witness {
            text: text.into(),
            data,
        }
    }
}

/// The result of one named check.
///
/// Its verdict is earned by construction: the stored verdict is private, read through
/// [`CheckResult::verdict`], which never answers `Holds` (or `HoldsRestricted`) for a result
/// that examined nothing (`Skipped`), recorded an offender or a NaN worst deviation (`Fails`).
/// No public method turns another verdict into `Holds`: [`CheckResult::offend`] fails it,
/// [`CheckResult::skip`] skips it, [`CheckResult::mark_warning`] makes it a measurement and
/// [`CheckResult::restrict`] narrows a `Holds` to its domain.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckResult {
    /// SPEC.md ID of the statement, e.g. `D3.1.1` or `D3.1.6(edges)`.
    pub id: String,
    /// Short name of the check.
    pub name: String,
    /// The stored verdict; `Holds` until [`CheckResult::offend`] records an offender. Read it
    /// through [`CheckResult::verdict`].
    verdict: Verdict,
    /// Number of offending elements found (all of them, not only the listed ones).
    pub offenders: u64,
    /// The first [`MAX_WITNESSES`] offending elements.
    pub witnesses: Vec<Witness>,
    /// Number of elements or samples examined.
    pub examined: u64,
    /// Evaluation errors met (see [`super::OnError`]): offences or skipped samples, counted
    /// either way.
    pub eval_errors: u64,
    /// Seed of the sampler, when the check samples.
    pub seed: Option<u64>,
    /// Worst deviation found, when the check measures one.
    pub worst_deviation: Option<f64>,
    /// Tolerance used, derived from the precision in use, when the check is numerical.
    pub tolerance: Option<f64>,
    /// Free-form remark (method, precision, restriction).
    pub note: String,
}

impl CheckResult {
    /// A passing result with no offenders, nothing examined and no note.
    pub fn new(id: impl Into<String>, name: impl Into<String>) -> Self {
        CheckResult {
            id: id.into(),
            name: name.into(),
            verdict: Verdict::Holds,
            offenders: 0,
            witnesses: Vec::new(),
            examined: 0,
            eval_errors: 0,
            seed: None,
            worst_deviation: None,
            tolerance: None,
            note: String::new(),
        }
    }

    /// Record one offending element: counted always, listed while fewer than
    /// [`MAX_WITNESSES`] are listed. Sets the verdict to `Fails` unless it is a warning.
    pub fn offend(&mut self, w: impl FnOnce() -> Witness) {
        self.offenders += 1;
        if self.witnesses.len() < MAX_WITNESSES {
            self.witnesses.push(w());
        }
        if !matches!(self.verdict, Verdict::Warning) {
            self.verdict = Verdict::Fails;
        }
    }

    /// Sets the note.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.note = note.into();
        self
    }

    /// The verdict, as earned: a stored `Holds` or `HoldsRestricted` reads as `Fails` when an
    /// offender or a NaN worst deviation was recorded, and as `Skipped` when nothing was
    /// examined.
    pub fn verdict(&self) -> Verdict {
        match &self.verdict {
            Verdict::Holds | Verdict::HoldsRestricted { .. }
                if self.offenders > 0 || self.worst_deviation.is_some_and(f64::is_nan) =>
            {
                Verdict::Fails
            }
            Verdict::Holds | Verdict::HoldsRestricted { .. } if self.examined == 0 => {
                Verdict::Skipped {
                    reason: "nothing was examined".into(),
                }
            }
            v => v.clone(),
        }
    }

    /// The verdict is `Fails`.
    pub fn failed(&self) -> bool {
        self.verdict().is_failure()
    }

    /// The meaning of a passing verdict in SPEC.md, "checked and never violated", on
    /// something: `Holds` or `HoldsRestricted` with at least one element examined. A skipped
    /// check, a warning, or a `Holds` that examined nothing is not a pass (`!failed()` accepts
    /// all three).
    pub fn holds_with_evidence(&self) -> bool {
        matches!(
            self.verdict(),
            Verdict::Holds | Verdict::HoldsRestricted { .. }
        ) && self.examined > 0
    }

    /// The check could not run (a precondition failed, named by `reason`): `Skipped`, unless
    /// it already failed.
    pub fn skip(&mut self, reason: impl Into<String>) {
        if !self.verdict.is_failure() {
            self.verdict = Verdict::Skipped {
                reason: reason.into(),
            };
        }
    }

    /// A measurement, not a claim of the paper: a failure or a pass is reported as a
    /// `Warning` with its witnesses; a skipped check stays skipped.
    pub fn mark_warning(&mut self) {
        if !matches!(self.verdict, Verdict::Skipped { .. }) {
            self.verdict = Verdict::Warning;
        }
    }

    /// A `Holds` that holds on a stated restricted domain only. Any other verdict is kept.
    pub fn restrict(&mut self, domain: impl Into<String>) {
        if self.verdict == Verdict::Holds {
            self.verdict = Verdict::HoldsRestricted {
                domain: domain.into(),
            };
        }
    }

    /// Adopts a stored verdict when merging results of one statement (crate-internal;
    /// [`Self::verdict`] still normalises what is read, so this cannot make an unearned pass).
    pub(crate) fn adopt_verdict(&mut self, v: Verdict) {
        self.verdict = v;
    }

    /// The stored verdict, for merging (crate-internal; read [`Self::verdict`]).
    pub(crate) fn stored_verdict(&self) -> &Verdict {
        &self.verdict
    }
}

/// The serialised form: the verdict as earned ([`CheckResult::verdict`]).
#[derive(Serialize)]
struct CheckResultView<'a> {
    id: &'a str,
    name: &'a str,
    verdict: Verdict,
    offenders: u64,
    witnesses: &'a [Witness],
    examined: u64,
    #[serde(skip_serializing_if = "is_zero")]
    eval_errors: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    seed: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    worst_deviation: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tolerance: Option<f64>,
    #[serde(skip_serializing_if = "str::is_empty")]
    note: &'a str,
}

impl Serialize for CheckResult {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        CheckResultView {
            id: &self.id,
            name: &self.name,
            verdict: self.verdict(),
            offenders: self.offenders,
            witnesses: &self.witnesses,
            examined: self.examined,
            eval_errors: self.eval_errors,
            seed: self.seed,
            worst_deviation: self.worst_deviation,
            tolerance: self.tolerance,
            note: &self.note,
        }
        .serialize(s)
    }
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_with_evidence_needs_a_passing_verdict_and_something_examined() {
        let mut skipped = CheckResult::new("X", "x");
        skipped.skip("no input");
        assert!(!skipped.failed() && !skipped.holds_with_evidence());
        let empty = CheckResult::new("X", "x");
        assert!(matches!(empty.verdict(), Verdict::Skipped { .. }));
        assert!(!empty.holds_with_evidence());
        let mut held = CheckResult::new("X", "x");
        held.examined = 3;
        assert!(held.holds_with_evidence());
        let mut restricted = held.clone();
        restricted.restrict("d");
        assert_eq!(
            restricted.verdict(),
            Verdict::HoldsRestricted { domain: "d".into() }
        );
        assert!(restricted.holds_with_evidence());
        let mut warned = held.clone();
        warned.mark_warning();
        assert!(!warned.holds_with_evidence());
        let mut failed = held.clone();
        failed.offend(|| Witness::new("w", serde_json::Value::Null));
        assert!(failed.failed() && !failed.holds_with_evidence());
    }

    /// SPEC X-harness (verdicts by construction): a stored pass is read as what was earned.
    #[test]
    fn x_harness_verdict_is_earned_holds_needs_examined_no_offender_no_nan() {
        let mut r = CheckResult::new("X", "x");
        assert!(
            matches!(r.verdict(), Verdict::Skipped { .. }),
            "nothing examined"
        );
        r.examined = 2;
        assert_eq!(r.verdict(), Verdict::Holds);
        r.worst_deviation = Some(f64::NAN);
        assert_eq!(
            r.verdict(),
            Verdict::Fails,
            "a NaN worst deviation never holds"
        );
        r.worst_deviation = Some(0.5);
        r.offenders = 1;
        assert_eq!(r.verdict(), Verdict::Fails, "an offender never holds");
        // Restricting or skipping never turns a failure into a pass.
        let mut f = CheckResult::new("X", "x");
        f.examined = 1;
        f.offend(|| Witness::new("w", serde_json::Value::Null));
        f.restrict("d");
        f.skip("late");
        assert_eq!(f.verdict(), Verdict::Fails);
        // What is serialised is the earned verdict.
        let empty = CheckResult::new("X", "x");
        let json = serde_json::to_value(&empty).expect("serialise");
        assert_eq!(json["verdict"]["skipped"]["reason"], "nothing was examined");
    }
}
