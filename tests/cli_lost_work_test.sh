#!/usr/bin/env bash
# No lost work, end to end: a PNG that does not fit (the file-size limit
# stands in for a full disk) is caught before it replaces the previous image;
# the next run to a folder removes what a killed run left there; a run that
# cannot fit in memory is refused at once with the figures.
set -u
morphogen=$1
work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

source "$here/cli_checks.sh"

# --- a PNG over the file-size limit ------------------------------------------
# OpenImageIO's PNG writer does not report the short write; the image is read
# back before its rename. A noisy 256 x 256 start is ~100 KiB of PNG, its
# session under 4 KiB: only the image does not fit in 16 KiB.
noisy=(render --preset turk_small_spots --size 256 --steps 1 --no-settle --backend cpu)
"$morphogen" "${noisy[@]}" --seed 1 --out p.png >out.txt 2>err.txt || fail "the first render failed"
keep p.png p.json
(ulimit -f 16 && exec "$morphogen" "${noisy[@]}" --seed 2 --out p.png) >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && has "p.png: writing the image failed" && ! grep -q '\.~' err.txt &&
  unchanged p.png p.json && [ -z "$(temporaries)" ]; then
  ok "a PNG over the file-size limit: exit 2 naming p.png, previous image and session kept"
else
  fail "PNG over the limit: exit $rc, temporaries: $(temporaries)"
fi

# --- what a killed run left ---------------------------------------------------
# A temporary and a staged frame folder named for a process that has ended
# (as a kill -9 leaves them): the next run to the folder removes them.
gone=$(sh -c 'echo $$')
head -c 100000 /dev/urandom >".~p.$gone-0.png"
mkdir ".~frame_staging.$gone-1" && echo frame >".~frame_staging.$gone-1/frame_00000.png"
# A live process's temporary stays (this shell's).
echo mine >".~p.$$-0.png"
if "$morphogen" render --preset gs_coral --size 16 --steps 1 --no-settle --backend cpu \
  --out p2.png >out.txt 2>err.txt && [ ! -e ".~p.$gone-0.png" ] &&
  [ ! -e ".~frame_staging.$gone-1" ] && [ -e ".~p.$$-0.png" ]; then
  ok "the next run to a folder removes a killed run's temporaries, not a live one's"
else
  fail "stale temporaries: $(temporaries)"
fi
rm -f ".~p.$$-0.png"

# --- memory ------------------------------------------------------------------
# 8192 x 8192 x 2 chemicals: two copies of the state are 1 GiB, over a 600 MB
# address space: refused before the run, with the figures.
(ulimit -v 600000 && exec "$morphogen" render --preset gs_coral --size 8192 --steps 1 \
  --no-settle --backend cpu --out big.png) >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && has "8192x8192 grid of 2 chemicals" && has "needs at least 1.0 GiB" &&
  has "this process may still allocate" && [ ! -e big.png ]; then
  ok "a run that cannot fit: exit 2 with what it needs and what is left"
else
  fail "memory estimate: exit $rc"
fi

[ -z "$(temporaries)" ] || fail "temporaries left: $(temporaries)"
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all lost-work checks passed"
