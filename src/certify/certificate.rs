//! Results and the certificate format (serde), and its rendering as check results.

use super::result::PropertyResult;
use serde::{Deserialize, Serialize};

// ---------------------------------------------------------------------------------------------
// Results and certificates.
// ---------------------------------------------------------------------------------------------

/// A certificate file: all results of one run (or a merge of shards).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Certificate {
    /// File format tag, `pseudomanifold-certificate/1`.
    pub format: String,
    /// M: every configuration with degrees 3..=M is in scope.
    pub max_degree: u32,
    /// [`Model::name`] of the construction proven.
    pub model: String,
    /// `(k, n)` for a shard, `None` for a complete run or a merge.
    pub shard: Option<(usize, usize)>,
    /// Number of configurations proven (summed over the shards of a merge).
    pub configs: usize,
    /// One result per (configuration, property).
    pub results: Vec<PropertyResult>,
    /// Wall-clock time of the run, in ms (the largest shard's for a merge).
    pub wall_millis: u64,
    /// Worker threads used (the first shard's for a merge).
    pub jobs: usize,
    /// Statements shared by many results, by property: a result whose `statement` is empty
    /// in the file has this one ([`Certificate::compact`], [`Certificate::expand`]).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub statements: std::collections::BTreeMap<String, String>,
}

impl Certificate {
    /// Move each property's most common statement into `statements` and clear it in the
    /// results that share it (the file format; statements are long, results many).
    pub fn compact(&mut self) {
        use std::collections::BTreeMap;
        let mut counts: BTreeMap<(&str, &str), usize> = BTreeMap::new();
        for r in &self.results {
            *counts.entry((&r.property, &r.statement)).or_default() += 1;
        }
        let mut best: BTreeMap<String, (usize, String)> = BTreeMap::new();
        for ((p, st), n) in counts {
            let e = best.entry(p.to_string()).or_insert((0, String::new()));
            if n > e.0 {
                *e = (n, st.to_string());
            }
        }
        for r in &mut self.results {
            if best
                .get(&r.property)
                .is_some_and(|(_, st)| *st == r.statement)
            {
                r.statement.clear();
            }
        }
        self.statements
            .extend(best.into_iter().map(|(p, (_, st))| (p, st)));
    }
    /// Undo [`Certificate::compact`]: fill empty statements from `statements`.
    pub fn expand(&mut self) {
        for r in &mut self.results {
            if r.statement.is_empty() {
                if let Some(st) = self.statements.get(&r.property) {
                    r.statement = st.clone();
                }
            }
        }
    }
}

/// The two bytes that open every gzip member (RFC 1952, ID1 ID2).
pub const GZIP_MAGIC: [u8; 2] = [0x1f, 0x8b];

/// Decompressed certificates larger than this are refused (the M = 32 JSON is 28 MB): a
/// corrupt or hostile file cannot exhaust memory.
pub const MAX_CERTIFICATE_BYTES: u64 = 1 << 30;

/// Does `path` name a compressed certificate (written gzip by [`write_certificate`])?
pub fn is_gzip_path(path: &std::path::Path) -> bool {
    path.extension().is_some_and(|e| e == "gz")
}

/// Read a certificate file (the format of [`write_certificate`]): JSON, or gzip-compressed
/// JSON, recognised by its magic bytes whatever the file is called. A `.gz` file without them,
/// a truncated or corrupt gzip stream (the CRC-32 and length of its trailer are checked) and
/// malformed JSON are typed errors.
pub fn read_certificate(path: &std::path::Path) -> Result<Certificate, CertifyError> {
    let name = || path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| CertifyError::Io {
        path: name(),
        source,
    })?;
    let text = if bytes.starts_with(&GZIP_MAGIC) {
        gunzip(&bytes).map_err(|source| CertifyError::Compressed {
            path: name(),
            source,
        })?
    } else if is_gzip_path(path) {
        return Err(CertifyError::Compressed {
            path: name(),
            source: std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                "named .gz but does not start with the gzip magic bytes 1f 8b",
            ),
        });
    } else {
        String::from_utf8(bytes).map_err(|e| CertifyError::Io {
            path: name(),
            source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
        })?
    };
    let mut c: Certificate = serde_json::from_str(&text).map_err(|source| CertifyError::Json {
        path: name(),
        source,
    })?;
    c.expand();
    Ok(c)
}

/// Decompress a gzip certificate (one member), at most [`MAX_CERTIFICATE_BYTES`].
fn gunzip(bytes: &[u8]) -> std::io::Result<String> {
    use std::io::Read;
    let mut text = String::new();
    let mut dec = flate2::read::GzDecoder::new(bytes).take(MAX_CERTIFICATE_BYTES + 1);
    dec.read_to_string(&mut text)?;
    if text.len() as u64 > MAX_CERTIFICATE_BYTES {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("decompresses to more than {MAX_CERTIFICATE_BYTES} bytes"),
        ));
    }
    Ok(text)
}

/// Write a certificate file: compacted ([`Certificate::compact`]), one result per line (small
/// enough to keep in the repository, still diffable); gzip-compressed (best compression, no
/// time stamp: the same certificate gives the same bytes) when `out` ends in `.gz`.
pub fn write_certificate(cert: &Certificate, out: &std::path::Path) -> Result<(), CertifyError> {
    let mut file = cert.clone();
    file.compact();
    let mut json = serde_json::to_string(&file).map_err(|source| CertifyError::Json {
        path: out.display().to_string(),
        source,
    })?;
    json = json.replace("},{\"key\"", "},\n{\"key\"");
    json.push('\n');
    if !is_gzip_path(out) {
        return write_text(out, &json);
    }
    let gz = gzip(json.as_bytes()).map_err(|source| CertifyError::Compressed {
        path: out.display().to_string(),
        source,
    })?;
    std::fs::write(out, gz).map_err(|source| CertifyError::Io {
        path: out.display().to_string(),
        source,
    })
}

fn gzip(bytes: &[u8]) -> std::io::Result<Vec<u8>> {
    use std::io::Write;
    let mut enc = flate2::GzBuilder::new()
        .mtime(0)
        .write(Vec::new(), flate2::Compression::best());
    enc.write_all(bytes)?;
    enc.finish()
}

/// Write a text file (certificate or summary), naming it in the error.
pub fn write_text(path: &std::path::Path, text: &str) -> Result<(), CertifyError> {
    std::fs::write(path, text).map_err(|source| CertifyError::Io {
        path: path.display().to_string(),
        source,
    })
}

/// Errors of the certificate tools.
#[derive(Debug, thiserror::Error)]
pub enum CertifyError {
    /// A certificate or summary file could not be read or written.
    #[error("I/O error on {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The underlying I/O error.
        source: std::io::Error,
    },
    /// A certificate file is not valid certificate JSON (or a certificate could not be serialised).
    #[error("malformed certificate {path}: {source}")]
    Json {
        /// The file.
        path: String,
        /// The JSON error.
        source: serde_json::Error,
    },
    /// A gzip certificate is truncated or corrupt (or named `.gz` without being gzip).
    #[error("corrupt compressed certificate {path}: {source}")]
    Compressed {
        /// The file.
        path: String,
        /// What the decompressor found.
        source: std::io::Error,
    },
    /// Certificates to merge disagree (max degree, model), overlap, or none was given.
    #[error("certificates do not fit together: {0}")]
    Mismatch(String),
    /// An invalid command-line value (`--shard`, `--max-degree`) or thread-pool setup failure.
    #[error("bad argument: {0}")]
    BadArg(String),
}
