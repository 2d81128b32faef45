//! The tests of `tests/surface/oracle.rs` that run the `ppm` binary (see `tests/cli/main.rs`).

use pseudomanifold::construction::maps::rotate_frac;
use pseudomanifold::construction::{EdgeConfig, Paper, Ppm, PpmGluing, P2};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

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

/// A "faster implementation" with a planted bug: R_(u,w) rotates the wrong way.
fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/icosahedron_binary_le.ply")
}

fn load(path: &Path) -> SimplicialSurface {
    let raw = read_mesh(path, &ReadOptions::default()).expect("readable");
    validate(&raw).surface.expect("valid")
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
