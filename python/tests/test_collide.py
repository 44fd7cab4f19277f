"""collide() on the two-cones pair: the result's parts agree with each other and with the CLI."""
import gc
import json
import os
import subprocess

import numpy as np
import pytest

import recode
from conftest import cones_tip_to_tip

# docs/algorithm.md: cases 3-6 are the interfering ones.
INTERFERING_CASES = [3, 4, 5, 6]


def test_the_case_map_is_a_2d_uint8_array_over_the_mor():
    a, b = cones_tip_to_tip()
    result = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02, axis="x"))
    assert result.collide and bool(result)
    (contact,) = result.contacts
    x0, y0, x1, y1 = contact.mor
    case_map = result.case_map
    assert case_map.dtype == np.uint8
    assert case_map.ndim == 2
    assert case_map.shape == (y1 - y0, x1 - x0)
    assert case_map.max() <= 8
    # The map's histogram is the counts, and its interfering cases the interfering pixels.
    assert np.array_equal(np.bincount(case_map.ravel(), minlength=9), contact.case_counts)
    assert np.isin(case_map, INTERFERING_CASES).sum() == result.interfering_pixels
    assert np.array_equal(result.case_counts, contact.case_counts)


def test_contact_points_lie_in_the_contact_box_one_per_pixel():
    a, b = cones_tip_to_tip()
    result = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02, axis="x"))
    points, box = result.contact.points, result.contact.box
    assert points.shape == (result.interfering_pixels, 3)
    assert points.dtype == np.float64
    assert np.all(points >= box[0]) and np.all(points <= box[1])
    # The tips overlap between z = 1.75 and z = 2, on the axis.
    assert 1.75 - 0.02 <= box[0, 2] and box[1, 2] <= 2.0 + 0.02
    assert result.contact.area == pytest.approx(result.interfering_pixels * 0.02 ** 2)
    assert 0.0 < result.contact.max_depth <= 0.25 + 0.02


def test_views_keep_their_result_alive():
    a, b = cones_tip_to_tip()
    points = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02)).contact.points
    case_map = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02)).case_map
    gc.collect()
    expected = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02))
    assert np.array_equal(points, expected.contact.points)
    assert np.array_equal(case_map, expected.case_map)


def test_apart_objects_do_not_collide():
    a, b = cones_tip_to_tip()
    b.set_transform(rotation=np.diag([1.0, -1.0, -1.0]), translation=[0, 0, 4.5])
    result = recode.collide(a, b)
    assert not result.collide and not result
    assert result.interfering_pixels == 0
    assert result.case_map is None
    assert result.contact.box is None
    assert result.contact.points.shape == (0, 3)


def test_the_request_holds_what_it_was_given():
    request = recode.CollisionRequest(pixel_size=0.5, resolution=99, mor="max", axis="y",
                                      contact=False)
    assert (request.pixel_size, request.resolution, request.mor, request.axis,
            request.contact) == (0.5, 99, "max", "y", False)
    request.pixel_size = None
    assert request.pixel_size is None
    assert "resolution=99" in repr(request)


def test_without_contact_passes_there_are_no_points():
    a, b = cones_tip_to_tip()
    result = recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02, contact=False))
    assert result.collide
    assert result.contact.points.shape == (0, 3)
    assert result.contact.box is None
    assert result.contact.pixels == result.interfering_pixels


@pytest.mark.skipif("RECODE_CLI" not in os.environ, reason="RECODE_CLI (the recode program) not given")
def test_the_same_axis_and_pixel_size_as_recode_pair_give_its_pixels():
    # `recode pair` runs the same cones along x at 256 pixels over its window (docs/cli.md);
    # collide() with that axis and pixel size sees the same interfering pixels (docs/api.md).
    cli = json.loads(subprocess.run([os.environ["RECODE_CLI"], "pair", "--json", "--no-timing"],
                                    check=True, capture_output=True, text=True).stdout)
    umin, _, umax, _ = cli["frame"]["window"]
    pixel = (umax - umin) / cli["frame"]["resolution"][0]
    a, b = cones_tip_to_tip()
    result = recode.collide(a, b, recode.CollisionRequest(pixel_size=pixel, axis="x"))
    assert cli["frame"]["axis"] == "x"
    assert result.collide == cli["collide"]
    assert result.interfering_pixels == cli["interfering_pixels"]
