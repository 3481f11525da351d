#!/usr/bin/env python3
"""Joins single-bed stored wear files (wear/update_00001.wear of one-update lifetime runs on the
same design, one bed each) into the stored wear of the beds together, as the lifetime loop writes
it for one run over all of them (dem_wear_source.cc: the phases' volumes the beds' mean, each
bed's vertex volumes its own line): merge_wear.py OUT IN1 IN2 ..."""
import sys

def fnv1a_hex(data):
    h = 0xcbf29ce484222325
    for b in data:
        h ^= b
        h = (h * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return "%016x" % h

def read(path):
    raw = open(path, "rb").read()
    at = raw.rfind(b"checksum = ")
    if at < 0 or raw[at + 11:].strip().decode() != fnv1a_hex(raw[:at]):
        sys.exit(path + ": no stored wear file, or its checksum does not match")
    keys, values = [], {}
    for line in raw[:at].decode().splitlines():
        k, v = line.split(" = ", 1)
        keys.append(k)
        values[k] = v
    return keys, values

out, inputs = sys.argv[1], sys.argv[2:]
files = [read(p) for p in inputs]
keys, first = files[0]
for k in keys: # the same design, case and update in every file
    if k in ("phase_volume", "bed_seeds") or k.startswith("volume_bed_"):
        continue
    for p, (_, v) in zip(inputs, files):
        if v.get(k) != first[k]:
            sys.exit(f"{p}: its {k} is not {inputs[0]}'s: not one-bed wear of the same case, update and design")
for p, (_, v) in zip(inputs, files):
    if len(v["bed_seeds"].split()) != 1:
        sys.exit(f"{p}: holds {len(v['bed_seeds'].split())} beds (one wanted)")
n = len(files)
phase = [0.0] * len(first["phase_volume"].split())
for _, v in files: # added in the beds' order, each over n (as the loop adds them)
    for i, x in enumerate(v["phase_volume"].split()):
        phase[i] += float(x) / n
merged = dict(first)
merged["phase_volume"] = " ".join("%.17g" % x for x in phase)
merged["bed_seeds"] = " ".join(v["bed_seeds"] for _, v in files)
order = [k for k in keys if not k.startswith("volume_bed_")]
for b, (_, v) in enumerate(files):
    merged["volume_bed_%d" % (b + 1)] = v["volume_bed_1"]
    order.append("volume_bed_%d" % (b + 1))
text = "".join("%s = %s\n" % (k, merged[k]) for k in order).encode()
open(out, "wb").write(text + b"checksum = " + fnv1a_hex(text).encode() + b"\n")
