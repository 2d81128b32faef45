#!/bin/sh
# Usage: fuzz/run.sh TARGET SECONDS [extra libFuzzer flags]
# One single-core campaign (no -jobs/-workers: one process); a hang is an input taking more
# than 1 s (-timeout=1), an OOM is RSS above 2 GiB. Appends one line per campaign to
# fuzz/campaigns.tsv: date, target, seconds scheduled, executions, exec/s, cov, ft, corpus size,
# artifacts, exit code, and wall seconds actually fuzzed (the build is done first, untimed).
# Uses nightly when installed, else stable with RUSTC_BOOTSTRAP=1 (cargo-fuzz needs -Z flags).
set -eu
[ $# -ge 2 ] || { echo "usage: $0 TARGET SECONDS [libFuzzer flags]" >&2; exit 2; }
t=$1; secs=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
[ -d "corpus/$t" ] || ./make_seeds.sh > /dev/null
mkdir -p logs "artifacts/$t"
log="logs/$t-$(date +%Y%m%dT%H%M%S).log"
# The default build (what the fuzz targets link) needs no target-CPU flag: its multi-precision
# and interval arithmetic are pure Rust (docs/multiprecision.md).
# PPM_FUZZ_STABLE=1 forces the stable path (CI: it must not depend on nightly being present).
if [ "${PPM_FUZZ_STABLE:-0}" != 1 ] && rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
    tc="+nightly"
else
    tc=""
    export RUSTC_BOOTSTRAP=1
fi
dict=""
case "$t" in read_off|read_obj|read_ply_ascii|pipeline) dict="-dict=dict/text.dict" ;; esac
cargo $tc fuzz build -s none "$t" > "$log" 2>&1
start=$(date +%s)
set +e
cargo $tc fuzz run -s none "$t" "corpus/$t" -- \
    -max_total_time="$secs" -timeout=1 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="artifacts/$t/" $dict "$@" >> "$log" 2>&1
rc=$?
wall=$(( $(date +%s) - start ))
set -e
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
eps=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
last=$(grep -E '^#[0-9]+' "$log" | tail -1)
cov=$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
ft=$(echo "$last" | sed -n 's/.*ft: \([0-9]*\).*/\1/p')
corp=$(echo "$last" | sed -n 's/.*corp: \([0-9]*\).*/\1/p')
crashes=$(ls "artifacts/$t" | wc -l)
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$secs" "${execs:-?}" "${eps:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$crashes" "$rc" "$wall" >> campaigns.tsv
echo "$t: ${secs}s scheduled, ${wall}s fuzzed, ${execs:-?} execs, ${eps:-?} exec/s, cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?}, artifacts $crashes, exit $rc (log $log)"
exit $rc
