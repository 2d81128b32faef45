#!/usr/bin/env bash
# Print mutants/results.tsv as the Markdown table of docs/mutants.md: per module its latest
# sampled run and, when the missed mutants were re-tested after new tests ("MODULE (again)"
# rows), the score after them.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
awk -F'\t' -f "$here/wilson.awk" -f <(cat <<'AWK'
function wilson(c, n, sampled) {
    if (n == 0) return "—"
    if (!sampled) return sprintf("%.0f %%", 100 * c / n)
    wilson_interval(c, n)
    return sprintf("%.0f %% [%.0f %%, %.0f %%]", 100 * WILSON_P, 100 * WILSON_LO, 100 * WILSON_HI)
}
NR > 1 {
    m = $3
    if (m ~ / \(again\)$/) { sub(/ \(again\)$/, "", m); again[m] = $0; next }
    if (!(m in first)) order[++n] = m
    first[m] = $0; delete again[m]
}
END {
    print "| Module | Commit | Sample | Generated | Tested | Caught | Missed | Timeout | Unviable | Score (95 % interval) | After new tests | Time |"
    print "|---|---|---|---:|---:|---:|---:|---:|---:|---|---|---:|"
    for (i = 1; i <= n; i++) {
        m = order[i]; split(first[m], f, "\t")
        caught = f[7] + f[9]; viable = f[7] + f[8] + f[9]
        after = "—"
        if (m in again) {
            split(again[m], g, "\t")
            after = wilson(caught + g[7] + g[9], viable, f[4] != 1) " (" g[2] ")"
        }
        # DENOM (shard 0) or K/DENOM (shard K): one mutant in DENOM either way.
        sample = f[4] == 1 ? "all" : (f[4] ~ /\// ? "1/" substr(f[4], index(f[4], "/") + 1) " (shard " substr(f[4], 1, index(f[4], "/") - 1) ")" : "1/" f[4])
        printf "| `%s` | %s | %s | %d | %d | %d | %d | %d | %d | %s | %s | %d min |\n",
            m, f[2], sample, f[5], f[6], f[7], f[8], f[9], f[10], wilson(caught, viable, f[4] != 1), after, int((f[14] + 59) / 60)
    }
}
AWK
) "$here/results.tsv"
