"""One pair at 1,000 poses from Python (docs/benchmarks.md, "Python: threads and batches"): the
two cones of examples/python/two_cones.py (pixel size 0.01), the upper one upside down, moved
along x from -0.2 to 0.2 and up from 3.5 to 4.0, as bench/batch_bench.cpp (the C++ API, one
recode::collide per pose) times it. Times recode.collide_poses on the 1,000 poses (one call,
threads=1 and threads=0), and the same poses one recode.collide call each, as a Python loop
would; the median of REPEATS runs of each.

  PYTHONPATH=build/python python3 bench/python_batch_bench.py
  build/bench/recode_batch_bench --benchmark_min_time=3      # the C++ time for the ratio
"""
import statistics
import time

import numpy as np

import recode

POSES = 1000
REPEATS = 5


def poses():
    t = np.arange(POSES) / (POSES - 1)
    m = np.tile(np.eye(4), (POSES, 1, 1))
    m[:, :3, :3] = np.diag([1.0, -1.0, -1.0])
    m[:, 0, 3] = -0.2 + 0.4 * t
    m[:, 2, 3] = 3.5 + 0.5 * t
    return m


def median_ms(run):
    run()  # warm: the devices for the frame sizes
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        run()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def main():
    cone = recode.cone(1.0, 2.0, 32)
    lower, upper = recode.CollisionObject(cone), recode.CollisionObject(cone)
    p = poses()
    one = recode.CollisionRequest(pixel_size=0.01)
    every = recode.CollisionRequest(pixel_size=0.01, threads=0)
    batch = recode.collide_poses(lower, upper, poses_b=p, request=one)

    def loop():
        for pose in p:
            upper.set_transform(pose)
            recode.collide(lower, upper, one)

    print(f"{POSES} poses, {int(batch.collide.sum())} in contact")
    for name, request in (("threads=1", one), ("threads=0", every)):
        ms = median_ms(lambda: recode.collide_poses(lower, upper, poses_b=p, request=request))
        print(f"collide_poses, {name}: {ms:.1f} ms")
    print(f"recode.collide in a Python loop: {median_ms(loop):.1f} ms")


if __name__ == "__main__":
    main()
