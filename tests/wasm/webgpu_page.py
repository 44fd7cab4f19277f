"""Writes the WebGPU back end's self-contained check page (backends/webgpu/page): the template
with the WebAssembly module, the two WGSL files (the contract, then the stages: WGSL has no
include) and the replay script inlined, so that the page opens from file://."""

import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
WEBGPU = os.path.join(ROOT, "backends", "webgpu")


def read(*parts):
    with open(os.path.join(*parts), encoding="utf-8") as f:
        return f.read()


def write_page(module_js, out_html):
    wgsl = read(WEBGPU, "shaders", "exact_contract32.wgsl") + "\n" + \
        read(WEBGPU, "shaders", "exact32_webgpu.wgsl")
    if "</script" in wgsl:
        raise ValueError("the WGSL sources would end their script element")
    html = read(WEBGPU, "page", "webgpu_page.html")
    # Replaced one at a time and in this order, so that no inlined text is scanned for the next
    # placeholder.
    head, rest = html.split("@WGSL@")
    middle, tail = rest.split("@MODULE@")
    before, after = tail.split("@REPLAY@")
    page = head + wgsl + middle + read(module_js) + before + \
        read(WEBGPU, "page", "webgpu_replay.js") + after
    with open(out_html, "w", encoding="utf-8") as f:
        f.write(page)
    return len(page)
