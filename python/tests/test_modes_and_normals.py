"""The request's `normal` and `mode`: contact normals and penetration depth per block contact,
and the adaptive and conservative pair modes (docs/algorithm.md, "Beyond the paper")."""
import numpy as np
import pytest

import recode
from conftest import CUBE_FACES, CUBE_VERTICES


def unit_cubes(offset):
    cube = recode.ConvexBlock.from_arrays(CUBE_VERTICES, CUBE_FACES)
    return recode.CollisionObject(cube), recode.CollisionObject(cube, translation=offset)


@pytest.mark.parametrize("axis", ["auto", "x", "y", "z"])
def test_the_normal_of_a_slab_overlap_is_its_thin_side(axis):
    # The cubes overlap in the box [0.9, 1] x [0.2, 1] x [0.1, 1]: thinnest along x, 0.1 wide,
    # so B leaves A soonest along +x, whatever axis the pair is drawn along.
    a, b = unit_cubes([0.9, 0.2, 0.1])
    pixel = 0.02
    result = recode.collide(a, b, recode.CollisionRequest(pixel_size=pixel, axis=axis,
                                                          normal=True))
    (contact,) = result.contacts
    normal = contact.contact.normal
    assert normal.shape == (3,) and normal.dtype == np.float64
    assert np.linalg.norm(normal) == pytest.approx(1.0)
    assert np.degrees(np.arccos(min(1.0, normal @ [1.0, 0.0, 0.0]))) < 5.0
    assert contact.contact.penetration_depth == pytest.approx(0.1, abs=pixel)
    # Normals of different block pairs do not add up: the merged region has none.
    assert result.contact.normal is None and result.contact.penetration_depth is None


def test_without_the_request_there_is_no_normal():
    a, b = unit_cubes([0.9, 0.2, 0.1])
    (contact,) = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02)).contacts
    assert contact.contact.normal is None and contact.contact.penetration_depth is None


def test_a_sliver_thinner_than_a_pixel_is_seen_by_the_adaptive_and_conservative_modes():
    # The cubes overlap by 0.001 along x; drawn along z with pixels of 0.05, no pixel centre
    # falls in that strip, so the paper's algorithm misses the contact.
    a, b = unit_cubes([0.999, 0.2, 0.1])
    request = recode.CollisionRequest(pixel_size=0.05, axis="z")
    assert request.mode == "reference"
    assert not recode.collide(a, b, request)

    request.mode = "adaptive"
    adaptive = recode.collide(a, b, request)
    assert adaptive.collide and adaptive.apart_at_limit == 0
    (contact,) = adaptive.contacts
    assert contact.refine_level >= 1
    assert contact.frame.pixel_size < 0.05

    conservative = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.05, axis="z",
                                                                mode="conservative"))
    assert conservative.collide
    assert conservative.contacts[0].refine_level == 0


def test_the_modes_agree_on_clear_cases():
    for offset, expected in (([0.5, 0.5, 0.5], True), ([1.5, 0.0, 0.0], False)):
        a, b = unit_cubes(offset)
        for mode in ("reference", "adaptive", "conservative", "skip-apart"):
            request = recode.CollisionRequest(pixel_size=0.05, mode=mode)
            assert recode.collide(a, b, request).collide == expected, (offset, mode)


def test_the_skip_apart_mode_draws_no_pair_it_proves_apart():
    # Two balls of radius 0.5 (hulls of 400 points), centres 1.2 apart along (1, 1, 1): their
    # boxes overlap, the balls stay 0.2 apart. Proven apart: nothing drawn, where the reference
    # draws the pair. Overlapping cubes are drawn, with the reference's contact.
    k = np.arange(400) + 0.5
    polar, azimuth = np.arccos(1 - 2 * k / 400), np.pi * (1 + 5 ** 0.5) * k
    points = 0.5 * np.stack([np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar),
                             np.cos(polar)], axis=1)
    ball = recode.ConvexBlock.from_hull(points)
    a = recode.CollisionObject(ball)
    b = recode.CollisionObject(ball, translation=np.full(3, 1.2 / 3 ** 0.5))
    apart = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.05, mode="skip-apart"))
    assert (apart.block_pairs_skipped, apart.block_pairs_drawn) == (1, 0)
    assert not apart.collide
    assert recode.collide(a, b, recode.CollisionRequest(pixel_size=0.05)).block_pairs_drawn == 1
    a, b = unit_cubes([0.9, 0.2, 0.1])
    skip = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.05, mode="skip-apart"))
    reference = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.05))
    assert (skip.block_pairs_skipped, skip.block_pairs_drawn) == (0, 1)
    assert skip.interfering_pixels == reference.interfering_pixels > 0


def test_an_unknown_mode_is_refused_with_the_choices():
    with pytest.raises(ValueError, match="mode: 'fast' is not a pair mode "
                                         r"\(reference, adaptive, conservative or skip-apart\)"):
        recode.CollisionRequest(mode="fast")
    request = recode.CollisionRequest()
    with pytest.raises(ValueError, match="mode: 'Adaptive'"):
        request.mode = "Adaptive"
    assert "normal=False, mode='reference'" in repr(request)
