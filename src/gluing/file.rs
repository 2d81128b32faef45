//! The text format read by `ppm gluing FILE`: 1-D gluing data in TOML, decided by the exact
//! backend. Rationals are strings ("1/3", "-2", "0.25") or TOML integers; TOML floats are refused
//! because they are inexact.
//!
//! ```toml
//! name = "fork (App. A.2)"      # optional
//!
//! [[domain]]                    # a p-domain Ω_i (repeat an id to make a union of intervals)
//! id = 1
//! interval = ["-3", "-1"]       # the open interval (-3, -1)
//!
//! [[glue]]                      # one piece of Ω_ij ⊆ Ω_i and of φ_ji : Ω_ij → Ω_ji
//! i = 1
//! j = 2
//! omega_ij = ["-3", "-2"]       # this piece of Ω_ij
//! a = "1"                       # φ_ji(x) = a·x + b on the piece
//! b = "4"
//! ```
//!
//! Every ordered pair is listed explicitly, as the paper lists them: φ_12 is not derived from
//! φ_21 — the checker decides 3(b). Several `[[glue]]` entries with the same (i, j) form a
//! gluing domain with several pieces. A pair with no entry has Ω_ij = ∅, except the diagonal:
//! without an (i, i) entry, Ω_ii = Ω_i and φ_ii = id (list (i, i) explicitly to override).
//!
//! Limits: [`MAX_FILE_BYTES`], [`MAX_DOMAIN_ENTRIES`], [`MAX_GLUE_ENTRIES`],
//! [`MAX_RATIONAL_CHARS`]; past each, a [`GluingFileError`] naming the file and field.

use super::error::GluingFileError;
use super::exact1d::interval::{parse_q, Interval, Q};
use super::exact1d::Exact1d;
use super::Idx;
use std::io::Read;
use std::path::Path;
use toml::Value;

/// Largest gluing file read, in bytes.
pub const MAX_FILE_BYTES: u64 = 1 << 20;
/// Most `[[domain]]` entries in a file.
pub const MAX_DOMAIN_ENTRIES: usize = 256;
/// Most `[[glue]]` entries in a file. The exact checks are polynomial in the number of pieces
/// (the cocycle checks compose every pair of pieces; about 1 s for 128 + 128 pieces on one pair,
/// release build), so these limits bound the time a file can take, as they bound its memory.
pub const MAX_GLUE_ENTRIES: usize = 256;
/// Longest rational, in characters (decimal parsing of big integers is quadratic).
pub const MAX_RATIONAL_CHARS: usize = 512;
/// Largest exact work W² accepted, W = Σ over the file's intervals and pieces of (1 + the
/// decimal digits of their rationals). The decisions compose pieces pairwise (the cocycle
/// checks, up to (Σ pieces)² cells) and big-rational arithmetic costs grow with the digits, so
/// the entry limits alone did not bound the time (one domain, 256 pieces of 255-digit rationals:
/// 16–60 s). Measured (release, loaded 2-core machine): W² = 1.6e8 (64 pieces, 64 digits)
/// 5.7 s; 6e8 (32 pieces, 255 digits) 15 s, now refused.
pub const MAX_EXACT_WORK: u128 = 200_000_000;

/// Decimal digits of a rational (numerator and denominator), from their bit lengths.
fn digits(q: &Q) -> u128 {
    (q.numer().bits() + q.denom().bits()) as u128 * 30_103 / 100_000 + 1
}

/// A parsed gluing file.
#[derive(Clone, Debug)]
pub struct GluingFile {
    /// The optional top-level `name`.
    pub name: Option<String>,
    /// The gluing data the file describes.
    pub data: Exact1d,
}

/// Read and parse a gluing file.
pub fn read_gluing_file(path: &Path) -> Result<GluingFile, GluingFileError> {
    let io = |source| GluingFileError::Io {
        file: path.to_path_buf(),
        source,
    };
    let f = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    // Read one byte past the limit, so a larger file is refused without reading it whole.
    f.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        let size = std::fs::metadata(path).map_or(bytes.len() as u64, |m| m.len());
        return Err(GluingFileError::TooLarge {
            file: path.to_path_buf(),
            bytes: size,
            limit: MAX_FILE_BYTES,
        });
    }
    let text = String::from_utf8(bytes)
        .map_err(|e| io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))?;
    parse_gluing_str(&text, path)
}

struct Ctx<'a> {
    file: &'a Path,
}

impl Ctx<'_> {
    fn err(&self, field: impl Into<String>, message: impl Into<String>) -> GluingFileError {
        GluingFileError::Field {
            file: self.file.to_path_buf(),
            field: field.into(),
            message: message.into(),
        }
    }
    fn rational(&self, field: &str, v: Option<&Value>) -> Result<Q, GluingFileError> {
        match v {
            None => Err(self.err(field, "missing")),
            Some(Value::String(s)) if s.len() > MAX_RATIONAL_CHARS => Err(self.err(
                field,
                format!(
                    "a rational of {} characters; at most {MAX_RATIONAL_CHARS} are read",
                    s.len()
                ),
            )),
            Some(Value::String(s)) => parse_q(s)
                .ok_or_else(|| self.err(field, format!("\"{s}\" is not a rational like \"1/3\""))),
            Some(Value::Integer(n)) => Ok(Q::from_integer((*n).into())),
            Some(Value::Float(_)) => Err(self.err(
                field,
                "floats are inexact; write the rational as a string, e.g. \"0.5\" or \"1/2\"",
            )),
            Some(other) => Err(self.err(
                field,
                format!("expected a rational, found {}", other.type_str()),
            )),
        }
    }
    fn index(&self, field: &str, v: Option<&Value>) -> Result<Idx, GluingFileError> {
        match v {
            None => Err(self.err(field, "missing")),
            Some(Value::Integer(n)) => Idx::try_from(*n)
                .map_err(|_| self.err(field, format!("{n} is not an index in 0..=2^32-1"))),
            Some(other) => Err(self.err(
                field,
                format!("expected an integer index, found {}", other.type_str()),
            )),
        }
    }
    /// An open interval ["lo", "hi"]; lo ≥ hi is allowed and means the empty set.
    fn interval(
        &self,
        field: &str,
        v: Option<&Value>,
    ) -> Result<Option<Interval>, GluingFileError> {
        let arr = match v {
            None => return Err(self.err(field, "missing")),
            Some(Value::Array(a)) if a.len() == 2 => a,
            Some(_) => return Err(self.err(field, "expected an array of two rationals [lo, hi]")),
        };
        let lo = self.rational(&format!("{field}[0]"), arr.first())?;
        let hi = self.rational(&format!("{field}[1]"), arr.get(1))?;
        Ok(Interval::new(lo, hi))
    }
    /// A typed error when a table array has more than `max` entries.
    fn at_most(&self, field: &str, len: usize, max: usize) -> Result<(), GluingFileError> {
        if len > max {
            return Err(self.err(field, format!("{len} entries; at most {max} are read")));
        }
        Ok(())
    }
    fn check_keys(
        &self,
        field: &str,
        t: &toml::Table,
        allowed: &[&str],
    ) -> Result<(), GluingFileError> {
        for k in t.keys() {
            if !allowed.contains(&k.as_str()) {
                return Err(self.err(
                    format!("{field}.{k}"),
                    format!("unknown key (allowed: {})", allowed.join(", ")),
                ));
            }
        }
        Ok(())
    }
}

fn tables<'a>(
    ctx: &Ctx,
    root: &'a toml::Table,
    key: &str,
) -> Result<Vec<&'a toml::Table>, GluingFileError> {
    match root.get(key) {
        None => Ok(Vec::new()),
        Some(Value::Array(a)) => a
            .iter()
            .enumerate()
            .map(|(n, v)| {
                v.as_table().ok_or_else(|| {
                    ctx.err(format!("{key}[{n}]"), format!("expected a table [[{key}]]"))
                })
            })
            .collect(),
        Some(_) => Err(ctx.err(key, format!("expected an array of tables [[{key}]]"))),
    }
}

/// Parse gluing data from TOML text; `file` names the source in errors.
pub fn parse_gluing_str(text: &str, file: &Path) -> Result<GluingFile, GluingFileError> {
    let ctx = Ctx { file };
    let root: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| GluingFileError::Syntax {
            file: file.to_path_buf(),
            message: e.to_string(),
        })?;
    ctx.check_keys("(top level)", &root, &["name", "domain", "glue"])?;
    let name = match root.get("name") {
        None => None,
        Some(Value::String(s)) => Some(s.clone()),
        Some(_) => return Err(ctx.err("name", "expected a string")),
    };
    let mut data = Exact1d::default();
    let domains = tables(&ctx, &root, "domain")?;
    if domains.is_empty() {
        return Err(ctx.err(
            "domain",
            "no [[domain]] given: the index set I must be non-empty",
        ));
    }
    ctx.at_most("domain", domains.len(), MAX_DOMAIN_ENTRIES)?;
    let mut work: u128 = 0;
    for (n, t) in domains.iter().enumerate() {
        let f = format!("domain[{n}]");
        ctx.check_keys(&f, t, &["id", "interval"])?;
        let id = ctx.index(&format!("{f}.id"), t.get("id"))?;
        match ctx.interval(&format!("{f}.interval"), t.get("interval"))? {
            Some(iv) => {
                work += 1 + digits(&iv.lo) + digits(&iv.hi);
                data.add_domain(id, iv)
            }
            None => data.add_empty_domain(id),
        }
    }
    let glue = tables(&ctx, &root, "glue")?;
    ctx.at_most("glue", glue.len(), MAX_GLUE_ENTRIES)?;
    for (n, t) in glue.iter().enumerate() {
        let f = format!("glue[{n}]");
        ctx.check_keys(&f, t, &["i", "j", "omega_ij", "a", "b"])?;
        let i = ctx.index(&format!("{f}.i"), t.get("i"))?;
        let j = ctx.index(&format!("{f}.j"), t.get("j"))?;
        for (which, id) in [("i", i), ("j", j)] {
            if !data.domains.contains_key(&id) {
                return Err(ctx.err(
                    format!("{f}.{which}"),
                    format!("no [[domain]] with id = {id}"),
                ));
            }
        }
        let a = ctx.rational(&format!("{f}.a"), t.get("a"))?;
        let b = ctx.rational(&format!("{f}.b"), t.get("b"))?;
        // An empty piece contributes nothing to Ω_ij (Ω_ij = ∅ is allowed by Def. 3.4.1).
        if let Some(dom) = ctx.interval(&format!("{f}.omega_ij"), t.get("omega_ij"))? {
            work += 1 + digits(&a) + digits(&b) + digits(&dom.lo) + digits(&dom.hi);
            data.add_piece(i, j, dom, a, b);
        }
    }
    let w2 = work.saturating_mul(work);
    if w2 > MAX_EXACT_WORK {
        return Err(ctx.err(
            "glue",
            format!(
                "exact work W² = {w2} exceeds {MAX_EXACT_WORK} (W = Σ over intervals and pieces of 1 + the digits of their rationals = {work}; the checks compose pieces pairwise): use fewer pieces or shorter rationals"
            ),
        ));
    }
    Ok(GluingFile {
        name,
        data: data.with_default_diagonal(),
    })
}
