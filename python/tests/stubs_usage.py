"""A program as a user writes one, type-checked (not run) by mypy --strict against the stubs in
test_stubs.py: every call of the API it makes must check."""
import numpy as np
import recode
import recode.conformance as rc

cone = recode.cone(1.0, 2.0, 32)
a = recode.CollisionObject(cone)
b = recode.CollisionObject(cone, rotation=np.diag([1.0, -1.0, -1.0]), translation=[0.0, 0.0, 3.75])
request = recode.CollisionRequest(pixel_size=0.02, axis="x")
request.mor = "max"
result = recode.collide(a, b, request, device="vulkan-compute")
if result:
    pixels: int = result.interfering_pixels
    box = result.contact.box
    for c in result.contacts:
        print(c.frame.width, c.case_map.shape, c.contact.points)
devices = [d["name"] for d in recode.devices() if d["available"]]
m = recode.CollisionManager(device="cpu")
i = m.add(a)
m.update(i, translation=[1.0, 0.0, 0.0])
for contact in m.collide(request):
    print(contact.a, contact.result.case_counts)
m.collide(request, lambda x, y, r: None)
print(m.stats["candidate_pairs"])
batch = recode.collide_batch([a, b], np.array([[0, 1]]), request=request)
print(batch.collide, len(batch))
for v in rc.vectors():
    r = rc.check(v, v.depth, v.stencil)
    print(r.passed, r.stage, [e.why for e in r.explained])
report = rc.run(lambda w, h, cmds: (np.zeros((h, w)), np.zeros((h, w))))
print(report.to_junit(), report.counts)
g = recode.CollisionGeometry.compound([cone, (cone, np.eye(4))])
print(len(g), g.block(0).name)
ring = recode.torus(2.0, 0.5)
shell = recode.CollisionGeometry.closed(recode.ClosedMesh.from_arrays(ring.vertices, ring.faces, "ring"))
hit = recode.collide(recode.CollisionObject(ring), recode.CollisionObject(shell))
if hit.layered is not None:
    volume: float = hit.layered.overlap_volume
    print(volume, hit.layered.containment, hit.layered.layers, hit.layered.overlap_steps.shape)
print(batch.overlap_volume, recode.CONTAINMENT[int(batch.containment[0])], batch.layers)
