"""Closed meshes (recode.ClosedMesh, recode.torus): made and validated, collided by the layered
pair against convex blocks and closed meshes, with oracles from geometry (a peg through a torus's
hole or tube, a ball inside the tube, a hollow box's cavity and wall, lens and box volumes by
their formulas); batches give recode.collide's layered answers; results pickle; what the layered
pair cannot answer is refused."""
import copy
import math
import pickle

import numpy as np
import pytest

import recode

R, TUBE = 2.0, 0.5  # the torus's radii


def torus():
    return recode.CollisionObject(recode.torus(R, TUBE, segments=96, rings=48))


def peg(radius, x):
    """A peg along z from z = -2 to 2 through (x, 0)."""
    return recode.CollisionObject(recode.cylinder(radius, 4.0, 64), translation=[x, 0.0, -2.0])


def box_mesh(half, name="box"):
    """A box as a ClosedMesh, from the convex block's arrays."""
    block = recode.box(half, half, half)
    return recode.ClosedMesh.from_arrays(block.vertices, block.faces, name)


def hollow_box():
    """A box of half side 2 with a cavity of half side 1.5: the cavity's wall faces inward."""
    outer, inner = recode.box(2, 2, 2), recode.box(1.5, 1.5, 1.5)
    vertices = np.vstack([outer.vertices, inner.vertices])
    faces = np.vstack([outer.faces, inner.faces[:, ::-1] + len(outer.vertices)])
    return recode.ClosedMesh.from_arrays(vertices, faces, "hollow box")


def test_a_closed_mesh_is_validated_and_the_rule_named():
    ring = recode.torus(2.0, 0.5, 16, 8)
    assert isinstance(ring, recode.ClosedMesh) and ring.name == "torus"
    assert ring.vertices.shape == (128, 3) and ring.faces.shape == (256, 3)
    same = recode.ClosedMesh.from_arrays(ring.vertices, ring.faces, "ring")
    assert np.array_equal(same.faces, ring.faces)
    with pytest.raises(recode.MeshError, match=r"^ring: .*edge"):
        recode.ClosedMesh.from_arrays(ring.vertices, ring.faces[:-1], "ring")  # a hole
    with pytest.raises(recode.MeshError, match=r"^ring: Euler characteristic"):  # no convex block
        recode.ConvexBlock.from_arrays(ring.vertices, ring.faces, "ring")
    g = recode.CollisionGeometry.closed(ring)
    assert g.closed_mesh is ring or g.closed_mesh.name == "torus"
    assert len(g) == 1 and recode.CollisionGeometry.single(recode.box(1, 1, 1)).closed_mesh is None
    with pytest.raises(ValueError, match="is a closed mesh, not convex blocks"):
        g.block(0)
    with pytest.raises(TypeError, match="a ClosedMesh cannot be part of a compound"):
        recode.CollisionGeometry.compound([recode.box(1, 1, 1), ring])


def test_a_peg_through_the_hole_is_apart_one_through_the_tube_interferes():
    ring = torus()
    hole = recode.collide(ring, peg(0.5, 0.0))
    assert not hole and hole.layered is not None
    assert hole.layered.overlap_volume == 0.0 and hole.layered.containment == "none"
    assert hole.layered.layers == (0, 1)  # seen along z, the hole holds no torus
    tube = recode.collide(ring, peg(0.2, R), recode.CollisionRequest(axis="x"))
    assert tube and tube.layered.collide and tube.layered.frame.axis == "x"
    (contact,) = tube.contacts
    assert contact.layered and contact.case_map.shape == (0, 0)
    assert contact.interfering_pixels == tube.interfering_pixels == tube.layered.interfering_pixels
    assert tube.layered.layers == (2, 1)  # along x, twice through the torus (an annulus)
    assert tube.layered.passes == 4 + 2 * (2 + 1)
    # The per-pixel maps: over the MOR, interfering where the overlap has length (or touches).
    x0, y0, x1, y1 = tube.layered.mor
    assert tube.layered.overlap_steps.shape == (y1 - y0, x1 - x0)
    assert tube.layered.interferes.sum() == tube.interfering_pixels
    assert np.all(tube.layered.interferes[tube.layered.overlap_steps > 0] == 1)
    # Every contact point lies in the tube and in the peg, within a pixel.
    pixel = tube.layered.frame.pixel_size
    p = tube.contact.points
    assert len(p) > 0
    assert np.all(np.hypot(np.hypot(p[:, 0], p[:, 1]) - R, p[:, 2]) <= TUBE + pixel)
    assert np.all(np.hypot(p[:, 0] - R, p[:, 1]) <= 0.2 + pixel)


def test_a_ball_inside_the_tube_is_contained_with_its_own_volume():
    ball = recode.CollisionObject(recode.sphere(0.3, 32, 16), translation=[0.0, R, 0.0])
    inside = recode.collide(ball, torus())
    assert inside.layered.containment == "a_inside_b"
    assert recode.collide(torus(), ball).layered.containment == "b_inside_a"
    # The overlap is the ball's polyhedron: its exact volume (the divergence theorem over its
    # faces) within 2 %, about a pixel along the rim of its projection.
    v = ball.geometry.block(0).vertices[ball.geometry.block(0).faces.astype(np.int64)]
    volume = np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6
    assert inside.layered.overlap_volume == pytest.approx(volume, rel=0.02)


def test_a_ball_in_the_cavity_is_apart_one_in_the_wall_is_contained():
    hollow = recode.CollisionObject(hollow_box())
    cavity = recode.collide(recode.CollisionObject(recode.sphere(1.0)), hollow)
    assert not cavity and cavity.layered.containment == "none" and cavity.layered.layers[1] == 2
    wall = recode.collide(recode.CollisionObject(recode.sphere(0.2), translation=[1.75, 0, 0]),
                          hollow)
    assert wall and wall.layered.containment == "a_inside_b"


def test_volumes_match_the_lens_and_box_formulas():
    # Unit balls with centres 1 apart: pi (4r + d)(2r - d)^2 / 12. Within 2 % (tessellation and
    # pixels, docs/api.md).
    a = recode.CollisionObject(recode.ClosedMesh.from_arrays(
        recode.sphere(1.0, 96, 48).vertices, recode.sphere(1.0, 96, 48).faces, "ball"))
    b = recode.CollisionObject(recode.sphere(1.0, 96, 48), translation=[1, 0, 0])
    assert recode.collide(a, b).layered.overlap_volume == pytest.approx(5 * math.pi / 12, rel=0.02)
    # Boxes of half side 1 offset (0.5, 0.3, 0.2): 1.5 x 1.7 x 1.8 within 1 % (a pixel along each
    # side of the projected overlap).
    boxes = recode.collide(recode.CollisionObject(box_mesh(1.0)),
                           recode.CollisionObject(box_mesh(1.0, "b"), translation=[0.5, 0.3, 0.2]))
    assert boxes.layered.overlap_volume == pytest.approx(1.5 * 1.7 * 1.8, rel=0.01)
    assert boxes.layered.containment == "none"


def test_batches_give_the_layered_answers_of_collide():
    ring, stick = torus(), peg(0.2, 0.0)
    poses = np.tile(np.eye(4), (7, 1, 1))
    poses[:, 0, 3] = np.linspace(0.0, 3.0, 7)  # from the hole across the tube and out
    poses[:, 2, 3] = -2.0
    batch = recode.collide_poses(ring, stick, poses_b=poses)
    assert batch.layered.all()
    for i, pose in enumerate(poses):
        stick.set_transform(pose)
        one = recode.collide(ring, stick)
        assert batch.collide[i] == one.collide
        assert batch.overlap_volume[i] == one.layered.overlap_volume
        assert recode.CONTAINMENT[batch.containment[i]] == one.layered.containment
        assert tuple(batch.layers[i]) == one.layered.layers
        assert batch.passes[i] == one.layered.passes
    assert batch.collide.any() and not batch.collide.all()
    # A convex pair in the same batch: not layered, no volume, no containment.
    objects = [ring, peg(0.2, R), recode.CollisionObject(recode.box(1, 1, 1), translation=[R, 0, 0])]
    mixed = recode.collide_batch(objects, np.array([[0, 1], [1, 2]]))
    assert list(mixed.layered) == [True, False] and list(mixed.collide) == [True, True]
    assert mixed.overlap_volume[0] > 0 and np.isnan(mixed.overlap_volume[1])
    assert mixed.containment[1] == -1 and list(mixed.layers[1]) == [0, 0]


def test_closed_meshes_and_layered_results_pickle():
    ring = recode.torus(R, TUBE, 32, 16)
    assert pickle.loads(pickle.dumps(ring)).faces.tolist() == ring.faces.tolist()
    assert copy.deepcopy(ring) is ring
    obj = recode.CollisionObject(ring, translation=[0.1, 0, 0])
    back = pickle.loads(pickle.dumps(obj))
    assert back.geometry.closed_mesh is not None
    result = recode.collide(obj, peg(0.2, R))
    again = pickle.loads(pickle.dumps(result))
    assert again.layered.overlap_volume == result.layered.overlap_volume
    assert again.layered.containment == result.layered.containment
    assert again.layered.layers == result.layered.layers
    assert again.layered.passes == result.layered.passes
    assert again.layered.frame.width == result.layered.frame.width
    assert np.array_equal(again.layered.overlap_steps, result.layered.overlap_steps)
    assert again.contacts[0].layered
    assert recode.collide(back, peg(0.2, R)).layered.overlap_volume == result.layered.overlap_volume


def test_what_the_layered_pair_cannot_answer_is_refused():
    with pytest.raises(ValueError, match=r"mode adaptive applies to pairs of convex blocks.*"
                                         r"reference mode only"):
        recode.collide(torus(), peg(0.2, R), recode.CollisionRequest(mode="adaptive"))
    two = recode.CollisionObject(recode.CollisionGeometry.compound(
        [recode.box(0.2, 0.2, 0.2), (recode.box(0.2, 0.2, 0.2), np.eye(4))], name="two cubes"))
    with pytest.raises(ValueError, match=r"compound 'two cubes' of 2 blocks.*one solid on each"):
        recode.collide(two, torus())
