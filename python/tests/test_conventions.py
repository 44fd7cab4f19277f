"""Python conventions: every class's repr says what the object holds, and the C++ API's errors
arrive as Python exceptions carrying its message."""
import re

import pytest

import recode
from conftest import cones_tip_to_tip


def contact_result():
    a, b = cones_tip_to_tip()
    return recode.collide(a, b, recode.CollisionRequest(pixel_size=0.02, axis="x", normal=True))


def test_no_class_has_the_default_repr():
    # object.__repr__ ("<recode.X object at 0x...>") says nothing of what an object holds.
    a, b = cones_tip_to_tip()
    manager = recode.CollisionManager()
    manager.add(a)
    manager.add(b)
    result = contact_result()
    samples = [recode.box(1, 1, 1), recode.CollisionGeometry.single(recode.box(1, 1, 1)), a,
               recode.CollisionRequest(), result, result.contact, result.contacts[0],
               result.contacts[0].frame, manager, manager.collide()[0]]
    classes = {type(s) for s in samples}
    module_classes = {v for v in vars(recode).values()
                      if isinstance(v, type) and not issubclass(v, BaseException)}
    # Classes another part of the module adds are sampled by their own tests; these are all of
    # the collision API's.
    assert classes <= module_classes
    for sample in samples:
        assert " object at 0x" not in repr(sample), type(sample).__name__


def test_reprs_show_the_contents():
    a, b = cones_tip_to_tip()
    assert repr(a) == "<recode.CollisionObject 'cone' at translation=[0.0, 0.0, 0.0]>"
    assert repr(b) == ("<recode.CollisionObject 'cone' at translation=[0.0, 0.0, 3.75], "
                       "rotated 180.0 deg about [1.0, 0.0, 0.0]>")
    parts = [recode.box(1, 1, 1, name=f"b{i}") for i in range(6)]
    assert repr(recode.CollisionGeometry.compound(parts)) == (
        "<recode.CollisionGeometry 6 blocks: 'b0', 'b1', 'b2', 'b3', ... (2 more)>")
    result = contact_result()
    contact = result.contacts[0]
    frame = contact.frame
    assert repr(frame).startswith(
        f"<recode.Frame axis='x' {frame.width} x {frame.height} pixels of 0.02 over window=(")
    assert repr(contact) == (
        f"<recode.BlockContact blocks 0, 0: {contact.interfering_pixels} interfering pixels, "
        f"axis x, frame {frame.width} x {frame.height}, mor={contact.mor}>")
    region = repr(contact.contact)
    assert region.startswith(f"<recode.ContactRegion {contact.contact.pixels} pixels, area=")
    assert "box=[[" in region and "normal=[1.0, 0.0, 0.0]" in region
    apart = recode.collide(recode.CollisionObject(recode.box(1, 1, 1)),
                           recode.CollisionObject(recode.box(1, 1, 1), translation=[5, 0, 0]))
    assert repr(apart.contact) == "<recode.ContactRegion empty>"
    manager = recode.CollisionManager()
    for obj in cones_tip_to_tip():
        manager.add(obj)
    assert repr(manager) == ("<recode.CollisionManager 2 objects; last collide(): 0 candidate "
                             "pairs, 0 in contact>")
    manager.collide()
    assert repr(manager).endswith("last collide(): 1 candidate pairs, 1 in contact>")


def test_a_block_index_past_the_count_is_an_index_error_naming_the_count():
    g = recode.CollisionGeometry.single(recode.box(1, 1, 1))
    with pytest.raises(IndexError, match="^index 1 is out of range: the geometry has 1 block$"):
        g.block(1)
    with pytest.raises(IndexError, match="the geometry has 1 block"):
        g.block_pose(3)


def test_the_apis_invalid_argument_keeps_its_message():
    # A frame over the limit: recode::collide's std::invalid_argument, word for word.
    a, b = cones_tip_to_tip()
    with pytest.raises(ValueError) as caught:
        recode.collide(a, b, recode.CollisionRequest(pixel_size=1e-5))
    assert re.search(r"\b16384\b", str(caught.value))
    assert not str(caught.value).startswith(("std::", "Unable to"))


def test_a_mesh_file_that_is_a_directory_is_a_mesh_error_with_the_readers_message(tmp_path):
    folder = tmp_path / "cube.obj"
    folder.mkdir()
    with pytest.raises(recode.MeshError, match=re.escape(str(folder)) + ": "):
        recode.ConvexBlock.from_file(folder)


def test_an_unknown_device_names_the_choices():
    a, b = cones_tip_to_tip()
    names = ", ".join(d["name"] for d in recode.devices())
    with pytest.raises(ValueError, match=re.escape(f'unknown device "metal" (devices: {names})')):
        recode.collide(a, b, device="metal")
