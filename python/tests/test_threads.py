"""Threads (docs/api.md#threads): queries run without the GIL on copies of their inputs.

Several threads querying one CollisionManager, or calling collide() on shared objects, get the
single-thread results, field by field; and a query that runs while another thread moves its
objects answers for one pose or the other, never for a mixture (the check that fails when a
query reads the Python-owned objects without the GIL instead of its copies).
"""
import threading

import numpy as np
import pytest

import recode
from conftest import HALF_TURN_X

THREADS = 8


def same_region(x, y):
    assert np.array_equal(x.points, y.points)
    assert (x.box is None) == (y.box is None)
    if x.box is not None:
        assert np.array_equal(x.box, y.box)
    assert (x.pixels, x.area, x.max_depth, x.collapsed_pixels) == \
        (y.pixels, y.area, y.max_depth, y.collapsed_pixels)


def same_result(x, y):
    """Every field but the timings."""
    assert (x.collide, x.interfering_pixels, x.box_tests, x.block_pairs_drawn,
            x.block_pairs_skipped, x.apart_at_limit) == \
        (y.collide, y.interfering_pixels, y.box_tests, y.block_pairs_drawn,
         y.block_pairs_skipped, y.apart_at_limit)
    same_region(x.contact, y.contact)
    assert np.array_equal(x.case_counts, y.case_counts)
    assert len(x.contacts) == len(y.contacts)
    for c, d in zip(x.contacts, y.contacts):
        assert (c.block_a, c.block_b, c.mor, c.interfering_pixels, c.refine_level) == \
            (d.block_a, d.block_b, d.mor, d.interfering_pixels, d.refine_level)
        assert (c.frame.axis, c.frame.window, c.frame.width, c.frame.height) == \
            (d.frame.axis, d.frame.window, d.frame.width, d.frame.height)
        assert np.array_equal(c.case_map, d.case_map)
        same_region(c.contact, d.contact)


def same_contacts(xs, ys):
    assert [(c.a, c.b) for c in xs] == [(c.a, c.b) for c in ys]
    for c, d in zip(xs, ys):
        same_result(c.result, d.result)


def run_threads(count, work):
    """Runs work(i) on `count` threads at once; re-raises the first failure."""
    errors = []
    start = threading.Barrier(count)

    def body(i):
        try:
            start.wait()
            work(i)
        except BaseException as e:  # noqa: BLE001 - handed to the main thread
            errors.append(e)

    threads = [threading.Thread(target=body, args=(i,)) for i in range(count)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    if errors:
        raise errors[0]


def ring_of_cones(count=10):
    """Cones on a circle, each tip to tip with an upside-down cone above, and touching its
    neighbours' sides: contacts between neighbours and across."""
    cone = recode.cone(1.0, 2.0, 24)
    objects = []
    for k in range(count):
        angle = 2 * np.pi * k / count
        x, y = 1.7 * np.cos(angle), 1.7 * np.sin(angle)
        objects.append(recode.CollisionObject(cone, translation=[x, y, 0.0]))
        objects.append(recode.CollisionObject(cone, rotation=HALF_TURN_X,
                                              translation=[x, y, 3.7 + 0.01 * k]))
    return objects


@pytest.mark.parametrize("threads_per_query", [1, 2])
def test_eight_threads_on_one_manager_give_the_single_thread_results(threads_per_query):
    manager = recode.CollisionManager()
    for o in ring_of_cones():
        manager.add(o)
    request = recode.CollisionRequest(resolution=48, threads=threads_per_query)
    expected = manager.collide(request)
    assert len(expected) > 10
    got = [[] for _ in range(THREADS)]

    def work(i):
        for _ in range(3):
            got[i].append(manager.collide(request))

    run_threads(THREADS, work)
    for per_thread in got:
        for contacts in per_thread:
            same_contacts(contacts, expected)
    assert manager.stats["pairs_in_contact"] == len(expected)


def test_eight_threads_calling_collide_give_the_single_thread_results():
    objects = ring_of_cones(4)
    request = recode.CollisionRequest(resolution=48)
    pairs = [(i, j) for i in range(len(objects)) for j in range(i + 1, len(objects))]
    expected = [recode.collide(objects[i], objects[j], request) for i, j in pairs]
    assert sum(r.collide for r in expected) >= 4

    def work(t):
        for k in range(len(pairs)):
            i, j = pairs[(k + t) % len(pairs)]
            same_result(recode.collide(objects[i], objects[j], request),
                        expected[(k + t) % len(pairs)])

    run_threads(THREADS, work)


# Two poses of the upper cone, both in contact with the lower one but with different frames
# and counts: a query that read one pose's boxes and the other's blocks would match neither.
POSE_P = np.eye(4)
POSE_P[:3, :3] = HALF_TURN_X
POSE_P[:3, 3] = [0.0, 0.0, 3.75]
POSE_Q = np.eye(4)
POSE_Q[:3, :3] = HALF_TURN_X @ np.array([[np.cos(0.15), 0, np.sin(0.15)], [0, 1, 0],
                                         [-np.sin(0.15), 0, np.cos(0.15)]])
POSE_Q[:3, 3] = [0.05, 0.0, 3.4]
READS = 1500


def key(result):
    return (result.collide, result.interfering_pixels, result.block_pairs_drawn,
            None if result.contact.box is None else result.contact.box.tobytes(),
            result.case_counts.tobytes(), result.contact.points.tobytes())


def test_a_result_read_while_another_thread_moves_its_objects_is_one_poses_result():
    cone = recode.cone(1.0, 2.0, 64)
    a = recode.CollisionObject(cone)
    b = recode.CollisionObject(cone, POSE_P)
    request = recode.CollisionRequest(resolution=24)
    expected = {}
    for pose in (POSE_P, POSE_Q):
        b.set_transform(pose)
        expected[key(recode.collide(a, b, request))] = pose
    assert len(expected) == 2
    stop = threading.Event()
    seen = []

    def writer():
        while not stop.is_set():
            b.set_transform(POSE_Q)
            b.set_transform(POSE_P)

    def reader():
        for _ in range(READS):
            result = recode.collide(a, b, request)
            # Read the whole result (its arrays are its own) while the writer runs.
            seen.append(key(result))
            assert result.contact.points.shape[0] == result.contact.pixels or \
                result.contact.pixels == 0

    moving = threading.Thread(target=writer)
    moving.start()
    try:
        run_threads(2, lambda i: reader())
    finally:
        stop.set()
        moving.join()
    unknown = [k for k in seen if k not in expected]
    assert not unknown, f"{len(unknown)} of {len(seen)} results match neither pose"


def test_a_manager_query_while_another_thread_moves_its_objects():
    cone = recode.cone(1.0, 2.0, 64)
    a = recode.CollisionObject(cone)
    b = recode.CollisionObject(cone, POSE_P)
    manager = recode.CollisionManager()
    manager.add(a)
    ib = manager.add(b)
    request = recode.CollisionRequest(resolution=24)
    expected = {}
    for pose in (POSE_P, POSE_Q):
        manager.update(ib, pose)
        (contact,) = manager.collide(request)
        expected[key(contact.result)] = pose
    assert len(expected) == 2
    stop = threading.Event()
    seen = []

    def writer():
        while not stop.is_set():
            b.set_transform(POSE_Q)  # moved from Python, the manager's object too
            b.set_transform(POSE_P)

    def reader():
        for _ in range(READS):
            (contact,) = manager.collide(request)
            seen.append(key(contact.result))

    moving = threading.Thread(target=writer)
    moving.start()
    try:
        run_threads(2, lambda i: reader())
    finally:
        stop.set()
        moving.join()
    unknown = [k for k in seen if k not in expected]
    assert not unknown, f"{len(unknown)} of {len(seen)} results match neither pose"
