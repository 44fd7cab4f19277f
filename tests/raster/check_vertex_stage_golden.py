#!/usr/bin/env python3
"""Reads the vertex-stage golden file (format recode-vertex-stage-1, docs/rasterization.md
section 9) as a back end in another language would, and recomputes every expected window vertex
from the file's inputs with the vertex stage of section 2.1, written here from that page alone:
Python's floats are IEEE-754 doubles, each operation rounded on its own (never fused), and
struct's "f" rounds a double to the nearest float, ties to even.

Usage: check_vertex_stage_golden.py FILE. Prints "vertex-stage golden OK: N vectors, M vertices"
and exits 0 when every vertex matches bit for bit, else names the first mismatches and exits 1.
"""

import json
import math
import struct
import sys


def double(text):
    """A double from its hexadecimal string, which must be the canonical float.hex() form."""
    value = float.fromhex(text)
    if value.hex() != text:
        raise ValueError("not canonical float.hex(): %r (expected %r)" % (text, value.hex()))
    return value


def float_bits(value):
    """The 32-bit pattern of the float nearest to the double `value` (ties to even)."""
    return struct.unpack("<I", struct.pack("<f", value))[0]


def snap(x):
    """x to the 1/256-pixel grid: nearbyint(x * 256) / 256, round half to even, sign kept."""
    scaled = x * 256.0
    rounded = float(round(scaled))  # Python's round() on a float: half to even
    if rounded == 0.0:
        rounded = math.copysign(0.0, scaled)  # nearbyint keeps the sign of a zero
    return rounded / 256.0


def vertex_stage(pose, window, p):
    l, t = pose["linear"], pose["translation"]
    world = [
        ((l[0] * p[0] + l[1] * p[1]) + l[2] * p[2]) + t[0],
        ((l[3] * p[0] + l[4] * p[1]) + l[5] * p[2]) + t[1],
        (l[6] * p[0] + (l[7] * p[1] + l[8] * p[2])) + t[2],
    ]
    u, v, d = (world[a] for a in window["axes"])
    x = (u - window["umin"]) / window["urange"] * window["width"]
    y = (v - window["vmin"]) / window["vrange"] * window["height"]
    z = (window["depth_max"] - d) / window["depth_range"]
    if not (abs(x) <= 32768.0 and abs(y) <= 32768.0 and 0.0 <= z <= 1.0):
        raise ValueError("not a drawable position: %r" % ((x, y, z),))
    return float_bits(snap(x)), float_bits(snap(y)), float_bits(z)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_vertex_stage_golden.py FILE")
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.read().split("\n")
    if lines[-1] != "":
        sys.exit("%s: does not end with a newline" % sys.argv[1])
    records = [json.loads(line) for line in lines[:-1]]
    header, vectors = records[0], records[1:]
    if header.get("format") != "recode-vertex-stage-1":
        sys.exit("%s: format is %r" % (sys.argv[1], header.get("format")))
    if header["vectors"] != len(vectors):
        sys.exit("header says %d vectors, the file has %d" % (header["vectors"], len(vectors)))
    mismatches, vertices = [], 0
    for vector in vectors:
        pose = {key: [double(s) for s in vector["pose"][key]] for key in ("linear", "translation")}
        window = {key: (value if key == "axes" else double(value))
                  for key, value in vector["window"].items()}
        if sorted(window["axes"]) != [0, 1, 2]:
            sys.exit("%s: axes %r are not a permutation" % (vector["name"], window["axes"]))
        counts = {len(vector[key]) for key in ("local", "expected", "expected_bits")}
        if len(counts) != 1:
            sys.exit("%s: local, expected and expected_bits differ in length" % vector["name"])
        for i, (local, decimals, bits) in enumerate(
                zip(vector["local"], vector["expected"], vector["expected_bits"])):
            vertices += 1
            expected = tuple(int(b, 16) for b in bits)
            # The decimals are the same floats: each reads back as the double of its float.
            if tuple(float_bits(float(x)) for x in decimals) != expected or any(
                    struct.unpack("<f", struct.pack("<I", b))[0] != float(x)
                    for b, x in zip(expected, decimals)):
                mismatches.append("%s vertex %d: decimals %r are not the bits %r"
                                  % (vector["name"], i, decimals, bits))
            got = vertex_stage(pose, window, [double(s) for s in local])
            if got != expected:
                mismatches.append("%s vertex %d: expected %s, computed %s" % (
                    vector["name"], i, bits, ["0x%08x" % b for b in got]))
    if header["vertices"] != vertices:
        sys.exit("header says %d vertices, the file has %d" % (header["vertices"], vertices))
    if mismatches:
        print("\n".join(mismatches[:20]))
        sys.exit("%d of %d vertices differ" % (len(mismatches), vertices))
    print("vertex-stage golden OK: %d vectors, %d vertices" % (len(vectors), vertices))


if __name__ == "__main__":
    main()
