"""Shared pieces of the module's tests: the two-cones pair of `recode pair` and a unit cube."""
import os
import pathlib

import numpy as np
import pytest

import recode

# The cube of examples/data/cube.obj as arrays: corners by bits (x: bit 0, y: bit 1, z: bit 2),
# two counter-clockwise triangles per side seen from outside.
CUBE_VERTICES = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
CUBE_FACES = np.array([
    [0, 2, 3], [0, 3, 1],  # z = 0, seen from below
    [4, 5, 7], [4, 7, 6],  # z = 1
    [0, 1, 5], [0, 5, 4],  # y = 0
    [2, 6, 7], [2, 7, 3],  # y = 1
    [0, 4, 6], [0, 6, 2],  # x = 0
    [1, 3, 7], [1, 7, 5],  # x = 1
])

HALF_TURN_X = np.diag([1.0, -1.0, -1.0])


def cones_tip_to_tip():
    """Two cones of radius 1 and height 2, the upper one upside down with its apex 0.25 into
    the lower one's (the built-in pair of `recode pair`)."""
    cone = recode.cone(1.0, 2.0, 32)
    return (recode.CollisionObject(cone),
            recode.CollisionObject(cone, rotation=HALF_TURN_X, translation=[0, 0, 3.75]))


@pytest.fixture
def data_dir():
    return pathlib.Path(os.environ.get(
        "RECODE_EXAMPLE_DATA_DIR",
        pathlib.Path(__file__).resolve().parents[2] / "examples" / "data"))
