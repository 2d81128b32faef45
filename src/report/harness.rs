//! The check harness: the one sample → evaluate → measure → witness accumulator every checker
//! (mesh, gluing, construction, surface, certify) records its findings with.
//!
//! The rules, stated once (developers' guide: "a check that cannot fail is a defect"):
//!
//! 1. **A non-finite deviation is an offence.** [`Check::deviation`] treats NaN and ±∞ as
//!    outside every tolerance and records the worst deviation as +∞. Comparisons are written
//!    `!(d <= tol)`, never `d > tol`, and maxima with [`dev_max`], never `f64::max` (which
//!    drops a NaN).
//! 2. **An evaluation error is counted, never dropped.** [`Check::error`] takes an explicit
//!    [`OnError`] rule: an error where the statement claims the map is defined is an
//!    offence with a witness ([`OnError::Offence`]); an error that only says the sample lies
//!    outside the statement's domain is a skipped sample ([`OnError::Skip`]), counted in
//!    [`CheckResult::eval_errors`] and named in the note.
//! 3. **Zero examined samples is `Skipped`**, never `Holds` ([`Check::finish`]).
//! 4. **A statement's as-written and restricted forms are one [`Restricted`] pair**: the same
//!    samples feed both, the restricted one only on its domain, and the restricted verdict is
//!    `HoldsRestricted { domain }` exactly when the restriction is a real one.

use super::{CheckResult, Verdict, Witness};

/// What an evaluation error means for the statement being checked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OnError {
    /// The statement claims the evaluation succeeds here: the error is an offence.
    Offence,
    /// The error says the sample lies outside the statement's domain: the sample is skipped
    /// (counted and named in the note, not examined).
    Skip,
}

/// The larger of two deviations, NaN-propagating (unlike `f64::max`, which returns the other
/// operand when one is NaN and so hides a NaN from every later comparison).
pub fn dev_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Rule 1 for an interval enclosure `[lo, hi]` of a deviation at a point: it refutes the
/// bound `tol` when it surely exceeds it (`lo > tol`) or when it is not a finite enclosure
/// (an empty or unbounded enclosure of a point evaluation is a NaN or an overflow).
pub(crate) fn enclosure_exceeds(lo: f64, hi: f64, tol: f64) -> bool {
    !(lo <= tol && lo.is_finite() && hi.is_finite())
}

/// A uniformly distributed point of the standard triangle as barycentric coordinates
/// (λ, μ, ν): (μ, ν) uniform in the unit square, folded across μ + ν = 1. Every sampled check
/// of a statement "for all points of a triangle" draws from this one function (two `f64`
/// draws per point), so a sampler that leaves the triangle is caught by its test here.
pub fn uniform_in_triangle<R: rand::Rng + ?Sized>(rng: &mut R) -> [f64; 3] {
    let (a, b): (f64, f64) = (rng.gen(), rng.gen());
    let (a, b) = if a + b > 1.0 {
        (1.0 - a, 1.0 - b)
    } else {
        (a, b)
    };
    [1.0 - a - b, a, b]
}

/// Accumulates the result of one check under the rules of this module.
#[derive(Debug, Clone)]
pub struct Check {
    r: CheckResult,
    worst: Option<f64>,
    first_skip: Option<String>,
    skipped: u64,
}

impl Check {
    /// A check of the statement `id` ("D4.1.5", "T5.4.1", …) with a short name.
    pub fn new(id: impl Into<String>, name: impl Into<String>) -> Self {
        Check {
            r: CheckResult::new(id, name),
            worst: None,
            first_skip: None,
            skipped: 0,
        }
    }

    /// Adopt a result assembled elsewhere (e.g. from a certificate) so that [`Check::finish`]
    /// applies the rules to it.
    pub fn from_result(r: CheckResult) -> Self {
        let worst = r.worst_deviation;
        Check {
            r,
            worst,
            first_skip: None,
            skipped: 0,
        }
    }

    /// A sampled, numerical check: its seed and its (fixed) tolerance.
    pub fn sampled(id: impl Into<String>, name: impl Into<String>, seed: u64, tol: f64) -> Self {
        Check::new(id, name).with_seed(seed).with_tolerance(tol)
    }

    /// Sets the sampler's seed.
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.r.seed = Some(seed);
        self
    }

    /// The check's sampler, seeded with the seed it reports (0 when none was set), so the
    /// printed seed reproduces the samples by construction.
    pub fn sampler(&self) -> rand_chacha::ChaCha8Rng {
        use rand::SeedableRng;
        rand_chacha::ChaCha8Rng::seed_from_u64(self.r.seed.unwrap_or(0))
    }

    /// Sets the note (kept by `finish("")`).
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.r.note = note.into();
        self
    }

    /// Sets the fixed tolerance [`Check::deviation`] compares with.
    pub fn with_tolerance(mut self, tol: f64) -> Self {
        self.r.tolerance = Some(tol);
        self
    }

    /// The fixed tolerance (0 when none was set).
    pub fn tol(&self) -> f64 {
        self.r.tolerance.unwrap_or(0.0)
    }

    /// The result so far (read-only).
    pub fn result(&self) -> &CheckResult {
        &self.r
    }

    /// Examine one deviation against the fixed tolerance. Rule 1: a non-finite deviation is an
    /// offence.
    pub fn deviation(&mut self, d: f64, w: impl FnOnce() -> Witness) {
        let tol = self.tol();
        self.deviation_within(d, tol, w);
    }

    /// Examine one deviation against a per-sample tolerance `tol` (the reported tolerance is the
    /// largest one used). Rule 1: a non-finite deviation is an offence.
    pub fn deviation_within(&mut self, d: f64, tol: f64, w: impl FnOnce() -> Witness) {
        self.r.examined += 1;
        self.r.tolerance = Some(self.r.tolerance.map_or(tol, |t| t.max(tol)));
        let shown = if d.is_finite() { d } else { f64::INFINITY };
        self.worst = Some(self.worst.map_or(shown, |x| x.max(shown)));
        if !(d.is_finite() && d <= tol) {
            self.r.offend(w);
        }
    }

    /// Examine one decided condition.
    pub fn holds(&mut self, ok: bool, w: impl FnOnce() -> Witness) {
        self.r.examined += 1;
        if !ok {
            self.r.offend(w);
        }
    }

    /// Count `n` examined elements of an exact check (offences are recorded by
    /// [`Check::offend`]).
    pub fn examined(&mut self, n: u64) {
        self.r.examined += n;
    }

    /// Record an offence not tied to one examined sample (a failed precondition, an empty
    /// witness search).
    pub fn offend(&mut self, w: impl FnOnce() -> Witness) {
        self.r.offend(w);
    }

    /// Rule 2: an evaluation failed. Counted always; by `rule` an offence (the witness is
    /// recorded, and the sample counts as examined) or a skipped sample (named in the note).
    pub fn error(
        &mut self,
        rule: OnError,
        err: impl std::fmt::Display,
        w: impl FnOnce() -> Witness,
    ) {
        self.r.eval_errors += 1;
        match rule {
            OnError::Offence => {
                self.r.examined += 1;
                self.r.offend(w);
            }
            OnError::Skip => {
                self.skipped += 1;
                if self.first_skip.is_none() {
                    self.first_skip = Some(err.to_string());
                }
            }
        }
    }

    /// [`Check::deviation`] of an evaluated deviation, or [`Check::error`] with `rule`.
    pub fn measure<E: std::fmt::Display>(
        &mut self,
        d: Result<f64, E>,
        rule: OnError,
        w: impl FnOnce() -> Witness,
    ) {
        match d {
            Ok(d) => self.deviation(d, w),
            Err(e) => self.error(rule, e, w),
        }
    }

    /// The verdict is `Fails` so far.
    pub fn failed(&self) -> bool {
        self.r.failed()
    }

    /// Mark the result as a measurement, not a claim of the paper: offences become a warning.
    pub fn finish_as_warning(self, note: impl Into<String>) -> CheckResult {
        let mut r = self.finish(note);
        if r.failed() {
            r.mark_warning();
        }
        r
    }

    /// Close the check with its note (an empty `note` keeps the note already set). Rule 3: nothing examined (and nothing failed) is
    /// `Skipped`; rule 2: skipped evaluation errors are named in the note.
    pub fn finish(mut self, note: impl Into<String>) -> CheckResult {
        let mut note: String = note.into();
        if note.is_empty() {
            note = std::mem::take(&mut self.r.note);
        }
        if self.worst.is_none() && self.r.tolerance.is_some() {
            self.worst = Some(0.0);
        }
        if self.worst.is_some() {
            self.r.worst_deviation = self.worst;
        }
        if let Some(first) = &self.first_skip {
            let skipped = format!(
                "{} sample(s) skipped: evaluation outside the statement's domain (first: {first})",
                self.skipped
            );
            note = if note.is_empty() {
                skipped
            } else {
                format!("{note}; {skipped}")
            };
        }
        self.r.note = note;
        if self.r.examined == 0
            && matches!(
                self.r.stored_verdict(),
                Verdict::Holds | Verdict::HoldsRestricted { .. }
            )
        {
            self.r.skip(if self.r.eval_errors > 0 {
                "every sample failed to evaluate; nothing was examined"
            } else {
                "no sample fell in the domain of the statement"
            });
        }
        self.r
    }
}

/// Exact (non-sampled) checkers fill the result's fields directly while they count elements;
/// [`Check::finish`] still applies rule 3 to them.
impl std::ops::Deref for Check {
    type Target = CheckResult;
    fn deref(&self) -> &CheckResult {
        &self.r
    }
}

impl std::ops::DerefMut for Check {
    fn deref_mut(&mut self) -> &mut CheckResult {
        &mut self.r
    }
}

/// Rule 4: the as-written statement and its restriction, checked on the same samples. The
/// restricted result has the ID `"{id}[restricted]"`.
#[derive(Debug, Clone)]
pub struct Restricted {
    /// The statement as written.
    pub all: Check,
    /// The statement on its restricted domain.
    pub restricted: Check,
}

impl Restricted {
    /// Both checks of statement `id`, sampled with `seed`, at tolerance `tol`.
    pub fn sampled(id: &str, name: &str, seed: u64, tol: f64) -> Self {
        Restricted {
            all: Check::sampled(id, name, seed, tol),
            restricted: Check::sampled(format!("{id}[restricted]"), name, seed, tol),
        }
    }

    /// Examine one deviation: always for the statement as written, and for the restriction when
    /// the sample lies in its domain.
    pub fn deviation(&mut self, d: f64, in_domain: bool, w: impl Fn() -> Witness) {
        self.all.deviation(d, &w);
        if in_domain {
            self.restricted.deviation(d, w);
        }
    }

    /// Examine one decided condition on both.
    pub fn holds(&mut self, ok: bool, in_domain: bool, w: impl Fn() -> Witness) {
        self.all.holds(ok, &w);
        if in_domain {
            self.restricted.holds(ok, w);
        }
    }

    /// Close both. The restricted result reads `HoldsRestricted { domain }` when it holds and
    /// `is_restriction` (the domain is smaller than the stated one); otherwise it keeps the
    /// as-written verdict vocabulary.
    pub fn finish(self, note: String, domain: String, is_restriction: bool) -> Vec<CheckResult> {
        let all = self.all.finish(note.clone());
        let mut res = self.restricted.finish(note);
        if is_restriction {
            res.restrict(domain);
        }
        vec![all, res]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn w() -> Witness {
        Witness::new("w", json!({}))
    }

    #[test]
    fn nan_and_infinite_deviations_are_offences() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut c = Check::sampled("X", "x", 1, 1.0);
            c.deviation(0.5, w);
            c.deviation(bad, w);
            let r = c.finish("");
            assert!(r.failed(), "{bad} must fail");
            assert_eq!(r.offenders, 1);
            assert_eq!(r.worst_deviation, Some(f64::INFINITY));
        }
        assert!(dev_max(f64::NAN, 1.0).is_nan() && dev_max(1.0, f64::NAN).is_nan());
    }

    #[test]
    fn errors_are_counted_by_rule() {
        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.deviation(0.5, w);
        c.error(OnError::Offence, "boom", w);
        let r = c.finish("");
        assert!(r.failed());
        assert_eq!(r.eval_errors, 1);
        assert_eq!(r.examined, 2, "an offending error is an examined sample");

        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.deviation(0.0, w);
        c.error(OnError::Skip, "outside", w);
        let r = c.finish("n");
        assert_eq!(r.verdict(), Verdict::Holds);
        assert_eq!(r.eval_errors, 1);
        assert!(r.note.contains("1 sample(s) skipped") && r.note.contains("outside"));

        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.error(OnError::Skip, "outside", w);
        assert!(matches!(c.finish("").verdict(), Verdict::Skipped { .. }));

        // The note counts the skipped samples only, not the errors that were offences.
        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.error(OnError::Offence, "boom", w);
        c.error(OnError::Skip, "outside", w);
        let r = c.finish("");
        assert_eq!(r.eval_errors, 2);
        assert!(r.note.contains("1 sample(s) skipped"), "{}", r.note);
    }

    /// SPEC X-harness, rule 1 for enclosures (used by the certify provers).
    #[test]
    fn x_harness_enclosure_refutes_when_surely_above_or_not_finite() {
        assert!(!enclosure_exceeds(0.5, 2.0, 1.0), "straddling: not refuted");
        assert!(!enclosure_exceeds(1.0, 1.0, 1.0), "lo = tol: not refuted");
        assert!(enclosure_exceeds(1.5, 2.0, 1.0), "lo > tol: refuted");
        for (lo, hi) in [
            (f64::NAN, 0.5),
            (0.5, f64::NAN),
            (0.5, f64::INFINITY),
            (f64::NEG_INFINITY, 0.5),
        ] {
            assert!(enclosure_exceeds(lo, hi, 1.0), "[{lo}, {hi}] must refute");
        }
    }

    /// SPEC X-harness: the worst deviation reported is the largest one examined.
    #[test]
    fn x_harness_worst_deviation_is_the_largest() {
        let mut c = Check::sampled("X", "x", 1, 1.0);
        for d in [0.25, 0.75, 0.5] {
            c.deviation(d, w);
        }
        assert_eq!(c.finish("").worst_deviation, Some(0.75));
        assert_eq!(dev_max(0.25, 0.75), 0.75);
        assert_eq!(dev_max(0.75, 0.25), 0.75);
    }

    /// SPEC X-harness, rule 3 for exact checks: counted elements make the check examined.
    #[test]
    fn x_harness_exact_counts_are_examined() {
        let mut c = Check::new("X", "x");
        c.examined(3);
        c.examined(2);
        let r = c.finish("");
        assert_eq!(r.examined, 5);
        assert_eq!(r.verdict(), Verdict::Holds);
    }

    /// SPEC X-harness: `measure` routes a value to rule 1 and an error to rule 2; `failed`
    /// tracks the verdict as samples arrive.
    #[test]
    fn x_harness_measure_routes_values_and_errors() {
        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.measure(Ok::<f64, &str>(0.5), OnError::Offence, w);
        c.measure(Err("outside"), OnError::Skip, w);
        assert!(!c.failed());
        assert_eq!((c.examined, c.eval_errors), (1, 1));
        c.measure(Ok::<f64, &str>(2.0), OnError::Offence, w);
        assert!(c.failed());
        let r = c.finish("");
        assert_eq!((r.examined, r.offenders, r.eval_errors), (2, 1, 1));
    }

    /// SPEC X-harness, rule 3: the skip reason says whether samples failed to evaluate.
    #[test]
    fn x_harness_skip_reason_names_the_cause() {
        let reason = |r: CheckResult| match r.verdict() {
            Verdict::Skipped { reason } => reason,
            v => panic!("expected skipped, got {v:?}"),
        };
        let mut c = Check::sampled("X", "x", 1, 1.0);
        c.error(OnError::Skip, "outside", w);
        assert!(reason(c.finish("")).contains("every sample failed to evaluate"));
        let c = Check::sampled("X", "x", 1, 1.0);
        assert!(reason(c.finish("")).contains("no sample fell in the domain"));
    }

    /// SPEC X-harness, rule 4 for decided conditions: a failure outside the restricted domain
    /// fails only the statement as written.
    #[test]
    fn x_harness_restricted_pair_of_decided_conditions() {
        let mut p = Restricted::sampled("X", "x", 1, 1.0);
        p.holds(false, false, w);
        p.holds(true, true, w);
        let v = p.finish(String::new(), "d".into(), true);
        assert!(v[0].failed());
        assert_eq!((v[0].examined, v[1].examined), (2, 1));
        assert_eq!(
            v[1].verdict(),
            Verdict::HoldsRestricted { domain: "d".into() }
        );
    }

    #[test]
    fn nothing_examined_is_skipped() {
        let r = Check::new("X", "x").finish("");
        assert!(matches!(r.verdict(), Verdict::Skipped { .. }));
        let p = Restricted::sampled("X", "x", 1, 1.0).finish(String::new(), "d".into(), true);
        assert!(p
            .iter()
            .all(|r| matches!(r.verdict(), Verdict::Skipped { .. })));
    }

    #[test]
    fn restricted_pair() {
        let mut p = Restricted::sampled("X", "x", 1, 1.0);
        p.deviation(2.0, false, w);
        p.deviation(0.5, true, w);
        let v = p.finish(String::new(), "d".into(), true);
        assert!(v[0].failed());
        assert_eq!(v[1].id, "X[restricted]");
        assert_eq!(
            v[1].verdict(),
            Verdict::HoldsRestricted { domain: "d".into() }
        );
    }

    /// The triangle sampler stays in the closed triangle, is uniform there (each coordinate's
    /// mean 1/3; the part μ + ν > 1/2 has 3/4 of the area) and is determined by the seed.
    #[test]
    fn x_harness_uniform_in_triangle_is_uniform_in_the_triangle() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let n = 40_000;
        let (mut mean, mut far) = ([0.0; 3], 0usize);
        for _ in 0..n {
            let b = uniform_in_triangle(&mut rng);
            assert!(b.iter().all(|x| (0.0..=1.0).contains(x)), "{b:?}");
            assert!(
                (b.iter().sum::<f64>() - 1.0).abs() <= 2.0 * f64::EPSILON,
                "{b:?}"
            );
            for d in 0..3 {
                mean[d] += b[d] / n as f64;
            }
            far += usize::from(b[1] + b[2] > 0.5);
        }
        // Standard error of a mean ≈ 0.24/√n = 0.0012; of the fraction ≈ 0.0022.
        for m in mean {
            assert!((m - 1.0 / 3.0).abs() < 0.006, "{mean:?}");
        }
        assert!((far as f64 / n as f64 - 0.75).abs() < 0.011, "{far}");
        let again = uniform_in_triangle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(7));
        let first = uniform_in_triangle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(7));
        assert_eq!(again, first);
    }
}
