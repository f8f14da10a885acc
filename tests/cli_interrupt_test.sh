#!/usr/bin/env bash
# Ctrl-C during a long render stops it after the current chunk and still
# writes the image and a session whose "steps" is what actually ran.
set -u
morphogen=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

"$morphogen" render --preset gs_coral --size 256 --steps 100000000 --backend cpu \
  --out cut.png 2>stderr.txt &
pid=$!
# Wait until the run has made progress (the first progress line), then interrupt.
for _ in $(seq 100); do
  grep -q "steps/s" stderr.txt 2>/dev/null && break
  sleep 0.1
done
kill -INT "$pid"
wait "$pid"
rc=$?

fail() { echo "FAIL: $*"; cat stderr.txt; exit 1; }
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1 for an interrupted run"
grep -q "interrupted after" stderr.txt || fail "no 'interrupted after' message"
[ -s cut.png ] || fail "no image written"
[ -s cut.json ] || fail "no session written"
steps=$(sed -n 's/.*"steps": \([0-9]*\).*/\1/p' cut.json)
[ -n "$steps" ] && [ "$steps" -gt 0 ] && [ "$steps" -lt 100000000 ] ||
  fail "session steps '$steps' should be the finished count"
# The written session reproduces the interrupted image.
"$morphogen" render --session cut.json --backend cpu --out again.png 2>/dev/null ||
  fail "re-running the written session failed"
cmp -s cut.png again.png || fail "the written session does not reproduce the image"
echo "ok: interrupted after $steps steps; image and session written and reproducible"
