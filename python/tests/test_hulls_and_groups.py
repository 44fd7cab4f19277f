"""Blocks from point sets (convex hulls) and one object per multi-group OBJ file, as robotics and
game collision meshes arrive: the expected corners and boxes come from how the inputs are built
(and from the comments of the data files), not from the module's output."""
import itertools
import pathlib

import numpy as np
import pytest

import recode

MESHES = pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"


def corner_set(points):
    return {tuple(p) for p in np.asarray(points).tolist()}


def test_the_hull_of_a_cube_with_inner_face_and_repeated_points_keeps_its_corners():
    corners = np.array(list(itertools.product([0.0, 2.0], repeat=3)))
    inner = np.array([[1.0, 1.0, 1.0], [0.5, 1.5, 0.25]])
    on_faces = np.array([[1.0, 1.0, 0.0], [2.0, 1.0, 1.0], [0.0, 0.5, 2.0]])
    on_edges = np.array([[1.0, 0.0, 0.0], [2.0, 2.0, 1.5]])
    points = np.vstack([inner, corners, on_faces, corners[:3], on_edges])
    block = recode.ConvexBlock.from_hull(points, name="cube hull")
    assert block.name == "cube hull"
    assert corner_set(block.vertices) == corner_set(corners)
    # A closed triangulated surface of a cube: 12 triangles.
    assert block.faces.shape == (12, 3)


def test_points_in_one_plane_have_no_hull():
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.2, 0]], dtype=float)
    with pytest.raises(recode.MeshError, match="convex hull"):
        recode.ConvexBlock.from_hull(flat, name="flat")


def test_a_plate_like_mesh_is_refused_as_a_block_and_accepted_as_a_hull():
    # data/meshes/plate_like.obj: 8 vertices, 16 faces, an edge used by three triangles.
    plate = MESHES / "plate_like.obj"
    with pytest.raises(recode.MeshError, match="hull"):
        recode.ConvexBlock.from_file(plate)
    block = recode.ConvexBlock.from_file_hull(plate)
    assert block.vertices.shape[1] == 3
    assert 4 <= block.vertices.shape[0] <= 8


def test_a_convex_decomposition_is_one_object_with_a_block_per_group():
    # data/meshes/l_shape_parts.obj's comment: convex_0 [0,1] x [0,1], convex_1 [1,3] x [0,1],
    # convex_2 [0,1] x [1,3], all over z in [0, 1].
    boxes = [([0, 0, 0], [1, 1, 1]), ([1, 0, 0], [3, 1, 1]), ([0, 1, 0], [1, 3, 1])]
    geometry = recode.CollisionGeometry.from_obj_groups(MESHES / "l_shape_parts.obj")
    assert len(geometry) == 3
    for i, (low, high) in enumerate(boxes):
        block = geometry.block(i)
        assert "convex_%d" % i in block.name
        assert np.array_equal(block.vertices.min(axis=0), low)
        assert np.array_equal(block.vertices.max(axis=0), high)


def test_a_cube_touching_only_the_foot_of_the_l_collides_with_its_block_1():
    geometry = recode.CollisionGeometry.from_obj_groups(MESHES / "l_shape_parts.obj", hull=True)
    l_shape = recode.CollisionObject(geometry)
    probe = recode.CollisionObject(recode.box(0.25, 0.25, 0.25), translation=[2.5, 0.5, 0.5])
    result = recode.collide(l_shape, probe, recode.CollisionRequest(pixel_size=0.02))
    assert result.collide
    assert [c.block_a for c in result.contacts] == [1]
    in_notch = recode.CollisionObject(recode.box(0.25, 0.25, 0.25), translation=[2.0, 2.0, 0.5])
    assert not recode.collide(l_shape, in_notch, recode.CollisionRequest(pixel_size=0.02)).collide


def test_a_missing_file_is_file_not_found():
    with pytest.raises(FileNotFoundError):
        recode.CollisionGeometry.from_obj_groups(MESHES / "no_such_file.obj")
    with pytest.raises(FileNotFoundError):
        recode.ConvexBlock.from_file_hull(MESHES / "no_such_file.obj")
