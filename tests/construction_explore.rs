use pseudomanifold::construction::checks::*;
use pseudomanifold::construction::*;
use pseudomanifold::report::render_text;

#[test]
#[ignore]
fn explore() {
    let e = EdgeConfig::new(6, 0, 6, 0).unwrap();
    println!(
        "{}",
        render_text(&check_p4_1_1_guw_smooth::<f64, _>(&Paper, &e, 1, 400, 53))
    );
}
