"""Blocks and shapes: made from arrays, files and the primitive solids, and read back."""
import numpy as np
import pytest

import recode
from conftest import CUBE_FACES, CUBE_VERTICES


def test_a_block_from_arrays_keeps_its_vertices_and_faces():
    block = recode.ConvexBlock.from_arrays(CUBE_VERTICES, CUBE_FACES, name="cube")
    assert block.name == "cube"
    assert np.array_equal(block.vertices, CUBE_VERTICES)
    assert block.faces.dtype == np.uint32
    assert np.array_equal(block.faces, CUBE_FACES)


def test_lists_and_other_dtypes_are_converted():
    block = recode.ConvexBlock.from_arrays(CUBE_VERTICES.astype(np.float32).tolist(),
                                           CUBE_FACES.astype(np.uint64))
    assert np.array_equal(block.vertices, CUBE_VERTICES)
    assert np.array_equal(block.faces, CUBE_FACES)


def test_block_arrays_are_read_only_views():
    block = recode.ConvexBlock.from_arrays(CUBE_VERTICES, CUBE_FACES)
    with pytest.raises(ValueError):
        block.vertices[0, 0] = 5.0


def test_a_block_from_an_obj_file(data_dir):
    block = recode.ConvexBlock.from_file(data_dir / "cube.obj")
    assert block.name.endswith("cube.obj")
    assert block.vertices.shape == (8, 3)
    # The file's cube spans the unit cube, as CUBE_VERTICES do.
    assert np.array_equal(block.vertices.min(axis=0), [0, 0, 0])
    assert np.array_equal(block.vertices.max(axis=0), [1, 1, 1])


def test_primitive_solids_have_the_documented_counts():
    # generators.hpp: a cone has segments + 2 vertices and 2 * segments faces; a box 8 and 12.
    assert recode.cone(1.0, 2.0, 16).vertices.shape == (18, 3)
    assert recode.cone(1.0, 2.0, 16).faces.shape == (32, 3)
    assert recode.box(1, 2, 3).faces.shape == (12, 3)
    assert np.array_equal(recode.box(1, 2, 3).vertices.max(axis=0), [1, 2, 3])


def test_a_compound_places_its_blocks():
    cube = recode.ConvexBlock.from_arrays(CUBE_VERTICES, CUBE_FACES)
    shifted = np.eye(4)
    shifted[:3, 3] = [5, 0, 0]
    shape = recode.CollisionGeometry.compound([cube, (cube, shifted)])
    assert len(shape) == 2
    assert np.array_equal(shape.block_pose(1), shifted)
    assert shape.block(0) is not None
    # The object's world box spans both blocks.
    obj = recode.CollisionObject(shape)
    assert np.array_equal(obj.world_box, [[0, 0, 0], [6, 1, 1]])


def test_an_object_reports_its_pose_and_moves():
    obj = recode.CollisionObject(recode.box(1, 1, 1))
    assert np.array_equal(obj.transform, np.eye(4))
    obj.set_transform(translation=[1, 2, 3])
    assert np.array_equal(obj.transform[:3, 3], [1, 2, 3])
    assert np.array_equal(obj.world_box, [[0, 1, 2], [2, 3, 4]])
