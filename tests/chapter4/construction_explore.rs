//! Exploration harness (ignored): prints the verdicts of all checks on a range of configurations.
use pseudomanifold::construction::checks::*;
use pseudomanifold::construction::*;
use pseudomanifold::report::CheckResult;

fn show(rs: &[CheckResult]) {
    for r in rs {
        let w = r
            .witnesses
            .first()
            .map(|w| w.text.clone())
            .unwrap_or_default();
        println!(
            "  {:<18} {:<36} ex {:>4} off {:>4} worst {:.2e} tol {:.2e} | {}",
            r.verdict().label(),
            r.id,
            r.examined,
            r.offenders,
            r.worst_deviation.unwrap_or(0.0),
            r.tolerance.unwrap_or(0.0),
            &w.chars().take(260).collect::<String>()
        );
    }
}

#[test]
#[ignore]
fn explore() {
    for (mu, i, mw, j) in [(3, 1, 5, 2), (7, 2, 4, 1), (12, 3, 6, 0), (11, 0, 6, 3)] {
        let e = EdgeConfig::new(mu, i, mw, j).unwrap();
        println!("==== {e:?} f64");
        show(&run_edge_checks::<f64>(&e, 1, 300, 53));
    }
    for (mu, mw, mx) in [(6, 6, 6), (3, 5, 7), (3, 3, 3), (12, 4, 11), (4, 12, 5)] {
        let t = TriangleConfig::ccw(mu, mw, mx, 1 % mu, 2 % mw, 0).unwrap();
        println!("==== {t:?} f64");
        show(&run_triangle_checks::<f64>(&t, 1, 300, 53));
    }
    for m in [3, 6, 10, 11, 12, 13] {
        let s = StarConfig::uniform(m, 6).unwrap();
        println!("==== star {m}");
        show(&check_star_overlaps::<f64, _>(
            &Paper, &s, false, 1, 300, 53,
        ));
        show(&check_star_overlaps::<f64, _>(&Paper, &s, true, 1, 300, 53));
    }
}
