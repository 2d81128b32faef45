#!/usr/bin/env bash
# Print mutants/results.tsv as the Markdown table of docs/mutants.md (latest row per module).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
awk -F'\t' 'NR > 1 { last[$3] = $0; if (!($3 in seen)) { seen[$3] = 1; order[++n] = $3 } }
END {
    print "| Module | Commit | Date | Sample | Generated | Tested | Caught | Missed | Timeout | Unviable | Score (95 % interval) | Time |"
    print "|---|---|---|---|---:|---:|---:|---:|---:|---:|---|---:|"
    for (i = 1; i <= n; i++) {
        split(last[order[i]], f, "\t")
        sample = f[4] == 1 ? "all" : "1/" f[4]
        ci = f[4] == 1 ? "" : sprintf(" [%.0f %%, %.0f %%]", 100 * f[12], 100 * f[13])
        score = f[11] == "NA" ? "—" : sprintf("%.0f %%%s", 100 * f[11], ci)
        printf "| `%s` | %s | %s | %s | %d | %d | %d | %d | %d | %d | %s | %d min |\n",
            f[3], f[2], f[1], sample, f[5], f[6], f[7], f[8], f[9], f[10], score, int((f[14] + 59) / 60)
    }
}' "$here/results.tsv"
