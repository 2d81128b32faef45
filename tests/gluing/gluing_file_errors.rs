//! Bad gluing files give typed errors naming the file and the field, never a panic.

use pseudomanifold::gluing::file::{parse_gluing_str, read_gluing_file};
use pseudomanifold::gluing::GluingFileError;
use std::path::Path;

fn field_err(text: &str) -> (String, String) {
    match parse_gluing_str(text, Path::new("bad.toml")) {
        Err(GluingFileError::Field {
            file,
            field,
            message,
        }) => {
            assert_eq!(file, Path::new("bad.toml"));
            (field, message)
        }
        other => panic!("expected a field error, got {other:?}"),
    }
}

const DOM: &str = "[[domain]]\nid = 1\ninterval = [\"0\", \"1\"]\n";

#[test]
fn d3_4_1_file_errors_name_the_field() {
    assert_eq!(field_err("").0, "domain");
    assert_eq!(
        field_err("[[domain]]\nid = 1\ninterval = [\"0\", \"x\"]\n").0,
        "domain[0].interval[1]"
    );
    assert_eq!(
        field_err("[[domain]]\nid = -1\ninterval = [\"0\", \"1\"]\n").0,
        "domain[0].id"
    );
    assert_eq!(
        field_err("[[domain]]\nid = 1\ninterval = [0.5, 1]\n").0,
        "domain[0].interval[0]"
    );
    assert_eq!(
        field_err("[[domain]]\nid = 1\ninterval = [\"0\"]\n").0,
        "domain[0].interval"
    );
    let glue = |body: &str| format!("{DOM}[[glue]]\n{body}");
    assert_eq!(
        field_err(&glue(
            "i = 1\nj = 7\nomega_ij = [\"0\",\"1\"]\na = \"1\"\nb = \"0\"\n"
        ))
        .0,
        "glue[0].j"
    );
    assert_eq!(
        field_err(&glue("i = 1\nj = 1\nomega_ij = [\"0\",\"1\"]\nb = \"0\"\n")).0,
        "glue[0].a"
    );
    assert_eq!(
        field_err(&glue(
            "i = 1\nj = 1\nomega_ij = [\"0\",\"1\"]\na = \"1/0\"\nb = \"0\"\n"
        ))
        .0,
        "glue[0].a"
    );
    assert_eq!(
        field_err(&glue(
            "i = 1\nj = 1\nomega = [\"0\",\"1\"]\na = \"1\"\nb = \"0\"\n"
        ))
        .0,
        "glue[0].omega"
    );
    assert_eq!(field_err(&format!("glue = 3\n{DOM}")).0, "glue");
    assert_eq!(field_err(&format!("{DOM}glue = 3\n")).0, "domain[0].glue");
}

#[test]
fn d3_4_1_file_syntax_and_io_errors() {
    assert!(matches!(
        parse_gluing_str("[[domain", Path::new("x.toml")),
        Err(GluingFileError::Syntax { .. })
    ));
    let e = read_gluing_file(Path::new("/nonexistent/gluing.toml")).unwrap_err();
    assert!(matches!(e, GluingFileError::Io { .. }));
    assert!(e.to_string().contains("/nonexistent/gluing.toml"));
}

#[test]
fn d3_4_1_file_accepts_fractions_decimals_and_integers() {
    let t = "[[domain]]\nid = 1\ninterval = [\"-1/3\", 2]\n[[domain]]\nid = 2\ninterval = [\"2.5\", \"3.25\"]\n";
    let f = parse_gluing_str(t, Path::new("ok.toml")).expect("parses");
    assert_eq!(f.data.omega(1).to_string(), "(-1/3, 2)");
    assert_eq!(f.data.omega(2).to_string(), "(5/2, 13/4)");
    // Default diagonal: Ω_ii = Ω_i, φ_ii = id.
    assert_eq!(f.data.omega_ij(2, 2), f.data.omega(2));
}

/// Resource bounds of the format (`gluing::file::MAX_*`): past each, a typed error naming the
/// file and the field, before any check runs.
#[test]
fn d3_4_1_file_limits_are_typed_errors() {
    use pseudomanifold::gluing::file::{
        MAX_DOMAIN_ENTRIES, MAX_FILE_BYTES, MAX_GLUE_ENTRIES, MAX_RATIONAL_CHARS,
    };
    let many_domains: String = (0..=MAX_DOMAIN_ENTRIES)
        .map(|n| format!("[[domain]]\nid = {n}\ninterval = [0, 1]\n"))
        .collect();
    let (field, message) = field_err(&many_domains);
    assert_eq!(field, "domain");
    assert!(
        message.contains(&MAX_DOMAIN_ENTRIES.to_string()),
        "{message}"
    );
    let ok_domains: String = (0..MAX_DOMAIN_ENTRIES)
        .map(|n| format!("[[domain]]\nid = {n}\ninterval = [0, 1]\n"))
        .collect();
    assert!(parse_gluing_str(&ok_domains, Path::new("ok.toml")).is_ok());

    let glue = "[[glue]]\ni = 1\nj = 1\nomega_ij = [0, 1]\na = 1\nb = 0\n";
    let many_glue = format!("{DOM}{}", glue.repeat(MAX_GLUE_ENTRIES + 1));
    assert_eq!(field_err(&many_glue).0, "glue");
    let ok_glue = format!("{DOM}{}", glue.repeat(MAX_GLUE_ENTRIES));
    assert!(parse_gluing_str(&ok_glue, Path::new("ok.toml")).is_ok());

    let long = "1".repeat(MAX_RATIONAL_CHARS + 1);
    let (field, message) = field_err(&format!(
        "[[domain]]\nid = 1\ninterval = [\"0\", \"{long}\"]\n"
    ));
    assert_eq!(field, "domain[0].interval[1]");
    assert!(message.contains("characters"), "{message}");
    let fits = "1".repeat(MAX_RATIONAL_CHARS);
    assert!(parse_gluing_str(
        &format!("[[domain]]\nid = 1\ninterval = [\"0\", \"{fits}\"]\n"),
        Path::new("ok.toml")
    )
    .is_ok());

    let dir = std::env::temp_dir().join(format!("ppm-gluing-limit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let big = dir.join("big.toml");
    // A comment of two-byte characters, so the cut at the limit splits one of them: still
    // `TooLarge` (with the real size), not an encoding error.
    let padding = "é".repeat(usize::try_from(MAX_FILE_BYTES / 2).expect("fits"));
    let text = format!("{DOM}#{padding}\n");
    std::fs::write(&big, &text).expect("write");
    let e = read_gluing_file(&big).unwrap_err();
    assert!(
        matches!(e, GluingFileError::TooLarge { bytes, .. } if bytes == text.len() as u64),
        "{e:?}"
    );
    assert!(e.to_string().contains("big.toml"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}
