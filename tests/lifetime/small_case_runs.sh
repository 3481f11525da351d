# Helpers of the lifetime checks on the small case (sourced; needs abrade, src, out and
# updates set):
#  run DIR SETS...: `abrade run cases/lifetime/small.prm` on three beds for $updates updates
#    into $out/DIR (its log in $out/DIR.log, shown when it fails);
#  refused WHAT TEXT SETS...: the run with SETS exits with 2 and says TEXT, else the check fails.
case_file="$src/cases/lifetime/small.prm"
run() {
  local dir=$1; shift
  "$abrade" run "$case_file" --quiet --output "$out/$dir" --set "Lifetime/Seeds=1,2,3" \
    --set "Lifetime/Maximum updates=$updates" "$@" > "$out/$dir.log" 2>&1 || { cat "$out/$dir.log"; exit 1; }
}
refused() {
  local what=$1 text=$2; shift 2
  set +e
  "$abrade" run "$case_file" --quiet --output "$out/refused" --set "Lifetime/Maximum updates=1" "$@" > "$out/refused.log" 2>&1
  local rc=$?
  set -e
  rm -rf "$out/refused"
  [ "$rc" = 2 ] || { echo "$what: exit $rc, not 2"; cat "$out/refused.log"; exit 1; }
  grep -q -- "$text" "$out/refused.log" || { echo "$what: the message does not say '$text'"; cat "$out/refused.log"; exit 1; }
}
