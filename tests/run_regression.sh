#!/usr/bin/env bash
# ASPECT-style regression test: runs `abrade run NAME.prm` and compares every file of the
# reference folder NAME/ with numdiff. Tolerances come from a line in the .prm:
#   # numdiff: -a 1e-10 -r 1e-6
# With ABRADE_REGENERATE=1 the reference folder is overwritten with the new output instead.
#   run_regression.sh ABRADE PRM OUTDIR
set -euo pipefail
abrade=$1 prm=$2 out=$3
name=$(basename "$prm" .prm)
ref=$(dirname "$prm")/$name
tol=$(sed -n 's/^# *numdiff: *//p' "$prm" | head -1)
[[ -n "$tol" ]] || tol="-a 1e-10 -r 1e-8"
rm -rf "$out"
"$abrade" run "$prm" --output "$out" --quiet
if [[ "${ABRADE_REGENERATE:-0}" == 1 ]]; then
  [[ -d "$ref" ]] || { echo "no reference folder $ref: create it with the files to compare"; exit 1; }
  for f in $(cd "$ref" && find . -type f); do cp "$out/$f" "$ref/$f"; done
  echo "regenerated $ref"; exit 0
fi
[[ -d "$ref" ]] || { echo "missing reference folder $ref"; exit 1; }
# fields are separated by blanks and commas (CSV), so that the tolerances apply to each number
sep=$' \t\n,'
status=0
for f in $(cd "$ref" && find . -type f | sort); do
  if [[ ! -f "$out/$f" ]]; then echo "missing output $f"; status=1; continue; fi
  if numdiff -q -s "$sep" $tol "$ref/$f" "$out/$f" >/dev/null; then
    echo "ok: $f ($tol)"
  else
    echo "DIFFERS: $f ($tol)"; numdiff -S -s "$sep" $tol "$ref/$f" "$out/$f" | tail -20; status=1
  fi
done
exit $status
