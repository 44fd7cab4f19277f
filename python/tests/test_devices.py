"""device=: collide() and CollisionManager on every device of recode.devices(); an exact one
gives the cpu device's results."""
import numpy as np
import pytest

import recode
from conftest import cones_tip_to_tip

REQUEST = recode.CollisionRequest(pixel_size=0.02, axis="x")


def exact_devices():
    return [d["name"] for d in recode.devices() if d["exact"] and d["available"]]


def test_the_cpu_device_is_always_there_and_exact():
    (cpu,) = [d for d in recode.devices() if d["name"] == "cpu"]
    assert cpu["available"] and cpu["exact"]
    assert {"name", "description", "exact", "available", "missing"} == set(cpu)
    assert cpu["missing"] == ""


def test_a_device_not_built_says_why_and_refuses_with_that_reason():
    for d in recode.devices():
        assert bool(d["missing"]) != d["available"], d
        if not d["available"]:
            a, b = cones_tip_to_tip()
            with pytest.raises(ValueError, match="not in this module: install "):
                recode.collide(a, b, REQUEST, device=d["name"])


@pytest.mark.parametrize("device", exact_devices())
def test_an_exact_device_gives_the_cpu_result(device):
    a, b = cones_tip_to_tip()
    reference = recode.collide(a, b, REQUEST)
    result = recode.collide(a, b, REQUEST, device=device)
    assert reference.collide and result.collide
    assert result.interfering_pixels == reference.interfering_pixels > 0
    assert np.array_equal(result.case_map, reference.case_map)
    assert np.array_equal(result.contact.points, reference.contact.points)


@pytest.mark.parametrize("device", exact_devices())
def test_a_manager_on_an_exact_device_finds_the_cpu_contacts(device):
    results = {}
    for name in ("cpu", device):
        manager = recode.CollisionManager(device=name)
        for i in range(3):
            manager.add(recode.CollisionObject(recode.box(0.5, 0.5, 0.5), translation=[0.9 * i, 0, 0]))
        results[name] = [(c.a, c.b, c.result.interfering_pixels)
                         for c in manager.collide(recode.CollisionRequest(pixel_size=0.05))]
    assert results[device] == results["cpu"] and len(results["cpu"]) == 2


def test_an_unknown_device_is_a_value_error_naming_the_choices():
    a, b = cones_tip_to_tip()
    with pytest.raises(ValueError, match='unknown device "metal"|device "metal"'):
        recode.collide(a, b, REQUEST, device="metal")
    with pytest.raises(ValueError, match='metal'):
        recode.CollisionManager(device="metal")
