//! The certificate tables say what the summaries say (SPEC `L4.2.1(cert)`): every row of
//! certificates/README.md names a summary whose header line carries the same degree range and
//! configuration count, and SPEC.md quotes the same counts.

use std::path::Path;

/// (max degree, configurations) from a summary's header line.
fn summary_header(text: &str) -> Option<(u32, u64)> {
    let head = text.lines().next()?;
    let deg = head.split("degrees 3..=").nth(1)?;
    let m: u32 = deg.split(',').next()?.trim().parse().ok()?;
    let before = head.split(" configurations").next()?;
    let n: u64 = before.rsplit(' ').next()?.parse().ok()?;
    Some((m, n))
}

#[test]
fn l4_2_1_cert_docs_quote_the_summaries_configuration_counts() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("certificates/README.md")).expect("README");
    let spec = std::fs::read_to_string(root.join("SPEC.md")).expect("SPEC.md");
    // Compared with line breaks as spaces: SPEC.md wraps its prose.
    let spec = spec.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut rows = 0;
    for line in readme
        .lines()
        .filter(|l| l.starts_with("| `CERTIFICATE_SUMMARY_M"))
    {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let file = cells[1]
            .split('`')
            .nth(1)
            .expect("summary file name in backticks");
        let text = std::fs::read_to_string(root.join("certificates").join(file))
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        let (m, n) = summary_header(&text).unwrap_or_else(|| panic!("{file}: header"));
        assert_eq!(cells[2], format!("3..={m}"), "{file}: degrees in README");
        assert_eq!(cells[3], n.to_string(), "{file}: configurations in README");
        if m == 20 {
            // SPEC `L4.2.1(cert)` and `L4.2.2(cert)`: every triangle configuration of the
            // summary certified on the whole set (no δ), the count SPEC.md quotes.
            for id in ["L4.2.1(cert)", "L4.2.2(cert)"] {
                let row = text
                    .lines()
                    .find(|l| l.starts_with(&format!("| `{id}` |")))
                    .unwrap_or_else(|| panic!("{file}: no {id} row"));
                let c: Vec<&str> = row.split('|').map(str::trim).collect();
                assert_eq!(c[2], c[3], "{file}: {id} not certified everywhere: {row}");
                assert!(c[4..7].iter().all(|x| *x == "0"), "{file}: {row}");
                if id == "L4.2.1(cert)" {
                    assert!(
                        spec.contains(&format!(
                            "for all {} triangle configurations with degrees ≤ 20",
                            c[2]
                        )),
                        "SPEC.md does not quote the summary's {} triangle configurations",
                        c[2]
                    );
                }
            }
        }
        // No δ anywhere in a committed summary: every property row is certified on the whole
        // stated set or refuted by a witness (no result certified only outside δ, none
        // inconclusive), so its `max δ` cell is empty.
        let mut props = 0;
        for row in text
            .lines()
            .filter(|l| l.starts_with("| `") && l.contains("(cert)"))
        {
            let c: Vec<&str> = row.split('|').map(str::trim).collect();
            if c.len() < 13 {
                continue; // the per-configuration table has fewer columns
            }
            assert_eq!(c[4], "0", "{file}: certified only outside δ: {row}");
            assert_eq!(c[6], "0", "{file}: inconclusive: {row}");
            assert_eq!(c[9], "—", "{file}: a δ in the summary: {row}");
            props += 1;
        }
        assert!(props >= 8, "{file}: {props} property rows read");
        if m >= 16 {
            assert!(
                spec.contains(&format!("(M = {m}: {n} configurations"))
                    || spec.contains(&format!("(M = {m}, {n} configurations")),
                "SPEC.md does not quote M = {m} with the summary's {n} configurations"
            );
        }
        rows += 1;
    }
    assert!(rows >= 3, "certificates/README.md lists {rows} summaries");
}

#[test]
fn l4_2_1_cert_docs_header_parser_reads_degree_and_count() {
    let h =
        "# Certificate summary: degrees 3..=20, model paper, 12006 configurations, 24390 results";
    assert_eq!(summary_header(h), Some((20, 12006)));
    assert_eq!(summary_header("# something else"), None);
}
