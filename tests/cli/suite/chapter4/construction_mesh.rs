//! The tests of `tests/chapter4/construction_mesh.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

#[test]
fn d4_1_9_figure_renders_valid_svg() {
    use pseudomanifold::construction::figure::render_svg;
    for (mu, mw) in [(5, 7), (3, 12), (6, 6)] {
        let svg = render_svg(mu, mw).expect("valid degrees");
        svg_well_formed(&svg).unwrap_or_else(|e| panic!("({mu},{mw}): {e}"));
        assert!(svg.starts_with("<svg"));
        // m_u gluing domains in u's copy plus Ω_wu, and grid lines in both panels.
        assert!(svg.matches("<polygon").count() > 2 + mu as usize);
        assert!(svg.matches("<polyline").count() > 2 * (mu + mw) as usize);
    }
    assert!(render_svg(2, 5).is_err(), "degree 2 is refused");
    assert!(
        svg_well_formed("<svg><g></svg>").is_err(),
        "the checker can fail"
    );
    // The CLI writes it.
    let out = std::env::temp_dir().join(format!("ppm-fig-{}.svg", std::process::id()));
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["figure", "--degrees", "4,9", "-o"])
        .arg(&out)
        .status()
        .expect("run");
    assert!(st.success());
    let svg = std::fs::read_to_string(&out).expect("written");
    svg_well_formed(&svg).expect("well formed");
    let _ = std::fs::remove_file(out);
}

/// Minimal well-formedness check of an SVG document: one root `svg` element, every element
/// closed, attribute values quoted, every coordinate a finite number.
fn svg_well_formed(s: &str) -> Result<(), String> {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = s;
    let mut roots = 0;
    while let Some(i) = rest.find('<') {
        let j = rest[i..].find('>').ok_or("unterminated tag")? + i;
        let tag = &rest[i + 1..j];
        if let Some(name) = tag.strip_prefix('/') {
            let open = stack.pop().ok_or("closing tag without opening")?;
            if open != name.trim() {
                return Err(format!("</{name}> closes <{open}>"));
            }
        } else if !tag.ends_with('/') {
            let name = tag
                .split_whitespace()
                .next()
                .ok_or("empty tag")?
                .to_string();
            if stack.is_empty() {
                roots += 1;
            }
            stack.push(name);
        }
        if tag.matches('"').count() % 2 != 0 {
            return Err(format!("unbalanced quotes in <{tag}>"));
        }
        rest = &rest[j + 1..];
    }
    if !stack.is_empty() || roots != 1 {
        return Err(format!("unclosed {stack:?} or {roots} roots"));
    }
    if s.contains("NaN") || s.contains("inf") {
        return Err("non-finite coordinate".into());
    }
    Ok(())
}
