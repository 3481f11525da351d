#!/usr/bin/env bash
# A multi-level knife-bed (19.4 mm pellets in |y| < 0.24 m, 27.5 mm beyond) poured twice
# through the bed job (bed_preparation.cc): the first pour's fine column holds less than the
# case pours over it (the finer pellets spread into the shells), the refilled second holds more
# of it, the log and summary.json say so with the bed's seed, the total mass stays (the bulk gave
# what the fine region took), and the saved bed rerun with one pour is used with a warning.
# The fine box's margin (fine_region_margin.cc): 0.225 m beside the knife's path (|y| < 0.24 m,
# the knife 0.03 m thick) is under 1.2 times the depth its edge reaches below the bed's surface
# (z = 0.6 - 1.5 m/s x 0.2667 s = 0.2 m; the surface from the bed file here, the mean of its
# columns' tops): a warning; with |y| < 0.48 m (0.465 m) a line and no warning; with the box
# wide below the knife's path only, the upper face's margin, warned. The bed made with the narrow
# box and used with a wider one is named in a warning.
#   check_multi_level_pours.sh ABRADE CASE_DIR OUTDIR
set -euo pipefail
abrade=$1 cases=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
fine=(--set "Particles/Coarse graining/Fine region min=-0.97, -0.24, 0.03" --set "Particles/Coarse graining/Fine region max=0.97, 0.24, 0.85"
      --set "Particles/Coarse graining/Fine region factor=2.828" --set "Simulation/Threads=2" --quiet)
"$abrade" run "$cases/coarse_graining.prm" --output "$out/bed" --set Job=bed "${fine[@]}" \
  --set "Particles/Coarse graining/Fine region pours=2" --set "Particles/Settling/Bed file=$out/bed.bed"
grep -q "Multi-level bed, pour 1 of 2" "$out/bed/log.txt" || { echo "no first pour in the log"; exit 1; }
python3 - "$out/bed/summary.json" "$out/bed.bed" <<'PY'
import json, struct, sys
pours = json.load(open(sys.argv[1]))["results"]["coarse_graining"]["pours"]
assert [p["pour"] for p in pours] == [1, 2] and all(p["seed"] == 1 for p in pours), pours
first, second = pours[0]["footprint_share"][0], pours[1]["footprint_share"][0]
print(f"the fine column held {100 * first:.2f} % poured once, {100 * second:.2f} % refilled")
assert first < 0.985, "poured once, the fine column should lack mass (the finer pellets spread into the shells)"
assert second > first + 0.01, "the refilled pour should hold more of the fine column's mass"
# the saved bed's total mass is the case's: what the fine region gained the bulk gave (to half
# a bulk pellet: 4/3 pi 0.0275^3 3700 = 0.32 kg)
b = open(sys.argv[2], "rb").read()
n = struct.unpack_from("<Q", b, 8)[0]
mass = sum(struct.unpack_from(f"<{n}d", b, 24 + 10 * 8 * n))
print(f"bed: {n} pellets, {mass:.2f} kg")
assert abs(mass - 3383.1) < 0.4, mass
PY
"$abrade" run "$cases/coarse_graining.prm" --output "$out/once" --set Job=bed "${fine[@]}" \
  --set "Particles/Coarse graining/Fine region pours=1" --set "Particles/Settling/Bed file=$out/bed.bed"
grep -q "it was poured more than once, and Particles/Coarse graining/Fine region pours is 1" "$out/once/log.txt" ||
  { echo "the refilled bed was used for a one-pour case without a warning"; exit 1; }
grep -q "warning: Particles/Coarse graining/Fine region: wall knife's path comes" "$out/once/log.txt" ||
  { echo "no warning for a fine box 0.225 m beside the knife's path"; exit 1; }
# the same bed with a wider box (0.465 m, no margin warning; the bed was made with the narrow box:
# a warning names it) and with a box wide below the knife but not above (the upper face's 0.225 m)
"$abrade" run "$cases/coarse_graining.prm" --output "$out/wide" --set Job=bed "${fine[@]}" \
  --set "Particles/Coarse graining/Fine region min=-0.97, -0.48, 0.03" --set "Particles/Coarse graining/Fine region max=0.97, 0.48, 0.85" \
  --set "Particles/Settling/Bed file=$out/bed.bed"
grep -q "finest particles (radius 0.01944 m) are not within 10 % of the" "$out/wide/log.txt" ||
  { echo "a bed made with another fine region was used without a warning"; exit 1; }
! grep -q "finest particles (radius 0.01944 m) are not within" "$out/once/log.txt" ||
  { echo "the refilled bed of the case's own fine region was named as made with another"; exit 1; }
! grep -q "warning: Particles/Coarse graining/Fine region" "$out/wide/log.txt" || { echo "a margin warning for 0.465 m"; exit 1; }
"$abrade" run "$cases/coarse_graining.prm" --output "$out/upper" --set Job=bed "${fine[@]}" \
  --set "Particles/Coarse graining/Fine region min=-0.97, -0.48, 0.03" --set "Particles/Coarse graining/Fine region max=0.97, 0.24, 0.85" \
  --set "Particles/Settling/Bed file=$out/bed.bed"
python3 - "$out/bed.bed" "$out/once/log.txt" "$out/wide/log.txt" "$out/upper/log.txt" <<'PY'
import math, re, struct, sys
b = open(sys.argv[1], "rb").read()
n = struct.unpack_from("<Q", b, 8)[0]
x, y, z = (struct.unpack_from(f"<{n}d", b, 24 + k * 8 * n) for k in range(3))
r = struct.unpack_from(f"<{n}d", b, 24 + 9 * 8 * n)
tops = {}  # the highest top in each 0.1 m column of the box |x|, |y| < 0.9 m
for xi, yi, zi, ri in zip(x, y, z, r):
    if abs(xi) < 0.9 and abs(yi) < 0.9:
        key = (int((xi + 0.9) // 0.1), int((yi + 0.9) // 0.1))
        tops[key] = max(tops.get(key, -1.0), zi + ri)
surface = sum(tops.values()) / len(tops)
depth = surface - (0.6 - 1.5 * 0.2666667)  # the edge's lowest point: z = 0.6 - 1.5 m/s x 0.2667 s
print(f"bed surface {surface:.4f} m (highest top {max(zi + ri for zi, ri in zip(z, r)):.4f} m): the edge {depth:.4f} m below it")
pattern = re.compile(r"(warning: )?.*wall knife's path comes ([-0-9.e]+) m from the fine region's face at y = ([-0-9.e]+) m, "
                     r"([0-9.e]+) times the depth of its lowest point below the bed's surface \(([0-9.e]+) m;")
# each face too near warned (both of the narrow box), else a line for the nearest
for log, warned, faces in ((sys.argv[2], True, {-0.24, 0.24}), (sys.argv[3], False, {-0.48, 0.48}), (sys.argv[4], True, {0.24})):
    found = [m for m in map(pattern.match, open(log)) if m]
    assert len(found) == (len(faces) if warned else 1), (log, found)
    for m in found:
        margin, at, ratio, said = float(m[2]), float(m[3]), float(m[4]), float(m[5])
        half = abs(at)
        print(f"{log}: margin {margin} m at y = {at} m, {ratio} depths, depth {said} m")
        assert (m[1] is not None) == warned, log
        assert abs(margin - (half - 0.015)) < 1e-3, (log, margin)  # the knife is 0.03 m thick, centred on y = 0
        assert at in faces, (log, at)
        assert abs(said - depth) < 0.006, (log, said, depth)  # two definitions of the surface: a few mm
        assert abs(ratio - margin / said) < 5e-3 * ratio, (log, ratio)  # (each printed to 3 digits)
        if warned:  # the face moved to 1.2 depths beyond the knife's face (room for the shells to y = 0.97 m)
            move = re.search(r"move the face to y = ([-0-9.e]+) m \(1\.2 times the depth beyond the path", m.string)
            assert move, (log, m.string)
            assert abs(float(move[1]) - math.copysign(0.015 + 1.2 * said, at)) < 1.5e-3, (log, move[1], said)
    assert not warned or {float(m[3]) for m in found} == faces, (log, found)
PY
echo "ok: the refilled pour holds more of the fine column's mass, the total stays, a bed of other pours is named, the fine box's margin and depth are the knife's and the bed's"
