#!/bin/sh
# Two builds of particles (say Release -O3 and the sanitizer build at -O1)
# must print the same state hash for every example scene and the same suite
# results hash. Builds nothing: it only runs both binaries and compares.
#   cross_build.sh THIS_PARTICLES OTHER_PARTICLES SCENES_DIR SCRATCH_DIR
set -eu
this=$1 other=$2 scenes=$3 scratch=$4
[ -x "$other" ] || { echo "cross_build: no binary at $other" >&2; exit 1; }
mkdir -p "$scratch"
status=0
for scene in "$scenes"/*.json; do
  a=$("$this" run --hash "$scene" 2>&1 >/dev/null)
  b=$("$other" run --hash "$scene" 2>&1 >/dev/null)
  if [ "$a" = "$b" ]; then echo "same  $a  $(basename "$scene")"; else
    echo "DIFFERENT $(basename "$scene"): '$a' vs '$b'"; status=1; fi
done
"$this" suite --cases 20 --no-mutants --report "$scratch/this" >/dev/null
"$other" suite --cases 20 --no-mutants --report "$scratch/other" >/dev/null
a=$(grep '"results_hash"' "$scratch/this/report.json")
b=$(grep '"results_hash"' "$scratch/other/report.json")
if [ "$a" = "$b" ]; then echo "same suite $a"; else echo "DIFFERENT suite: $a vs $b"; status=1; fi
exit $status
