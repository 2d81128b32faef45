//! The pictures in README.md and docs/ are the ones their printed commands make today
//! (SPEC `X-docs-pictures`): every `cargo run --release -- render|figure … -o docs/img/…`
//! line of a shell block is run again (the test build of the same binary; `ppm render` and
//! `ppm figure` are deterministic) and its output compared byte for byte with the committed
//! file. A stale picture fails here.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The (document, argument list, committed output) of every picture command in the docs.
fn picture_commands(root: &Path) -> Vec<(String, Vec<String>, PathBuf)> {
    let mut docs = vec![root.join("README.md")];
    if let Ok(rd) = std::fs::read_dir(root.join("docs")) {
        let mut more: Vec<PathBuf> = rd
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "md"))
            .collect();
        more.sort();
        docs.extend(more);
    }
    let mut out = Vec::new();
    for doc in docs {
        let Ok(text) = std::fs::read_to_string(&doc) else {
            continue;
        };
        for line in text.lines() {
            let Some(rest) = line.trim().strip_prefix("cargo run --release -- ") else {
                continue;
            };
            let args: Vec<String> = rest.split_whitespace().map(String::from).collect();
            let Some(o) = args.iter().position(|a| a == "-o") else {
                continue;
            };
            let Some(target) = args.get(o + 1) else {
                continue;
            };
            if target.starts_with("docs/img/") {
                out.push((doc.display().to_string(), args.clone(), root.join(target)));
            }
        }
    }
    out
}

#[test]
fn x_docs_pictures_are_remade_byte_for_byte_by_their_commands() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let cmds = picture_commands(root);
    assert!(
        cmds.len() >= 3,
        "expected the README's picture commands, found {}",
        cmds.len()
    );
    let tmp = std::env::temp_dir().join(format!("ppm-docs-pictures-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temp dir");
    for (i, (doc, args, committed)) in cmds.iter().enumerate() {
        // Every input a command reads must ship with the repository (a clone with nothing
        // beside it remakes every picture).
        for a in args {
            assert!(
                !a.contains("../shared"),
                "{doc}: picture command reads {a}, which a clone does not have"
            );
        }
        let name = committed.file_name().expect("file name");
        let fresh = tmp.join(format!("{i}-{}", name.to_string_lossy()));
        let mut argv = args.clone();
        let o = argv.iter().position(|a| a == "-o").expect("-o");
        argv[o + 1] = fresh.display().to_string();
        let run = Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(&argv)
            .current_dir(root)
            .output()
            .expect("run ppm");
        assert!(
            run.status.success(),
            "{doc}: `ppm {}` failed: {}",
            args.join(" "),
            String::from_utf8_lossy(&run.stderr)
        );
        let new = std::fs::read(&fresh).expect("fresh picture");
        let old = std::fs::read(committed)
            .unwrap_or_else(|e| panic!("{doc}: {}: {e}", committed.display()));
        assert!(
            new == old,
            "{doc}: {} is stale: `cargo run --release -- {}` makes a different file ({} bytes, committed {} bytes); run it and commit the result",
            committed.display(),
            args.join(" "),
            new.len(),
            old.len()
        );
    }
    let _ = std::fs::remove_dir_all(&tmp);
    crate::common::verdicts::record(
        "X-docs-pictures",
        crate::common::verdicts::Seen::Holds,
        cmds.len() as u64,
    );
}

#[test]
fn x_docs_pictures_finds_the_readme_commands() {
    // The parser itself: a command in a shell block is found with its output path; a command
    // writing elsewhere is not a docs picture.
    let root = std::env::temp_dir().join(format!("ppm-docs-parse-{}", std::process::id()));
    std::fs::create_dir_all(root.join("docs")).expect("dir");
    std::fs::write(
        root.join("README.md"),
        "```sh\ncargo run --release -- render a.obj --panels -o docs/img/x.png\ncargo run --release -- sample a.obj -o out.ply\n```\n",
    )
    .expect("write");
    let cmds = picture_commands(&root);
    assert_eq!(cmds.len(), 1);
    assert_eq!(cmds[0].1[0], "render");
    assert!(cmds[0].2.ends_with("docs/img/x.png"));
    let _ = std::fs::remove_dir_all(&root);
}
