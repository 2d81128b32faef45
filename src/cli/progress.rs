//! Progress lines of the long commands on stderr: a line rewritten in place (`\r`) on a
//! terminal, nothing when stderr is a file or a pipe (a log would fill with one long line).

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use crate::report::rate_eta;

/// A progress line `"{label}: done/total {unit} (p%, rate, ETA t s)"`, shown only when stderr
/// is a terminal and `wanted`. Call [`Line::finish`] after the work to end the line.
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
