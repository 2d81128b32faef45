//! Progress lines of the long commands on stderr: a line rewritten in place (`\r`) on a
//! terminal, nothing when stderr is a file or a pipe (a log would fill with one long line).

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// A progress line `"{label}: done/total {unit} (p%, rate/s, ETA t s)"`, shown only when stderr is a terminal
/// and `wanted`. Call [`Line::finish`] after the work to end the line.
pub(super) struct Line {
    label: &'static str,
    unit: &'static str,
    shown: bool,
    /// Whether the hook was called (a construction that reports no progress leaves no line
    /// to end).
    updated: AtomicBool,
    /// When the line was made: the rate and the ETA are measured from it.
    start: Instant,
}

impl Line {
    /// A progress line for `label` (e.g. "ppm sample") counting `unit` (e.g. "points").
    pub(super) fn new(label: &'static str, unit: &'static str, wanted: bool) -> Self {
        Line {
            label,
            unit,
            shown: wanted && std::io::stderr().is_terminal(),
            updated: AtomicBool::new(false),
            start: Instant::now(),
        }
    }

    /// The hook to pass to the library (`None` when hidden).
    pub(crate) fn hook(&self) -> Option<impl Fn(usize, usize) + Sync + '_> {
        self.shown.then_some(move |d: usize, total: usize| {
            self.updated.store(true, Ordering::Relaxed);
            let (rate, eta) = rate_eta(d, total, self.start.elapsed().as_secs_f64());
            eprint!(
                "\r{}: {d}/{total} {} ({:.0}%, {rate}, ETA {eta})   ",
                self.label,
                self.unit,
                100.0 * d as f64 / total.max(1) as f64
            );
        })
    }

    /// End the line (a newline after the last update, when one was shown).
    pub(super) fn finish(&self) {
        if self.updated.load(Ordering::Relaxed) {
            eprintln!();
        }
    }
}

/// The rate ("12.3k/s") and the time left ("41 s") of `done` of `total` after `secs`; "?" while
/// nothing is done yet (no rate to extrapolate from).
fn rate_eta(done: usize, total: usize, secs: f64) -> (String, String) {
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

#[cfg(test)]
mod tests {
    use super::rate_eta;

    #[test]
    fn rate_and_eta_extrapolate_the_elapsed_time() {
        assert_eq!(rate_eta(500, 2000, 2.0), ("250.0/s".into(), "6 s".into()));
        assert_eq!(rate_eta(3000, 5000, 1.5), ("2.0k/s".into(), "1 s".into()));
        assert_eq!(rate_eta(0, 10, 1.0), ("?/s".into(), "?".into()));
    }
}
