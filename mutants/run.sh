#!/usr/bin/env bash
# One module's mutation campaign (cargo-mutants), reproducibly, appending one row to
# mutants/results.tsv. docs/mutants.md explains the table and the sampling.
#
#   mutants/run.sh MODULE [DENOM]      # DENOM: test every DENOM-th mutant (default 1 = all)
#   mutants/run.sh MODULE DENOM again  # re-test only the mutants the last run of MODULE missed
#                                      # (cargo-mutants --iterate), after new tests were added
#   mutants/run.sh --list              # the modules, their files and test binaries
#
# The campaign runs in a git worktree beside this repository (../<repo>-mutants, detached at
# HEAD), so `../shared` resolves exactly as it does here and the tree you work in is never
# mutated (PPM_MUTANTS_TREE names another place). Its target directory persists between
# campaigns (incremental builds).
# Every cargo command of the campaign builds and runs only the module's test binaries (-C), so
# one mutant costs one incremental build of the library and those binaries, not the suite.
# A sample takes mutant i when i % DENOM == K (cargo-mutants' round-robin shard K/DENOM, K from
# PPM_MUTANTS_SHARD, 0 if unset): systematic, deterministic for a given commit, and spread over
# every file of the module. A fresh sample of a module whose earlier sample's survivors were
# aimed at by new tests takes another K, so that it does not measure those survivors again.
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
results="$here/mutants/results.tsv"

# name | file globs (space separated) | tests (space separated): `lib` = the library's unit
#        tests, `proofs` = that test binary (proofs/main.rs), any other name a theme of the suite binary
#        (tests/suite: `mesh`, `gluing`, `chapter4`, `surface`, `seeds`)
#      | test names to skip (optional: the corpus-wide tests, minutes per mutant)
#      | test-name filters (optional, space separated: only tests whose path contains one of
#        them, e.g. the module's own tests in a theme that also holds slow engines)
modules() {
    cat <<'EOF'
mesh-validate|src/mesh/validate/*.rs|lib mesh gluing
gluing-exact1d|src/gluing/exact1d/*.rs|lib gluing
gluing-sampled|src/gluing/sampled/*.rs|lib gluing
construction|src/construction/maps.rs src/construction/checks/*.rs src/construction/abstract_view.rs src/construction/mesh_gluing.rs src/construction/figure.rs|lib chapter4 gluing||tests:: chapter4:: gluing:: docs_pictures
surface|src/surface/fit.rs src/surface/fit_linear.rs src/surface/weights.rs src/surface/pps.rs src/surface/eval.rs src/surface/checks/*.rs src/surface/bezier.rs src/surface/scalar_ext.rs src/surface/admissible.rs|lib surface gluing|corpus
certify|src/certify/*.rs|lib chapter4
exact|src/exact/*.rs|lib proofs
oracle|src/oracle/*.rs src/oracle/*/*.rs|lib surface
report-harness|src/report/harness.rs src/report/check_result.rs src/report.rs|lib gluing
conditions|src/conditions/*.rs|lib chapter4 mesh
loop-subdiv|src/surface/loop_subdiv/*.rs|lib surface|corpus
sigma-v|src/surface/sigma_v/*.rs|lib surface|corpus|sigma_v
msplines|src/msplines/*.rs|lib seeds||msplines
sdiff|src/sdiff/*.rs src/sdiff/*/*.rs|lib seeds||sdiff
render|src/render/*.rs|lib surface||render docs_pictures
fitting|src/fitting/*.rs|lib seeds||fitting
numeric|src/numeric/*.rs|lib chapter4 gluing mesh
mesh-io|src/mesh/io/*.rs src/mesh/load.rs|lib mesh
EOF
}

if [[ "${1:-}" == "--list" || $# -lt 1 ]]; then
    modules | column -t -s '|'
    [[ $# -lt 1 ]] && exit 2 || exit 0
fi

module="$1"
denom="${2:-1}"
again="${3:-}"
row="$(modules | awk -F'|' -v m="$module" '$1 == m')"
if [[ -z "$row" ]]; then
    echo "unknown module '$module'; mutants/run.sh --list names them" >&2
    exit 2
fi
IFS='|' read -r _ globs tests skips filter <<<"$row"
shard="${PPM_MUTANTS_SHARD:-0}"
if ! [[ "$shard" =~ ^[0-9]+$ ]] || ((shard >= denom)); then
    echo "PPM_MUTANTS_SHARD=$shard is not a shard of 0..$((denom - 1))" >&2
    exit 2
fi
# The sample column: DENOM for shard 0 (as every earlier row), K/DENOM otherwise.
sample="$denom"
((shard == 0)) || sample="$shard/$denom"

command -v cargo-mutants >/dev/null || {
    echo "cargo-mutants is not installed: cargo install cargo-mutants --locked" >&2
    exit 2
}

commit="$(git -C "$here" rev-parse HEAD)"
tree="${PPM_MUTANTS_TREE:-$(dirname "$here")/$(basename "$here")-mutants}"
# One campaign per tree: a second one would check its commit out under the first one's
# in-place mutants and share its target directory.
exec 9>"$tree.lock"
if ! flock -n 9; then
    echo "a campaign already runs in $tree; give this one another PPM_MUTANTS_TREE" >&2
    exit 2
fi
if [[ -d "$tree" ]]; then
    git -C "$tree" checkout --quiet --detach --force "$commit"
    git -C "$tree" clean -fdq -e target
else
    git -C "$here" worktree add --quiet --detach "$tree" "$commit"
fi

files=()
for g in $globs; do files+=(-f "$g"); done
outdir="$tree/target/mutants-$module${again:+-again}"
mkdir -p "$tree/target" # a fresh worktree has no target directory yet
args=(--in-place --profile mutants --output "$outdir" "${files[@]}")
themes=() haslib=0
for t in $tests; do
    case "$t" in
        lib) haslib=1 args+=(-C --lib) ;;
        proofs) args+=(-C "--test=$t") ;;
        *) themes+=("$t::") ;;
    esac
done
if [[ ${#themes[@]} -gt 0 ]]; then
    args+=(-C --test=suite)
    # libtest's filters apply to every binary of the run. Without a row filter, the themes (and
    # `tests::`, the module every unit test of the library sits in) select what the row's
    # binaries held before the themes became one suite binary.
    if [[ -z "${filter:-}" ]]; then
        filter="${themes[*]}"
        if [[ $haslib == 1 ]]; then filter="tests:: $filter"; fi
    fi
fi
if [[ "$again" == again ]]; then
    # Exactly the mutants the last run of the module missed (their names are stable while the
    # module's files are unchanged, e.g. after adding tests).
    prev="$tree/target/mutants-$module/mutants.out/missed.txt"
    [[ -s "$prev" ]] || { echo "no missed mutants recorded for $module" >&2; exit 2; }
    while IFS= read -r name; do
        args+=(--re "^$(printf '%s' "$name" | sed 's/[][\.*^$+?(){}|]/\\&/g')\$")
    done <"$prev"
elif [[ "$denom" != 1 ]]; then
    args+=(--shard "$shard/$denom" --sharding round-robin)
fi
if [[ -n "${skips:-}" || -n "${filter:-}" ]]; then
    args+=(--cargo-test-arg=--)
    for f in ${filter:-}; do args+=("--cargo-test-arg=$f"); done
    for s in ${skips:-}; do args+=(--cargo-test-arg=--skip "--cargo-test-arg=$s"); done
fi
# cargo-mutants' test timeout is a multiple of the unmutated run's time; on a machine shared
# with other builds that run is not representative, and a false timeout would count as caught.
# PPM_MUTANTS_TIMEOUT_MULTIPLIER raises the multiple (cargo-mutants' default applies if unset).
if [[ -n "${PPM_MUTANTS_TIMEOUT_MULTIPLIER:-}" ]]; then
    args+=(--timeout-multiplier "$PPM_MUTANTS_TIMEOUT_MULTIPLIER")
fi

generated="$(cd "$tree" && cargo mutants --list "${files[@]}" | wc -l)"
start="$(date +%s)"
status=0
(cd "$tree" && cargo mutants "${args[@]}") || status=$?
# cargo-mutants exits 2 when mutants were missed and 3 on timeouts; both are results.
if [[ $status -ne 0 && $status -ne 2 && $status -ne 3 ]]; then
    echo "cargo-mutants failed (exit $status); no row written" >&2
    exit "$status"
fi
out="$outdir/mutants.out"
count() { if [[ -f "$out/$1.txt" ]]; then grep -c . "$out/$1.txt" || true; else echo 0; fi; }
if [[ "$again" == again ]]; then
    # cargo-mutants' name filter can also select mutants outside the sample (seen on `surface`):
    # a re-test counts only the mutants the earlier run missed.
    count() { if [[ -f "$out/$1.txt" ]]; then grep -cxFf "$prev" "$out/$1.txt" || true; else echo 0; fi; }
fi
caught=$(count caught)
missed=$(count missed)
timeout=$(count timeout)
unviable=$(count unviable)
secs=$(($(date +%s) - start))

# Score = caught / (caught + missed); a timeout counts as caught (the mutant changed behaviour
# enough to hang a test), as cargo-mutants itself reports it. 95 % Wilson interval for a sample.
read -r score lo hi < <(awk -v c="$((caught + timeout))" -v n="$((caught + timeout + missed))" \
    -f "$here/mutants/wilson.awk" -f <(echo 'BEGIN {
    if (n == 0) { print "NA NA NA"; exit }
    wilson_interval(c, n)
    printf "%.3f %.3f %.3f\n", WILSON_P, WILSON_LO, WILSON_HI }'))

[[ -f "$results" ]] || printf 'date\tcommit\tmodule\tdenom\tgenerated\ttested\tcaught\tmissed\ttimeout\tunviable\tscore\tci95_lo\tci95_hi\tseconds\n' >"$results"
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' \
    "$(date -u +%Y-%m-%d)" "${commit:0:10}" "$module${again:+ (again)}" "$sample" "$generated" \
    "$((caught + missed + timeout + unviable))" "$caught" "$missed" "$timeout" "$unviable" \
    "$score" "$lo" "$hi" "$secs" >>"$results"
echo "module $module: caught $caught, missed $missed, timeout $timeout, unviable $unviable, score $score [$lo, $hi]"
if [[ $missed -gt 0 ]]; then
    echo "missed mutants ($out/missed.txt):"
    cat "$out/missed.txt"
fi
