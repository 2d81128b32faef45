//! The measured effect of each difference between the paper and the authors' code: the
//! `authors-code` surface is rebuilt with one stage switched back to the paper's rule, and
//! its eval / S′ compared with the authors' tables (../shared/reference/authors-pps/pn/).
//! Run: `cargo run --release --example authors_stages [MESH_NAMES…]`; the numbers go to
//! docs/authors-code.md.

use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::oracle::tsv_diff::{diff_rows, parse_tsv};
use pseudomanifold::surface::{AuthorsStages, NormalRule, PnTriangles, Pps, PpsOptions, Profile};

fn main() {
    let Some(dir) = ["../shared", "../../shared"]
        .iter()
        .map(|s| std::path::Path::new(s).join("reference/authors-pps"))
        .find(|d| d.is_dir())
    else {
        eprintln!("../shared/reference/authors-pps is absent");
        return;
    };
    let names: Vec<String> = std::env::args().skip(1).collect();
    let names = if names.is_empty() {
        [
            "cube",
            "bob_small",
            "eight",
            "anchor",
            "spot",
            "bunny",
            "torus",
            "skull_low",
        ]
        .map(String::from)
        .to_vec()
    } else {
        names
    };
    let all = AuthorsStages::ALL;
    type Variant = (&'static str, Profile, NormalRule, AuthorsStages);
    let variants: [Variant; 9] = [
        (
            "authors-code",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            all,
        ),
        (
            "normals angle-weighted",
            Profile::AuthorsCode,
            NormalRule::AngleWeighted,
            all,
        ),
        (
            "l = max(m+1, 7)",
            Profile::Paper,
            NormalRule::PlainMean,
            all,
        ),
        (
            "labels from first face",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            AuthorsStages {
                labels: false,
                ..all
            },
        ),
        (
            "SVD fit on our grid",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            AuthorsStages {
                normal_equations: false,
                ..all
            },
        ),
        (
            "polar angle atan2",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            AuthorsStages {
                polar_angle: false,
                ..all
            },
        ),
        (
            "chart rule of Sec. 6.1.4",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            AuthorsStages {
                nearest_chart: false,
                ..all
            },
        ),
        (
            "blend all of J_v(p)",
            Profile::AuthorsCode,
            NormalRule::PlainMean,
            AuthorsStages {
                triangle_blend: false,
                ..all
            },
        ),
        (
            "paper profile",
            Profile::Paper,
            NormalRule::AngleWeighted,
            AuthorsStages::default(),
        ),
    ];
    println!("mesh\tvariant\tpps_max\tpps_p50\tsprime_max");
    for name in &names {
        let mesh = dir.join(format!("meshes/{name}.off"));
        let Ok(raw) = read_mesh(&mesh, &ReadOptions::default()) else {
            eprintln!("skip {name}: no mesh");
            continue;
        };
        let Some(k) = validate(&raw).surface else {
            eprintln!("skip {name}: not a surface");
            continue;
        };
        let Ok(text) = std::fs::read_to_string(dir.join(format!("pn/{name}.tsv"))) else {
            continue;
        };
        let Ok(rows) = parse_tsv(&text, k.num_faces()) else {
            continue;
        };
        for (label, profile, rule, stages) in variants {
            let pn = PnTriangles::with_rule(&k, rule);
            let opts = PpsOptions {
                profile,
                ..PpsOptions::default()
            };
            let pps = Pps::build_staged(&k, &pn, opts, stages);
            let r = diff_rows(&k, &raw.faces, &pps, &pn, &rows, 1e-9, 1);
            let q = |n: &str| r.quantities.iter().find(|q| q.name == n);
            let (pm, p50) = q("pps").map_or((f64::NAN, f64::NAN), |q| (q.point.max, q.point.p50));
            let sm = q("sprime").map_or(f64::NAN, |q| q.point.max);
            println!("{name}\t{label}\t{pm:.2e}\t{p50:.2e}\t{sm:.2e}");
            if !stages.polar_angle && profile == Profile::AuthorsCode && pm > 1e-9 {
                // A witness of defect D1 (docs/authors-code.md): their value vs the value
                // without the defect.
                if let Some(w) = q("pps").and_then(|q| q.worst.first()) {
                    eprintln!(
                        "D1 witness {name}: line {} face {} bary {:?}: theirs {:?}, without the defect {:?}",
                        w.line, w.face, w.bary, w.theirs, w.ours
                    );
                }
            }
        }
    }
}
