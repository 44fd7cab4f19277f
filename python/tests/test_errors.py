"""Bad input: each mistake is a ValueError or TypeError (or FileNotFoundError, KeyError,
IndexError) whose message names the argument, the value and the rule."""
import numpy as np
import pytest

import recode
from conftest import CUBE_FACES, CUBE_VERTICES, cones_tip_to_tip


def block(vertices=CUBE_VERTICES, faces=CUBE_FACES):
    return recode.ConvexBlock.from_arrays(vertices, faces, name="cube")


@pytest.mark.parametrize("vertices, message", [
    (CUBE_VERTICES[:, :2], r"vertices: expected an \(n, 3\) array .*got shape \(8, 2\)"),
    (CUBE_VERTICES.ravel(), r"vertices: .*got shape \(24,\)"),
    (np.where(np.arange(24).reshape(8, 3) == 7, np.nan, CUBE_VERTICES),
     r"vertices\[2, 1\] is nan: coordinates must be finite"),
])
def test_bad_vertices_are_value_errors(vertices, message):
    with pytest.raises(ValueError, match=message):
        block(vertices=vertices)


def test_vertices_that_are_not_numbers_are_type_errors():
    with pytest.raises(TypeError, match="vertices: expected real numbers, got dtype <U1"):
        block(vertices=np.full((8, 3), "a"))
    with pytest.raises(TypeError, match="vertices: expected real numbers, got dtype object"):
        block(vertices=object())


def test_bad_faces_name_the_index_and_the_rule():
    with pytest.raises(TypeError, match="faces: expected integer vertex indices, got dtype float64"):
        block(faces=CUBE_FACES.astype(float))
    too_large = CUBE_FACES.copy()
    too_large[3, 1] = 8
    with pytest.raises(ValueError, match=r"faces\[3, 1\] is 8: there are 8 vertices, so indices "
                                         r"run from 0 to 7"):
        block(faces=too_large)
    negative = CUBE_FACES.copy()
    negative[0, 2] = -1
    with pytest.raises(ValueError, match=r"faces\[0, 2\] is -1: vertex indices count from 0"):
        block(faces=negative)
    with pytest.raises(ValueError, match=r"faces: expected an \(m, 3\) array"):
        block(faces=CUBE_FACES[:, :2])


def test_a_block_that_is_not_a_closed_convex_block_is_a_mesh_error(data_dir):
    assert issubclass(recode.MeshError, ValueError)
    with pytest.raises(recode.MeshError, match="dented_cube.obj: .*not convex"):
        recode.ConvexBlock.from_file(data_dir / "dented_cube.obj")
    # Five sides of the cube: not closed. The message starts with the block's name.
    with pytest.raises(recode.MeshError, match="^cube: "):
        block(faces=CUBE_FACES[:10])


def test_a_missing_file_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such mesh file"):
        recode.ConvexBlock.from_file(tmp_path / "absent.obj")


def test_a_malformed_file_names_its_line(tmp_path):
    path = tmp_path / "broken.obj"
    path.write_text("v 0 0 0\nv 1 0 zero\n")
    with pytest.raises(recode.MeshError, match="broken.obj:2: "):
        recode.ConvexBlock.from_file(path)


def test_primitive_parameters_are_checked():
    with pytest.raises(ValueError, match="segments"):
        recode.cone(1.0, 2.0, 2)


@pytest.mark.parametrize("pose, message", [
    (np.diag([2.0, 1.0, 1.0, 1.0]), "not a rotation: R\\^T R differs from the identity by 3"),
    (np.diag([-1.0, 1.0, 1.0, 1.0]), "is a reflection"),
    (np.eye(3), r"pose: expected a 4 x 4 matrix .*got shape \(3, 3\)"),
    (np.vstack([np.eye(4)[:3], [0, 0, 1, 1]]), r"the last row is \[0, 0, 1, 1\]"),
    (np.full((4, 4), np.inf), "pose\\[0, 0\\] is inf"),
])
def test_poses_must_be_rigid_motions(pose, message):
    with pytest.raises(ValueError, match=message):
        recode.CollisionObject(recode.box(1, 1, 1), pose)


def test_pose_arguments_are_exclusive_and_shaped():
    obj = recode.CollisionObject(recode.box(1, 1, 1))
    with pytest.raises(ValueError, match="not both"):
        obj.set_transform(np.eye(4), translation=[1, 2, 3])
    with pytest.raises(ValueError, match=r"translation: expected 3 numbers, got shape \(2,\)"):
        obj.set_transform(translation=[1, 2])
    with pytest.raises(ValueError, match="rotation: expected a 3 x 3 rotation matrix"):
        obj.set_transform(rotation=np.eye(4))
    with pytest.raises(TypeError, match="shape: expected a ConvexBlock or a CollisionGeometry"):
        recode.CollisionObject("cone")


@pytest.mark.parametrize("arguments, message", [
    ({"mor": "medium"}, "mor: 'medium' is not a MOR mode \\(min, max or full\\)"),
    ({"axis": "w"}, "axis: 'w' is not a view axis \\(x, y, z or auto\\)"),
    ({"pixel_size": -1.0}, "pixel_size: -1.0 is not a positive finite number"),
    ({"pixel_size": float("nan")}, "pixel_size: nan is not a positive finite number"),
    ({"resolution": 0}, "resolution: 0 is outside 1..16384"),
    ({"resolution": 20000}, "resolution: 20000 is outside 1..16384"),
])
def test_bad_requests_are_value_errors(arguments, message):
    with pytest.raises(ValueError, match=message):
        recode.CollisionRequest(**arguments)


def test_a_frame_too_large_is_the_apis_value_error():
    a, b = cones_tip_to_tip()
    # 2.1 world units at 1e-5: about 210,000 pixels a side, over the 16384 a frame may have.
    with pytest.raises(ValueError, match="16384"):
        recode.collide(a, b, recode.CollisionRequest(pixel_size=1e-5))


def test_unknown_ids_and_indices():
    manager = recode.CollisionManager()
    with pytest.raises(KeyError, match="no collision object with id 3"):
        manager.remove(3)
    with pytest.raises(KeyError):
        manager.update(0, translation=[0, 0, 0])
    with pytest.raises(IndexError):
        recode.CollisionGeometry.single(recode.box(1, 1, 1)).block(1)
    with pytest.raises(TypeError, match=r"parts\[1\]: expected a ConvexBlock or a "):
        recode.CollisionGeometry.compound([recode.box(1, 1, 1), "box"])
    with pytest.raises(ValueError, match="at least one block"):
        recode.CollisionGeometry.compound([])
