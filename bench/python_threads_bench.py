"""Queries a second from Python threads (docs/benchmarks.md, "Python: threads and batches"):
recode.collide on the two cones of examples/python/two_cones.py (pixel size 0.01), CALLS calls
on each of 1 and 2 threads sharing the two objects; queries a second over all threads, and the
time of a call on each, and the CPU time the process used over the wall time (at most 1 while
one thread at a time runs; on a machine other work also loads, queries a second follow the
cores this process gets, the CPU share shows whether its threads ran at once). The median of
REPEATS runs. First a control: the same pure-Python loop in 1 and 2 processes, so the line
says how much parallel work the machine gives this process at that moment (2.0: two free cores).

  PYTHONPATH=build/python python3 bench/python_threads_bench.py [CALLS=300]
"""
import multiprocessing
import statistics
import sys
import threading
import time

import numpy as np

import recode

REPEATS = 5


def run(threads, calls, a, b, request):
    start = threading.Barrier(threads + 1)

    def work():
        start.wait()
        for _ in range(calls):
            recode.collide(a, b, request)

    workers = [threading.Thread(target=work) for _ in range(threads)]
    for w in workers:
        w.start()
    start.wait()
    t0, c0 = time.perf_counter(), time.process_time()
    for w in workers:
        w.join()
    wall = time.perf_counter() - t0
    return wall, (time.process_time() - c0) / wall


def busy(_):
    total = 0
    for i in range(5_000_000):
        total += i
    return total


def machine_parallelism():
    """Work of 2 processes over the work of 1 in the same wall time (no GIL between them)."""
    times = []
    for n in (1, 2):
        with multiprocessing.Pool(n) as pool:
            pool.map(busy, range(n))  # warm
            start = time.perf_counter()
            pool.map(busy, range(n))
            times.append(time.perf_counter() - start)
    return 2 * times[0] / times[1]


def main():
    calls = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    cone = recode.cone(1.0, 2.0, 32)
    a = recode.CollisionObject(cone)
    b = recode.CollisionObject(cone, rotation=np.diag([1.0, -1.0, -1.0]),
                               translation=[0.0, 0.0, 3.75])
    request = recode.CollisionRequest(pixel_size=0.01)
    print(f"control: 2 processes do {machine_parallelism():.2f}x the work of 1")
    recode.collide(a, b, request)  # warm
    base = None
    for threads in (1, 2):
        runs = [run(threads, calls, a, b, request) for _ in range(REPEATS)]
        seconds = statistics.median(r[0] for r in runs)
        cpu = statistics.median(r[1] for r in runs)
        rate = threads * calls / seconds
        base = base or rate
        print(f"{threads} thread{'s' if threads > 1 else ''}: {rate:.0f} queries/s, "
              f"{seconds / calls * 1e3:.2f} ms a call on each, {rate / base:.2f}x one thread, "
              f"CPU {cpu:.2f} x wall")


if __name__ == "__main__":
    main()
