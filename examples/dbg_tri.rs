use pseudomanifold::certify::*;
fn main() {
    let a: Vec<u32> = std::env::args()
        .skip(1)
        .map(|x| x.parse().unwrap())
        .collect();
    let k = ConfigKey::Triangle {
        m_u: a[0],
        m_w: a[1],
        m_x: a[2],
        ccw: a[3] == 1,
    };
    let mut s = Settings::default();
    if a.len() > 4 {
        s.check_diam = a[4] as f64 / 1000.0;
    }
    let t = std::time::Instant::now();
    let rs = prove_triangle(k, &Model::paper(), &s);
    println!(
        "{:?} boxes {} depth {} {:?} {}",
        rs[0].outcome,
        rs[0].boxes,
        rs[0].max_depth,
        t.elapsed(),
        &rs[0].statement[rs[0].statement.len() - 60..]
    );
    let t = std::time::Instant::now();
    let r = prove_inverse(a[0], a[1], &Model::paper(), &s);
    println!(
        "inv {:?} boxes {} depth {} {:?} {}",
        r.outcome,
        r.boxes,
        r.max_depth,
        t.elapsed(),
        r.centre_bound.unwrap_or(-1.0)
    );
}
