"""The module gives the C++ API's results, bit for bit, on pairs of the generated suite.

recode_python_suite_expectations (suite_expectations.cpp, path in RECODE_SUITE_EXPECTATIONS)
writes each pair's meshes and, for three requests, the pose and the whole CollisionResult the
C++ API returned. Here the same meshes and poses go in through NumPy and every field must come
out equal: verdict, counts, frames, every case map, contact points, box, area, depth. The C++
API itself is checked against core::collidePair on the full suite (tests/api).
"""
import json
import os
import subprocess

import numpy as np
import pytest

import recode

PAIRS = 70  # 10 of each of the suite's 7 configurations


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    helper = os.environ.get("RECODE_SUITE_EXPECTATIONS")
    if not helper:
        pytest.skip("RECODE_SUITE_EXPECTATIONS (the C++ helper) not given; ctest sets it")
    path = tmp_path_factory.mktemp("suite") / "expected.json"
    subprocess.run([helper, str(path), str(PAIRS)], check=True)
    with open(path) as f:
        return json.load(f)["pairs"]


def block(mesh, name):
    return recode.ConvexBlock.from_arrays(np.array(mesh["vertices"], dtype=float),
                                          np.array(mesh["faces"], dtype=np.int64), name)


def request_of(r):
    return recode.CollisionRequest(pixel_size=r["pixel_size"], resolution=r["resolution"],
                                   axis=r["axis"])


def same_contact(got, expected):
    points = np.array(expected["points"], dtype=float).reshape(-1, 3)
    assert np.array_equal(got.points, points)
    if expected["box"] is None:
        assert got.box is None
    else:
        assert np.array_equal(got.box, np.array(expected["box"]))
    assert got.pixels == expected["pixels"]
    assert got.area == expected["area"]
    assert got.max_depth == expected["max_depth"]
    assert got.collapsed_pixels == expected["collapsed_pixels"]


def same_result(got, expected):
    assert got.collide == expected["collide"]
    assert got.interfering_pixels == expected["interfering_pixels"]
    assert got.box_tests == expected["box_tests"]
    assert got.block_pairs_drawn == expected["block_pairs_drawn"]
    same_contact(got.contact, expected["contact"])
    assert len(got.contacts) == len(expected["contacts"])
    for c, e in zip(got.contacts, expected["contacts"]):
        assert (c.block_a, c.block_b) == (e["block_a"], e["block_b"])
        assert c.frame.axis == e["frame"]["axis"]
        assert c.frame.window == tuple(e["frame"]["window"])
        assert (c.frame.width, c.frame.height) == (e["frame"]["width"], e["frame"]["height"])
        assert c.mor == tuple(e["mor"])
        assert np.array_equal(c.case_counts, e["case_counts"])
        assert c.case_map.dtype == np.uint8
        assert c.case_map.shape == tuple(e["case_map_shape"])
        assert np.array_equal(c.case_map.ravel(), np.array(e["case_map"], dtype=np.uint8))
        assert c.interfering_pixels == e["interfering_pixels"]
        same_contact(c.contact, e["contact"])


@pytest.mark.parametrize("case", [0, 1, 2], ids=["z-pixel-size", "auto-64", "posed-auto-48"])
def test_results_equal_the_cpp_apis(suite, case):
    collisions = 0
    for index, pair in enumerate(suite):
        c = pair["cases"][case]
        pose = np.array(c["pose"])
        a, b = block(pair["a"], "a"), block(pair["b"], "b")
        if index % 2 == 0:  # both ways of giving a pose
            objects = recode.CollisionObject(a, pose), recode.CollisionObject(b, pose)
        else:
            objects = (recode.CollisionObject(a, rotation=pose[:3, :3], translation=pose[:3, 3]),
                       recode.CollisionObject(b, rotation=pose[:3, :3], translation=pose[:3, 3]))
        result = recode.collide(*objects, request_of(c["request"]))
        try:
            same_result(result, c["expected"])
        except AssertionError as e:
            raise AssertionError(f"{pair['label']}: {e}") from e
        collisions += result.collide
    # Not vacuous: about a third of these pairs collide (21 to 25 of 70 with these requests),
    # each compared down to its case map and contact points.
    assert collisions >= len(suite) // 5
