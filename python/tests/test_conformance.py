"""recode.conformance: the conformance suite through the Python API.

The NumPy example back end (examples/backends/numpy_backend.py) run in this process passes
every golden vector; its copy with the top-left fill rule (numpy_backend_top_left.py) fails,
named `top_left_fill`, at the coverage stage, and the JUnit and JSON reports written from
Python equal those of `recode conform --exec` on the same copy ($RECODE_CLI, run once, beside
the in-process run). check() gives one vector's facts; bad input and a back end that breaks are
Python exceptions or the report's error, as in the program.
"""
import importlib.util
import json
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import recode
from recode import conformance

ROOT = pathlib.Path(__file__).resolve().parents[2]
BACKENDS = ROOT / "examples" / "backends"
GOLDEN = ROOT / "data" / "golden"
TOP_LEFT_COMMAND = f"{sys.executable} {BACKENDS / 'numpy_backend_top_left.py'}"


def fresh_module(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def numpy_backend():
    """A private copy of examples/backends/numpy_backend.py (not in sys.modules)."""
    return fresh_module("numpy_backend", BACKENDS / "numpy_backend.py")


def top_left_backend():
    """numpy_backend_top_left.py as it is: it imports numpy_backend and swaps its fill rule, so
    it is given a private copy to patch, which is returned (the one `import numpy_backend`
    would give is left alone)."""
    base = numpy_backend()
    saved = sys.modules.get("numpy_backend")
    sys.modules["numpy_backend"] = base
    try:
        fresh_module("numpy_backend_top_left", BACKENDS / "numpy_backend_top_left.py")
    finally:
        if saved is None:
            del sys.modules["numpy_backend"]
        else:
            sys.modules["numpy_backend"] = saved
    return base


def as_backend(module):
    """The example's rasterizer as the callable run() takes."""
    def backend(width, height, commands):
        _, result = module.run_request(
            {"id": 0, "width": width, "height": height, "commands": commands})
        if isinstance(result, str):
            raise conformance.Refused(result)
        return result.depth, result.stencil
    return backend


@pytest.fixture(scope="module")
def vectors():
    return conformance.vectors()


@pytest.fixture(scope="module")
def by_name(vectors):
    return {v.name: v for v in vectors}


@pytest.fixture(scope="module")
def top_left():
    """The top-left copy run in this process and, at the same time, by `recode conform`."""
    junit = pathlib.Path(os.environ.get("TMPDIR", "/tmp")) / f"recode-conformance-{os.getpid()}.xml"
    program = subprocess.Popen(
        [os.environ["RECODE_CLI"], "conform", "--exec", TOP_LEFT_COMMAND, "--json",
         "--junit", str(junit)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        module = top_left_backend()
        report = conformance.run(as_backend(module), name=module.NAME)  # golden_dir()
        stdout, stderr = program.communicate(timeout=300)
        assert program.returncode == 2, stderr
        written = junit.read_text()
    finally:
        program.kill()
        junit.unlink(missing_ok=True)
    return {"module": module, "report": report, "json": json.loads(stdout), "junit": written}


def test_the_vectors_are_the_golden_files(vectors, by_name):
    files = sorted(p.relative_to(GOLDEN).as_posix() for p in GOLDEN.rglob("*.json"))
    assert [v.name for v in vectors] == files
    assert pathlib.Path(conformance.golden_dir()) == GOLDEN
    v = by_name["kit/slivers_3.json"]
    document = json.loads((GOLDEN / v.name).read_text())
    assert (v.width, v.height, v.description) == (
        document["width"], document["height"], document["description"])
    assert v.commands == document["commands"]
    assert v.depth.shape == (v.height, v.width) and v.depth.dtype == np.uint32
    assert v.stencil.dtype == np.uint8 and not v.depth.flags.writeable
    assert v.depth.tolist() == document["expected"]["depth"]  # rows, the bottom one first
    assert v.stencil.tolist() == document["expected"]["stencil"]
    assert json.loads(v.to_json()) == document
    assert repr(v) == "<recode.conformance.Vector kit/slivers_3.json: 24 x 16, 6 commands>"


def test_any_directory_and_its_errors(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "one.json").write_text((GOLDEN / "fill_square.json").read_text())
    (tmp_path / "two.json").write_text((GOLDEN / "fill_fan.json").read_text())
    assert [v.name for v in conformance.vectors(tmp_path)] == ["a/one.json", "two.json"]
    assert conformance.Vector.from_file(tmp_path / "two.json").name == "two.json"
    with pytest.raises(FileNotFoundError, match=r"nowhere: not a directory"):
        conformance.vectors(tmp_path / "nowhere")
    (tmp_path / "bad.json").write_text('{"format": "recode-golden-1", "width": 0}')
    with pytest.raises(conformance.FormatError, match=r"bad\.json"):
        conformance.vectors(tmp_path)
    assert issubclass(conformance.FormatError, ValueError)


def test_the_numpy_back_end_passes_every_vector_in_process(vectors):
    module = numpy_backend()
    report = conformance.run(as_backend(module), vectors, name=module.NAME)
    assert report.passed, report.text()
    assert report.counts["passed"] == len(vectors) and not report.failures
    assert report.summary() == f"{len(vectors)} vectors: {len(vectors)} passed, 0 failed\n"
    assert report.behaves_like == [] and report.verdict == ""


def test_the_top_left_copy_fails_named_at_the_coverage_stage(top_left):
    report = top_left["report"]
    assert not report.passed and report.error is None
    assert report.behaves_like == ["top_left_fill"]
    assert report.verdict.startswith("behaves like: ")
    assert report.verdict.endswith("(top_left_fill)")
    assert len(report.failures) == report.counts["failed"] > 0
    for v in report.failures:
        assert v.stage == "coverage", v
        assert v.contract_section == "rasterization.md section 4 (coverage and the fill rule)"
        assert v.behaves_like == ["top_left_fill"]
        assert v.api["forbidden_pixels"] == 0 and "the tie rule" in v.api["freedoms"]
        assert v.explained and all(e.reading == "top_left_fill" for e in v.explained)
    text = report.text()
    assert text.startswith(f"recode conform: back end {top_left['module'].NAME}, "
                           f"{len(report.vectors)} golden vectors under {GOLDEN}\n")
    assert "\nFailures explained:\n" in text and text.endswith(report.summary())
    assert str(report) == text


def normalised_junit(text):
    return re.sub(r' time="[^"]*"', ' time="T"', text)


def without_seconds(document):
    document = dict(document)
    document["results"] = [{k: x for k, x in r.items() if k != "seconds"}
                           for r in document["results"]]
    return document


def test_the_reports_written_from_python_equal_the_programs(top_left):
    report = top_left["report"]
    assert normalised_junit(report.to_junit()) == normalised_junit(top_left["junit"])
    assert without_seconds(json.loads(report.to_json(exec=TOP_LEFT_COMMAND))) == \
        without_seconds(top_left["json"])
    assert "<html" in report.to_html() and "kit/slivers_3.json,coverage\n" in report.to_baseline()


def test_check_gives_one_vectors_facts(top_left, by_name):
    vector = by_name["kit/slivers_3.json"]
    module = top_left["module"]
    depth, stencil = as_backend(module)(vector.width, vector.height, vector.commands)
    result = conformance.check(vector, depth, stencil)
    assert not result.passed and result.status == "FAIL"
    assert (result.stage, result.refused) == ("coverage", None)
    assert "top_left_fill" in result.behaves_like
    assert result.bad_pixel_count == len(result.bad_pixels) > 0
    bad = result.bad_pixels
    assert (bad["got_depth"] == depth[bad["y"], bad["x"]]).all()
    assert (bad["expected_stencil"] == vector.stencil[bad["y"], bad["x"]]).all()
    assert result.depth_pixel_count == int((bad["got_depth"] != bad["expected_depth"]).sum())
    first = result.explained[0]
    assert (first.x, first.y) == (int(bad["x"][0]), int(bad["y"][0]))
    assert first.stage == "coverage" and first.reading == "top_left_fill"
    assert first.history.startswith(f"pixel ({first.x}, {first.y}): ")
    assert first.api_allowed and "the tie rule" in first.api_freedoms and first.api_clause is None
    assert first.api.startswith("within the APIs' freedom")
    # The same facts as the program's, which ran it among all the vectors.
    [entry] = [r for r in top_left["json"]["results"] if r["file"] == vector.name]
    assert {k: x for k, x in result.to_json().items() if k != "seconds"} == \
        {k: x for k, x in entry.items() if k != "seconds"}
    in_run = [v for v in top_left["report"].vectors if v.name == vector.name][0]
    assert str(result) == str(in_run) == result.text(4)
    assert str(result).startswith("  FAIL  kit/slivers_3.json: ")
    assert "stage: coverage, rasterization.md section 4" in str(result)
    # The answer flat, bottom row first, is the same answer; the expected one passes.
    assert conformance.check(vector, depth.ravel(), stencil.ravel()).bad_pixel_count == \
        result.bad_pixel_count
    passed = conformance.check(vector, vector.depth, vector.stencil.tolist())
    assert passed.passed and passed.stage is None and str(passed) == "  pass  kit/slivers_3.json\n"


def test_bad_pixels_are_packed_records_of_the_documented_fields(top_left, by_name):
    vector = by_name["kit/slivers_3.json"]
    depth, stencil = as_backend(top_left["module"])(vector.width, vector.height, vector.commands)
    bad = conformance.check(vector, depth, stencil).bad_pixels
    assert bad.dtype == np.dtype([("x", "<i4"), ("y", "<i4"), ("expected_depth", "<u4"),
                                  ("got_depth", "<u4"), ("expected_stencil", "u1"),
                                  ("got_stencil", "u1")])
    assert bad.dtype.itemsize == 18 and len(bad) > 0
    assert (bad["expected_depth"] == vector.depth[bad["y"], bad["x"]]).all()
    assert (bad["got_stencil"] == stencil[bad["y"], bad["x"]]).all()
    none = conformance.check(vector, vector.depth, vector.stencil).bad_pixels
    assert none.dtype == bad.dtype and none.shape == (0,)


def test_a_refusal(by_name):
    result = conformance.check(by_name["fill_square.json"], refused="no draws today")
    assert (result.passed, result.stage, result.refused) == (False, "validation", "no draws today")
    assert "the back end refused the stream: no draws today" in str(result)


@pytest.mark.parametrize("depth, error, message", [
    (np.zeros((16, 23)), TypeError, r"^depth: expected integers, got dtype float64$"),
    (np.zeros((16, 23), dtype=int), ValueError,
     r"^depth: expected shape \(16, 24\) \(height, width; row 0 the bottom row\) or \(384,\), "
     r"got \(16, 23\)$"),
    (np.full((16, 24), 1 << 24), ValueError,
     r"^depth\[0, 0\]: expected an integer in 0\.\.16777215, got 16777216$"),
    (np.full(384, -1), ValueError, r"^depth\[0\]: expected an integer in 0\.\.16777215, got -1$"),
    ("deep", TypeError, r"^depth: expected integers, got dtype <U4$"),
])
def test_bad_answers_name_the_buffer(by_name, depth, error, message):
    vector = by_name["kit/slivers_3.json"]
    with pytest.raises(error, match=message):
        conformance.check(vector, depth, vector.stencil)


def test_a_back_end_that_breaks(by_name):
    two = [by_name["fill_square.json"], by_name["fill_fan.json"]]
    report = conformance.run(lambda w, h, c: (np.zeros(w, int), np.zeros(h, int)), two)
    assert (report.error_kind, report.error_vector) == ("malformed", "fill_square.json")
    assert report.error.startswith("fill_square.json: request 1: answer.depth: expected shape")
    assert not report.passed and '<error type="malformed"' in report.to_junit()
    report = conformance.run(lambda w, h, c: None, two, name="none")
    assert report.error == "fill_square.json: request 1: the back end returned None, " \
                           "expected (depth, stencil)"

    def refuses(width, height, commands):
        raise conformance.Refused(f"{len(commands)} commands are too many")
    report = conformance.run(refuses, two)
    assert report.backend == "refuses" and report.error is None
    assert [v.refused for v in report.vectors][0].endswith("commands are too many")
    assert {v.stage for v in report.vectors} == {"validation"}

    def raises(width, height, commands):
        raise ZeroDivisionError("a bug in the back end")
    with pytest.raises(ZeroDivisionError, match="a bug in the back end"):
        conformance.run(raises, two)
    with pytest.raises(TypeError, match="backend: expected a callable"):
        conformance.run(3, two)


def test_a_baseline(by_name, tmp_path):
    vector = by_name["fill_square.json"]
    refuses = lambda w, h, c: (_ for _ in ()).throw(conformance.Refused("no"))  # noqa: E731
    report = conformance.run(refuses, [vector], baseline={vector.name: "validation"})
    assert report.passed and report.vectors[0].status == "expected failure"
    (tmp_path / "baseline.txt").write_text(f"{vector.name},coverage\n")
    report = conformance.run(refuses, [vector], baseline=tmp_path / "baseline.txt")
    assert not report.passed and report.vectors[0].baseline_stage == "coverage"
    with pytest.raises(ValueError, match=r"baseline\[fill_square\.json\]: unknown stage 'edges'"):
        conformance.run(refuses, [vector], baseline={vector.name: "edges"})
    (tmp_path / "bad.txt").write_text("fill_square.json\n")
    with pytest.raises(RuntimeError, match=r"bad\.txt:1: \"fill_square\.json\" has no stage"):
        conformance.run(refuses, [vector], baseline=tmp_path / "bad.txt")


def test_the_module_is_a_submodule():
    assert recode.conformance is conformance
    assert issubclass(conformance.Refused, Exception)


def test_reprs_show_the_contents(by_name):
    vector = by_name["fill_square.json"]
    result = conformance.check(vector, refused="no")
    assert repr(result) == "<recode.conformance.VectorResult fill_square.json: FAIL, refused, " \
                           "stage validation>"
    depth = np.array(vector.depth)
    depth[0, 0] -= 1
    result = conformance.check(vector, depth, vector.stencil)
    assert repr(result).startswith(
        "<recode.conformance.VectorResult fill_square.json: FAIL, 1 bad pixels, stage ")
    assert repr(result.explained[0]).startswith("<recode.conformance.Explanation pixel (0, 0): ")
    report = conformance.run(lambda w, h, c: (vector.depth, vector.stencil), [vector], name="me")
    assert repr(report) == "<recode.conformance.Report me: 1 vectors, 1 passed, 0 failed>"
