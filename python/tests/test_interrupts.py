"""Ctrl-C and progress in collide_poses and collide_batch (docs/api.md#batches): a long batch
runs without the GIL, yet SIGINT raises KeyboardInterrupt within a second, with no query still
running after it; `progress` hears of every query, from the calling thread, a few times a second
at most."""
import os
import select
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import recode
from conftest import HALF_TURN_X, cones_tip_to_tip

# A child that starts a batch far too long to finish (minutes), says when it runs, and on
# KeyboardInterrupt says how many queries it had done and how much CPU time the process spent
# in the half second after it (worker threads still running queries would spend it).
CHILD = r"""
import signal, sys, time
import numpy as np
import recode

signal.signal(signal.SIGINT, signal.default_int_handler)  # even where the parent ignores it
kind, threads, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
cone = recode.cone(1.0, 2.0, 16)
a, b = recode.CollisionObject(cone), recode.CollisionObject(cone)
request = recode.CollisionRequest(resolution=32, threads=threads)
done = 0

def progress(k):
    global done
    done += k  # before the print: the parent's SIGINT may land as soon as the line is out
    if done == k:
        print("running", flush=True)  # the queries have begun

print("calling", flush=True)
try:
    if kind == "poses":  # with progress, which says when the queries run
        poses = np.tile(np.eye(4), (n, 1, 1))
        poses[:, :3, :3] = np.diag([1.0, -1.0, -1.0])
        poses[:, 2, 3] = np.linspace(3.5, 4.0, n)
        recode.collide_poses(a, b, poses_b=poses, request=request, progress=progress)
    else:  # without: the signal alone must stop it
        recode.collide_batch([a, b], np.tile([[0, 1]], (n, 1)), request=request)
    print("finished", flush=True)
except KeyboardInterrupt:
    print(f"interrupted {done}", flush=True)
    cpu = time.process_time()
    time.sleep(0.5)
    print(f"cpu {time.process_time() - cpu:.3f}", flush=True)
"""


def read_line(child, timeout):
    ready, _, _ = select.select([child.stdout], [], [], timeout)
    return child.stdout.readline().strip() if ready else None


@pytest.mark.parametrize("kind, threads", [("poses", 1), ("batch", 2)])
def test_ctrl_c_stops_a_long_batch_within_a_second(kind, threads):
    n = 200_000
    child = subprocess.Popen([sys.executable, "-c", CHILD, kind, str(threads), str(n)],
                             stdout=subprocess.PIPE, text=True, env=os.environ)
    try:
        assert read_line(child, 60) == "calling"
        if kind == "poses":
            assert read_line(child, 60) == "running"
        else:
            time.sleep(1.0)  # well inside the batch: checking its pairs takes milliseconds
        child.send_signal(signal.SIGINT)
        sent = time.monotonic()
        line = read_line(child, 5)
        latency = time.monotonic() - sent
        assert line is not None and line.startswith("interrupted"), line
        print(f"{kind}, threads={threads}: KeyboardInterrupt {latency:.3f} s after SIGINT")
        assert latency < 1.0
        if kind == "poses":  # it had begun and had not finished
            assert 0 < int(line.split()[1]) < n
        cpu = float(read_line(child, 5).split()[1])
        assert cpu < 0.2, f"{cpu} s of CPU after the interrupt: queries still running"
        assert child.wait(10) == 0
    finally:
        child.kill()
        child.wait()


def poses_of(n):
    matrices = np.tile(np.eye(4), (n, 1, 1))
    matrices[:, :3, :3] = HALF_TURN_X
    matrices[:, 2, 3] = np.linspace(3.5, 4.1, n)
    return matrices


def test_progress_totals_the_queries_from_the_calling_thread():
    a, b = cones_tip_to_tip()
    calls = []
    request = recode.CollisionRequest(resolution=32)
    batch = recode.collide_poses(a, b, poses_b=poses_of(50), request=request,
                                 progress=lambda k: calls.append((k, threading.get_ident())))
    assert sum(k for k, _ in calls) == 50 == len(batch)
    assert all(k > 0 and ident == threading.get_ident() for k, ident in calls)
    # Frames over two threads: the queries are counted wherever they ran.
    calls.clear()
    frames = np.tile(np.eye(4), (30, 2, 1, 1))
    frames[:, 1] = poses_of(30)
    request.threads = 2
    batch = recode.collide_batch([a, b], np.array([[0, 1], [1, 0], [0, 0]]), frames,
                                 request=request, progress=calls.append)
    assert batch.shape == (30, 3) and sum(calls) == 90
    # Without queries, nothing to report.
    calls.clear()
    recode.collide_batch([a, b], np.zeros((0, 2), dtype=int), progress=calls.append)
    assert calls == []


def test_progress_is_called_a_few_times_a_second_at_most():
    a, b = cones_tip_to_tip()
    calls = []
    start = time.monotonic()
    recode.collide_poses(a, b, poses_b=poses_of(3000),
                         request=recode.CollisionRequest(resolution=32), progress=calls.append)
    seconds = time.monotonic() - start
    assert sum(calls) == 3000
    assert len(calls) <= seconds / 0.2 + 2, f"{len(calls)} calls in {seconds:.2f} s"


def test_an_exception_from_progress_stops_the_batch_and_is_raised():
    a, b = cones_tip_to_tip()

    def stop(k):
        raise RuntimeError(f"stop after {k}")

    with pytest.raises(RuntimeError, match="stop after"):
        recode.collide_poses(a, b, poses_b=poses_of(10), progress=stop)
    with pytest.raises(TypeError, match="progress: expected a callable .*, got <class 'int'>"):
        recode.collide_poses(a, b, poses_b=poses_of(10), progress=3)
