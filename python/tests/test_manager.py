"""CollisionManager: three boxes in a row, the middle one touching both neighbours."""
import numpy as np

import recode


def row_of_boxes():
    """Unit boxes (half extent 0.5) centred at x = 0, 0.9 and 1.8: boxes 0-1 and 1-2 overlap by
    0.1 along x, boxes 0 and 2 are 0.8 apart."""
    manager = recode.CollisionManager()
    objects = [recode.CollisionObject(recode.box(0.5, 0.5, 0.5), translation=[0.9 * i, 0, 0])
               for i in range(3)]
    ids = [manager.add(o) for o in objects]
    return manager, objects, ids


def pairs(contacts):
    return [(c.a, c.b) for c in contacts]


REQUEST = recode.CollisionRequest(pixel_size=0.05)


def test_neighbours_are_in_contact():
    manager, objects, ids = row_of_boxes()
    assert len(manager) == 3 and ids == [0, 1, 2]
    contacts = manager.collide(REQUEST)
    assert pairs(contacts) == [(0, 1), (1, 2)]
    assert manager.stats == {"candidate_pairs": 2, "pairs_in_contact": 2}
    # Each pair's result is collide()'s on the same two objects.
    for c in contacts:
        direct = recode.collide(objects[c.a], objects[c.b], REQUEST)
        assert c.result.interfering_pixels == direct.interfering_pixels > 0
        assert np.array_equal(c.result.contact.points, direct.contact.points)


def test_moving_an_object_in_python_moves_it_in_the_manager():
    manager, objects, ids = row_of_boxes()
    objects[2].set_transform(translation=[5, 0, 0])
    assert pairs(manager.collide(REQUEST)) == [(0, 1)]
    manager.update(ids[2], translation=[0, 0.5, 0])  # now inside boxes 0 and 1 both
    assert pairs(manager.collide(REQUEST)) == [(0, 1), (0, 2), (1, 2)]
    assert np.array_equal(objects[2].transform[:3, 3], [0, 0.5, 0])
    assert manager.object(ids[2]) is objects[2]


def test_the_callback_sees_the_same_pairs():
    manager, _, _ = row_of_boxes()
    seen = []
    assert manager.collide(REQUEST, lambda a, b, result: seen.append((a, b, result.collide))) is None
    assert seen == [(0, 1, True), (1, 2, True)]


def test_removed_ids_are_not_reused():
    manager, objects, ids = row_of_boxes()
    manager.remove(ids[1])
    assert len(manager) == 2
    assert manager.collide(REQUEST) == []
    assert manager.add(objects[1]) == 3
    assert pairs(manager.collide(REQUEST)) == [(0, 3), (2, 3)]


def test_threads_change_nothing_but_the_time():
    manager, objects, ids = row_of_boxes()
    in_turn = manager.collide(recode.CollisionRequest(pixel_size=0.05))
    on_threads = manager.collide(recode.CollisionRequest(pixel_size=0.05, threads=0))
    assert pairs(in_turn) == pairs(on_threads)
    for a, b in zip(in_turn, on_threads):
        assert a.result.interfering_pixels == b.result.interfering_pixels
        assert np.array_equal(a.result.contact.points, b.result.contact.points)
    request = recode.CollisionRequest(threads=4)
    assert request.threads == 4 and "threads=4" in repr(request)
    try:
        recode.CollisionRequest(threads=-1)
    except ValueError as e:
        assert "threads is -1" in str(e)
    else:
        raise AssertionError("threads=-1 was accepted")
