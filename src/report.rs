//! Reports as data: every checker returns a [`CheckResult`] (serde-serialisable), rendered as
//! text or JSON by the CLI. A result always carries the SPEC.md ID of the statement it checks.
//! Checkers record their findings through the one harness, [`Check`] (see [`harness`] for its
//! rules: NaN is an offence, evaluation errors are counted, nothing examined is skipped).

mod check_result;
pub(crate) mod harness;
pub use check_result::{CheckResult, Verdict, Witness, MAX_WITNESSES};
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

/// The rate ("12.3k/s") and the time left ("41 s") of `done` of `total` items after `secs`
/// seconds, as progress lines show them (the command line's, and `fitting`'s tracing lines);
/// "?" while nothing is done yet (no rate to extrapolate from).
pub fn rate_eta(done: usize, total: usize, secs: f64) -> (String, String) {
    if done == 0 || secs <= 0.0 {
        return ("?/s".into(), "?".into());
    }
    let rate = done as f64 / secs;
    let left = total.saturating_sub(done) as f64 / rate;
    let r = if rate >= 1e3 {
        format!("{:.1}k/s", rate / 1e3)
    } else {
        format!("{rate:.1}/s")
    };
    (r, format!("{left:.0} s"))
}

/// Render a list of results as a text table, one line per check plus indented witnesses.
pub fn render_text(results: &[CheckResult]) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    for r in results {
        let verdict = r.verdict();
        let _ = write!(s, "{:<8} {:<18} {:<48}", verdict.label(), r.id, r.name);
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
        match &verdict {
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
    use super::{rate_eta, render_text, tick, Check, Witness};
    use std::sync::atomic::AtomicUsize;
    use std::sync::Mutex;

    #[test]
    fn tick_counts_one_item_per_call_and_shows_done_of_total() {
        let seen = Mutex::new(Vec::new());
        let show = |d: usize, t: usize| seen.lock().unwrap().push((d, t));
        let done = AtomicUsize::new(0);
        for _ in 0..3 {
            tick(Some(&show), &done, 7);
        }
        assert_eq!(*seen.lock().unwrap(), vec![(1, 7), (2, 7), (3, 7)]);
    }

    /// One line per check with its counts, then its note and witnesses indented; the counts,
    /// the note and the "more" line only when there is something to say.
    #[test]
    fn render_text_says_offences_notes_and_witnesses_only_when_there_are_some() {
        let mut bad = Check::new("X-bad", "a failing check");
        bad.holds(true, || Witness::new("never", serde_json::json!({})));
        for k in 0..3 {
            bad.holds(false, || {
                Witness::new(format!("witness {k}"), serde_json::json!({}))
            });
        }
        let bad = bad.finish("a note");
        let mut good = Check::new("X-good", "a holding check");
        good.holds(true, || Witness::new("never", serde_json::json!({})));
        let good = good.finish("");
        let text = render_text(&[bad, good]);
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].contains("X-bad") && lines[0].contains("examined 4, offending 3"));
        assert_eq!(lines[1].trim(), "note: a note");
        assert_eq!(lines[2].trim(), "- witness 0");
        let good_line = lines
            .iter()
            .find(|l| l.contains("X-good"))
            .expect("its line");
        assert!(good_line.trim_end().ends_with("examined 1"), "{good_line}");
        assert!(!text.contains("note: \n") && text.matches("note:").count() == 1);
    }

    #[test]
    fn rate_and_eta_extrapolate_the_elapsed_time() {
        assert_eq!(rate_eta(500, 2000, 2.0), ("250.0/s".into(), "6 s".into()));
        assert_eq!(rate_eta(3000, 5000, 1.5), ("2.0k/s".into(), "1 s".into()));
        assert_eq!(rate_eta(0, 10, 1.0), ("?/s".into(), "?".into()));
    }
}
