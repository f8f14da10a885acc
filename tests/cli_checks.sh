# Helpers the shell tests of the command line share (sourced; $morphogen set).
# Each check prints "ok: ..." or "FAIL: ..." with the last stderr, and counts
# the failures in $failures.
failures=0
fail() { echo "FAIL: $*"; [ -f err.txt ] && sed 's/^/  stderr: /' err.txt; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }
temporaries() { find . -name '.~*' | sort | tr '\n' ' '; }
# run EXPECTED_RC ARGS...: morphogen with stderr in err.txt; fails on another exit code.
run() {
  local want=$1
  shift
  "$morphogen" "$@" >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq "$want" ] || { fail "morphogen $*: exit $rc, want $want"; return 1; }
}
has() { grep -q -- "$1" err.txt || { fail "stderr lacks '$1'"; return 1; }; }
unchanged() { # FILE...: each equal to its .old copy
  for f in "$@"; do cmp -s "$f" "$f.old" || { fail "$f changed"; return 1; }; done
}
keep() { for f in "$@"; do cp "$f" "$f.old"; done; }
