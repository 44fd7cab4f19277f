"""Pickling (docs/api.md#pickling): blocks, geometries, objects, requests and results pickle and
deep-copy; what comes back answers as the original does, field by field; a state of another
format is a clear error; and a batch split over processes (multiprocessing with "spawn", a dask
LocalCluster) gives the one-process result."""
import copy
import multiprocessing
import pickle

import numpy as np
import pytest

import recode
from conftest import CUBE_FACES, CUBE_VERTICES, HALF_TURN_X, cones_tip_to_tip

# Timings differ between two runs of the same query; every other field must not.
TIMES = {"collision_us", "device_setup_us", "timing_us"}


def round_trip(value):
    return pickle.loads(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))


def same(a, b, where="result", times=True):
    """a and b equal in every public field, recursively (arrays exactly, NaN equal to NaN)."""
    if isinstance(a, (bool, int, float, str, type(None))):
        assert a == b or (a != a and b != b), f"{where}: {a!r} != {b!r}"
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{where}[{i}]", times)
    else:
        assert type(a) is type(b), where
        for name in dir(a):
            if name.startswith("_") or (name in TIMES and not times):
                continue
            try:
                x = getattr(a, name)
            except ValueError:  # case_map of a result with several block contacts
                with pytest.raises(ValueError):
                    getattr(b, name)
                continue
            if not callable(x):
                same(x, getattr(b, name), f"{where}.{name}", times)


def scene():
    """A compound of two blocks (one posed inside it) against the two cones: several block
    contacts, normals, case maps and frames to carry over."""
    cube = recode.ConvexBlock.from_arrays(CUBE_VERTICES, CUBE_FACES, name="cube")
    lifted = np.eye(4)
    lifted[2, 3] = 1.5
    compound = recode.CollisionGeometry.compound([cube, (cube, lifted)], name="tower")
    lower, upper = cones_tip_to_tip()
    tower = recode.CollisionObject(compound, translation=[-0.5, -0.5, 1.3])
    request = recode.CollisionRequest(pixel_size=0.03, normal=True, mor="full", axis="x")
    return lower, upper, tower, request


def test_a_result_comes_back_equal_field_by_field():
    lower, upper, tower, request = scene()
    for a, b in [(lower, upper), (tower, upper), (lower, tower)]:
        result = recode.collide(a, b, request)
        assert result.collide
        same(result, round_trip(result))
        same(result, copy.deepcopy(result))
    apart = recode.collide(lower, recode.CollisionObject(recode.box(1, 1, 1), translation=[9, 0, 0]))
    same(apart, round_trip(apart))
    several = recode.collide(tower, upper, request)
    assert len(several.contacts) == 2  # the case of several block contacts is covered


def test_objects_geometries_and_blocks_answer_as_the_originals():
    lower, upper, tower, request = scene()
    for a, b in [(lower, upper), (tower, upper)]:
        a2, b2 = round_trip(a), round_trip(b)
        assert np.array_equal(a2.transform, a.transform)
        assert a2.geometry.block_count == a.geometry.block_count
        same(recode.collide(a, b, request), recode.collide(a2, b2, request), times=False)
        same(recode.collide(a, b, request),
             recode.collide(copy.deepcopy(a), copy.deepcopy(b), request), times=False)
    # A single block's geometry stays single (one node: its box tests count as before), a
    # compound keeps its name, blocks, their poses and names.
    single = round_trip(lower.geometry)
    compound = round_trip(tower.geometry)
    assert compound.block_count == 2 and single.block_count == 1
    assert np.array_equal(compound.block_pose(1), tower.geometry.block_pose(1))
    for g, g2 in [(lower.geometry, single), (tower.geometry, compound)]:
        for i in range(g.block_count):
            assert g2.block(i).name == g.block(i).name
            assert np.array_equal(g2.block(i).vertices, g.block(i).vertices)
            assert np.array_equal(g2.block(i).faces, g.block(i).faces)
    hull = recode.ConvexBlock.from_hull(np.random.default_rng(3).normal(size=(40, 3)), "hull")
    assert np.array_equal(round_trip(hull).vertices, hull.vertices)
    # Immutable shapes are their own deep copies; an object's copy is its own (it moves alone)
    # and shares the shape, as in C++.
    assert copy.deepcopy(hull) is hull and copy.deepcopy(tower.geometry) is tower.geometry
    # Objects sharing a geometry share it again when pickled together.
    shape = recode.CollisionGeometry.single(recode.cone(1.0, 2.0, 16))
    first, second = recode.CollisionObject(shape), recode.CollisionObject(shape, pose=np.eye(4))
    first2, second2 = round_trip([first, second])
    geometry = first2.geometry
    assert second2.geometry is geometry and geometry is not shape
    moved = copy.deepcopy(lower)
    moved.set_transform(translation=[5, 0, 0])
    assert lower.transform[0, 3] == 0 and moved.geometry is lower.geometry


def test_a_request_and_a_batch_result_come_back_equal():
    request = recode.CollisionRequest(pixel_size=0.05, resolution=100, mor="max", axis="y",
                                      contact=False, normal=True, mode="adaptive", threads=3)
    for r in (round_trip(request), copy.deepcopy(request)):
        assert repr(r) == repr(request)
    assert round_trip(recode.CollisionRequest()).pixel_size is None
    lower, upper, tower, request = scene()
    poses = np.tile(np.eye(4), (20, 1, 1))
    poses[:, :3, :3] = HALF_TURN_X
    poses[:, 2, 3] = np.linspace(3.5, 4.1, 20)
    batch = recode.collide_poses(lower, upper, poses_b=poses, request=request)
    back = round_trip(batch)
    assert back.shape == batch.shape and len(back) == len(batch)
    same(batch, back)


def test_a_state_of_another_format_is_a_clear_error():
    request = recode.CollisionRequest()
    make, args, state = request.__reduce_ex__(2)[:3]
    other = make(*args)
    with pytest.raises(ValueError, match=r"recode\.CollisionRequest: the pickled state is of "
                                         r"format 99, this module reads format 2"):
        other.__setstate__((99,) + state[1:])
    with pytest.raises(ValueError, match=r"recode\.CollisionRequest: the pickled state has 2 items"):
        other.__setstate__(state[:3])
    lower, upper = cones_tip_to_tip()
    result = recode.collide(lower, upper)
    make, args, state = result.__reduce_ex__(2)[:3]
    with pytest.raises(ValueError, match=r"recode\.CollisionResult: the pickled state is of "
                                         r"format 0"):
        make(*args).__setstate__((0,) + state[1:])
    block = recode.box(1, 1, 1)
    make, args, state = block.__reduce_ex__(2)[:3]
    inside_out = (state[0], state[1], state[2], state[3][:, ::-1])
    with pytest.raises(recode.MeshError):  # a tampered block is validated again
        make(*args).__setstate__(inside_out)


def split_batch(objects, pairs, frames, request):
    """One worker's part of a batch split by frames (its arguments arrive pickled)."""
    return recode.collide_batch(objects, pairs, frames, request=request)


def batch_split_by_frames():
    lower, upper, tower, request = scene()
    objects = [lower, upper, tower]
    frames = np.tile(np.eye(4), (12, 3, 1, 1))
    frames[:, 1, :3, :3] = HALF_TURN_X
    frames[:, 1, 2, 3] = np.linspace(3.2, 4.4, 12)
    frames[:, 2, 0, 3] = np.linspace(-1.5, 1.0, 12)
    pairs = np.array([[0, 1], [0, 2], [2, 1]])
    chunks = [(objects, pairs, chunk, request) for chunk in np.array_split(frames, 3)]
    return recode.collide_batch(objects, pairs, frames, request=request), chunks


def same_as_one_process(one, parts):
    for name in ("collide", "interfering_pixels", "contact_pixels", "case_counts", "contact_box",
                 "contact_area", "max_depth", "normal", "penetration_depth",
                 "block_pairs_drawn"):
        joined = np.concatenate([getattr(p, name) for p in parts])
        assert np.array_equal(joined, getattr(one, name), equal_nan=joined.dtype.kind == "f"), name
    assert one.collide.any() and not one.collide.all()


def test_a_batch_split_over_spawned_processes_gives_the_one_process_result():
    one, chunks = batch_split_by_frames()
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        parts = pool.starmap(split_batch, chunks)
    same_as_one_process(one, parts)


def test_a_batch_split_over_a_dask_cluster_gives_the_one_process_result():
    distributed = pytest.importorskip(
        "distributed", reason="dask.distributed is not installed (Debian: python3-distributed, "
                              "which scripts/setup.sh installs)")
    one, chunks = batch_split_by_frames()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        futures = [client.submit(split_batch, *chunk, pure=False) for chunk in chunks]
        parts = client.gather(futures)
    same_as_one_process(one, parts)
