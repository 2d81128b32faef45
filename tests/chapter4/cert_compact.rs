//! CERT-compact: certificates written gzip-compressed (`*.json.gz`) read back identical,
//! deterministically; a truncated or corrupt one is a typed error (planted faults); the
//! committed compact certificates parse and their summaries are the committed ones.

use pseudomanifold::certify::{
    prove_config, read_certificate, summary_table, write_certificate, Certificate, CertifyError,
    ConfigKey, Model, Settings, GZIP_MAGIC,
};
use std::path::{Path, PathBuf};

fn small() -> Certificate {
    let mut results = Vec::new();
    for key in [
        ConfigKey::Vertex { m: 4 },
        ConfigKey::Edge { m_u: 4, m_w: 4 },
    ] {
        results.extend(prove_config(key, &Model::paper(), &Settings::default()));
    }
    Certificate {
        format: "pseudomanifold-certificate/1".into(),
        max_degree: 4,
        model: "paper".into(),
        shard: None,
        configs: 2,
        results,
        wall_millis: 0,
        jobs: 1,
        statements: Default::default(),
    }
}

fn tmp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("cert_compact_{}_{name}", std::process::id()))
}

#[test]
fn cert_compact_gzip_round_trip_is_identical_and_deterministic() {
    let cert = small();
    let (gz, gz2, json) = (tmp("a.json.gz"), tmp("b.json.gz"), tmp("c.json"));
    for p in [&gz, &gz2, &json] {
        write_certificate(&cert, p).expect("write");
    }
    let bytes = std::fs::read(&gz).expect("read");
    assert!(bytes.starts_with(&GZIP_MAGIC));
    assert_eq!(
        bytes,
        std::fs::read(&gz2).expect("read"),
        "same certificate, same bytes"
    );
    let plain = std::fs::read(&json).expect("read");
    assert!(
        bytes.len() < plain.len(),
        "{} vs {}",
        bytes.len(),
        plain.len()
    );
    // Reading fills `statements` (the file's compaction): compare results, and the two files.
    let back = read_certificate(&gz).expect("gzip reads");
    assert_eq!(back.results, cert.results);
    assert_eq!(read_certificate(&json).expect("JSON reads"), back);
    // Recognised by its magic bytes, whatever the name.
    let renamed = tmp("d.json");
    std::fs::write(&renamed, &bytes).expect("write");
    assert_eq!(read_certificate(&renamed).expect("gzip by magic"), back);
    crate::common::verdicts::record(
        "CERT-compact",
        crate::common::verdicts::Seen::Holds,
        cert.results.len() as u64,
    );
    for p in [&gz, &gz2, &json, &renamed] {
        let _ = std::fs::remove_file(p);
    }
}

#[test]
fn cert_compact_planted_truncated_or_corrupt_gzip_is_a_typed_error() {
    let gz = tmp("e.json.gz");
    write_certificate(&small(), &gz).expect("write");
    let bytes = std::fs::read(&gz).expect("read");
    let bad = tmp("f.json.gz");
    let mut flipped = bytes.clone();
    let mid = flipped.len() / 2;
    flipped[mid] ^= 0x40;
    let mut crc = bytes.clone();
    let n = crc.len();
    crc[n - 6] ^= 1; // the trailer's CRC-32
    let cases: Vec<(&str, Vec<u8>)> = vec![
        ("truncated by half", bytes[..bytes.len() / 2].to_vec()),
        ("truncated trailer", bytes[..bytes.len() - 4].to_vec()),
        ("only the magic", GZIP_MAGIC.to_vec()),
        ("a flipped bit", flipped),
        ("a wrong CRC", crc),
        ("plain JSON named .gz", b"{\"format\":1}".to_vec()),
    ];
    for (what, b) in cases {
        std::fs::write(&bad, &b).expect("write");
        match read_certificate(&bad) {
            Err(CertifyError::Compressed { path, .. }) => assert!(path.ends_with("f.json.gz")),
            // A flipped bit may also leave valid deflate whose text is not a certificate.
            Err(CertifyError::Json { .. }) if what == "a flipped bit" => {}
            other => panic!("{what}: {other:?}"),
        }
    }
    crate::common::verdicts::record("CERT-compact", crate::common::verdicts::Seen::Caught, 6);
    let _ = std::fs::remove_file(&gz);
    let _ = std::fs::remove_file(&bad);
}

/// The committed compact certificate of degree M parses and `summary_table` of it is the
/// committed summary, byte for byte (SPEC `CERT-compact`).
fn committed_matches_summary(m: u32) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("certificates");
    let cert = read_certificate(&root.join(format!("certificate_M{m}.json.gz")))
        .unwrap_or_else(|e| panic!("certificate_M{m}.json.gz: {e}"));
    assert_eq!(cert.max_degree, m);
    let summary = std::fs::read_to_string(root.join(format!("CERTIFICATE_SUMMARY_M{m}.md")))
        .expect("summary");
    // SPEC `CERT-f64-g-chart`: every degree's g_v and g_v⁻¹ bounded on the whole chart square.
    let g: Vec<_> = cert
        .results
        .iter()
        .filter_map(|r| r.g_chart.as_ref())
        .collect();
    assert_eq!(
        g.len(),
        m as usize - 2,
        "M = {m}: degrees with a g-chart bound"
    );
    assert!(
        g.iter().all(|g| g.unresolved == 0
            && g.g_v.is_some_and(|b| b < 1e-13)
            && g.g_v_inv.is_some_and(|b| b < 1e-13)),
        "M = {m}: {g:?}"
    );
    // SPEC `CERT-f64-props`: every other property of every configuration carries its proven
    // f64 bound, and every round trip and witness decision it rests on is certified exact.
    let unbounded: Vec<_> = cert
        .results
        .iter()
        .filter(|r| r.property != "P4.2.3(cert)")
        .filter(|r| match &r.f64_bound {
            Some(b) => !b.bound.is_some_and(|v| v < 1e-11) || b.decided == Some(false),
            None => true,
        })
        .map(|r| (r.key, r.property.clone()))
        .collect();
    assert!(
        unbounded.is_empty(),
        "M = {m}: {} results without a bound, e.g. {:?}",
        unbounded.len(),
        unbounded.first()
    );
    assert!(summary_table(&cert) == summary, "M = {m}: the summary of the committed certificate differs from CERTIFICATE_SUMMARY_M{m}.md");
}

#[test]
fn cert_compact_committed_m16_and_m20_match_their_summaries() {
    committed_matches_summary(16);
    committed_matches_summary(20);
}

#[test]
fn cert_compact_committed_m32_matches_its_summary() {
    committed_matches_summary(32);
}
