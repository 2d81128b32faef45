//! The verdict assertions of every test, and what they saw of each SPEC.md row: every
//! assertion of a verdict on real input ([`assert_holds`], [`assert_fails_as_written`], or an
//! explicit [`record`]) appends (row ID, verdict, examined) to
//! `<target>/spec-verdicts/<test binary>.jsonl`; the `verdicts` test binary, which runs after
//! the others, compares them with the verdicts SPEC.md states (SPEC `X-spec-verdicts`).
//!
//! One file per test binary, truncated by the binary's first record: the files say what the
//! latest run of each binary saw. Shared by the integration tests, the proofs and the crate's
//! unit tests (`#[path]`-included), so every kind of test records the same way.

use pseudomanifold::report::{CheckResult, Verdict};
use std::io::Write;
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

/// A verdict asserted by a test on real (not planted) input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Seen {
    /// Checked and never violated, on `examined` > 0 cases.
    Holds,
    /// Holds on a stated restricted domain.
    Restricted,
    /// Fails as written, with a witness.
    Fails,
    /// Proven (interval or exact certificate).
    Certified,
    /// A planted fault was caught (the row is about a checker).
    Caught,
    /// A quantity was measured and reported (the row states a measurement, not a claim).
    Measured,
}

impl Seen {
    /// The word written in the record file.
    pub fn word(self) -> &'static str {
        match self {
            Seen::Holds => "holds",
            Seen::Restricted => "restricted",
            Seen::Fails => "fails",
            Seen::Certified => "certified",
            Seen::Caught => "caught",
            Seen::Measured => "measured",
        }
    }
}

/// `<target>/spec-verdicts`, found from the running test executable
/// (`<target>/<profile>/deps/<name>-<hash>`), so it works for every kind of test binary and
/// any `CARGO_TARGET_DIR`.
pub fn record_dir() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let target = exe.parent()?.parent()?.parent()?;
    Some(target.join("spec-verdicts"))
}

/// The test binary's name without cargo's hash suffix.
fn binary_name() -> String {
    let stem = std::env::current_exe()
        .ok()
        .and_then(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .unwrap_or_else(|| "unknown".to_string());
    match stem.rsplit_once('-') {
        Some((name, hash)) if hash.chars().all(|c| c.is_ascii_hexdigit()) => name.to_string(),
        _ => stem,
    }
}

static FILE: OnceLock<Option<Mutex<std::fs::File>>> = OnceLock::new();

/// Record that a test asserted `seen` for the SPEC row `id` on `examined` cases. Recording is
/// best effort (an unwritable target directory loses records, which the `verdicts` binary then
/// reports as unrecorded rows), never a test failure by itself.
pub fn record(id: &str, seen: Seen, examined: u64) {
    let file = FILE.get_or_init(|| {
        let dir = record_dir()?;
        std::fs::create_dir_all(&dir).ok()?;
        let path = dir.join(format!("{}.jsonl", binary_name()));
        std::fs::File::create(path).ok().map(Mutex::new)
    });
    if let Some(f) = file {
        let line = serde_json::json!({"id": id, "seen": seen.word(), "examined": examined});
        let mut f = f.lock().unwrap_or_else(|e| e.into_inner());
        let _ = writeln!(f, "{line}");
    }
}

/// Panics with the rendered report unless `r` holds on something examined
/// (`CheckResult::holds_with_evidence`: a skipped check, or one that examined nothing, is not a
/// pass); records the verdict for SPEC `X-spec-verdicts`.
#[track_caller]
pub fn assert_holds(r: &CheckResult) {
    assert_holds_for("check", r);
}

/// [`assert_holds`] with the case named in the message (a mesh, a parameter set).
#[track_caller]
pub fn assert_holds_for(what: &str, r: &CheckResult) {
    assert!(
        r.holds_with_evidence(),
        "{what}: {} should hold on something examined:\n{}",
        r.id,
        pseudomanifold::report::render_text(std::slice::from_ref(r))
    );
    let seen = match r.verdict() {
        Verdict::HoldsRestricted { .. } => Seen::Restricted,
        _ => Seen::Holds,
    };
    record(&r.id, seen, r.examined);
}

/// The statement fails as written on real input, with a witness, on something examined; records
/// the verdict for SPEC `X-spec-verdicts`.
#[track_caller]
pub fn assert_fails_as_written(r: &CheckResult) {
    assert!(
        r.failed() && !r.witnesses.is_empty() && r.examined > 0,
        "{} should fail as written, with a witness, on something examined:\n{}",
        r.id,
        pseudomanifold::report::render_text(std::slice::from_ref(r))
    );
    record(&r.id, Seen::Fails, r.examined);
}

/// A planted fault is caught: the check fails with a witness. Recorded as `caught` (it says
/// nothing of the paper's statement; a row about a checker states it).
#[track_caller]
pub fn assert_caught(r: &CheckResult) {
    assert!(
        r.failed() && !r.witnesses.is_empty(),
        "{}: the planted fault was not caught:\n{}",
        r.id,
        pseudomanifold::report::render_text(std::slice::from_ref(r))
    );
    record(&r.id, Seen::Caught, r.examined.max(1));
}
