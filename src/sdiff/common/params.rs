//! Parameter files (TOML) of a simplicial map, in either dimension (the planar `params`,
//! D = 2, and `tet::params`, D = 3: one format, one parser): the family, the control points,
//! weights and g's keyed by *global* vertex ids, the optional iso-values (format in the planar
//! `params`).

use super::poly1::Poly1;
use super::rational::Q;
use num_bigint::BigInt;
use serde::Deserialize;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Longest number string accepted.
pub(crate) const MAX_NUMBER_CHARS: usize = 512;
/// Largest parameter file accepted.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Errors in a parameter file; each names the file and the entry.
#[derive(Debug, thiserror::Error)]
pub enum ParamError {
    /// Could not read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// Larger than [`MAX_FILE_BYTES`].
    #[error("{path}: {bytes} bytes, more than the limit {MAX_FILE_BYTES}")]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        bytes: u64,
    },
    /// TOML syntax or shape.
    #[error("{path}: {message}")]
    Syntax {
        /// The file.
        path: PathBuf,
        /// toml's message (with line and column).
        message: String,
    },
    /// A value that is not acceptable.
    #[error("{path}: {entry}: {message}")]
    Bad {
        /// The file.
        path: PathBuf,
        /// Which entry, e.g. `control[3]`.
        entry: String,
        /// What is wrong.
        message: String,
    },
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawParams {
    family: String,
    #[serde(default)]
    degree: Option<usize>,
    #[serde(default)]
    control: Vec<RawControl>,
    #[serde(default)]
    weight: Vec<RawWeight>,
    #[serde(default)]
    g: Vec<RawG>,
    #[serde(default)]
    iso: Option<RawIso>,
}
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawControl {
    at: Vec<u32>,
    point: Vec<toml::Value>,
    #[serde(default)]
    triangle: Option<usize>,
    #[serde(default)]
    tet: Option<usize>,
}
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawWeight {
    at: Vec<u32>,
    q: toml::Value,
    #[serde(default)]
    triangle: Option<usize>,
    #[serde(default)]
    tet: Option<usize>,
}

/// The cell override of an entry: `triangle = f` in 2-D files, `tet = f` in 3-D ones (the
/// other key is an error, not ignored).
fn cell_of<const D: usize>(
    triangle: Option<usize>,
    tet: Option<usize>,
) -> Result<Option<usize>, String> {
    match (D, triangle, tet) {
        (2, t, None) | (3, None, t) => Ok(t),
        (2, _, Some(_)) => {
            Err("`tet` is a key of 3-D files; a planar file overrides with `triangle`".into())
        }
        _ => Err("`triangle` is a key of planar files; a 3-D file overrides with `tet`".into()),
    }
}
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawG {
    vertex: u32,
    coeffs: Vec<toml::Value>,
}
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawIso {
    f: Vec<toml::Value>,
    #[serde(default)]
    c: Option<toml::Value>,
}

/// The family requested by a parameter file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FamilySpec {
    /// Eq. (9).
    Monotonic,
    /// Eq. (10).
    Polynomial,
    /// Eq. (11).
    Rational,
}

/// A sorted global-vertex multiset (the key of a control point or weight).
pub(crate) type Multiset = Vec<u32>;

/// A parsed parameter file for simplices of dimension D (the planar one, D = 2, and the
/// tetrahedral one of `tet::params`, D = 3: one format, one parser).
#[derive(Debug, Clone)]
pub struct Spec<const D: usize> {
    /// The family.
    pub family: FamilySpec,
    /// Degree n (polynomial / rational).
    pub degree: usize,
    /// Control points c_I in ℝ^D, by multiset; `(Some(f), I)` overrides in simplex f.
    pub control: HashMap<(Option<usize>, Multiset), [Q; D]>,
    /// Weights q_I.
    pub weights: HashMap<(Option<usize>, Multiset), Q>,
    /// g_v per vertex (monotonic).
    pub g: HashMap<u32, Poly1>,
    /// Iso-values f_v and the level c, when given.
    pub iso: Option<(Vec<Q>, Q)>,
}

/// Parses a number: integer, "p/q", decimal string, or float (exact double).
pub(crate) fn parse_number(v: &toml::Value) -> Result<Q, String> {
    match v {
        toml::Value::Integer(i) => Ok(Q::from_integer(BigInt::from(*i))),
        toml::Value::Float(x) => Q::from_float(*x).ok_or_else(|| format!("{x} is not finite")),
        toml::Value::String(s) => parse_str(s),
        other => Err(format!("expected a number, found {other}")),
    }
}

fn parse_str(s: &str) -> Result<Q, String> {
    let s = s.trim();
    if s.len() > MAX_NUMBER_CHARS {
        return Err(format!("number longer than {MAX_NUMBER_CHARS} characters"));
    }
    let int = |t: &str| {
        t.parse::<BigInt>()
            .map_err(|_| format!("'{t}' is not an integer"))
    };
    if let Some((p, q)) = s.split_once('/') {
        let (p, q) = (int(p.trim())?, int(q.trim())?);
        if q == BigInt::from(0) {
            return Err(format!("'{s}' has a zero denominator"));
        }
        return Ok(Q::new(p, q));
    }
    if let Some((a, b)) = s.split_once('.') {
        if b.starts_with(['+', '-']) || b.contains(['e', 'E']) {
            return Err(format!("'{s}': exponents are not accepted; write p/q"));
        }
        let neg = a.trim_start().starts_with('-');
        let whole = if a.is_empty() || a == "-" || a == "+" {
            BigInt::from(0)
        } else {
            int(a)?.magnitude().clone().into()
        };
        let frac = if b.is_empty() {
            BigInt::from(0)
        } else {
            int(b)?
        };
        let den = num_traits::pow(BigInt::from(10), b.len());
        let mag = Q::new(whole * &den + frac, den);
        return Ok(if neg { -mag } else { mag });
    }
    Ok(Q::from_integer(int(s)?))
}

/// Reads and parses a parameter file for dimension D, degrees up to `max_degree`.
pub(crate) fn read_spec<const D: usize>(
    path: &Path,
    max_degree: usize,
) -> Result<Spec<D>, ParamError> {
    let meta = std::fs::metadata(path).map_err(|source| ParamError::Io {
        path: path.into(),
        source,
    })?;
    if meta.len() > MAX_FILE_BYTES {
        return Err(ParamError::TooLarge {
            path: path.into(),
            bytes: meta.len(),
        });
    }
    let text = std::fs::read_to_string(path).map_err(|source| ParamError::Io {
        path: path.into(),
        source,
    })?;
    parse_spec(&text, path, max_degree)
}

/// Parses the text of a parameter file for dimension D (`path` only names it in errors).
pub(crate) fn parse_spec<const D: usize>(
    text: &str,
    path: &Path,
    max_degree: usize,
) -> Result<Spec<D>, ParamError> {
    let raw: RawParams = toml::from_str(text).map_err(|e| ParamError::Syntax {
        path: path.into(),
        message: e.to_string(),
    })?;
    let bad = |entry: String, message: String| ParamError::Bad {
        path: path.into(),
        entry,
        message,
    };
    let family = match raw.family.as_str() {
        "polynomial" => FamilySpec::Polynomial,
        "rational" => FamilySpec::Rational,
        "monotonic" => FamilySpec::Monotonic,
        other => {
            return Err(bad(
                "family".into(),
                format!("'{other}' is not polynomial, rational or monotonic"),
            ))
        }
    };
    let degree = match (family, raw.degree) {
        (FamilySpec::Monotonic, _) => 0,
        (_, None) => return Err(bad("degree".into(), "required for this family".into())),
        (_, Some(0)) => return Err(bad("degree".into(), "must be at least 1".into())),
        (_, Some(n)) if n > max_degree => {
            return Err(bad(
                "degree".into(),
                format!("{n} is above the limit {max_degree} for dimension {D}"),
            ))
        }
        (_, Some(n)) => n,
    };
    let key = |at: &[u32], entry: &str| -> Result<Multiset, ParamError> {
        if at.len() != degree {
            return Err(bad(
                entry.into(),
                format!("`at` has {} ids, the degree is {degree}", at.len()),
            ));
        }
        let mut m = at.to_vec();
        m.sort_unstable();
        Ok(m)
    };
    let mut control = HashMap::new();
    for (k, c) in raw.control.iter().enumerate() {
        let entry = format!("control[{k}]");
        if family == FamilySpec::Monotonic {
            return Err(bad(
                entry,
                "control points belong to the polynomial and rational families".into(),
            ));
        }
        if c.point.len() != D {
            let n = ["two", "three"]
                .get(D.wrapping_sub(2))
                .copied()
                .unwrap_or("D");
            return Err(bad(entry, format!("`point` needs {n} coordinates")));
        }
        let mut p: [Q; D] = std::array::from_fn(|_| Q::from_integer(0.into()));
        for (slot, v) in p.iter_mut().zip(&c.point) {
            *slot = parse_number(v).map_err(|m| bad(entry.clone(), m))?;
        }
        let cell = cell_of::<D>(c.triangle, c.tet).map_err(|m| bad(entry.clone(), m))?;
        if control.insert((cell, key(&c.at, &entry)?), p).is_some() {
            return Err(bad(entry, "given twice".into()));
        }
    }
    let mut weights = HashMap::new();
    for (k, w) in raw.weight.iter().enumerate() {
        let entry = format!("weight[{k}]");
        if family != FamilySpec::Rational {
            return Err(bad(entry, "weights belong to the rational family".into()));
        }
        let v = parse_number(&w.q).map_err(|m| bad(entry.clone(), m))?;
        let cell = cell_of::<D>(w.triangle, w.tet).map_err(|m| bad(entry.clone(), m))?;
        if weights.insert((cell, key(&w.at, &entry)?), v).is_some() {
            return Err(bad(entry, "given twice".into()));
        }
    }
    let mut g = HashMap::new();
    for (k, e) in raw.g.iter().enumerate() {
        let entry = format!("g[{k}]");
        if family != FamilySpec::Monotonic {
            return Err(bad(entry, "g belongs to the monotonic family".into()));
        }
        if e.coeffs.is_empty() || e.coeffs.len() > max_degree + 1 {
            return Err(bad(
                entry,
                format!("needs 1 to {} coefficients", max_degree + 1),
            ));
        }
        let cs = e
            .coeffs
            .iter()
            .map(parse_number)
            .collect::<Result<Vec<_>, _>>()
            .map_err(|m| bad(entry.clone(), m))?;
        if g.insert(e.vertex, Poly1(cs)).is_some() {
            return Err(bad(entry, "given twice".into()));
        }
    }
    let iso = match raw.iso {
        None => None,
        Some(i) => {
            let f =
                i.f.iter()
                    .map(parse_number)
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|m| bad("iso.f".into(), m))?;
            let c = match &i.c {
                Some(v) => parse_number(v).map_err(|m| bad("iso.c".into(), m))?,
                None => Q::from_integer(0.into()),
            };
            Some((f, c))
        }
    };
    Ok(Spec {
        family,
        degree,
        control,
        weights,
        g,
        iso,
    })
}

impl<const D: usize> Spec<D> {
    /// The control point (when given) and the weight (1 when not) of the multiset `key` in
    /// simplex f: the override for f first, then the entry of every simplex.
    pub fn entry(&self, f: usize, key: Multiset) -> (Option<&[Q; D]>, Q) {
        let c = self
            .control
            .get(&(Some(f), key.clone()))
            .or_else(|| self.control.get(&(None, key.clone())));
        let w = self
            .weights
            .get(&(Some(f), key.clone()))
            .or_else(|| self.weights.get(&(None, key)));
        (c, w.cloned().unwrap_or_else(|| Q::from_integer(1.into())))
    }

    /// Checks every key names vertices of the complex and a face of some cell (of the named
    /// one for an override), every g a vertex, and that `iso.f` has one value per vertex.
    pub(crate) fn check_keys<const C: usize>(
        &self,
        path: &Path,
        nv: usize,
        cells: &[[u32; C]],
        cell: &str,
    ) -> Result<(), ParamError> {
        let bad = |entry: String, message: String| ParamError::Bad {
            path: path.into(),
            entry,
            message,
        };
        let face_of_some = |m: &Multiset, only: Option<usize>| -> bool {
            cells
                .iter()
                .enumerate()
                .any(|(f, t)| only.map_or(true, |x| x == f) && m.iter().all(|v| t.contains(v)))
        };
        let keys = self
            .control
            .keys()
            .map(|x| ("control", x))
            .chain(self.weights.keys().map(|x| ("weight", x)));
        for (what, (only, m)) in keys {
            if let Some(f) = only {
                if *f >= cells.len() {
                    return Err(bad(
                        format!("{what} at {m:?}"),
                        format!("{cell} {f} does not exist ({} in K)", cells.len()),
                    ));
                }
            }
            if m.iter().any(|&v| v as usize >= nv) || !face_of_some(m, *only) {
                return Err(bad(
                    format!("{what} at {m:?}"),
                    format!("names no face of a {cell} of K"),
                ));
            }
        }
        if let Some(v) = self.g.keys().find(|&&v| v as usize >= nv) {
            return Err(bad(
                format!("g at vertex {v}"),
                format!("the complex has {nv} vertices"),
            ));
        }
        if let Some((f, _)) = &self.iso {
            if f.len() != nv {
                return Err(bad(
                    "iso.f".into(),
                    format!("{} values for {nv} vertices", f.len()),
                ));
            }
        }
        Ok(())
    }
}
