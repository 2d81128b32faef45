#!/bin/sh
# Builds the seed corpus fuzz/corpus/<target>/ from ../shared/meshes (good and bad), the
# fixtures in tests/data (including tests/data/hostile) and the regression inputs in
# tests/data/fuzz-regressions. Files over 64 KiB are cut to their first 16 KiB (a truncated
# mesh is a useful bad input; a 3 MB seed would only slow every execution down).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
shared=${SHARED_MESHES:-$root/../shared/meshes}
[ -d "$shared" ] || shared=/work/shared/meshes
c=$here/corpus
add() { # target file
    mkdir -p "$c/$1"
    name=$(basename "$2")
    size=$(wc -c < "$2")
    if [ "$size" -gt 65536 ]; then head -c 16384 "$2" > "$c/$1/$name.head"; else cp "$2" "$c/$1/$name"; fi
}
add_sel() { # target selector-byte file : prepend one byte
    mkdir -p "$c/$1"
    name=$(basename "$3")
    { printf "\\$(printf %03o "$2")"; head -c 16384 "$3"; } > "$c/$1/$2-$name"
}
for f in "$shared"/good/* "$shared"/bad/* "$root"/tests/data/*.* "$root"/tests/data/hostile/* "$root"/tests/data/fuzz-regressions/*; do
    [ -f "$f" ] || continue
    case "$f" in
        *.off|*.OFF) add read_off "$f"; add_sel pipeline 0 "$f" ;;
        *.obj) add read_obj "$f"; add_sel pipeline 1 "$f" ;;
        *.ply) add read_ply_ascii "$f"; add_sel read_ply_binary 0 "$f"; add_sel pipeline 2 "$f" ;;
        */gluing_file-*|*.toml) add gluing_file "$f" ;;
        *) for t in read_off read_obj read_ply_ascii; do add $t "$f"; done ;;
    esac
done
# Bodies of well-formed binary PLY files behind header 1 (4 float vertices, 4 faces).
mkdir -p "$c/read_ply_binary" "$c/validate" "$c/surface_ops"
python3 - "$c/read_ply_binary" <<'PY'
import struct, sys, os
d = sys.argv[1]
verts = [(1,1,1),(1,-1,-1),(-1,1,-1),(-1,-1,1)]
faces = [(0,1,2),(0,3,1),(0,2,3),(1,3,2)]
le = b"".join(struct.pack("<fff", *v) for v in verts) + b"".join(struct.pack("<Biii", 3, *f) for f in faces)
be = b"".join(struct.pack(">fff", *v) for v in verts) + b"".join(struct.pack(">Biii", 3, *f) for f in faces)
open(os.path.join(d, "tet_le_body"), "wb").write(b"\x01" + le)
open(os.path.join(d, "tet_be_body"), "wb").write(b"\x02" + be)
PY
# Oracle protocol: one request of every op (docs/oracle.md), and one session of several.
mkdir -p "$c/oracle_protocol" "$c/gluing_file"
o=$c/oracle_protocol
printf '%s\n' '{"op":"degree","v":0}' > "$o/degree"
printf '%s\n' '{"op":"labels","v":0,"id":1}' > "$o/labels"
printf '%s\n' '{"op":"member","u":0,"w":1,"p":[0.3,0.1],"test":"lens"}' > "$o/member"
printf '%s\n' '{"op":"phi","u":0,"w":1,"p":[0.3,0.1],"id":"a"}' > "$o/phi"
printf '%s\n' '{"op":"g","v":0,"p":[0.3,0.1]}' '{"op":"g_inv","v":0,"p":[0.3,0.1]}' > "$o/g"
printf '%s\n' '{"op":"h","p":[0.3,0.1]}' '{"op":"rotate","u":0,"w":1,"p":[0.3,0.1]}' > "$o/h"
printf '%s\n' '{"op":"set_precision","bits":64}' '{"op":"eval","face":3,"bary":[0.25,0.25,0.5]}' > "$o/eval"
printf '%s\n' '{"op":"set_profile","profile":"authors-code"}' '{"op":"theta","v":0,"p":[0.3,0.1]}' > "$o/theta"
printf '%s\n' '{"op":"theta_derivatives","v":0,"p":[0.3,0.1],"order":2}' '{"op":"gamma","v":0,"p":[0.5,0.1]}' > "$o/derivatives"
printf '%s\n' '{"op":"psi","v":0,"p":[3.0,0.1]}' '{"op":"psi_control","v":1}' > "$o/psi"
# Adversarial-sweep inputs: derivatives at an edge midpoint (ξ near H₂ of a neighbour),
# membership at 1024+ bits (unit roundoff below 2^-1023), out-of-simplex barycentrics.
printf '%s\n' '{"op":"eval","face":1,"bary":[0.5,0.5,0]}' '{"op":"theta_derivatives","v":0,"p":[2.4997998108697437e-17,-0.408248290463863],"order":3}' > "$o/adv_edge_midpoint"
printf '%s\n' '{"op":"set_precision","bits":1024}' '{"op":"member","u":0,"w":1,"p":[0.3,0.1],"test":"literal"}' '{"op":"set_precision","bits":4096}' '{"op":"phi","u":0,"w":1,"p":[0.3,0.1]}' > "$o/adv_precision_1024"
printf '%s\n' '{"op":"eval","face":1,"bary":[-0.5,1.5,0]}' '{"op":"eval","face":1,"bary":[1e308,1e308,-1e308]}' > "$o/adv_bad_barycentric"
# f64 overflow where MPFR is finite (reply shape), a failed load then a query, a non-UTF-8 line.
printf '%s\n' '{"op":"g","v":0,"p":[1e300,1e300]}' '{"op":"load","path":"/nonexistent.off"}' '{"op":"degree","v":0}' > "$o/adv_reply_shape"
printf '{"op":"h","p":[0.3,0.1]}\n\377\376\n{"op":"degree","v":0}\n' > "$o/adv_non_utf8"
# A gluing piece whose midpoint is the fixed point of a wrong φ_ii (witness must differ).
printf '%s\n' 'name = "fixed point at the midpoint"' '[[domain]]' 'id = 1' 'interval = ["1", "2"]' '[[glue]]' 'i = 1' 'j = 1' 'omega_ij = ["1", "2"]' 'a = "2"' 'b = "-3/2"' > "$c/gluing_file/adv_fixed_point.toml"
# Gluing files: the bundled examples.
for f in "$root"/examples/gluing/*.toml; do [ -f "$f" ] && cp "$f" "$c/gluing_file/"; done
# Structured targets start from a few random byte strings (libFuzzer grows them).
for i in 1 2 3 4 5 6 7 8; do
    head -c $((i * 64)) /dev/urandom > "$c/validate/rand$i"
    head -c $((i * 32)) /dev/urandom > "$c/surface_ops/rand$i"
done
echo "seed corpus in $c:"; for d in "$c"/*; do echo "  $(basename "$d"): $(ls "$d" | wc -l) files"; done
