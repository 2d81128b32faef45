//! Keeps SPEC.md and the tests in step: every statement ID in SPEC.md must have a test whose
//! function name carries it (lower-cased, non-alphanumerics → `_`, runs collapsed), e.g.
//! `D3.4.1(3c)` → `d3_4_1_3c`.

use std::path::{Path, PathBuf};

fn sanitize(id: &str) -> String {
    let mut out = String::new();
    for ch in id.chars() {
        if ch.is_ascii_alphanumeric() {
            out.push(ch.to_ascii_lowercase());
        } else if !out.ends_with('_') {
            out.push('_');
        }
    }
    out.trim_matches('_').to_string()
}

/// IDs are the backticked first cell of each table row of SPEC.md.
fn spec_ids(spec: &str) -> Vec<String> {
    spec.lines()
        .filter_map(|l| {
            let l = l.trim();
            let rest = l.strip_prefix("| `")?;
            let end = rest.find('`')?;
            Some(rest[..end].to_string())
        })
        .collect()
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Names of functions marked `#[test]` (possibly with other attributes in between).
fn test_fns(src: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut pending = false;
    for line in src.lines() {
        let t = line.trim();
        if t.starts_with("#[test]") || t.contains("kani::proof") || t.starts_with("#[quickcheck]") {
            pending = true;
            continue;
        }
        if pending {
            if let Some(pos) = t.find("fn ") {
                let name: String = t[pos + 3..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                names.push(name);
                pending = false;
            } else if !t.starts_with("#[") && !t.is_empty() && !t.starts_with("//") {
                pending = false;
            }
        }
    }
    names
}

fn carries(name: &str, key: &str) -> bool {
    let n = format!("_{name}_");
    n.contains(&format!("_{key}_"))
}

#[test]
fn spec_ids_have_tests() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let spec = std::fs::read_to_string(root.join("SPEC.md")).expect("SPEC.md");
    let ids = spec_ids(&spec);
    assert!(ids.len() >= 10, "SPEC.md has too few rows: {}", ids.len());
    let mut files = Vec::new();
    for d in ["tests", "src", "proofs"] {
        rust_files(&root.join(d), &mut files);
    }
    let mut names = Vec::new();
    for f in &files {
        if let Ok(s) = std::fs::read_to_string(f) {
            names.extend(test_fns(&s));
        }
    }
    let missing: Vec<&String> = ids
        .iter()
        .filter(|id| {
            let key = sanitize(id);
            !names.iter().any(|n| carries(n, &key))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "SPEC.md IDs without a test carrying them: {missing:?}"
    );
    // IDs are stable and unique.
    let mut sorted = ids.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), ids.len(), "duplicate IDs in SPEC.md");
}

#[test]
fn spec_sync_detects_a_missing_test() {
    // The checker itself can fail: an ID with no test is reported.
    let spec = "| `D9.9.9(1a)` | planted | - | - | holds |\n| `D3.1.1` | x | - | - | holds |";
    let ids = spec_ids(spec);
    assert_eq!(ids, vec!["D9.9.9(1a)", "D3.1.1"]);
    let names = ["d3_1_1_collinear_face_is_caught_exactly".to_string()];
    let missing: Vec<&String> = ids
        .iter()
        .filter(|id| !names.iter().any(|n| carries(n, &sanitize(id))))
        .collect();
    assert_eq!(missing, vec!["D9.9.9(1a)"]);
    assert_eq!(sanitize("D3.4.1(3c)"), "d3_4_1_3c");
    assert!(
        !carries("d3_1_10_x", "d3_1_1"),
        "D3.1.1 must not match D3.1.10"
    );
}
