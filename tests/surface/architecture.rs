//! The floors of docs/architecture.md (SPEC `X-floors`): numbers → mesh → gluing →
//! constructions (Ch. 4, then the surfaces built on them) → checks, certificates, pictures →
//! oracle → cli. A module may import only from its own floor or the floors below. The imports
//! that still go up are listed in `ALLOWED_UP` (each one a planned move, named in
//! docs/architecture.md); a new upward import fails, and so does a listed one that is gone
//! (the list only shrinks).

use crate::spec_sync::rust_files;
use std::collections::BTreeSet;
use std::path::Path;

/// Each top-level module of src/ and its floor.
const FLOORS: &[(&str, u32)] = &[
    ("numeric", 0),
    ("report", 0),
    ("exact", 0),
    ("mesh", 1),
    ("gluing", 2),
    ("construction", 3),
    ("surface", 4),
    ("msplines", 4),
    ("sdiff", 4),
    ("fitting", 4),
    ("conditions", 5),
    ("certify", 5),
    ("render", 5),
    ("oracle", 6),
    ("cli", 7),
];

/// Upward imports not yet moved (from, to), with the move that removes each.
const ALLOWED_UP: &[(&str, &str)] = &[];

fn floor(m: &str) -> Option<u32> {
    FLOORS.iter().find(|(n, _)| *n == m).map(|(_, f)| *f)
}

/// The top-level modules named as `crate::X` in code (comments dropped).
fn imports(src: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in src.lines() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            let after = &rest[i + 7..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                out.insert(name);
            }
            rest = after;
        }
    }
    out
}

/// (from, to) of every import from a higher floor in src/.
fn upward_imports(root: &Path) -> BTreeSet<(String, String)> {
    let mut up = BTreeSet::new();
    for (m, f) in FLOORS {
        let mut files = Vec::new();
        rust_files(&root.join("src").join(m), &mut files);
        let single = root.join("src").join(format!("{m}.rs"));
        if single.is_file() {
            files.push(single);
        }
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap_or_default();
            for to in imports(&text) {
                if floor(&to).is_some_and(|g| g > *f) {
                    up.insert((m.to_string(), to));
                }
            }
        }
    }
    up
}

#[test]
fn x_floors_no_module_imports_from_a_floor_above_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    // Every top-level module has a floor.
    let mut dirs = Vec::new();
    for e in std::fs::read_dir(root.join("src")).expect("src").flatten() {
        let name = e
            .file_name()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if !["lib", "main"].contains(&name.as_str()) {
            dirs.push(name);
        }
    }
    for d in &dirs {
        assert!(floor(d).is_some(), "src/{d} has no floor in FLOORS");
    }
    let up = upward_imports(root);
    let allowed: BTreeSet<(String, String)> = ALLOWED_UP
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    let new: Vec<_> = up.difference(&allowed).collect();
    let gone: Vec<_> = allowed.difference(&up).collect();
    assert!(new.is_empty(), "imports from a higher floor: {new:?}");
    assert!(
        gone.is_empty(),
        "moved: remove from ALLOWED_UP and docs/architecture.md: {gone:?}"
    );
    let scanned = dirs.len() as u64;
    crate::common::verdicts::record("X-floors", crate::common::verdicts::Seen::Holds, scanned);
}

#[test]
fn x_floors_import_scan_reads_code_not_comments() {
    let src = "use crate::surface::Pps; // crate::cli in a comment\n/// crate::oracle\nfn f() { crate::mesh::x(); }";
    let got: Vec<String> = imports(src).into_iter().collect();
    assert_eq!(got, vec!["mesh".to_string(), "surface".to_string()]);
}

#[test]
fn x_floors_planted_upward_import_is_found() {
    let root = std::env::temp_dir().join(format!("ppm-floors-{}", std::process::id()));
    std::fs::create_dir_all(root.join("src/mesh")).expect("dir");
    std::fs::write(
        root.join("src/mesh/x.rs"),
        "use crate::cli::run;\nuse crate::numeric::Q;\n",
    )
    .expect("write");
    let up = upward_imports(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(
        up.into_iter().collect::<Vec<_>>(),
        vec![("mesh".to_string(), "cli".to_string())]
    );
}
