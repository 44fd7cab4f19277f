#!/usr/bin/env python3
"""The pixel-size sweep of docs/accuracy.md: RECODE's verdict on every pair of blocks of two
different objects, judged by CGAL's exact intersection, on the bench scenes at several pixel
sizes. It runs `recode verify SCENE --cgal --frame K --pixel-size S --json --no-timing` per
scene, frame and pixel size and prints one Markdown table row per scene and pixel size:
true contacts, RECODE's misses and extra pairs, and the smallest exact overlap volume missed.

Usage: docs/bench/accuracy_sweep.py RECODE_BINARY [SCENE ...]   (run from the repository root)
"""
import json
import subprocess
import sys

# scene file, frames judged, the run's pixel size (`recode run NAME --frames 1 --json`).
SCENES = {
    "random-cones": (range(0, 100, 10), 0.018117837302353758),
    "hand-grasp": (range(0, 75, 6), 0.004),
    "comb-translate-offset": (range(0, 32, 2), 0.002),
    "random-shapes": (range(0, 100, 10), 0.018374569237517412),
}
FACTORS = [1, 4, 16]


def verify(recode, scene, frame, pixel):
    out = subprocess.run(
        [recode, "verify", f"data/scenes/{scene}.json", "--cgal", "--frame", str(frame),
         "--pixel-size", repr(pixel), "--json", "--no-timing"],
        capture_output=True, text=True, check=False)
    if out.returncode not in (0, 2):
        sys.exit(f"{scene} frame {frame} pixel {pixel}: {out.stderr.strip()}")
    return json.loads(out.stdout)["pairs"]


def main():
    recode = sys.argv[1]
    scenes = sys.argv[2:] or list(SCENES)
    print("| scene | pixel size | × run's | frames | true contacts | missed | miss rate | extra "
          "| smallest missed overlap volume |")
    print("|---|---|---|---|---|---|---|---|---|")
    for scene in scenes:
        frames, base = SCENES[scene]
        for factor in FACTORS:
            pixel = base * factor
            truth = missed = extra = 0
            smallest = None
            for frame in frames:
                for pair in verify(recode, scene, frame, pixel):
                    exact = pair["cgal"]["intersect"]
                    truth += exact
                    if exact and not pair["collide"]:
                        missed += 1
                        volume = pair["cgal"]["volume"]
                        smallest = volume if smallest is None else min(smallest, volume)
                    extra += pair["collide"] and not exact
            rate = f"{100.0 * missed / truth:.1f} %" if truth else "-"
            print(f"| {scene} | {pixel:.4g} | {factor:g} | {len(frames)} | {truth} | {missed} "
                  f"| {rate} | {extra} | {'-' if smallest is None else f'{smallest:.2g}'} |",
                  flush=True)


if __name__ == "__main__":
    main()
