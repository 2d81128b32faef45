//! `ppm diff`: compare another implementation's answers against the reference.
//!
//! Input: JSON lines, each a protocol request (see [`super::Request`]) plus the other
//! implementation's `"value"` (a number, a number array — nested arrays such as
//! `psi_control`'s are flattened — or a boolean for `member`). Each line is
//! answered by the reference at the session's precision and the deviation |value − reference|
//! is measured in MPFR. The report gives per-op statistics (max, mean, percentiles), the worst
//! items with their arguments, and whether every deviation is within the tolerance.
//!
//! The reference is fixed for the whole table by the command line (mesh, precision, profile,
//! S′): lines that would change it (`load`, `set_certificate`, `set_precision`, `set_profile`, `set_surface`, `set_construction`) are
//! refused as problems, not executed. A table with nothing compared is not a pass.

use super::protocol::Session;
use crate::numeric::{Mp, Scalar};
use serde::Serialize;
use serde_json::Value;

/// One compared item.
#[derive(Debug, Clone, Serialize)]
pub struct Item {
    /// 1-based line of the input.
    pub line: usize,
    /// The request of the line (without `"value"`).
    pub request: Value,
    /// |value − reference| (Euclidean, in MPFR); ∞ for an item not compared.
    pub deviation: f64,
    /// Set when the reference or the input could not be evaluated/compared.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub problem: Option<String>,
}

/// Summary statistics of the deviations.
#[derive(Debug, Clone, Serialize, Default)]
pub struct Stats {
    /// Number of deviations.
    pub count: usize,
    /// Largest deviation.
    pub max: f64,
    /// Mean deviation.
    pub mean: f64,
    /// Median (nearest-rank).
    pub p50: f64,
    /// 90th percentile (nearest-rank).
    pub p90: f64,
    /// 99th percentile (nearest-rank).
    pub p99: f64,
}

impl Stats {
    /// Statistics of a list of deviations (all zero for an empty list).
    pub fn of(mut d: Vec<f64>) -> Stats {
        if d.is_empty() {
            return Stats::default();
        }
        d.sort_by(f64::total_cmp);
        let q = |f: f64| d[((d.len() - 1) as f64 * f).round() as usize];
        Stats {
            count: d.len(),
            max: d[d.len() - 1],
            mean: d.iter().map(|x| x / d.len() as f64).sum::<f64>(),
            p50: q(0.5),
            p90: q(0.9),
            p99: q(0.99),
        }
    }
}

/// The diff report.
#[derive(Debug, Clone, Serialize)]
pub struct DiffReport {
    /// MPFR precision of the reference.
    pub mp_bits: u32,
    /// The tolerance applied.
    pub tolerance: f64,
    /// Statistics of the compared items' deviations.
    pub stats: Stats,
    /// Items that could not be compared (malformed line, reference error, missing value).
    pub problems: Vec<Item>,
    /// The worst items (largest deviation first).
    pub worst: Vec<Item>,
    /// Every item compared and within the tolerance (and at least one item compared).
    pub within_tolerance: bool,
}

/// Ops that would change the reference the table is compared against (fixed by the command
/// line for the whole table).
pub const SESSION_OPS: [&str; 6] = [
    "load",
    "set_certificate",
    "set_precision",
    "set_profile",
    "set_surface",
    "set_construction",
];

pub use crate::numeric::robust_norm;

/// Compare a JSON-lines table against the reference.
pub fn diff_table(
    session: &mut Session,
    table: &str,
    tolerance: f64,
    worst_n: usize,
) -> DiffReport {
    let mut items: Vec<Item> = Vec::new();
    let mut problems = Vec::new();
    for (i, line) in table.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let line_no = i + 1;
        let mut v: Value = match serde_json::from_str(line) {
            Ok(v) => v,
            Err(e) => {
                problems.push(Item {
                    line: line_no,
                    request: Value::Null,
                    deviation: f64::INFINITY,
                    problem: Some(format!("malformed line: {e}")),
                });
                continue;
            }
        };
        let theirs = v.as_object_mut().and_then(|o| o.remove("value"));
        let request = v.clone();
        if let Some(op) = v
            .get("op")
            .and_then(Value::as_str)
            .filter(|op| SESSION_OPS.contains(op))
        {
            problems.push(Item {
                line: line_no,
                request,
                deviation: f64::INFINITY,
                problem: Some(format!(
                    "\"{op}\" would change the reference for the lines after it; a diff table is compared against one reference, fixed by --mesh, --bits, --profile and --sprime"
                )),
            });
            continue;
        }
        let Some(theirs) = theirs else {
            problems.push(Item {
                line: line_no,
                request,
                deviation: f64::INFINITY,
                problem: Some("no \"value\" field".into()),
            });
            continue;
        };
        let resp = session.handle_line(&v.to_string());
        if !resp.ok {
            problems.push(Item {
                line: line_no,
                request,
                deviation: f64::INFINITY,
                problem: Some(format!("reference: {}", resp.error.unwrap_or(Value::Null))),
            });
            continue;
        }
        match compare(&theirs, resp.value.as_ref(), session.bits()) {
            Ok(d) => items.push(Item {
                line: line_no,
                request,
                deviation: d,
                problem: None,
            }),
            Err(msg) => problems.push(Item {
                line: line_no,
                request,
                deviation: f64::INFINITY,
                problem: Some(msg),
            }),
        }
    }
    let stats = Stats::of(items.iter().map(|i| i.deviation).collect());
    items.sort_by(|a, b| b.deviation.total_cmp(&a.deviation));
    items.truncate(worst_n);
    let within_tolerance = problems.is_empty() && stats.count > 0 && stats.max <= tolerance;
    DiffReport {
        mp_bits: session.bits(),
        tolerance,
        stats,
        problems,
        worst: items,
        within_tolerance,
    }
}

/// Deviation between the other implementation's value and the reference's (decimal strings
/// at `bits`, or a boolean).
fn compare(theirs: &Value, reference: Option<&Value>, bits: u32) -> Result<f64, String> {
    let reference = reference.ok_or("reference gave no value")?;
    if let (Some(a), Some(b)) = (theirs.as_bool(), reference.as_bool()) {
        return Ok(if a == b { 0.0 } else { 1.0 });
    }
    let ours = flatten(reference);
    let th = flatten(theirs);
    if ours.is_empty() {
        return Err("reference value is not numerical".into());
    }
    if th.len() != ours.len() {
        return Err(format!(
            "value has {} components, expected {}",
            th.len(),
            ours.len()
        ));
    }
    let mut diffs = Vec::with_capacity(ours.len());
    for (a, b) in th.iter().zip(&ours) {
        let a = a.as_f64().ok_or("value component is not a number")?;
        let rb = match (b.as_str(), b.as_f64()) {
            (Some(b), _) => Mp::parse_decimal(b, bits)
                .ok_or_else(|| format!("reference component {b:?} is not a decimal number"))?,
            (None, Some(x)) => Mp::from_f64(x, bits),
            _ => return Err("reference component is not a number".into()),
        };
        diffs.push(rb.sub(&Mp::from_f64(a, bits)).to_f64());
    }
    Ok(robust_norm(&diffs))
}

/// Text rendering of a diff report.
pub fn render(r: &DiffReport) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let st = &r.stats;
    let _ = writeln!(
        s,
        "compared {} items against the reference (MPFR {} bits): max {:.3e}, mean {:.3e}, p50 {:.3e}, p90 {:.3e}, p99 {:.3e}; tolerance {:.3e}",
        st.count, r.mp_bits, st.max, st.mean, st.p50, st.p90, st.p99, r.tolerance
    );
    for w in &r.worst {
        let _ = writeln!(
            s,
            "  line {:>6}: deviation {:.3e}  {}",
            w.line, w.deviation, w.request
        );
    }
    for p in &r.problems {
        let _ = writeln!(
            s,
            "  line {:>6}: NOT COMPARED: {}  {}",
            p.line,
            p.problem.as_deref().unwrap_or(""),
            p.request
        );
    }
    let _ = writeln!(
        s,
        "verdict: {}",
        if r.within_tolerance {
            "within tolerance"
        } else if r.stats.count == 0 {
            "NOTHING COMPARED (an empty table is not a pass)"
        } else {
            "OUTSIDE tolerance (or items not compared)"
        }
    );
    s
}

/// The leaves of a value (nested arrays flattened in order; a scalar is a one-element list).
fn flatten(v: &Value) -> Vec<&Value> {
    match v {
        Value::Array(a) => a.iter().flat_map(flatten).collect(),
        other => vec![other],
    }
}
