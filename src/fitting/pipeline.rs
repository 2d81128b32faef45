//! The stages of the fit run in order, with refinement rounds until ε is reached (the module
//! doc of `fitting`).

use super::base::{BaseMesh, RemovalLimits};
use super::fit::{rounding_bound, vertex_errors, Fit, FitError, FitOptions, Round};
use super::fitted::{BaseSurface, BaseSurfaceError};
use super::simplify::SimplifyOptions;
use super::{
    checks, crossing, embed_checks, embedded, fitted, local, refine, simplify, unblock, unsimplify,
};
use crate::mesh::SimplicialSurface;

fn percentile(v: &[f64], q: f64) -> f64 {
    let mut s: Vec<f64> = v.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(((s.len() as f64 - 1.0) * q).round() as usize)
        .copied()
        .unwrap_or(f64::NAN)
}

/// Repair rounds at most for a base mesh the validator refuses.
const MAX_REPAIRS: usize = 60;

/// The base faces as sorted vertex triples (which base meshes were embedded already).
fn face_key(base: &BaseMesh) -> Vec<[u32; 3]> {
    let mut f: Vec<[u32; 3]> = base.faces().map(|(_, c)| c).collect();
    f.sort_unstable();
    f
}

/// Simplification attempts: a base mesh the repair cannot make valid is simplified again
/// with half the deviation allowance (closer to S_T, so fewer crossings).
const ATTEMPTS: usize = 4;

/// The adaptive fit of S_T = `k` (module doc). `progress` receives one line per stage.
pub fn fit_surface(
    k: &SimplicialSurface,
    opts: &FitOptions,
    mut progress: impl FnMut(&str),
) -> Result<Fit, FitError> {
    if !(opts.epsilon > 0.0 && opts.epsilon.is_finite()) {
        return Err(FitError::BadEpsilon(opts.epsilon));
    }
    let estimate = super::fit::memory_estimate(k);
    if estimate > opts.memory_limit {
        return Err(FitError::TooLarge {
            faces: k.num_faces(),
            estimate,
            limit: opts.memory_limit,
        });
    }
    let (r, restarted) = attempts(k, opts, true, &mut progress);
    let embeds =
        |r: &Result<Fit, FitError>| matches!(r, Ok(f) if f.embedded.is_ok() && f.floater_params);
    if restarted && !embeds(&r) {
        // The restart is a chance, never a loss: where it does not end in an embedding, the
        // fit runs again without it (anchor at 10⁻³: after the restart a curve leaves the
        // surface before the fallback has run).
        progress("the restart after the walk's divergence did not embed: fitting again without the restart");
        return attempts(k, opts, false, &mut progress).0;
    }
    r
}

/// The simplification attempts (`ATTEMPTS`), each with half the deviation allowance of the one
/// before when the base mesh stays invalid or, if `restart`, when the walk diverges; whether a
/// divergence restarted the fit.
fn attempts(
    k: &SimplicialSurface,
    opts: &FitOptions,
    restart: bool,
    progress: &mut impl FnMut(&str),
) -> (Result<Fit, FitError>, bool) {
    let mut o = *opts;
    let mut attempt = 1;
    let mut restarted = false;
    loop {
        match fit_once(k, &o, restart && attempt < ATTEMPTS, progress) {
            Err(e @ (FitError::BaseInvalid { .. } | FitError::WalkDiverges { .. }))
                if attempt < ATTEMPTS =>
            {
                restarted |= matches!(e, FitError::WalkDiverges { .. });
                o.deviation_ratio /= 2.0;
                attempt += 1;
                progress(&format!(
                    "simplify again ({e}): deviation allowance {} epsilon",
                    o.deviation_ratio
                ));
            }
            r => return (r, restarted),
        }
    }
}

fn fit_once(
    k: &SimplicialSurface,
    opts: &FitOptions,
    may_restart: bool,
    progress: &mut impl FnMut(&str),
) -> Result<Fit, FitError> {
    let t0 = std::time::Instant::now();
    let mut base = BaseMesh::new(k);
    let sopts = opts.simplify_options();
    let mut hierarchy = simplify::simplify(&mut base, k, &sopts, |lvl, n| {
        progress(&format!("simplify: level {lvl}, {n} base vertices"))
    });
    progress(&format!(
        "simplify: {} levels, {} base vertices of {} ({:.1} s)",
        hierarchy.levels.len(),
        base.base_vertices().len(),
        k.num_vertices(),
        t0.elapsed().as_secs_f64()
    ));
    let pos = base.positions().to_vec();
    let mut rounds: Vec<Round> = Vec::new();
    let mut repairs = 0;
    let mut failed_at: Vec<(Vec<[u32; 3]>, embedded::Failure)> = Vec::new();
    let mut walk = unblock::Walk::default();
    // Base edges without a curve at the walk's last failed embedding (`WalkDiverges`).
    let mut last_blocked: Option<usize> = None;
    // The fallback where the walk cannot finish (`unsimplify`), and the vertices the refinement
    // made base vertices (kept by it).
    let mut restore = unsimplify::Restore::default();
    let mut refined: Vec<u32> = Vec::new();
    // The last embedding whose every check held, kept for the next round's local update.
    let mut prev: Option<local::Previous> = None;
    loop {
        let tr = std::time::Instant::now();
        let surface = match BaseSurface::new(&base) {
            Ok(s) => s,
            Err(BaseSurfaceError::NotASurface { classes, crossing }) => {
                repairs += 1;
                let names: Vec<&str> = classes.iter().map(|c| c.name()).collect();
                if repairs > MAX_REPAIRS || crossing.is_empty() {
                    return Err(FitError::BaseInvalid {
                        rounds: repairs,
                        classes: names.join(", "),
                    });
                }
                let st = repair(&mut base, &crossing, &pos);
                progress(&format!(
                    "repair: base mesh refused ({}), {} vertices inserted, {} edges flipped",
                    names.join(", "),
                    st.inserted,
                    st.flips
                ));
                if st.inserted == 0 && st.flips == 0 {
                    return Err(FitError::BaseInvalid {
                        rounds: repairs,
                        classes: names.join(", "),
                    });
                }
                continue;
            }
            Err(BaseSurfaceError::SigmaV(e)) => return Err(e.into()),
        };
        // The embedding and Floater's parameters are used when every check of theirs
        // holds; otherwise the simplification's parameters are, and the failure is reported
        // (`AF-embedding`, and the checks of the embedding that exists), never passed on.
        // A base mesh whose embedding failed is not embedded again (the failure is kept).
        // After a refinement, only what changed is embedded again (`local`); the local result
        // is used only when every check of the embedding holds on all of it, else all of S_T
        // is embedded again.
        let key = face_key(&base);
        let mut local_stats = None;
        let mut checked = None;
        let mut emb = match failed_at.iter().find(|(x, _)| *x == key) {
            Some((_, f)) => {
                progress("embed: failed at this base mesh before, not tried again");
                Err(f.clone())
            }
            None => match prev.as_ref().map(|p| {
                local::embed_local_ticking(k, &base, p, &mut ticker(progress, "local update"))
            }) {
                None => embed_all(k, &base, progress),
                Some(Ok((e, st))) => {
                    let checks = embed_checks::run(k, &base, &e);
                    let bad: Vec<&str> = checks
                        .iter()
                        .filter(|r| r.failed())
                        .map(|r| r.id.as_str())
                        .collect();
                    if bad.is_empty() {
                        local_stats = Some(st);
                        checked = Some(checks);
                        Ok(e)
                    } else {
                        progress(&format!(
                            "embed: the local update fails {}; embedding all of S_T again",
                            bad.join(", ")
                        ));
                        embed_all(k, &base, progress)
                    }
                }
                Some(Err(f)) => {
                    progress(&format!(
                        "embed: the local update failed ({}); embedding all of S_T again",
                        f.what
                    ));
                    embed_all(k, &base, progress)
                }
            },
        };
        if let Some(f) = emb.as_ref().err().cloned() {
            let new = !failed_at.iter().any(|(x, _)| *x == key);
            if new {
                failed_at.push((key.clone(), f.clone()));
            }
            // A base edge with no curve: the base mesh is changed there by a stellar operation
            // (seed 002 Part II: the AC·CB rule, read as the edge split of AB at a vertex C of
            // S_T; a flip first, once per pair), and embedded again (`unblock`: the walk never
            // repeats a base mesh and is bounded). When it gives up, the failure names the edge.
            if let (true, Some(first)) = (new, f.edge) {
                let blocked = if f.blocked.is_empty() {
                    vec![first]
                } else {
                    f.blocked.clone()
                };
                // A walk whose changes leave more base edges without a curve than it found
                // diverges (koala at 10⁻²: 17, then 40, then 60, and the fallback then keeps
                // S_T's triangles at all of them): before the last attempt, the fit starts
                // again from a closer simplification instead (`attempts`, `fit_surface`).
                if let Some(before) = last_blocked.filter(|&b| blocked.len() > b) {
                    if may_restart && !restore.active() {
                        return Err(FitError::WalkDiverges {
                            before,
                            after: blocked.len(),
                        });
                    }
                }
                last_blocked = Some(blocked.len());
                // The walk while it can finish: not after the fallback has run, and not with
                // more blocked edges than changes left (one change per round at worst).
                let mut gave_up = None;
                if !restore.active()
                    && blocked.len() <= unblock::MAX_CHANGES.saturating_sub(walk.changes)
                {
                    let done;
                    (done, gave_up) = unblock_all(
                        &mut base,
                        &mut walk,
                        &blocked,
                        &sopts.limits,
                        &failed_at,
                        |m| BaseSurface::new(m).is_ok(),
                    );
                    // Every blocked edge whose change the validator accepts is changed before
                    // embedding again (each embedding costs the whole of S_T). When it accepts
                    // none, the first blocked edge is changed alone, as one at a time did
                    // before (the refused base mesh then goes to `repair`).
                    let done = if done.is_empty() {
                        let done;
                        (done, gave_up) = unblock_all(
                            &mut base,
                            &mut walk,
                            &blocked[..1],
                            &sopts.limits,
                            &failed_at,
                            |_| true,
                        );
                        done
                    } else {
                        done
                    };
                    if !done.is_empty() {
                        progress(&format!(
                            "embed: failed ({}; {} base edges without a curve); {}; embedding again",
                            f.what,
                            f.blocked.len().max(1),
                            done.join("; ")
                        ));
                        continue;
                    }
                }
                // The fallback (`unsimplify`, SPEC `AF-unsimplify`): S_T's own triangles
                // kept around the blocked edges, the rest simplified again.
                let sites: Vec<unsimplify::Site> = blocked
                    .iter()
                    .map(|&(a, b)| unsimplify::Site::Edge(a, b))
                    .collect();
                let r = unsimplify_round(
                    k,
                    (&mut base, &mut hierarchy, &mut prev),
                    &sites,
                    &sopts,
                    &mut restore,
                    (&refined, !rounds.is_empty()),
                    &failed_at,
                );
                if let Some(how) = r {
                    progress(&format!(
                        "embed: failed ({}; {} base edges without a curve){}; {how}; embedding again",
                        f.what,
                        blocked.len(),
                        match &gave_up {
                            Some(g) => format!("; {g}"),
                            None => String::new(),
                        },
                    ));
                    continue;
                }
                if let Some(g) = gave_up {
                    let f = embedded::Failure {
                        what: format!("{}; {g}", f.what),
                        gave_up: Some(g),
                        ..f
                    };
                    if let Some(last) = failed_at.last_mut() {
                        last.1 = f.clone();
                    }
                    emb = Err(f);
                }
            } else if new && f.edge.is_none() && !f.faces.is_empty() && restore.active() {
                // Once the fallback has run, an embedding that fails at base faces without a
                // blocked edge (a curve leaving the surface after the shortening, a curved
                // triangle that cannot be mapped) goes to it too.
                let sites: Vec<unsimplify::Site> =
                    f.faces.iter().map(|&g| unsimplify::Site::Face(g)).collect();
                let r = unsimplify_round(
                    k,
                    (&mut base, &mut hierarchy, &mut prev),
                    &sites,
                    &sopts,
                    &mut restore,
                    (&refined, !rounds.is_empty()),
                    &failed_at,
                );
                if let Some(how) = r {
                    progress(&format!(
                        "embed: failed ({}; at base faces {:?}); {how}; embedding again",
                        f.what, f.faces
                    ));
                    continue;
                }
            }
        }
        if emb.is_ok() {
            last_blocked = None;
        }
        let mut all_hold = false;
        // Where the checks that make an embedding unusable fail (base faces named by their
        // witnesses), and, once the fallback has run, where any check of the embedding fails
        // (the base edges of the curves named): the fallback's sites.
        let mut check_sites: Vec<unsimplify::Site> = Vec::new();
        let mut check_failed: Vec<String> = Vec::new();
        let usable = match &emb {
            Ok(e) => {
                let checks = checked
                    .take()
                    .unwrap_or_else(|| embed_checks::run(k, &base, e));
                let bad: Vec<&str> = checks
                    .iter()
                    .filter(|r| r.failed())
                    .map(|r| r.id.as_str())
                    .collect();
                let usable = !checks.iter().any(|r| {
                    (r.id == "AF-param-bijective" || r.id == "AF-curved-disk") && r.failed()
                });
                all_hold = bad.is_empty();
                if !usable || (restore.active() && !all_hold) {
                    for r in checks.iter().filter(|r| r.failed()) {
                        for w in &r.witnesses {
                            if let Some(f) = w.data.get("face").and_then(|f| f.as_u64()) {
                                check_sites.push(unsimplify::Site::Face(f as u32));
                            } else if let Some(c) = w
                                .data
                                .get("curve")
                                .and_then(|c| c.as_u64())
                                .and_then(|c| e.emb.curves.get(c as usize))
                            {
                                check_sites.push(unsimplify::Site::Edge(c.a, c.b));
                            }
                        }
                        check_failed.push(r.id.clone());
                    }
                    check_sites.dedup();
                }
                let how = match &local_stats {
                    Some(st) => format!(
                        "local update: {} of {} curves kept, {} of {} curved triangles' maps kept{}; ",
                        st.kept_curves,
                        st.curves,
                        st.kept_maps,
                        st.maps,
                        match st.openings {
                            0 => String::new(),
                            n => format!(" ({n} tries after the first, each opening the faces where the one before failed)"),
                        }
                    ),
                    None => String::new(),
                };
                progress(&format!(
                    "embed: {how}{} curves ({} along an edge of S_T, {} in their faces' region, {} widened, {} on all of S_T, {} taken up and traced again, {} restarts), length {:.4e} -> {:.4e} in {} sweeps ({} moves); {} pieces; {}",
                    e.emb.curves.len(),
                    e.emb.stats.on_edges,
                    e.emb.stats.in_region,
                    e.emb.stats.widened,
                    e.emb.stats.unrestricted,
                    e.emb.stats.ripped,
                    e.emb.stats.restarts,
                    e.emb.stats.initial_length,
                    e.emb.stats.length,
                    e.emb.stats.sweeps,
                    e.emb.stats.moves,
                    e.overlay.pieces.len(),
                    match (bad.is_empty(), usable) {
                        (true, _) => "Floater's parameters used".to_string(),
                        (false, true) => format!("failed: {}; Floater's parameters used", bad.join(", ")),
                        (false, false) => format!("failed: {}; the simplification's parameters used", bad.join(", ")),
                    }
                ));
                usable
            }
            Err(f) => {
                progress(&format!(
                    "embed: failed ({}); the simplification's parameters used",
                    f.what
                ));
                false
            }
        };
        // An embedding whose map folds (or whose curved triangle is no disk), or, once the
        // fallback has run, any check of the embedding failing: S_T's own triangles kept
        // there, the rest simplified again (`unsimplify`, SPEC `AF-unsimplify`).
        if !check_sites.is_empty() {
            let key = face_key(&base);
            let at: Vec<String> = check_sites.iter().map(|x| x.to_string()).collect();
            let what = format!(
                "the embedding fails {} at {}",
                check_failed.join(", "),
                at.join(", ")
            );
            // Not embedded again: the result would be the same.
            failed_at.push((
                key,
                embedded::Failure {
                    what: what.clone(),
                    faces: Vec::new(),
                    edge: None,
                    blocked: Vec::new(),
                    gave_up: None,
                },
            ));
            let r = unsimplify_round(
                k,
                (&mut base, &mut hierarchy, &mut prev),
                &check_sites,
                &sopts,
                &mut restore,
                (&refined, !rounds.is_empty()),
                &failed_at,
            );
            if let Some(how) = r {
                progress(&format!("embed: {what}; {how}; embedding again"));
                continue;
            }
        }
        let params = match &emb {
            Ok(e) if usable => surface.params_of(&base, &e.params),
            _ => surface.params(&base),
        };
        let fitted = fitted::fit(&surface, &pos, &params, opts.kappa, opts.degree)?;
        let errors = vertex_errors(&fitted.pps, &pos, &params);
        let bound = rounding_bound(&fitted.pps);
        let offenders: Vec<u32> = errors
            .iter()
            .enumerate()
            .filter(|(_, &e)| !(e + bound <= opts.epsilon))
            .map(|(i, _)| i as u32)
            .collect();
        // Pieces folded by Floater's maps are counted per round (SPEC `AF-param-bijective`):
        // reported by the check, never expected.
        let folds = match &emb {
            Ok(e) if usable => embed_checks::check_bijective(&e.overlay, &base, &e.maps).offenders,
            _ => checks::orientations(k, &base).folded.len() as u64,
        } as usize;
        let max_error = errors
            .iter()
            .copied()
            .fold(0.0, crate::report::harness::dev_max);
        // Is S embedded (SPEC `AF-embedded`)? Its sample's offending triangles, located at
        // base faces, are refinement sites beside the vertices beyond ε (`AF-refine-embedded`).
        let cross = opts
            .embed_level
            .map(|l| crossing::check_embedded(&fitted.pps, l));
        let crosses = cross.as_ref().is_some_and(|c| c.crosses());
        let cross_slots: Vec<u32> = cross
            .as_ref()
            .map(|c| {
                c.faces
                    .iter()
                    .filter_map(|&f| surface.slot_of.get(f as usize).copied())
                    .collect()
            })
            .unwrap_or_default();
        let mut round = Round {
            base_vertices: surface.fine_of.len(),
            max_error,
            p99_error: percentile(&errors, 0.99),
            offenders: offenders.len(),
            folds: 0,
            crossing_triangles: cross.as_ref().map(|c| c.offending_triangles),
            crossing_faces: cross.as_ref().map(|c| c.faces.len()),
            refine: None,
            local: local_stats,
            seconds: 0.0,
        };
        progress(&format!(
            "fit round {}: {} charts (base vertices), max error {:.3e}, p99 {:.3e}, {} vertices beyond epsilon {:.3e}, {} folded triangles",
            rounds.len() + 1,
            round.base_vertices,
            round.max_error,
            round.p99_error,
            round.offenders,
            opts.epsilon,
            folds
        ));
        if let Some(c) = &cross {
            progress(&format!(
                "embedded (AF-embedded): level-{} sample of S, {} of {} triangles offend at {} base faces{}",
                c.level,
                c.offending_triangles,
                c.triangles,
                c.faces.len(),
                if c.crosses() && c.faces.is_empty() {
                    " (not located)"
                } else {
                    ""
                }
            ));
        }
        round.folds = folds;
        if offenders.is_empty() && !crosses {
            round.seconds = tr.elapsed().as_secs_f64();
            rounds.push(round);
            return Ok(Fit {
                epsilon: opts.epsilon,
                base,
                surface,
                params,
                embedded: emb,
                floater_params: usable,
                fitted,
                embed_level: opts.embed_level,
                errors,
                rounding_bound: bound,
                hierarchy,
                repairs,
                rounds,
                unblock: walk,
                restore,
            });
        }
        // With ε reached, the round goes on only because the sample crosses.
        let give_up = |rounds: usize| match &cross {
            Some(c) if offenders.is_empty() => FitError::NotEmbedded {
                rounds,
                level: c.level,
                triangles: c.offending_triangles,
                faces: c.faces.len(),
            },
            _ => FitError::NotReached {
                epsilon: opts.epsilon,
                rounds,
                offenders: offenders.len(),
                worst: max_error,
                folds,
                crossing_faces: cross.as_ref().map_or(0, |c| c.faces.len()),
            },
        };
        if rounds.len() + 1 >= opts.max_rounds {
            return Err(give_up(rounds.len() + 1));
        }
        prev = match emb {
            Ok(e) if usable && all_hold => Some(local::Previous::new(&base, e)),
            _ => None,
        };
        let mut st = refine::RefineStats::default();
        // The vertices beyond ε are chosen on this round's base mesh; the crossing faces are
        // refined first, each insertion kept only if the base mesh stays valid, then the ε
        // sites are inserted as before (`AF-refine-rule`).
        let eps_sites = refine::choose(&base, &errors, &offenders);
        let (at_crossings, no_candidate) = refine::choose_crossing(&base, &cross_slots);
        // Where no vertex of S_T is left near a crossing face (S_T's own triangles, e.g. a
        // sliver at a crease), its longest flippable edge is flipped (the slots are this
        // round's, so before any insertion).
        let mut flipped = 0;
        for &f in &no_candidate {
            if refine::flip_longest(&mut base, f, &pos) {
                flipped += 1;
            }
        }
        st.flips += flipped;
        let mut crossing_inserted = 0;
        let mut undone: Vec<u32> = Vec::new();
        for cands in &at_crossings {
            match refine::insert_valid(&mut base, cands, &mut st, |b| BaseSurface::new(b).is_ok()) {
                Some(x) => {
                    refined.push(x);
                    crossing_inserted += 1;
                }
                None => undone.extend(cands.first()),
            }
        }
        if !cross_slots.is_empty() {
            progress(&format!(
                "refine (AF-refine-embedded): {crossing_inserted} vertices of S_T inserted at {} crossing base faces ({} insertions undone: the base mesh would cross){}",
                cross_slots.len(),
                st.refused,
                if no_candidate.is_empty() {
                    String::new()
                } else {
                    format!(
                        ", {} faces with no vertex of S_T near: {flipped} edges flipped there",
                        no_candidate.len()
                    )
                }
            ));
        }
        for x in eps_sites {
            if !base.is_base(x) && refine::insert(&mut base, x, &mut st) {
                refined.push(x);
            }
        }
        // A round that would change nothing: the undone insertions are made after all, and a
        // base mesh the validator refuses goes to the repair (`AF-refine-rule`; the anchor's
        // creases at 10⁻² need it).
        if st.inserted == 0 && flipped == 0 {
            for x in undone {
                if !base.is_base(x) && refine::insert(&mut base, x, &mut st) {
                    refined.push(x);
                }
            }
            if st.inserted > 0 {
                progress(&format!(
                    "refine (AF-refine-embedded): no other change this round: {} undone insertions made, the repair's rule follows",
                    st.inserted
                ));
            }
        }
        round.refine = Some(st);
        round.seconds = tr.elapsed().as_secs_f64();
        rounds.push(round);
        if st.inserted == 0 && flipped == 0 {
            return Err(give_up(rounds.len()));
        }
    }
}

/// One round of the fallback (`unsimplify`) at `sites`: the vertices the refinement inserted
/// and the sites' neighbourhood kept — from the second round on, and after a fit round, every
/// current base vertex too — S_T simplified again. On success the fit continues from the new base mesh (never embedded
/// before) and its hierarchy, the previous embedding (if any) re-slotted to it for the local
/// update, and what was done is returned; None when every vertex is kept already.
fn unsimplify_round(
    k: &SimplicialSurface,
    (base, hierarchy, prev): (
        &mut BaseMesh,
        &mut simplify::Hierarchy,
        &mut Option<local::Previous>,
    ),
    sites: &[unsimplify::Site],
    sopts: &SimplifyOptions,
    restore: &mut unsimplify::Restore,
    (refined, fitted): (&[u32], bool),
    failed_at: &[(Vec<[u32; 3]>, embedded::Failure)],
) -> Option<String> {
    let n = base.positions().len();
    restore.add(n, refined.iter().copied());
    // From the second round on, and after a fit round, every current base vertex is kept too,
    // so the round changes the base mesh only near the sites and the vertices inserted since
    // the last simplification (`unsimplify` module doc).
    let held = (fitted || restore.active()).then(|| restore.keep_base(base));
    let before = restore.kept;
    let (m, h) = unsimplify::restore(k, base, sites, sopts, restore, |m| {
        let key = face_key(m);
        failed_at.iter().any(|(x, _)| *x == key)
    })?;
    let how = format!(
        "S_T's own triangles kept there (AF-unsimplify: {} more vertices of S_T kept as base vertices{}, {} in all, ring {}), simplified again: {} base vertices",
        restore.kept - before,
        match held {
            Some(h) => format!(" and every current base vertex ({h} not kept before)"),
            None => String::new(),
        },
        restore.kept,
        restore.rings.last().copied().unwrap_or(0),
        m.base_vertices().len()
    );
    // The last embedding whose every check held is updated locally where the faces are the
    // same (`local::Previous::reslot`); before a fit round there is none.
    *prev = prev.take().map(|p| p.reslot(&m));
    *base = m;
    *hierarchy = h;
    Some(how)
}

/// Seconds between two progress lines of one tracing (a tracing shorter than this prints none).
const TICK_SECONDS: f64 = 10.0;

/// A tracing's `tick` ([`super::route::curves_keeping`]) that prints, every [`TICK_SECONDS`],
/// the base edges traced, the rate and the time left of the pass (a restart is a new pass).
fn ticker<'a>(progress: &'a mut impl FnMut(&str), what: &'a str) -> impl FnMut(usize, usize) + 'a {
    let start = std::time::Instant::now();
    let (mut pass_start, mut pass, mut last, mut next) = (0.0, 1, 0, TICK_SECONDS);
    move |done, total| {
        let s = start.elapsed().as_secs_f64();
        if done < last {
            (pass_start, pass) = (s, pass + 1);
        }
        last = done;
        if s >= next && 0 < done && done < total {
            next = s + TICK_SECONDS;
            let (rate, eta) = crate::report::rate_eta(done, total, s - pass_start);
            progress(&format!(
                "embed: {what}, tracing pass {pass}: {done}/{total} base edges ({rate}, ETA {eta})"
            ));
        }
    }
}

/// The embedding of all of S_T, with progress lines for a long tracing.
fn embed_all(
    k: &SimplicialSurface,
    base: &BaseMesh,
    progress: &mut impl FnMut(&str),
) -> Result<embedded::Embedded, embedded::Failure> {
    embedded::embed_ticking(k, base, &mut ticker(progress, "all of S_T"))
}

/// The walk's changes at the blocked edges ([`unblock::Walk::change_all`]), as progress lines.
fn unblock_all(
    base: &mut BaseMesh,
    walk: &mut unblock::Walk,
    blocked: &[(u32, u32)],
    lim: &RemovalLimits,
    failed_at: &[(Vec<[u32; 3]>, embedded::Failure)],
    valid: impl Fn(&BaseMesh) -> bool,
) -> (Vec<String>, Option<unblock::GiveUp>) {
    let tried = |m: &BaseMesh| {
        let k = face_key(m);
        failed_at.iter().any(|(x, _)| *x == k)
    };
    let (done, gave_up) = walk.change_all(base, blocked, lim, tried, valid);
    let done = done
        .into_iter()
        .map(|((a, b), ch)| describe(a, b, ch))
        .collect();
    (done, gave_up)
}

/// One line of the progress report for a base-mesh change at edge a–b.
fn describe(a: u32, b: u32, ch: unblock::Change) -> String {
    match ch {
        unblock::Change::Flipped => format!("base edge {a}-{b} flipped"),
        unblock::Change::Removed { c } => format!(
            "base vertex {c} opposite edge {a}-{b} removed (AC·CB rule, no vertex of S_T left to split at)"
        ),
        unblock::Change::Split { c, edge_split: true } => {
            format!("base edge {a}-{b} split at vertex {c} of S_T (AC·CB rule)")
        }
        unblock::Change::Split { c, edge_split: false } => format!(
            "a base face at edge {a}-{b} split at vertex {c} of S_T (AC·CB rule; the edge's flip refused)"
        ),
    }
}

/// Refine the base mesh at base face slots `faces` (a refused base mesh's crossing faces):
/// insert the vertex of S_T furthest from its flat base triangle
/// among the face's own (else those of the faces around its corners); with none, flip the
/// face's longest flippable edge.
fn repair(base: &mut BaseMesh, faces: &[u32], pos: &[[f64; 3]]) -> refine::RefineStats {
    let mut st = refine::RefineStats::default();
    for &f in faces {
        let mut cand: Vec<u32> = base.members(f).to_vec();
        if cand.is_empty() {
            if let Some(c) = base.face(f) {
                for v in c {
                    for &g in base.faces_around(v) {
                        cand.extend_from_slice(base.members(g));
                    }
                }
            }
        }
        let worst = cand
            .into_iter()
            .max_by(|&a, &b| base.flat_deviation(a).total_cmp(&base.flat_deviation(b)));
        match worst {
            Some(x) if !base.is_base(x) => {
                refine::insert(base, x, &mut st);
            }
            _ => {
                if refine::flip_longest(base, f, pos) {
                    st.flips += 1;
                }
            }
        }
    }
    st
}
