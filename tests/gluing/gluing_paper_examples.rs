//! App. A.2's counterexamples and their repairs, read from `examples/gluing/*.toml` and decided
//! by the exact 1-D backend; plus the `ppm gluing` command on them.

use crate::common;

use pseudomanifold::gluing::exact1d::data::q;
use pseudomanifold::gluing::exact1d::decide::{self, check_4_with_radii};
use pseudomanifold::gluing::exact1d::Exact1d;
use pseudomanifold::gluing::file::read_gluing_file;
use pseudomanifold::gluing::relation::{check_claim, check_equivalence, related, GridSample};
use pseudomanifold::gluing::report::gluing_report;
use pseudomanifold::report::CheckResult;
use std::path::PathBuf;

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("examples/gluing/{name}.toml"))
}

fn load(name: &str) -> Exact1d {
    read_gluing_file(&path(name)).expect("example parses").data
}

fn by_id<'a>(rs: &'a [CheckResult], id: &str) -> &'a CheckResult {
    rs.iter()
        .find(|r| r.id == id)
        .unwrap_or_else(|| panic!("no result {id}"))
}

fn kinds(r: &CheckResult) -> Vec<String> {
    r.witnesses
        .iter()
        .map(|w| w.data["kind"].as_str().unwrap_or("").to_string())
        .collect()
}

#[test]
fn ca_2_line_counterexample_fails_3c_with_witness_half() {
    let g = load("line_counterexample");
    let rs = decide::check_all(&g);
    for id in [
        "D3.4.1(1)",
        "D3.4.1(2)",
        "D3.4.1(3)",
        "D3.4.1(3a)",
        "D3.4.1(3b)",
        "D3.4.1(4)",
    ] {
        common::assert_holds(by_id(&rs, id));
    }
    let c = by_id(&rs, "D3.4.1(3c)");
    assert!(c.failed());
    let w = &c.witnesses[0].data;
    assert_eq!(w["kind"], "inclusion");
    assert_eq!(
        (w["i"].as_u64(), w["j"].as_u64(), w["k"].as_u64()),
        (Some(1), Some(2), Some(3))
    );
    assert_eq!(
        (w["x"].as_str(), w["y"].as_str(), w["z"].as_str()),
        (Some("1/2"), Some("9/2"), Some("17/2"))
    );
    // The paper's claim about the line example: (3c) fails there, the rest holds.
    common::verdicts::record("CA.2-line", common::verdicts::Seen::Holds, rs.len() as u64);
}

#[test]
fn ca_2_line_relation_half_related_to_nine_halves_related_to_seventeen_halves_not_transitive() {
    let g = load("line_counterexample");
    let (x, y, z) = ((1, q(1, 2)), (2, q(9, 2)), (3, q(17, 2)));
    assert!(related(&g, &x, &y), "0.5 ∼ 4.5");
    assert!(related(&g, &y, &z), "4.5 ∼ 8.5");
    assert!(!related(&g, &x, &z), "0.5 ≁ 8.5");
    let r = check_equivalence(&g, &GridSample::from_points(vec![x.clone()]));
    assert!(r.failed());
    assert_eq!(kinds(&r), vec!["transitivity"]);
    assert!(
        r.witnesses[0]
            .text
            .contains("1/2∈Ω_1 ∼ 9/2∈Ω_2 ∼ 17/2∈Ω_3 but 1/2 ≁ 17/2"),
        "{}",
        r.witnesses[0].text
    );
}

#[test]
fn ca_2_gh_holds_on_line_counterexample_so_it_is_weaker_than_3c() {
    let g = load("line_counterexample");
    let gh = decide::check_grimm_hughes(&g, false);
    common::assert_holds(&gh);
    assert!(gh.examined > 0);
    assert!(decide::check_3c(&g).failed());
}

#[test]
fn ca_2_gh_strict_fails_on_line_counterexample_at_nine_halves() {
    // Erratum-style finding: if the proto-manifold condition requires its right side to be
    // defined, the counterexample violates it too, at (i,j,k) = (2,1,3), x = 4.5.
    let g = load("line_counterexample");
    let r = decide::check_grimm_hughes(&g, true);
    common::assert_fails_as_written(&r);
    let w = &r.witnesses[0].data;
    assert_eq!(w["kind"], "rhs_undefined");
    assert_eq!(
        (w["i"].as_u64(), w["j"].as_u64(), w["k"].as_u64()),
        (Some(2), Some(1), Some(3))
    );
    assert_eq!(w["x"], "9/2");
}

#[test]
fn ca_2_line_claim_of_thm_fails_class_meets_outside_gluing_domain() {
    let g = load("line_counterexample");
    let r = check_claim(&g, &GridSample::new(&g, 24));
    assert!(r.failed());
    assert!(kinds(&r).iter().all(|k| k == "not_in_gluing_domain"));
}

#[test]
fn ca_2_line_repaired_satisfies_everything() {
    let g = load("line_repaired");
    let s = GridSample::new(&g, 24);
    let mut rs = decide::check_all(&g);
    rs.push(check_equivalence(&g, &s));
    rs.push(check_claim(&g, &s));
    for r in &rs {
        common::assert_holds(r);
        assert!(r.examined > 0, "{} examined nothing", r.id);
    }
    assert!(related(&g, &(1, q(1, 2)), &(3, q(17, 2))));
}

#[test]
fn ca_2_fork_fails_only_4_with_witness_minus_two_two() {
    let g = load("fork");
    let rs = decide::check_all(&g);
    for r in &rs {
        if r.id == "D3.4.1(4)" {
            assert!(r.failed());
            let w = &r.witnesses[0].data;
            assert_eq!((w["i"].as_u64(), w["j"].as_u64()), (Some(1), Some(2)));
            assert_eq!((w["x"].as_str(), w["y"].as_str()), (Some("-2"), Some("2")));
        } else {
            common::assert_holds(r);
        }
    }
    let s = GridSample::new(&g, 24);
    common::assert_holds(&check_equivalence(&g, &s));
    common::assert_holds(&check_claim(&g, &s));
    // The paper's claim about the fork: only (4) fails.
    common::verdicts::record("CA.2-fork", common::verdicts::Seen::Holds, rs.len() as u64);
}

#[test]
fn ca_2_fork_repaired_holds_with_radii_half_half() {
    let g = load("fork_repaired");
    for r in decide::check_all(&g) {
        common::assert_holds(&r);
    }
    let (r, seps) = check_4_with_radii(&g);
    common::assert_holds(&r);
    let s = seps
        .iter()
        .find(|s| s.i == 1 && s.j == 2)
        .expect("pair (1,2) examined");
    assert_eq!((s.x.clone(), s.y.clone()), (q(-2, 1), q(2, 1)));
    assert_eq!((s.r_x.clone(), s.r_y.clone()), (q(1, 2), q(1, 2)));
}

#[test]
fn d3_4_1_circles_from_two_and_three_intervals_satisfy_everything() {
    for name in ["circle2", "circle3"] {
        let g = load(name);
        let s = GridSample::new(&g, 24);
        let mut rs = decide::check_all(&g);
        rs.push(check_equivalence(&g, &s));
        rs.push(check_claim(&g, &s));
        for r in &rs {
            common::assert_holds_for(name, r);
        }
        assert_eq!(g.k().len(), if name == "circle2" { 4 } else { 9 });
    }
}

#[test]
fn d3_4_1_4_radii_really_separate_on_a_fine_grid() {
    // The radii the exact (4) checker returns must work: no grid point of V_x ∩ Ω_ij maps into V_y.
    for name in [
        "fork_repaired",
        "line_repaired",
        "circle2",
        "circle3",
        "line_counterexample",
    ] {
        let g = load(name);
        let (_, seps) = check_4_with_radii(&g);
        assert!(!seps.is_empty());
        for s in seps {
            for t in -1000..=1000i64 {
                let xp = &s.x + &s.r_x * q(t, 1001);
                if let Some(y) = g.phi(s.j, s.i, &xp) {
                    let d = &y - &s.y;
                    let d = if d < q(0, 1) { -d } else { d };
                    assert!(d >= s.r_y, "{name}: {} ↦ {} inside V_y", xp, y);
                }
            }
        }
    }
}

#[test]
fn d3_4_1_cli_reports_verdict_table_with_witnesses() {
    let (text, ok) = gluing_report(&path("fork"), false).expect("runs");
    assert!(!ok);
    assert!(text.contains("FAILS    D3.4.1(4)"), "{text}");
    assert!(
        text.contains("x = -2 ∈ ∂Ω_(1,2) ∩ Ω_1, y = 2 ∈ ∂Ω_(2,1) ∩ Ω_2"),
        "{text}"
    );
    let (text, ok) = gluing_report(&path("circle3"), false).expect("runs");
    assert!(ok, "{text}");
    assert!(text.contains("all conditions hold"));
    let (json, ok) = gluing_report(&path("line_counterexample"), true).expect("runs");
    assert!(!ok);
    let v: serde_json::Value = serde_json::from_str(&json).expect("valid JSON");
    assert_eq!(v["all_hold"], false);
    let failed: Vec<&str> = v["results"]
        .as_array()
        .expect("array")
        .iter()
        .filter(|r| r["verdict"] == "fails")
        .filter_map(|r| r["id"].as_str())
        .collect();
    assert_eq!(
        failed,
        vec![
            "D3.4.1(3c)",
            "CA.2-GH-strict",
            "T3.4.1(equiv)",
            "T3.4.1(claim)"
        ]
    );
}
