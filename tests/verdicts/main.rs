//! SPEC.md's verdicts against what the tests saw (SPEC `X-spec-verdicts`). The other test
//! binaries record every verdict they assert on real input (`tests/common/verdicts.rs`);
//! this binary, whose name sorts after theirs so that `cargo test` runs it last, reads the
//! records and fails where
//! * a row says *holds* (or *certified*) and no test recorded it holding on something, or a
//!   test recorded it failing as written;
//! * a row says *fails* and no test recorded the failure;
//! * a row says *restricted* and no test recorded the restricted form holding;
//! * a row says *caught* (a row about a checker) or *measured* (a measurement, not a claim)
//!   and no test recorded a caught planted fault or a measurement;
//! * a row's verdict cell does not start with one of the words above, *definition* or
//!   *not checkable* (both need no record: the test named in the row exists, `spec_sync`);
//! * a row that `unrecorded.txt` lists as not yet recorded has records (the list only shrinks).
//!
//! Rows listed in `unrecorded.txt` are the ones whose tests do not yet record their verdict;
//! the list is printed with its length.

#[path = "../common/mod.rs"]
mod common;
use common::verdicts;

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The verdict a SPEC.md row states, from the first word of its verdict cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Stated {
    Holds,
    Certified,
    Fails,
    Restricted,
    Caught,
    Measured,
    Definition,
    NotCheckable,
}

/// Splits a table row on the `|` that are not escaped as `\|`.
fn cells(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut prev = '\0';
    for ch in line.trim().chars() {
        if ch == '|' && prev != '\\' {
            out.push(cur.trim().to_string());
            cur.clear();
        } else {
            cur.push(ch);
        }
        prev = ch;
    }
    if !cur.trim().is_empty() {
        out.push(cur.trim().to_string());
    }
    // A row starts and ends with `|`: drop the empty cells outside them.
    if out.first().is_some_and(|c| c.is_empty()) {
        out.remove(0);
    }
    out
}

fn classify(verdict: &str) -> Option<Stated> {
    let t: String = verdict
        .trim_start_matches(|c: char| c == '*' || c == '_' || c == '⚠' || c.is_whitespace())
        .to_lowercase();
    let starts = |w: &str| t.starts_with(w);
    if starts("holds restricted") || starts("holds only on") || starts("restricted") {
        Some(Stated::Restricted)
    } else if starts("holds") {
        Some(Stated::Holds)
    } else if starts("certified") {
        Some(Stated::Certified)
    } else if starts("fails") || starts("refuted") {
        Some(Stated::Fails)
    } else if starts("caught") {
        Some(Stated::Caught)
    } else if starts("measured") {
        Some(Stated::Measured)
    } else if starts("definition") {
        Some(Stated::Definition)
    } else if starts("not checkable") {
        Some(Stated::NotCheckable)
    } else {
        None
    }
}

/// (row ID, stated verdict or the malformed cell) for every row of SPEC.md's tables with a
/// backticked ID in its first cell.
fn spec_rows(spec: &str) -> Vec<(String, Result<Stated, String>)> {
    let mut out = Vec::new();
    for line in spec.lines().filter(|l| l.trim_start().starts_with("| `")) {
        let c = cells(line);
        let Some(id) = c.first().and_then(|f| f.split('`').nth(1)) else {
            continue;
        };
        let verdict = if c.len() == 5 {
            classify(&c[4])
                .ok_or_else(|| format!("verdict cell starts with {:?}", first_words(&c[4])))
        } else {
            Err(format!(
                "{} cells instead of 5 (escape `|` inside cells as `\\|`)",
                c.len()
            ))
        };
        out.push((id.to_string(), verdict));
    }
    out
}

fn first_words(s: &str) -> String {
    s.split_whitespace().take(4).collect::<Vec<_>>().join(" ")
}

/// One record: (ID, seen, examined).
type Record = (String, String, u64);

fn read_records(dir: &Path) -> Vec<Record> {
    let mut out = Vec::new();
    let Ok(rd) = std::fs::read_dir(dir) else {
        return out;
    };
    for e in rd.flatten() {
        let Ok(text) = std::fs::read_to_string(e.path()) else {
            continue;
        };
        for line in text.lines() {
            let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else {
                continue;
            };
            if let (Some(id), Some(seen), Some(n)) =
                (v["id"].as_str(), v["seen"].as_str(), v["examined"].as_u64())
            {
                out.push((id.to_string(), seen.to_string(), n));
            }
        }
    }
    out
}

/// The row a record speaks for: its own ID when that is a row; a `[restricted]` record speaks
/// for its base row (as a restricted verdict); otherwise the longest row ID that is a prefix
/// ending where a qualifier `(…)` or `[…]` starts (`D3.1.6(edges)` → `D3.1.6`).
fn row_of<'a>(id: &str, rows: &'a BTreeSet<String>) -> Option<(&'a String, bool)> {
    if let Some(r) = rows.get(id) {
        return Some((r, false));
    }
    if let Some(base) = id.strip_suffix("[restricted]") {
        if let Some(r) = rows.get(base) {
            return Some((r, true));
        }
    }
    rows.iter()
        .filter(|r| {
            id.len() > r.len()
                && id.starts_with(r.as_str())
                && matches!(id.as_bytes()[r.len()], b'(' | b'[')
        })
        .max_by_key(|r| r.len())
        .map(|r| (r, false))
}

/// The departures of the records from SPEC.md, and the rows no test recorded.
fn compare(
    rows: &[(String, Result<Stated, String>)],
    records: &[Record],
) -> (Vec<String>, BTreeSet<String>) {
    let ids: BTreeSet<String> = rows.iter().map(|r| r.0.clone()).collect();
    let mut seen: BTreeMap<&String, Vec<(&str, u64, bool)>> = BTreeMap::new();
    for (id, s, n) in records {
        if let Some((row, restricted)) = row_of(id, &ids) {
            seen.entry(row)
                .or_default()
                .push((s.as_str(), *n, restricted));
        }
    }
    let mut bad = Vec::new();
    let mut unrecorded = BTreeSet::new();
    for (id, stated) in rows {
        let stated = match stated {
            Ok(s) => *s,
            Err(why) => {
                bad.push(format!("{id}: malformed SPEC row: {why}"));
                continue;
            }
        };
        let recs = seen.get(id).cloned().unwrap_or_default();
        let has = |w: &str| recs.iter().any(|(s, n, r)| *s == w && *n > 0 && !r);
        let restricted_holds = recs
            .iter()
            .any(|(s, n, r)| *n > 0 && (*s == "restricted" || (*r && *s == "holds")));
        match stated {
            Stated::Definition | Stated::NotCheckable => {}
            Stated::Caught => {
                if !has("caught") {
                    unrecorded.insert(id.clone());
                }
            }
            Stated::Measured => {
                if !has("measured") {
                    unrecorded.insert(id.clone());
                }
            }
            Stated::Holds | Stated::Certified => {
                if has("fails") {
                    bad.push(format!(
                        "{id}: SPEC says {stated:?}, a test recorded it failing as written"
                    ));
                } else if !(has("holds") || has("certified")) {
                    unrecorded.insert(id.clone());
                }
            }
            Stated::Fails => {
                if !has("fails") {
                    if has("holds") {
                        bad.push(format!(
                            "{id}: SPEC says it fails as written, a test recorded it holding"
                        ));
                    } else {
                        unrecorded.insert(id.clone());
                    }
                }
            }
            Stated::Restricted => {
                if !restricted_holds {
                    unrecorded.insert(id.clone());
                }
            }
        }
    }
    (bad, unrecorded)
}

/// The rows `unrecorded.txt` lists (one ID a line; `#` comments).
fn listed(text: &str) -> BTreeSet<String> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(String::from)
        .collect()
}

#[test]
fn x_spec_verdicts_spec_md_states_what_the_tests_saw() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let spec = std::fs::read_to_string(root.join("SPEC.md")).expect("SPEC.md");
    let rows = spec_rows(&spec);
    assert!(rows.len() > 100, "SPEC.md rows: {}", rows.len());
    // The comparison itself first: it must catch each kind of departure before its verdict on
    // SPEC.md means anything (recorded, so that `X-spec-verdicts` is a row like the others).
    let n = comparison_self_check();
    verdicts::record("X-spec-verdicts", verdicts::Seen::Holds, n);
    let dir = verdicts::record_dir().expect("target directory");
    let records = read_records(&dir);
    assert!(
        !records.is_empty(),
        "no records in {}: run the whole suite (`cargo test`), whose other binaries record the verdicts they assert",
        dir.display()
    );
    let (mut bad, unrecorded) = compare(&rows, &records);
    // Which rows were recorded depends on the corpus (../shared): without it the other
    // binaries skip their corpus parts (and say how many), so only the contradictions are
    // decided here; the one rule for missing data skips the rest (and fails under CI=true).
    if common::shared_dir("x_spec_verdicts_spec_md_states_what_the_tests_saw").is_none() {
        assert!(
            bad.is_empty(),
            "{} departures:\n{}",
            bad.len(),
            bad.join("\n")
        );
        return;
    }
    let list_text = std::fs::read_to_string(root.join("tests/verdicts/unrecorded.txt"))
        .expect("tests/verdicts/unrecorded.txt");
    let allowed = listed(&list_text);
    for id in unrecorded.difference(&allowed) {
        bad.push(format!(
            "{id}: no test recorded the verdict SPEC.md states (assert it with the common helpers, or record it)"
        ));
    }
    for id in allowed.difference(&unrecorded) {
        if rows.iter().any(|r| &r.0 == id) {
            bad.push(format!(
                "{id}: recorded now: remove it from tests/verdicts/unrecorded.txt"
            ));
        } else {
            bad.push(format!(
                "{id}: listed in tests/verdicts/unrecorded.txt but no SPEC.md row has it"
            ));
        }
    }
    eprintln!(
        "X-spec-verdicts: {} rows, {} records from {}; {} rows not yet recorded (tests/verdicts/unrecorded.txt)",
        rows.len(),
        records.len(),
        dir.display(),
        unrecorded.len()
    );
    assert!(
        bad.is_empty(),
        "{} departures:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

#[test]
fn x_spec_verdicts_comparison_catches_each_departure() {
    comparison_self_check();
}

/// The comparison on a made-up table with one row per kind of departure; returns the number of
/// rows examined.
fn comparison_self_check() -> u64 {
    let spec = "\
| `H` | s | c | t | holds on the corpus |
| `F` | s | c | t | **fails as written** for m = 3 |
| `R` | s | c | t | restricted: m ≥ 4 |
| `D` | s | c | t | definition |
| `U` | s | c | t | holds |
| `M` | s | c \\| d | t | holds |
| `B` | s | c | t | 3 samples |
| `G` | s | c | t | holds |
";
    let rows = spec_rows(spec);
    assert_eq!(rows.len(), 8);
    assert!(rows[5].1.is_ok(), "an escaped pipe is not a cell border");
    let rec = |id: &str, s: &str, n: u64| (id.to_string(), s.to_string(), n);
    let records = vec![
        rec("H(edges)", "holds", 10),
        rec("F", "fails", 4),
        rec("R[restricted]", "holds", 2),
        rec("M", "holds", 1),
        rec("G", "fails", 3),
        rec("U", "holds", 0),
    ];
    let (bad, unrecorded) = compare(&rows, &records);
    // G: SPEC says holds, a test saw it fail. B: no verdict word.
    assert_eq!(bad.len(), 2, "{bad:?}");
    assert!(bad.iter().any(|b| b.starts_with("G:")));
    assert!(bad.iter().any(|b| b.starts_with("B:")));
    // U: recorded on nothing examined; nothing recorded for the others is a pass only for D.
    assert_eq!(
        unrecorded.into_iter().collect::<Vec<_>>(),
        vec!["U".to_string()]
    );
    assert_eq!(
        listed("# comment\nA\n\n B \n"),
        ["A", "B"].iter().map(|s| s.to_string()).collect()
    );
    rows.len() as u64
}
