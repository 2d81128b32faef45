//! The oracle protocol driven from a child process, `ppm diff`, and the self-test —
//! this crate's f64 path treated as "a faster implementation" and diffed against the MPFR
//! reference, with a planted sign flip in one rotation that the diff must catch.

use crate::common;

use pseudomanifold::construction::maps::rotate_frac;
use pseudomanifold::construction::{EdgeConfig, Paper, Ppm, PpmGluing, P2};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use pseudomanifold::numeric::Scalar;
use pseudomanifold::oracle::diff::diff_table;
use pseudomanifold::oracle::Session;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/icosahedron_binary_le.ply")
}

fn load(path: &Path) -> SimplicialSurface {
    let raw = read_mesh(path, &ReadOptions::default()).expect("readable");
    validate(&raw).surface.expect("valid")
}

#[test]
fn oracle_protocol_from_a_child_process() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ppm"))
        .args(["oracle", "--bits", "200"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("spawn ppm oracle");
    let mut stdin = child.stdin.take().expect("stdin");
    let requests = [
        r#"{"op":"phi","u":0,"w":1,"p":[0.3,0.1]}"#.to_string(),
        format!(
            r#"{{"op":"load","path":{:?},"id":"L"}}"#,
            fixture().display().to_string()
        ),
        r#"{"op":"labels","v":0}"#.into(),
        r#"{"op":"phi","u":0,"w":1,"p":[0.3,0.1],"id":7}"#.into(),
        r#"{"op":"phi","u":0,"w":1,"p":[0.0,0.0]}"#.into(),
        r#"{"op":"phi","u":0,"w":999,"p":[0.3,0.1]}"#.into(),
        r#"{"op":"phi","u":0,"w":1}"#.into(),
        "this is not json".into(),
        r#"{"op":"set_precision","bits":0}"#.into(),
        r#"{"op":"frobnicate"}"#.into(),
        r#"{"op":"member","u":0,"w":1,"p":[0.3,0.1],"test":"lens"}"#.into(),
        r#"{"op":"h","p":[0.25,-2.0]}"#.into(),
    ];
    for r in &requests {
        writeln!(stdin, "{r}").expect("write");
    }
    drop(stdin);
    let out = BufReader::new(child.stdout.take().expect("stdout"));
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(&l.expect("line")).expect("every answer is JSON"))
        .collect();
    assert!(child.wait().expect("exit").success());
    assert_eq!(lines.len(), requests.len(), "one answer per request");
    let kind = |i: usize| lines[i]["error"]["kind"].as_str().unwrap_or("").to_string();
    assert_eq!(kind(0), "no_mesh");
    assert_eq!(lines[1]["ok"], true);
    assert_eq!(lines[1]["id"], "L");
    assert_eq!(lines[1]["value"]["vertices"], 12);
    assert_eq!(lines[2]["value"].as_array().map(|a| a.len()), Some(5));
    assert_eq!(lines[3]["id"], 7);
    assert_eq!(lines[3]["mp_bits"], 200);
    let d = lines[3]["difference"].as_f64().expect("difference");
    assert!(d > 0.0 && d < 1e-14, "{d}");
    assert_eq!(kind(4), "not_in_domain");
    assert_eq!(kind(5), "no_such_element");
    assert_eq!(kind(6), "malformed_request");
    assert_eq!(kind(7), "malformed_request");
    assert_eq!(kind(8), "bad_precision");
    assert_eq!(kind(9), "malformed_request");
    assert_eq!(lines[10]["value"], true);
    assert_eq!(lines[11]["f64"], serde_json::json!([0.75, 2.0]));
    assert_eq!(lines[11]["difference"], 0.0);
}

/// Points of Ω_uw for an edge: lens points pulled back by R_(u,w)⁻¹∘g_u⁻¹.
fn domain_points(e: &EdgeConfig) -> Vec<P2<f64>> {
    let mut v = Vec::new();
    for a in 1..4 {
        for b in -1..=1 {
            let q = P2::new(0.2 + 0.6 * f64::from(a) / 4.0, 0.2 * f64::from(b));
            if let Ok(g) = Paper.g_v_inv(e.m_u, &q) {
                let p = Paper.r_uw_inv(e, &g);
                if Paper.in_omega_uw_literal(e, &p).is_true() {
                    v.push(p);
                }
            }
        }
    }
    v
}

/// A "faster implementation" with a planted bug: R_(u,w) rotates the wrong way.
struct SignFlip;
impl Ppm<f64> for SignFlip {
    fn r_uw(&self, e: &EdgeConfig, p: &P2<f64>) -> P2<f64> {
        rotate_frac(p, e.i as i64, e.m_u as i64)
    }
}

/// A model of φ: its answer for one edge configuration and point, if defined there.
type PhiModel<'a> = &'a dyn Fn(&EdgeConfig, &P2<f64>) -> Option<P2<f64>>;

/// The table of φ answers another implementation would produce, as JSON lines: one oriented
/// edge per edge configuration. φ_(u,w) depends only on (m_u, i, m_w, j) (Sec. 6.1.3), so a
/// second edge of the same configuration asks both paths the same questions again (bob_small's
/// 1,500 oriented edges have far fewer configurations; the MPFR side is the test's time).
fn phi_table(k: &SimplicialSurface, model: PhiModel<'_>) -> String {
    let g = PpmGluing::new(k);
    let mut t = String::new();
    let mut seen = std::collections::HashSet::new();
    for (a, b) in k.edges() {
        for (u, w) in [(a, b), (b, a)] {
            let e = g.edge_config(u, w).expect("config");
            if !seen.insert(e) {
                continue;
            }
            for p in domain_points(&e) {
                if let Some(q) = model(&e, &p) {
                    t.push_str(&format!(
                        "{{\"op\":\"phi\",\"u\":{},\"w\":{},\"p\":[{:?},{:?}],\"value\":[{:?},{:?}]}}\n",
                        u.0, w.0, p.x, p.y, q.x, q.y
                    ));
                }
            }
        }
    }
    t
}

/// The tolerance for f64 against MPFR: ε·(a stated condition factor for the ~60 operations
/// and the Lipschitz amplification ≤ 16 of the chain R⁻¹∘g_w⁻¹∘h∘g_u∘R).
const F64_TOL: f64 = 1024.0 * f64::EPSILON;

#[test]
fn oracle_self_test_f64_path_agrees_with_mp_and_planted_sign_flip_is_caught() {
    let mut meshes = vec![fixture()];
    meshes.extend(
        common::corpus("oracle_self_test_f64_path_agrees_with_mp")
            .into_iter()
            .filter(|m| m.good && m.faces <= 500)
            .map(|m| m.path),
    );
    for path in meshes {
        let k = load(&path);
        let good = phi_table(&k, &|e, p| Paper.g_uw(e, p).ok());
        let mut s = Session::with_surface(k.clone());
        let r = diff_table(&mut s, &good, F64_TOL, 5);
        eprintln!(
            "{}: {} items, max {:.3e} (tolerance {F64_TOL:.3e})",
            path.display(),
            r.stats.count,
            r.stats.max
        );
        assert!(r.stats.count > 50);
        assert!(r.problems.is_empty(), "{:?}", r.problems.first());
        assert!(
            r.within_tolerance,
            "{}",
            pseudomanifold::oracle::diff::render(&r)
        );
        // The planted sign flip is diffed on every eighth line of its table: the assertions
        // below need some line with an O(1) error, and the whole table (diffed above for the
        // good values) would add MPFR evaluations, not power.
        let bad: String = phi_table(&k, &|e, p| SignFlip.g_uw(e, p).ok())
            .lines()
            .step_by(8)
            .flat_map(|l| [l, "\n"])
            .collect();
        let r = diff_table(&mut s, &bad, F64_TOL, 5);
        assert!(
            r.stats.count > 5,
            "{} planted lines compared",
            r.stats.count
        );
        assert!(!r.within_tolerance);
        assert!(
            r.stats.max > 1e-3,
            "sign flip gives O(1) errors: {}",
            r.stats.max
        );
        let worst = &r.worst[0];
        assert_eq!(worst.request["op"], "phi");
    }
}

#[test]
fn oracle_diff_cli_exit_status_and_report() {
    let k = load(&fixture());
    let dir = std::env::temp_dir().join(format!("ppm-diff-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    let good = dir.join("good.jsonl");
    let bad = dir.join("bad.jsonl");
    std::fs::write(&good, phi_table(&k, &|e, p| Paper.g_uw(e, p).ok())).expect("write");
    std::fs::write(&bad, phi_table(&k, &|e, p| SignFlip.g_uw(e, p).ok())).expect("write");
    let run = |table: &Path| {
        Command::new(env!("CARGO_BIN_EXE_ppm"))
            .args(["diff", "--mesh"])
            .arg(fixture())
            .arg(table)
            .args(["--tolerance", "1e-12"])
            .output()
            .expect("run ppm diff")
    };
    let ok = run(&good);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stdout)
    );
    assert!(String::from_utf8_lossy(&ok.stdout).contains("within tolerance"));
    let ko = run(&bad);
    assert_eq!(ko.status.code(), Some(1));
    let text = String::from_utf8_lossy(&ko.stdout);
    assert!(text.contains("OUTSIDE tolerance"), "{text}");
    assert!(
        text.contains("\"op\":\"phi\""),
        "worst items listed with their arguments"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn oracle_mp_values_agree_across_precisions() {
    // The reference itself: 256-bit and 512-bit answers agree far below the f64 level.
    let k = load(&fixture());
    let g = PpmGluing::new(&k);
    let (u, w) = k.edges().next().expect("edge");
    let e = g.edge_config(u, w).expect("config");
    for p in domain_points(&e) {
        use pseudomanifold::numeric::Mp;
        let a = g
            .phi::<Mp>(w, u, &P2::<Mp>::from_f64(p.x, p.y, 256))
            .expect("φ 256");
        let b = g
            .phi::<Mp>(w, u, &P2::<Mp>::from_f64(p.x, p.y, 512))
            .expect("φ 512");
        let d = a.x.sub(&Mp::from_f64(0.0, 512)).sub(&b.x).to_f64().abs();
        assert!(d < 1e-70, "{d}");
    }
}

/// AU-tables, the unit of `ppm diff` on a TSV table: deviations are relative to the
/// bounding-box diagonal of K (computed here from the positions), per row and per coordinate
/// column; a table of this crate's own S′ values agrees exactly; a value shifted by δ of the
/// diagonal in x is reported as δ in the point and x statistics and 0 in y and z, and fails
/// a tolerance below δ; a row with a field missing is refused naming its line.
#[test]
fn au_tables_tsv_units_columns_and_field_count() {
    use pseudomanifold::mesh::VertexId;
    use pseudomanifold::oracle::tsv_diff::{diagonal, diff_rows, parse_tsv, TsvError};
    use pseudomanifold::surface::TargetSurface;
    let mesh = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/authors_pps/cube.off");
    let raw = read_mesh(&mesh, &ReadOptions::default()).expect("mesh");
    let k = validate(&raw).surface.expect("surface");
    let positions: Vec<[f64; 3]> = k.vertices().map(|v| k.position(v)).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &positions {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    let expected = (0..3).map(|d| (hi[d] - lo[d]).powi(2)).sum::<f64>().sqrt();
    let diag = diagonal(&k);
    assert_eq!(diag, expected);
    // Translated away from the origin: the diagonal is a length, not a position.
    let mut moved = raw.clone();
    for p in &mut moved.positions {
        p[0] += 10.0;
        p[2] -= 3.0;
    }
    let km = validate(&moved).surface.expect("surface");
    assert!((diagonal(&km) - diag).abs() <= 1e-12 * diag);

    let (pn, pps) = common::authors_code_pps(&k);
    let mut text = String::from("face\tlambda\tmu\tnu\tsprime_x\tsprime_y\tsprime_z\n");
    for (f, corners) in raw.faces.iter().enumerate() {
        for b in [[0.2, 0.3, 0.5], [1.0 / 3.0; 3]] {
            let fid = pseudomanifold::mesh::FaceId(f as u32);
            let p = pn.eval(fid, corners.map(VertexId), b);
            text.push_str(&format!(
                "{f}\t{}\t{}\t{}\t{}\t{}\t{}\n",
                b[0], b[1], b[2], p[0], p[1], p[2]
            ));
        }
    }
    let mut rows = parse_tsv(&text, k.num_faces()).expect("rows");
    let r = diff_rows(&k, &raw.faces, &pps, &pn, &rows, 1e-12, 3);
    let q = &r.quantities[0];
    assert_eq!(q.name, "sprime");
    assert_eq!(q.point.count, rows.len());
    assert_eq!(q.point.max, 0.0, "own values must agree exactly");
    assert!(r.within_tolerance);
    let delta = 1e-6;
    if let Some(p) = rows[3].sprime.as_mut() {
        p[0] += delta * diag;
    }
    let r = diff_rows(&k, &raw.faces, &pps, &pn, &rows, delta / 2.0, 3);
    let q = &r.quantities[0];
    assert!(
        (q.point.max - delta).abs() <= 1e-9 * delta,
        "{}",
        q.point.max
    );
    assert!((q.columns[0].max - delta).abs() <= 1e-9 * delta);
    assert_eq!((q.columns[1].max, q.columns[2].max), (0.0, 0.0));
    assert!(!r.within_tolerance, "a deviation above the tolerance");
    assert!(diff_rows(&k, &raw.faces, &pps, &pn, &rows, 2.0 * delta, 3).within_tolerance);

    let short = "face\tlambda\tmu\tnu\tsprime_x\tsprime_y\tsprime_z\n0\t1\t0\t0\t1\t1\n";
    match parse_tsv(short, k.num_faces()) {
        Err(TsvError::FieldCount {
            line: 2,
            found: 6,
            expected: 7,
        }) => {}
        other => panic!("{other:?}"),
    }
}
