//! Which multi-precision implementation `--precision mp:BITS` runs on: the pure-Rust default
//! [`super::Mp`] (always built) or MPFR `MpMpfr` (feature `mpfr`). The maps are
//! generic over [`super::Scalar`], so the choice is made once, where a run is dispatched.

use serde::Serialize;

/// A multi-precision backend compiled into this build.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub enum MpBackend {
    /// astro-float (pure Rust), the type [`super::Mp`].
    #[default]
    PureRust,
    /// MPFR via rug, the type [`super::MpMpfr`].
    #[cfg(feature = "mpfr")]
    Mpfr,
}

impl MpBackend {
    /// Every backend built into this binary.
    pub fn available() -> Vec<MpBackend> {
        vec![
            MpBackend::PureRust,
            #[cfg(feature = "mpfr")]
            MpBackend::Mpfr,
        ]
    }
    /// Command-line name: `astro` or `mpfr`.
    pub fn name(self) -> &'static str {
        match self {
            MpBackend::PureRust => "astro",
            #[cfg(feature = "mpfr")]
            MpBackend::Mpfr => "mpfr",
        }
    }
    /// Long description for reports.
    pub fn describe(self) -> &'static str {
        match self {
            MpBackend::PureRust => "astro-float (pure Rust)",
            #[cfg(feature = "mpfr")]
            MpBackend::Mpfr => "MPFR",
        }
    }
    /// Parse a command-line name; the error names the backends this build has.
    pub fn parse(s: &str) -> Result<MpBackend, String> {
        let names: Vec<&str> = Self::available().iter().map(|b| b.name()).collect();
        Self::available()
            .into_iter()
            .find(|b| b.name() == s)
            .ok_or_else(|| {
                let hint = if s == "mpfr" {
                    " (rebuild with `--features mpfr`)"
                } else {
                    ""
                };
                format!(
                    "--mp-backend {s}: this build has {}{hint}",
                    names.join(", ")
                )
            })
    }
}
