#!/usr/bin/env bash
# Output safety and numerical guards, end to end: a write that fails (a file
# over the size limit, a folder in the way) leaves the previous files at the
# output paths untouched and no temporaries; a result that is NaN or flat, a
# sweep with tiles that blew up, a propagator plot with nothing in it, are
# reported rather than written as if they were patterns.
set -u
morphogen=$1
work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

source "$here/cli_checks.sh"

small=(render --preset gs_coral --size 8 --steps 1 --no-settle --backend cpu)
# 16 custom colour stops: the session is over 1 KiB, the 8 x 8 image well under.
colours='#000000,#111111,#222222,#333333,#444444,#555555,#666666,#777777,#888888,#999999,#aaaaaa,#bbbbbb,#cccccc,#dddddd,#eeeeee,#ffffff'

# --- a failed session write: no new image either --------------------------
run 0 "${small[@]}" --seed 1 --out o.png || true
keep o.png o.json
# ulimit -f 1: files up to 1 KiB. The image's temporary is written, the
# session's fails (EFBIG): neither replaces its previous version.
(ulimit -f 1 && exec "$morphogen" "${small[@]}" --seed 2 --colours "$colours" --out o.png) \
  >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && has "o.json: writing the file failed" && unchanged o.png o.json &&
  [ -z "$(temporaries)" ]; then
  ok "a session over the file-size limit: exit 2, previous image and session kept, no temporaries"
else
  fail "failed session write: exit $rc, temporaries: $(temporaries)"
fi

# The image over the limit instead (raw floats of a noisy start): the same.
run 0 render --preset gs_coral --size 128 --steps 1 --no-settle --backend cpu --out e.exr || true
keep e.exr e.json
(ulimit -f 1 && exec "$morphogen" render --preset gs_coral --size 128 --steps 1 --no-settle \
  --backend cpu --seed 2 --out e.exr) >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && has "e.exr: writing the image failed" && unchanged e.exr e.json &&
  [ -z "$(temporaries)" ]; then
  ok "an image over the file-size limit: exit 2, previous files kept, no temporaries"
else
  fail "failed image write: exit $rc, temporaries: $(temporaries)"
fi

# A texture set is all or nothing too, with the image and session of the same run.
run 0 "${small[@]}" --seed 1 --out t.png --texture-set tex || true
keep t.png t.json tex/albedo.png tex/height.exr tex/session.json tex/texture_set.json
(ulimit -f 1 && exec "$morphogen" "${small[@]}" --seed 2 --colours "$colours" --out t.png \
  --texture-set tex) >out.txt 2>err.txt
rc=$?
if [ "$rc" -eq 2 ] && unchanged t.png t.json tex/albedo.png tex/height.exr tex/session.json \
  tex/texture_set.json && [ -z "$(temporaries)" ]; then
  ok "a failed texture-set write: previous set, image and session kept, no temporaries"
else
  fail "failed texture-set write: exit $rc, temporaries: $(temporaries)"
fi

# The session path is a folder: refused before the run, the image untouched.
mkdir -p d.json
run 0 "${small[@]}" --out d.png --session-out d_first.json || true
keep d.png
if run 2 "${small[@]}" --seed 3 --out d.png && has "d.json: cannot write here: it is a folder" &&
  unchanged d.png && [ -z "$(temporaries)" ]; then
  ok "a session path that is a folder: exit 2, image untouched, no temporaries"
fi

# --- numerical guards --------------------------------------------------------
# A semi-implicit run with a huge dt that ends uniform: written, with a warning.
if run 0 render --preset gs_coral --integrator semi_implicit --dt 15 --size 32 --steps 1500 \
  --no-settle --backend cpu --out flat.png && has "warning: the result is uniform" &&
  has "try a smaller --dt"; then
  ok "a run that collapsed to one value warns and names what to try"
fi
# The same result re-coloured from its raw state warns too.
if run 0 render --preset gs_coral --integrator semi_implicit --dt 15 --size 32 --steps 1500 \
  --no-settle --backend cpu --out flat.exr && run 0 colour flat.exr --out flat_again.png &&
  has "flat.exr: chemical v = .* everywhere"; then
  ok "colour warns about a flat raw state"
fi
# A pattern does not warn.
if run 0 "${small[@]}" --out fine.png && ! grep -q "uniform" err.txt; then
  ok "a pattern gets no flat warning"
else
  fail "a pattern was reported uniform"
fi

# A blow-up: exit 1 with the step range and a dt, nothing written (frames neither).
run 0 render --preset gs_coral --size 24 --steps 30 --backend cpu --frames 3 --out nan.png || true
keep nan.png nan.json nan_frames/frame_00000.png
if run 1 render --preset gs_coral --size 24 --steps 600 --integrator semi_implicit --dt 100 \
  --backend cpu --every 7 --out nan.png && has "blew up between step 1 and step 7" &&
  has "try a smaller time step such as --dt" && unchanged nan.png nan.json \
  nan_frames/frame_00000.png && [ ! -e nan_frames/frame_00003.png ] && [ -z "$(temporaries)" ]; then
  ok "a blow-up between frames: exit 1, step range, previous image, session and frames kept"
fi

# Sweep tiles that blew up: named in a warning, hatched, no nan/null in the stats.
if run 0 sweep --model turing_turk --x s:0.05:10 --y beta_mean:0:100 --grid 3x3 --tile 16 \
  --steps 200 --backend cpu --out sw && has "2 of 9 tiles went NaN or infinite" &&
  has "column 1, row 0 (s 5.025, beta_mean 0)" && has "column 2, row 0 (s 10, beta_mean 0)"; then
  if grep -Eqiw "nan|inf|infinity" sw/stats.csv || grep -Eqw "null|NaN" sw/stats.json; then
    fail "sweep stats hold nan/inf/null: $(cat sw/stats.csv)"
  elif ! grep -q '^1,0,5.025,0,,,,,,unstable$' sw/stats.csv; then
    fail "sweep stats.csv: the blown-up tile's row is not empty stats + unstable: $(cat sw/stats.csv)"
  elif [ "$(grep -c '"finite": false' sw/stats.json)" -ne 2 ]; then
    fail "sweep stats.json: want two tiles with \"finite\": false"
  else
    ok "sweep: blown-up tiles named, stats empty and marked, not nan/null"
  fi
fi

# A propagator plot with nothing in it (the density underflows at this radius): refused.
if run 2 propagator --tensor c --radius 100 --out empty.png && has "--radius 100" &&
  has "no positive value" && [ ! -e empty.png ] && ! grep -q isotropic out.txt; then
  ok "an empty propagator plot is refused, not called isotropic"
fi
if run 0 propagator --tensor "xx=1,yy=1" --out iso.png && grep -q "none (isotropic)" out.txt; then
  ok "an isotropic tensor still says isotropic"
fi

[ -z "$(temporaries)" ] || fail "temporaries left: $(temporaries)"
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all output-safety checks passed"
