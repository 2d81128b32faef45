#!/bin/sh
# Runs every target for SECONDS each, one after the other (one core).
secs=${1:-300}
cd "$(dirname "$0")"
for t in read_off read_obj read_ply_ascii read_ply_binary validate surface_ops pipeline oracle_protocol gluing_file; do
    ./run.sh "$t" "$secs" || true
done
