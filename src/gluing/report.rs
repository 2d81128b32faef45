//! The report of `ppm gluing FILE [--json]`: decide every condition of Def. 3.4.1 (and App. A.2's variants,
//! and the relation ∼ of Thm. 3.4.1) on a user-written 1-D gluing file (format: [`super::file`]).

use super::error::GluingFileError;
use super::exact1d::decide;
use super::file::read_gluing_file;
use super::relation;
use crate::report::{render_text, CheckResult};
use std::path::Path;

/// Run every check on the gluing file at `path`. Returns the rendered report (text table with
/// witnesses, or JSON) and whether every check holds.
pub fn gluing_report(path: &Path, json: bool) -> Result<(String, bool), GluingFileError> {
    let f = read_gluing_file(path)?;
    let mut results: Vec<CheckResult> = decide::check_all(&f.data);
    let sample = relation::GridSample::new(&f.data, 24);
    results.push(relation::check_equivalence(&f.data, &sample));
    results.push(relation::check_claim(&f.data, &sample));
    let all_hold = results.iter().all(|r| !r.failed());
    let out = if json {
        serde_json::json!({
            "file": path.display().to_string(),
            "name": f.name,
            "all_hold": all_hold,
            "results": results,
        })
        .to_string()
    } else {
        let mut s = format!(
            "gluing data {}{}\n",
            path.display(),
            f.name
                .as_ref()
                .map(|n| format!(" — {n}"))
                .unwrap_or_default()
        );
        for (i, d) in &f.data.domains {
            s.push_str(&format!("  Ω_{i} = {d}\n"));
        }
        for ((i, j), ps) in &f.data.glue {
            for p in ps {
                s.push_str(&format!(
                    "  φ_({j},{i}) : Ω_({i},{j}) → Ω_({j},{i}), {}\n",
                    p.describe()
                ));
            }
        }
        s.push_str(&render_text(&results));
        s.push_str(if all_hold {
            "all conditions hold\n"
        } else {
            "some conditions FAIL (witnesses above)\n"
        });
        s
    };
    Ok((out, all_hold))
}
