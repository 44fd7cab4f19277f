#!/usr/bin/env python3
"""recode run --mode skip-apart against the reference mode on built-in scenes: every frame's
pairs and contact regions, and its pair tests, must be the reference's; pairs skipped must be
some of those the reference found apart, and the stencil pixels read no more.

    check_skip_apart.py RECODE FRAMES SCENE...
"""
import json
import subprocess
import sys


def run(recode, scene, frames, mode):
    out = subprocess.run([recode, "run", scene, "--frames", frames, "--json", "--no-timing",
                          "--mode", mode], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    recode, frames, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
    failures = []
    for scene in scenes:
        ref, skip = run(recode, scene, frames, "reference"), run(recode, scene, frames, "skip-apart")
        for fr, fs in zip(ref["frames"], skip["frames"], strict=True):
            if fr["pairs"] != fs["pairs"] or fr["pair_tests"] != fs["pair_tests"]:
                failures.append(f"{scene} frame {fr['frame']}: pairs or pair tests differ")
                break
        rs, ss = ref["stats"], skip["stats"]
        skipped = ss["pair_tests_skipped"]
        if skipped > rs["pair_tests"] - rs["contacts"]:
            failures.append(f"{scene}: {skipped} skipped, more than the pairs found apart")
        if ss["stencil_pixels_read"] > rs["stencil_pixels_read"]:
            failures.append(f"{scene}: more stencil pixels read than the reference")
        print(f"{scene}: {rs['pair_tests']} pair tests, {rs['contacts']} contacts, "
              f"{skipped} skipped; stencil pixels read {rs['stencil_pixels_read']} -> "
              f"{ss['stencil_pixels_read']}")
    failing = {f.split(" ")[0].rstrip(":") for f in failures}
    for f in failures:
        print("FAIL:", f)
    print(f"skip-apart: {len(scenes) - len(failing)} of {len(scenes)} scenes as the reference")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
