//! The oracle interface: reference quantities of the construction, each evaluated in
//! f64 *and* in MPFR at a chosen precision, with the difference as the error estimate of the
//! f64 value. Faster implementations compare against these, point by point.
//!
//! * [`Session`] holds a validated mesh and answers [`Request`]s (the `ppm oracle` JSON-lines
//!   protocol, documented in `docs/oracle.md`).
//! * [`choice`] builds the construction a command or session chose as a `SmoothSurface`
//!   (`ppm eval` and the protocol's `eval` evaluate through it).
//! * [`diff`] compares another implementation's answers against the reference (`ppm diff`).
//! * [`surface_diff`] compares another implementation's sampled surface against the reference
//!   sampling of Sec. 6.2 (`ppm diff --surface`).
//! * [`tsv_diff`] compares a TSV table of eval and S′ points (`ppm diff MESH TABLE.tsv`).

pub mod choice;
pub mod diff;
mod mp_values;
pub mod protocol;
mod query;
mod reference;
pub mod surface_diff;
pub mod tsv_diff;

pub use mp_values::mp_distance;
pub use protocol::{OracleError, Request, Response, Session};

/// Read a text table, naming the line and byte of the first invalid UTF-8 sequence (the
/// error does not repeat the path).
pub(crate) fn read_text_table(path: &std::path::Path) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        format!("line {line}: not valid UTF-8 (byte {at} of the file)")
    })
}
