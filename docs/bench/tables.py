#!/usr/bin/env python3
"""The tables of docs/benchmarks.md from one `recode bench` CSV.

    python3 docs/bench/tables.py docs/bench/bench.csv > /tmp/tables.md

For each experiment: the mean collision time per frame of RECODE (the reference on the CPU
device, and its skip-apart mode) beside the peers; RECODE's other modes and devices as ratios
to the reference; the pairs each algorithm found on the judged frames, with missed / extra
against CGAL. Table 1 gets its MOR comparison. Only the standard library is used.
"""
import csv
import sys
from collections import defaultdict

PEERS = ["recode-cpu", "recode-skip-apart", "fcl-gjk", "fcl-obbrss", "bullet", "cgal"]
VARIANTS = ["recode-adaptive", "recode-conservative", "recode-view-axis", "recode-gl",
            "recode-gl-exact", "recode-vulkan"]
ACCURACY = ["recode-cpu", "recode-adaptive", "recode-conservative", "recode-view-axis",
            "fcl-gjk", "fcl-obbrss", "bullet"]


def ms(value):
    """Three significant digits, as the bench's summary writes them."""
    v = float(value)
    if v >= 1000:
        return f"{v:,.0f}"
    if v >= 100:
        return f"{v:.0f}"
    if v >= 10:
        return f"{v:.1f}"
    if v >= 1:
        return f"{v:.2f}"
    return f"{v:.3g}"


def count(value):
    return f"{int(value):,}"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def load(path):
    rows = defaultdict(dict)  # (experiment, scene, triangles) -> algorithm -> row
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            rows[(r["experiment"], r["scene"], int(r["triangles"]))][r["algorithm"]] = r
    return rows


def levels(rows, experiment):
    keys = [k for k in rows if k[0] == experiment]
    return sorted(keys, key=lambda k: (k[1], k[2]))


def times(rows, keys, many_scenes):
    present = [a for a in PEERS if any(a in rows[k] for k in keys)]
    header = (["scene"] if many_scenes else []) + ["triangles"] + present
    body = []
    for k in keys:
        cells = [k[1]] if many_scenes else []
        cells.append(count(k[2]))
        for a in present:
            r = rows[k].get(a)
            cells.append(f"{ms(r['mean_ms'])} ({ms(r['sd_ms'])})" if r else "–")
        body.append(cells)
    return table(header, body)


def variants(rows, keys, many_scenes):
    present = [a for a in VARIANTS if any(a in rows[k] for k in keys)]
    header = (["scene"] if many_scenes else []) + ["triangles", "recode-cpu ms"] + present
    body = []
    for k in keys:
        base = float(rows[k]["recode-cpu"]["mean_ms"])
        cells = [k[1]] if many_scenes else []
        cells += [count(k[2]), ms(base)]
        for a in present:
            r = rows[k].get(a)
            cells.append(f"{ms(r['mean_ms'])} ({float(r['mean_ms']) / base:.2f}×)" if r else "–")
        body.append(cells)
    return table(header, body)


def accuracy(rows, keys, many_scenes):
    present = [a for a in ACCURACY if any(a in rows[k] for k in keys)]
    header = (["scene"] if many_scenes else []) + ["triangles", "judged frames", "true"] + present
    body = []
    for k in keys:
        truth = rows[k]["cgal"]
        cells = [k[1]] if many_scenes else []
        cells += [count(k[2]), truth["judged_frames"], truth["truth"]]
        for a in present:
            r = rows[k].get(a)
            if not r:
                cells.append("–")
                continue
            cell = f"{r['found_judged']} ({r['missed']} / {r['extra']})"
            if r.get("seen_finer"):
                cell += f", {r['seen_finer']} seen finer"
            cells.append(cell)
        body.append(cells)
    if many_scenes:
        body = collapse_levels(body)
    return table(header, body)


def collapse_levels(body):
    """One row per scene when its counts are the same at every level (the combs)."""
    out = []
    for scene in dict.fromkeys(r[0] for r in body):
        rows = [r for r in body if r[0] == scene]
        if len({tuple(r[2:]) for r in rows}) == 1:
            out.append([scene, "every level"] + rows[0][2:])
        else:
            out += rows
    return out


def table1(rows):
    (key,) = levels(rows, "table1")
    names = [("recode-min", "MIN"), ("recode-max", "MAX"), ("recode-full", "FULL, pair frame"),
             ("recode-full-screen", "FULL, whole screen")]
    body = []
    for name, label in names:
        r = rows[key][name]
        body.append([f"{label} (`{name}`)", ms(r["mean_ms"]), ms(r["sd_ms"]), count(r["box_tests"]),
                     count(r["pair_tests"]), count(r["stencil_pixels_read"]),
                     count(r["depth_pixels_read"]), f"{r['found_judged']} ({r['missed']} / {r['extra']})"])
    header = ["MOR", "mean ms", "sd ms", "box tests", "pair tests", "stencil px read",
              "depth px read", "found (missed / extra)"]
    return f"hierarchy-9, {count(key[2])} triangles\n\n" + table(header, body)


def main():
    rows = load(sys.argv[1])
    print("### Table 1\n\n" + table1(rows) + "\n")
    for experiment in ["table2", "figure8", "comb", "random-cones"]:
        keys = levels(rows, experiment)
        if not keys:
            continue
        many = len({k[1] for k in keys}) > 1
        print(f"### {experiment}\n")
        print(times(rows, keys, many) + "\n")
        print(variants(rows, keys, many) + "\n")
        print(accuracy(rows, keys, many) + "\n")


if __name__ == "__main__":
    main()
