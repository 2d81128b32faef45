#!/usr/bin/env bash
# Which rows of mutants/results.tsv are samples of the code as it is: per module, its latest
# row (a sample or a re-test) and whether the module's files changed between that row's commit
# and HEAD (`git diff`). docs/mutants.md quotes its output.
#
#   mutants/stale.sh
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
cd "$here"
# The module list of mutants/run.sh (name | file globs | ...), without running the script.
eval "$(sed -n '/^modules() {/,/^}/p' mutants/run.sh)"
printf '%s\t%s\t%s\n' module commit "files since"
modules | while IFS='|' read -r name globs _; do
    commit="$(awk -F'\t' -v m="$name" '$3 == m || $3 == m " (again)" { c = $2 } END { print c }' mutants/results.tsv)"
    if [[ -z "$commit" ]]; then
        state="never sampled"
    elif ! git cat-file -e "$commit^{commit}" 2>/dev/null; then
        state="commit not in this history"
    else
        # shellcheck disable=SC2086 # the globs are pathspecs, split on purpose
        n="$(git diff --name-only "$commit" HEAD -- $globs | wc -l)"
        if [[ "$n" == 0 ]]; then state="unchanged"; else state="$n changed"; fi
    fi
    printf '%s\t%s\t%s\n' "$name" "${commit:-—}" "$state"
done
