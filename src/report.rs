//! Reports as data: every checker returns a [`CheckResult`] (serde-serialisable), rendered as
//! text or JSON by the CLI. A result always carries the SPEC.md ID of the statement it checks.
//! Checkers record their findings through the one harness, [`Check`] (see [`harness`] for its
//! rules: NaN is an offence, evaluation errors are counted, nothing examined is skipped).

use serde::Serialize;

pub mod harness;
pub use harness::{dev_max, uniform_in_triangle, Check, OnError, Restricted};

/// A progress hook of a long computation, called with (items done, total); the command line
/// decides whether and how to show it (the library prints nothing). Items are what the
/// computation counts: sample points (`ppm sample`), checked configurations (`ppm check
/// --spec`), certified configurations (`ppm certify`).
pub type Progress<'a> = Option<&'a (dyn Fn(usize, usize) + Sync)>;

/// Call `progress` with (done, total) after one more item, from any thread.
pub(crate) fn tick(progress: Progress, done: &std::sync::atomic::AtomicUsize, total: usize) {
    if let Some(show) = progress {
        let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        show(d, total);
    }
}

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
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckResult {
    /// SPEC.md ID of the statement, e.g. `D3.1.1` or `D3.1.6(edges)`.
    pub id: String,
    /// Short name of the check.
    pub name: String,
    /// The verdict; `Holds` until [`CheckResult::offend`] records an offender.
    pub verdict: Verdict,
    /// Number of offending elements found (all of them, not only the listed ones).
    pub offenders: u64,
    /// The first [`MAX_WITNESSES`] offending elements.
    pub witnesses: Vec<Witness>,
    /// Number of elements or samples examined.
    pub examined: u64,
    /// Evaluation errors met (see [`harness::OnError`]): offences or skipped samples, counted
    /// either way.
    #[serde(skip_serializing_if = "is_zero")]
    pub eval_errors: u64,
    /// Seed of the sampler, when the check samples.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Worst deviation found, when the check measures one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub worst_deviation: Option<f64>,
    /// Tolerance used, derived from the precision in use, when the check is numerical.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Free-form remark (method, precision, restriction).
    #[serde(skip_serializing_if = "String::is_empty")]
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

    /// The verdict is `Fails`.
    pub fn failed(&self) -> bool {
        self.verdict.is_failure()
    }

    /// The meaning of a passing verdict in SPEC.md, "checked and never violated", on
    /// something: `Holds` or `HoldsRestricted` with at least one element examined. A skipped
    /// check, a warning, or a `Holds` that examined nothing is not a pass (`!failed()` accepts
    /// all three).
    pub fn holds_with_evidence(&self) -> bool {
        matches!(
            self.verdict,
            Verdict::Holds | Verdict::HoldsRestricted { .. }
        ) && self.examined > 0
    }
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}

/// Render a list of results as a text table, one line per check plus indented witnesses.
pub fn render_text(results: &[CheckResult]) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    for r in results {
        let _ = write!(s, "{:<8} {:<18} {:<48}", r.verdict.label(), r.id, r.name);
        let _ = write!(s, " examined {}", r.examined);
        if r.offenders > 0 {
            let _ = write!(s, ", offending {}", r.offenders);
        }
        if r.eval_errors > 0 {
            let _ = write!(s, ", evaluation errors {}", r.eval_errors);
        }
        if let Some(seed) = r.seed {
            let _ = write!(s, ", seed {seed}");
        }
        if let Some(d) = r.worst_deviation {
            let _ = write!(s, ", worst deviation {d:.3e}");
        }
        if let Some(t) = r.tolerance {
            let _ = write!(s, ", tolerance {t:.3e}");
        }
        s.push('\n');
        match &r.verdict {
            Verdict::HoldsRestricted { domain } => {
                let _ = writeln!(s, "           restricted to: {domain}");
            }
            Verdict::Skipped { reason } => {
                let _ = writeln!(s, "           skipped: {reason}");
            }
            _ => {}
        }
        if !r.note.is_empty() {
            let _ = writeln!(s, "           note: {}", r.note);
        }
        for w in &r.witnesses {
            let _ = writeln!(s, "           - {}", w.text);
        }
        if r.offenders > r.witnesses.len() as u64 {
            let _ = writeln!(
                s,
                "           ... and {} more",
                r.offenders - r.witnesses.len() as u64
            );
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_with_evidence_needs_a_passing_verdict_and_something_examined() {
        let mut skipped = CheckResult::new("X", "x");
        skipped.verdict = Verdict::Skipped {
            reason: "no input".into(),
        };
        assert!(!skipped.failed() && !skipped.holds_with_evidence());
        let empty = CheckResult::new("X", "x");
        assert_eq!(empty.verdict, Verdict::Holds);
        assert!(!empty.holds_with_evidence());
        let mut held = CheckResult::new("X", "x");
        held.examined = 3;
        assert!(held.holds_with_evidence());
        let mut restricted = held.clone();
        restricted.verdict = Verdict::HoldsRestricted { domain: "d".into() };
        assert!(restricted.holds_with_evidence());
        let mut warned = held.clone();
        warned.verdict = Verdict::Warning;
        assert!(!warned.holds_with_evidence());
        let mut failed = held.clone();
        failed.offend(|| Witness::new("w", serde_json::Value::Null));
        assert!(failed.failed() && !failed.holds_with_evidence());
    }
}
