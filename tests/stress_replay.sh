#!/bin/sh
# particles stress writes every broken case as a scene that run and compare
# accept (docs/stress.md); at least one case is broken (tunnelling at 5 radii
# per step), so the loop is never empty.
#
#   sh stress_replay.sh PARTICLES OUT_DIR full|quick
#
# full (Release): each broken scene is replayed for its whole duration by run
# (both engines) and compare. quick (the ASan + UBSan build): run replays the
# first 0.05 s of each in both engines, and compare is left out: the 200-ball,
# 4-second piles take minutes each under the sanitizers, and what this test
# checks (the written scenes load and step) does not need their whole run.
set -e
p=$1
d=$2
mode=$3
rm -rf "$d"
"$p" stress --out "$d" >/dev/null 2>&1
ls "$d"/broken/*.json >/dev/null
head -1 "$d"/envelope.csv | grep -q '^axis,value,engine_stable'
for f in "$d"/broken/*.json; do
  if [ "$mode" = full ]; then
    "$p" run "$f" >/dev/null
    "$p" run "$f" --engine box2d >/dev/null 2>&1
    "$p" compare "$f" >/dev/null
  else
    "$p" run "$f" --duration 0.05 >/dev/null
    "$p" run "$f" --duration 0.05 --engine box2d >/dev/null 2>&1
  fi
done
