"""Per-pair time of the Python module (docs/api.md#cost): recode.collide on the built-in pair of
`recode pair` (two cones tip to tip, along x at its frame's pixel size) and on one pair of the
generated suite, auto axis at 256 (the default) and 64 pixels. Median wall time around the call over REPEATS warm
calls, and the median of result.collision_us (the C++ API's own timing inside the call).

  PYTHONPATH=build/python python3 bench/python_pair_bench.py \
      [SUITE.json from recode_python_suite_expectations OUT 504] [PAIR=28]
"""
import json
import statistics
import sys
import time

import numpy as np

import recode

REPEATS = 300
# The built-in pair's frame: 256 pixels over a window 4.125 wide (`recode pair --json`).
BUILTIN_PIXEL = 4.125 / 256


def measure(a, b, request):
    recode.collide(a, b, request)  # warm: the device for this frame size
    wall, inside = [], []
    for _ in range(REPEATS):
        start = time.perf_counter()
        result = recode.collide(a, b, request)
        wall.append((time.perf_counter() - start) * 1e6)
        inside.append(result.collision_us)
    return statistics.median(wall), statistics.median(inside), result.interfering_pixels


def main():
    cone = recode.cone(1.0, 2.0, 32)
    a = recode.CollisionObject(cone)
    b = recode.CollisionObject(cone, rotation=np.diag([1.0, -1.0, -1.0]), translation=[0, 0, 3.75])
    pixel = BUILTIN_PIXEL
    wall, inside, px = measure(a, b, recode.CollisionRequest(pixel_size=pixel, axis="x"))
    print(f"built-in pair, axis x, pixel {pixel:.5f}: {wall:.0f} us per call "
          f"(collision_us {inside:.0f}), {px} interfering pixels")
    if len(sys.argv) > 1:
        index = int(sys.argv[2]) if len(sys.argv) > 2 else 28
        pair = json.load(open(sys.argv[1]))["pairs"][index]
        blocks = [recode.ConvexBlock.from_arrays(np.array(pair[k]["vertices"]),
                                                 np.array(pair[k]["faces"]), k) for k in "ab"]
        objects = recode.CollisionObject(blocks[0]), recode.CollisionObject(blocks[1])
        for resolution in (256, 64):
            wall, inside, px = measure(*objects, recode.CollisionRequest(resolution=resolution))
            print(f"suite pair {index} ({pair['label']}), auto axis, resolution {resolution}: "
                  f"{wall:.0f} us per call (collision_us {inside:.0f}), {px} interfering pixels")


if __name__ == "__main__":
    main()
