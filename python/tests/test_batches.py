"""Batches (docs/api.md#batches): collide_batch and collide_poses give, as arrays, what
recode.collide gives one query at a time.

recode_python_scene_frames (scene_frames.cpp, path in RECODE_SCENE_FRAMES) writes every built-in
scene of `recode run --list`: each leaf block in its own coordinates and its world pose at every
frame. Each leaf becomes an object; the pairs are the leaves of different scene objects whose
world boxes overlap at some frame; one collide_batch call over all frames must equal the
one-at-a-time calls on every frame, field by field.
"""
import json
import os
import subprocess

import numpy as np
import pytest

import recode
from conftest import HALF_TURN_X, cones_tip_to_tip

SCENES = ["comb-translate-aligned", "comb-translate-offset", "comb-rotate-aligned",
          "comb-rotate-offset", "random-cones", "random-shapes", "hand-grasp", "hierarchy-9"]
REQUEST = recode.CollisionRequest(resolution=32, normal=True)


@pytest.fixture(scope="module")
def scenes(tmp_path_factory):
    helper = os.environ.get("RECODE_SCENE_FRAMES")
    if not helper:
        pytest.skip("RECODE_SCENE_FRAMES (the C++ helper) not given; ctest sets it")
    path = tmp_path_factory.mktemp("scenes") / "frames.json"
    subprocess.run([helper, str(path)], check=True)
    with open(path) as f:
        return {s["name"]: s for s in json.load(f)["scenes"]}


def test_the_scenes_are_the_built_in_ones(scenes):
    assert sorted(scenes) == sorted(SCENES)
    cli = os.environ.get("RECODE_CLI")
    if cli:
        listing = subprocess.run([cli, "run", "--list"], check=True, capture_output=True,
                                 text=True).stdout
        listed = [line.split()[0] for line in listing.splitlines()[1:] if line.strip()]
        assert sorted(listed) == sorted(SCENES)


def scene_objects(scene):
    objects = [recode.CollisionObject(recode.ConvexBlock.from_arrays(
        np.array(leaf["vertices"], dtype=float), np.array(leaf["faces"], dtype=np.int64),
        leaf["path"])) for leaf in scene["leaves"]]
    owner = np.array([leaf["object"] for leaf in scene["leaves"]])
    return objects, owner, np.array(scene["poses"], dtype=float)  # (F, M, 4, 4)


def candidate_pairs(objects, owner, poses):
    """Leaves of different scene objects whose world boxes overlap at some frame."""
    overlap = np.zeros((len(objects), len(objects)), dtype=bool)
    for frame in poses:
        boxes = []
        for o, pose in zip(objects, frame):
            o.set_transform(pose)
            boxes.append(o.world_box)
        lo, hi = np.array([b[0] for b in boxes]), np.array([b[1] for b in boxes])
        overlap |= np.all((lo[:, None, :] <= hi[None, :, :]) & (lo[None, :, :] <= hi[:, None, :]),
                          axis=2)
    i, j = np.nonzero(np.triu(overlap, 1) & (owner[:, None] != owner[None, :]))
    return np.stack([i, j], axis=1)


def same_as_one_call(batch, index, r):
    assert batch.collide[index] == r.collide
    assert batch.interfering_pixels[index] == r.interfering_pixels
    assert batch.contact_pixels[index] == r.contact.pixels
    assert np.array_equal(batch.case_counts[index], r.case_counts)
    if r.contact.box is None:
        assert np.isnan(batch.contact_box[index]).all()
    else:
        assert np.array_equal(batch.contact_box[index], r.contact.box)
    assert batch.contact_area[index] == r.contact.area
    assert batch.max_depth[index] == r.contact.max_depth
    assert batch.block_pairs_drawn[index] == r.block_pairs_drawn
    normals = [c for c in r.contacts if c.contact.normal is not None]
    if normals:
        best = max(normals, key=lambda c: c.interfering_pixels)  # the first of equals
        assert np.array_equal(batch.normal[index], best.contact.normal)
        assert batch.penetration_depth[index] == best.contact.penetration_depth
    else:
        assert np.isnan(batch.normal[index]).all()
        assert np.isnan(batch.penetration_depth[index])


@pytest.mark.parametrize("name", SCENES)
def test_a_batch_over_every_frame_equals_the_one_at_a_time_calls(scenes, name):
    objects, owner, poses = scene_objects(scenes[name])
    pairs = candidate_pairs(objects, owner, poses)
    assert len(pairs) > 0
    batch = recode.collide_batch(objects, pairs, poses, request=REQUEST)
    assert batch.shape == (len(poses), len(pairs))
    if name not in ("comb-rotate-aligned", "comb-rotate-offset"):  # no contact at 32 pixels
        assert batch.collide.any()
    for f, frame in enumerate(poses):
        for o, pose in zip(objects, frame):
            o.set_transform(pose)
        for k, (i, j) in enumerate(pairs):
            same_as_one_call(batch, (f, k), recode.collide(objects[i], objects[j], REQUEST))
    # On two threads (oneTBB, the C++ API's pool) the same arrays.
    request = recode.CollisionRequest(resolution=32, normal=True, threads=2)
    spread = recode.collide_batch(objects, pairs, poses, request=request)
    for field in ("collide", "interfering_pixels", "case_counts", "contact_box", "normal"):
        assert np.array_equal(getattr(spread, field), getattr(batch, field), equal_nan=True)


def test_a_batch_at_the_objects_own_poses_and_at_one_pose_each():
    a, b = cones_tip_to_tip()
    c = recode.CollisionObject(recode.cone(1.0, 2.0, 32), translation=[1.5, 0.0, 0.0])
    objects = [a, b, c]
    pairs = np.array([[0, 1], [0, 2], [1, 2], [2, 0]])
    batch = recode.collide_batch(objects, pairs, request=REQUEST)
    assert batch.shape == (4,) and len(batch) == 4
    for k, (i, j) in enumerate(pairs):
        same_as_one_call(batch, k, recode.collide(objects[i], objects[j], REQUEST))
    poses = np.stack([o.transform for o in objects])
    poses[2, 0, 3] = 3.0  # c moved away
    moved = recode.collide_batch(objects, pairs, poses, request=REQUEST)
    c.set_transform(poses[2])
    for k, (i, j) in enumerate(pairs):
        same_as_one_call(moved, k, recode.collide(objects[i], objects[j], REQUEST))
    assert not moved.collide[1]


def quaternion_rows(translations, half_turn_x):
    """(N, 7) rows x, y, z, qx, qy, qz, qw: the identity, or a half turn about x (exact)."""
    q = np.where(half_turn_x[:, None], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0])
    return np.hstack([translations, q])


def test_collide_poses_equals_one_call_per_pose_as_matrices_and_as_quaternions():
    a, b = cones_tip_to_tip()
    n = 40
    heights = np.linspace(3.5, 4.1, n)
    matrices = np.tile(np.eye(4), (n, 1, 1))
    matrices[:, :3, :3] = HALF_TURN_X
    matrices[:, 0, 3] = np.linspace(-0.2, 0.2, n)
    matrices[:, 2, 3] = heights
    batch = recode.collide_poses(a, b, poses_b=matrices, request=REQUEST)
    assert batch.shape == (n,)
    assert 0 < batch.collide.sum() < n
    for k in range(n):
        b.set_transform(matrices[k])
        same_as_one_call(batch, k, recode.collide(a, b, REQUEST))
    rows = quaternion_rows(matrices[:, :3, 3], np.ones(n, dtype=bool))
    by_rows = recode.collide_poses(a, b, poses_b=rows, request=REQUEST)
    assert np.array_equal(by_rows.interfering_pixels, batch.interfering_pixels)
    assert np.array_equal(by_rows.contact_box, batch.contact_box, equal_nan=True)
    # Both objects moved: a up by the same heights is b at a fixed pose.
    lifted = quaternion_rows(np.stack([np.zeros(n), np.zeros(n), 3.75 - heights], axis=1),
                             np.zeros(n, dtype=bool))
    b.set_transform(matrices[0])
    both = recode.collide_poses(a, b, poses_a=lifted,
                                poses_b=np.repeat(matrices[:1], n, axis=0), request=REQUEST)
    assert both.collide.sum() > 0


def errors(call, match, kind=ValueError):
    with pytest.raises(kind, match=match):
        call()


def test_bad_batches_are_refused_naming_the_argument_and_the_rule():
    a, b = cones_tip_to_tip()
    objects = [a, b, a, b, a]
    ok = np.array([[0, 1]])
    errors(lambda: recode.collide_batch(objects, np.array([[0, 1, 2]])),
           r"pairs: expected a \(K, 2\) array of indices into objects, got shape \(1, 3\)")
    errors(lambda: recode.collide_batch(objects, np.array([0, 1])),
           r"pairs: expected a \(K, 2\) array .* got shape \(2,\)")
    errors(lambda: recode.collide_batch(objects, np.array([[0.0, 1.0]])),
           r"pairs: expected integer indices into objects, got dtype float64", TypeError)
    errors(lambda: recode.collide_batch(objects, np.array([[0, 1], [2, 5]])),
           r"pairs\[1, 1\] is 5: there are 5 objects, so indices run from 0 to 4")
    errors(lambda: recode.collide_batch(objects, np.array([[0, 1], [-1, 2]])),
           r"pairs\[1, 0\] is -1: indices into objects count from 0")
    errors(lambda: recode.collide_batch([a, "b"], ok),
           r"objects\[1\]: expected a CollisionObject, got <class 'str'>", TypeError)
    errors(lambda: recode.collide_batch(objects, ok, np.tile(np.eye(4), (4, 1, 1))),
           r"poses: expected one pose per object, \(5, 4, 4\) or \(5, 7\) for 5 objects, or "
           r"frames of them, \(F, 5, 4, 4\) or \(F, 5, 7\); got \(4,\) poses")
    errors(lambda: recode.collide_batch(objects, ok, np.zeros((5, 3, 3))),
           r"poses: expected 4 x 4 matrices \(\.\.\., 4, 4\) or rows \(\.\.\., 7\) of x, y, z, "
           r"qx, qy, qz, qw, got shape \(5, 3, 3\)")
    scaled = np.tile(np.eye(4), (5, 1, 1))
    scaled[2, :3, :3] *= 2.0
    errors(lambda: recode.collide_batch(objects, ok, scaled),
           r"poses\[2\]: the upper-left 3 x 3 block is not a rotation: R\^T R differs")
    last_row = np.tile(np.eye(4), (2, 5, 1, 1))
    last_row[1, 3, 3, 0] = 1.0
    errors(lambda: recode.collide_batch(objects, ok, last_row),
           r"poses\[1, 3\]: the last row is \[1, 0, 0, 1\], it must be \[0, 0, 0, 1\]")
    nan = np.tile(np.eye(4), (5, 1, 1))
    nan[4, 0, 3] = np.nan
    errors(lambda: recode.collide_batch(objects, ok, nan),
           r"poses\[4\] has nan: pose entries must be finite")
    errors(lambda: recode.collide_poses(a, b, poses_b=[[0, 0, 3.75, 2, 0, 0, 0]]),
           r"poses_b\[0\]: the quaternion \(qx, qy, qz, qw\) = \(2, 0, 0, 0\) has norm 2; it "
           r"must be a unit quaternion")
    errors(lambda: recode.collide_poses(a, b), r"collide_poses: give poses_a, poses_b or both")
    errors(lambda: recode.collide_poses(a, b, poses_a=np.zeros((2, 7)) + [0, 0, 0, 0, 0, 0, 1],
                                        poses_b=np.zeros((3, 7)) + [0, 0, 0, 0, 0, 0, 1]),
           r"poses_a and poses_b: expected the same number of poses, got 2 and 3")
    errors(lambda: recode.collide_poses(a, b, poses_a=np.zeros((2, 2, 7)) + [0, 0, 0, 0, 0, 0, 1]),
           r"poses_a: expected N poses, \(N, 4, 4\) or \(N, 7\); got \(2, 2\) poses")
    errors(lambda: recode.collide_poses(a, b, poses_a=["x"]),
           r"poses_a: expected real numbers, got dtype <U1", TypeError)


def test_an_empty_batch():
    a, b = cones_tip_to_tip()
    batch = recode.collide_batch([a, b], np.zeros((0, 2), dtype=np.int64))
    assert batch.shape == (0,) and batch.collide.shape == (0,)
    assert "shape=(0,)" in repr(batch)
