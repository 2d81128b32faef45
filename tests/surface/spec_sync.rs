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

/// Every `.rs` file under `dir` (also the source scan of `architecture.rs`).
pub(crate) fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
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

/// The rows `mutants/run.sh` appended, per module: (tested, caught, missed) of its latest
/// sampled run (re-test rows, "MODULE (again)", are left out).
fn mutant_runs(tsv: &str) -> Vec<(String, String, [u64; 3])> {
    let mut out: Vec<(String, String, [u64; 3])> = Vec::new();
    for line in tsv.lines().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        if f.len() < 14 || f[2].ends_with("(again)") {
            continue;
        }
        let n = |i: usize| f[i].parse::<u64>().unwrap_or(u64::MAX);
        let row = (f[2].to_string(), f[1].to_string(), [n(5), n(6), n(7)]);
        match out.iter_mut().find(|r| r.0 == row.0) {
            Some(r) => *r = row,
            None => out.push(row),
        }
    }
    out
}

/// The module names of mutants/run.sh's `modules` list (the heredoc, one `name|…` per line).
fn run_sh_modules(script: &str) -> Vec<String> {
    script
        .lines()
        .skip_while(|l| l.trim() != "cat <<'EOF'")
        .skip(1)
        .take_while(|l| l.trim() != "EOF")
        .filter_map(|l| l.split('|').next())
        .map(|m| m.trim().to_string())
        .filter(|m| !m.is_empty())
        .collect()
}

/// SPEC X-mutants: docs/mutants.md shows the latest campaign of every module in
/// mutants/results.tsv with its numbers, and every module that missed mutants has a section
/// saying what became of each.
#[test]
fn x_mutants_docs_show_every_campaign_and_its_survivors() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tsv = std::fs::read_to_string(root.join("mutants/results.tsv")).expect("results.tsv");
    let doc = std::fs::read_to_string(root.join("docs/mutants.md")).expect("docs/mutants.md");
    let runs = mutant_runs(&tsv);
    assert!(!runs.is_empty(), "no campaign recorded");
    for (module, commit, [tested, caught, missed]) in runs {
        let row = doc
            .lines()
            .find(|l| l.starts_with(&format!("| `{module}` | {commit} |")))
            .unwrap_or_else(|| panic!("docs/mutants.md has no table row for {module} at {commit}"));
        // | Module | Commit | Sample | Generated | Tested | Caught | Missed | ...
        let cells: Vec<String> = row.split('|').map(|c| c.trim().to_string()).collect();
        let expected = [tested, caught, missed].map(|n| n.to_string());
        assert_eq!(
            cells.get(5..8),
            Some(&expected[..]),
            "{module}: tested/caught/missed in docs/mutants.md"
        );
        if missed > 0 {
            assert!(
                doc.contains(&format!("### `{module}`")),
                "{module} missed {missed} mutants and has no section saying what became of them"
            );
        }
    }
    // The goal as SPEC states it: a fresh sample of every module, each ≥ 90 %. Its verdict on
    // the record: every module whose latest fresh campaign scored below 0.9, and every module
    // with no campaign at all, is a witness that it is not met.
    let mut latest: Vec<(String, f64)> = Vec::new();
    for f in tsv
        .lines()
        .skip(1)
        .map(|l| l.split('\t').collect::<Vec<_>>())
    {
        if f.len() < 14 || f[2].ends_with("(again)") {
            continue;
        }
        let score: f64 = f[10].parse().unwrap_or(f64::NAN);
        match latest.iter_mut().find(|r| r.0 == f[2]) {
            Some(r) => r.1 = score,
            None => latest.push((f[2].to_string(), score)),
        }
    }
    let mut witnesses: Vec<String> = latest
        .iter()
        .filter(|(_, s)| s.is_nan() || *s < 0.9)
        .map(|(m, s)| format!("{m} {s:.3}"))
        .collect();
    // Every module mutants/run.sh knows (its `modules` list) needs a campaign of its own.
    let script = std::fs::read_to_string(root.join("mutants/run.sh")).expect("mutants/run.sh");
    let modules = run_sh_modules(&script);
    assert!(modules.len() >= 10, "mutants/run.sh lists {modules:?}");
    for m in &modules {
        if !latest.iter().any(|(n, _)| n == m) {
            witnesses.push(format!("{m}: never campaigned"));
        }
    }
    println!("X-mutants goal (≥ 90 % per module) not met: {witnesses:?}");
    assert!(
        !witnesses.is_empty(),
        "every module sampled at ≥ 90 %: SPEC X-mutants says fails, update it"
    );
    crate::common::verdicts::record(
        "X-mutants",
        crate::common::verdicts::Seen::Fails,
        (latest.len() + modules.len()) as u64,
    );
}

/// The X-mutants check itself: the latest run of a module counts, re-test rows do not.
#[test]
fn x_mutants_parser_keeps_the_latest_run_and_skips_re_tests() {
    let h = "date\tcommit\tmodule\tdenom\tgenerated\ttested\tcaught\tmissed\ttimeout\tunviable\tscore\tlo\thi\ts";
    let tsv = format!(
        "{h}\nd\tc1\tm\t2\t10\t5\t3\t2\t0\t0\t.6\t.2\t.9\t1\nd\tc2\tm\t2\t10\t5\t4\t1\t0\t0\t.8\t.3\t.9\t1\nd\tc3\tm (again)\t2\t10\t1\t1\t0\t0\t0\t1\t.2\t1\t1\n"
    );
    assert_eq!(
        mutant_runs(&tsv),
        vec![("m".to_string(), "c2".to_string(), [5, 4, 1])]
    );
}
