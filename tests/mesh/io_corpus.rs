//! Reads every mesh of the shared corpus (`../shared/meshes/`, next to the crate) and checks
//! the vertex and face counts against the `V` and `F` columns of its manifest.tsv. Skipped with
//! a note at exit when the corpus is absent (`common::shared_dir`).

use std::collections::BTreeSet;
use std::time::Instant;

use crate::common;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};

#[test]
fn corpus_counts_match_manifest() {
    let Some(dir) = common::corpus_dir("corpus_counts_match_manifest") else {
        return;
    };
    let manifest = std::fs::read_to_string(dir.join("manifest.tsv")).unwrap();
    let mut lines = manifest.lines();
    let head: Vec<&str> = lines.next().unwrap().split('\t').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let (cf, cv, cfaces) = (col("file"), col("V"), col("F"));
    let mut listed = BTreeSet::new();
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let row: Vec<&str> = line.split('\t').collect();
        let file = row[cf];
        let (v, f): (usize, usize) = (row[cv].parse().unwrap(), row[cfaces].parse().unwrap());
        let t = Instant::now();
        let m = read_mesh(&dir.join(file), &ReadOptions::default())
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        let dt = t.elapsed();
        assert_eq!((m.positions.len(), m.faces.len()), (v, f), "{file}");
        assert_eq!(m.triangulated_polygons, 0, "{file}");
        eprintln!(
            "{file}: {v} vertices, {f} faces, read in {:.1} ms",
            dt.as_secs_f64() * 1e3
        );
        listed.insert(file.to_string());
    }
    let mut on_disk = BTreeSet::new();
    for sub in ["good", "bad"] {
        for e in std::fs::read_dir(dir.join(sub)).unwrap() {
            let name = e.unwrap().file_name().into_string().unwrap();
            on_disk.insert(format!("{sub}/{name}"));
        }
    }
    assert_eq!(listed, on_disk, "manifest.tsv and good/, bad/ disagree");
}

/// Timing of the largest corpus mesh; printed, not asserted (run with `--release --nocapture`).
#[test]
fn koala_read_time() {
    let Some(dir) = common::corpus_dir("koala_read_time") else {
        return;
    };
    let path = dir.join("good/koala.obj");
    let mut best = f64::INFINITY;
    let mut faces = 0;
    for _ in 0..5 {
        let t = Instant::now();
        let m = read_mesh(&path, &ReadOptions::default()).unwrap();
        best = best.min(t.elapsed().as_secs_f64());
        faces = m.faces.len();
    }
    assert_eq!(faces, 99994);
    eprintln!(
        "good/koala.obj ({faces} faces): best of 5 reads {:.1} ms",
        best * 1e3
    );
}
