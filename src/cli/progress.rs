//! Progress lines of the long commands on stderr: a line rewritten in place (`\r`) on a
//! terminal, nothing when stderr is a file or a pipe (a log would fill with one long line).

use std::io::IsTerminal;

/// A progress line `"{label}: done/total {unit} (p%)"`, shown only when stderr is a terminal
/// and `wanted`. Call [`Line::finish`] after the work to end the line.
pub(super) struct Line {
    label: &'static str,
    unit: &'static str,
    shown: bool,
}

impl Line {
    /// A progress line for `label` (e.g. "ppm sample") counting `unit` (e.g. "points").
    pub fn new(label: &'static str, unit: &'static str, wanted: bool) -> Self {
        Line {
            label,
            unit,
            shown: wanted && std::io::stderr().is_terminal(),
        }
    }

    /// The hook to pass to the library (`None` when hidden).
    pub(crate) fn hook(&self) -> Option<impl Fn(usize, usize) + Sync + '_> {
        self.shown.then_some(move |d: usize, total: usize| {
            eprint!(
                "\r{}: {d}/{total} {} ({:.0}%)",
                self.label,
                self.unit,
                100.0 * d as f64 / total.max(1) as f64
            );
        })
    }

    /// End the line (a newline after the last update, when shown).
    pub fn finish(&self) {
        if self.shown {
            eprintln!();
        }
    }
}
