#!/bin/sh
# Prints the campaign table of README.md from campaigns.tsv, per target: campaigns, seconds
# fuzzed, executions, exec/s, cov/ft of the last campaign, campaigns that stopped on an
# artifact. Seconds fuzzed are counted conservatively: the measured wall time (column 11) when
# recorded; for older lines without it, the scheduled time of a campaign that ran to its end
# (exit 0) and nothing for one that stopped early.
cd "$(dirname "$0")"
awk -F'\t' '
{
  t = $2; n[t]++; if (!(t in order)) { order[t] = ++k; name[k] = t }
  s = ($11 != "") ? $11 : (($10 == 0) ? $3 : 0)
  secs[t] += s
  if ($4 ~ /^[0-9]+$/) ex[t] += $4
  if ($5 ~ /^[0-9]+$/) eps[t] = $5
  if ($6 ~ /^[0-9]+$/) cov[t] = $6 " / " $7
  if ($10 != 0) stopped[t]++
}
END {
  print "| target | campaigns | seconds fuzzed | minutes | executions | exec/s (last) | cov / ft (last) | stopped on an artifact | 30 min reached? |"
  print "|---|---|---|---|---|---|---|---|---|"
  for (i = 1; i <= k; i++) {
    t = name[i]
    printf "| `%s` | %d | %d | %.1f | %d | %s | %s | %d | %s |\n", t, n[t], secs[t], secs[t] / 60, ex[t], eps[t], cov[t], stopped[t] + 0, (secs[t] >= 1800) ? "yes" : "no"
  }
}' campaigns.tsv
