#!/usr/bin/env bash
# abrade calibrate reads what spreadsheets write (a byte order mark, quotes, CRLF) and refuses
# what it cannot fit, with the file and line, instead of reporting a W: both depth columns,
# a part.pvd whose time is not a number or does not increase, a measurement row with a cell
# missing, a location defined twice, a row copied twice, every measurement at 0 t, a point
# 10 m from the knife, tonnes in kg (the fit runs to the end of its range), 1e300 tonnes.
#   check_bad_inputs.sh ABRADE SOURCE_DIR OUTDIR
set -euo pipefail
abrade=$(realpath "$1") src=$2 out=$3
rm -rf "$out" && mkdir -p "$out" && cd "$out"
expect="bash $src/tests/expect_error.sh"
"$abrade" run "$src/tests/lifetime/analytic_uniform.prm" --quiet --output run --set "Lifetime/Maximum updates=3" > /dev/null
python3 - <<'PY'
import csv
rows = list(csv.DictReader(open("run/trajectory.csv")))
def table(name, f=lambda t, d: (t, d), point="0.075,0.015,0.06", extra=()):
    with open(name, "w") as out:
        out.write("x,y,z,tonnes,depth\n")
        for r in rows:
            t, d = f(float(r["tonnes"]), float(r["point_depth"]))
            out.write(f"{point},{t!r},{d!r}\n")
        for line in extra:
            out.write(line + "\n")
table("good.csv")
table("kg.csv", lambda t, d: (1000 * t, d))
table("huge.csv", lambda t, d: (t * 1e300, d))
table("zero.csv", lambda t, d: (0.0, d))
table("far.csv", point="10.075,0.015,0.06")
table("short_row.csv", extra=["0.075,0.015,0.06,100"])
lines = open("good.csv").read().splitlines()
# what spreadsheets write: a byte order mark, quoted names and cells, CRLF line ends
open("excel.csv", "w", newline="").write("\ufeff" + "\r\n".join(
    ['"x","y","z","tonnes","depth"'] + ['"' + '","'.join(l.split(",")) + '"' for l in lines[1:]]) + "\r\n")
open("both_depths.csv", "w").write("x,y,z,tonnes,depth,depth_mm\n0.075,0.015,0.06,1500,0.0015,1.5\n")
open("copied.csv", "w").write("\n".join(lines + [lines[2]]) + "\n")
open("locations.csv", "w").write("name,x,y,z\ntip,0.075,0.015,0.06\ntip,0.075,0.015,0.07\n")
open("by_name.csv", "w").write("location,tonnes,depth\ntip,1500,0.0015\n")
PY
# the valid table fits (scale 1: the run's own analytic rate)
"$abrade" calibrate --run run --measurements good.csv --output cal > /dev/null
python3 -c "import json; r = json.load(open('cal/calibration.json'))['runs'][0]; assert abs(r['scale'] - 1) < 1e-3, r"
"$abrade" calibrate --run run --measurements excel.csv --output cal_excel > /dev/null
python3 -c "import json; r = json.load(open('cal_excel/calibration.json'))['runs'][0]; assert abs(r['scale'] - 1) < 1e-3, r"
cal() { $expect 2 "$1" -- "$abrade" calibrate --run "${3:-run}" --measurements "$2" --output cal_bad; }
cal "run: the best fit lies at the end of the range searched" kg.csv
cal "run: the best fit lies at the end of the range searched" huge.csv
cal "zero.csv: every measurement is at 0 t" zero.csv
cal "both_depths.csv: both 'depth' \[m\] and 'depth_mm' columns" both_depths.csv
cal "far.csv:2: the point \(10.07.*lies 9.9.* m or more from the part's surface" far.csv
cal "short_row.csv:5: 4 cells, the header has 5" short_row.csv
cal "copied.csv:5: the same measurement as copied.csv:3" copied.csv
$expect 2 "locations.csv:3: location 'tip' is defined twice \(first on line 2\)" -- \
  "$abrade" calibrate --run run --measurements by_name.csv --locations locations.csv --output cal_bad
cp -r run text_time && sed -i '0,/timestep="0"/s//timestep="abc"/' text_time/part/part.pvd
cal "text_time/part/part.pvd:[0-9]+: timestep \"abc\" is not a number of tonnes" good.csv text_time
cp -r run back_in_time && python3 - back_in_time/part/part.pvd <<'PY' # the third time step (after 1500 t) back to 1000 t
import re, sys
text = open(sys.argv[1]).read()
steps = re.findall(r'timestep="[^"]*"', text)
i = text.index(steps[2], text.index(steps[1]) + len(steps[1]))
open(sys.argv[1], "w").write(text[:i] + 'timestep="1000"' + text[i + len(steps[2]):])
PY
cal "back_in_time/part/part.pvd:[0-9]+: timestep 1000 t does not follow 1500" good.csv back_in_time
echo "calibrate inputs: all refused with their file and line"
