"""The type stubs (python/recode-stubs) against the compiled module, so that they cannot drift:
every public name of the module is in the stubs and every name of the stubs in the module, for
functions and for each class's members; each function's and method's parameters have the names
the module's signatures give; a property is writable in the stubs (a plain annotation or a
setter) exactly when it is in the module. A submodule of the module is a stub file of its name
beside __init__.pyi, checked the same way. And mypy (Debian's `mypy`, scripts/setup.sh) accepts the
stubs and a typical program with --strict, and reports a program's wrong calls."""
import ast
import importlib.util
import os
import pathlib
import re
import shutil
import subprocess
import sys
import types

import pytest

import recode

STUBS = pathlib.Path(os.environ.get("RECODE_STUBS_DIR",
                                    pathlib.Path(__file__).resolve().parents[1] / "recode-stubs"))
# Names the module has and the stubs do not yet, as "name" or "Class.member" (dotted with the
# submodule's name for a submodule's: "conformance.check"; a submodule's name alone for one
# without a stub file yet). Whoever adds a name to the module
# adds it to the stubs; this list is for the time between, and is empty when they agree.
PENDING = set()
# Dunder methods compared; object's own (__repr__, __eq__, ...) are left out.
DUNDERS = {"__init__", "__len__", "__bool__", "__iter__", "__getitem__", "__contains__",
           "__call__", "__enter__", "__exit__"}


def pending_under(prefix):
    """The names of PENDING directly under `prefix` ("" or "Class." or "submodule.")."""
    return {p[len(prefix):] for p in PENDING if p.startswith(prefix) and "." not in p[len(prefix):]}


def stub_file(module_name):
    return STUBS / "__init__.pyi" if module_name == "recode" else \
        STUBS / (module_name.split(".", 1)[1].replace(".", "/") + ".pyi")


def public(name):
    return not name.startswith("_") or name in DUNDERS or name == "__version__"


class StubClass:
    def __init__(self, node):
        self.node = node
        self.members = {}      # name -> list of nodes (FunctionDef, AnnAssign)
        for item in node.body:
            if isinstance(item, ast.FunctionDef):
                self.members.setdefault(item.name, []).append(item)
            elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                self.members.setdefault(item.target.id, []).append(item)

    def writable(self, name):
        nodes = self.members[name]
        if any(isinstance(n, ast.AnnAssign) for n in nodes):
            return True
        return any(isinstance(d, ast.Attribute) and d.attr == "setter"
                   for n in nodes for d in n.decorator_list)


def parse_stub(path):
    """Public names of a stub file: functions (name -> nodes), classes (name -> StubClass),
    other names (annotations, assignments)."""
    tree = ast.parse(path.read_text(), str(path))
    functions, classes, others = {}, {}, set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.ClassDef):
            classes[node.name] = StubClass(node)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            others.add(node.target.id)
        elif isinstance(node, ast.Assign):
            others.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return ({k: v for k, v in functions.items() if public(k)},
            {k: v for k, v in classes.items() if public(k)},
            {k for k in others if public(k)})


def stub_parameters(node):
    a = node.args
    names = [p.arg for p in a.posonlyargs + a.args] + (["*" + a.vararg.arg] if a.vararg else []) \
        + [p.arg for p in a.kwonlyargs] + (["**" + a.kwarg.arg] if a.kwarg else [])
    if names and names[0] in ("self", "cls") and not any(
            isinstance(d, ast.Name) and d.id == "staticmethod" for d in node.decorator_list):
        names = names[1:]
    return names


def signatures(obj):
    """Each pybind11 signature's parameter names, from the docstring's signature lines (one, or
    one per overload); None for a callable without them."""
    doc = getattr(obj, "__doc__", None) or ""
    name = getattr(obj, "__name__", "")
    lines = [line for line in doc.splitlines()
             if re.match(r"^(\d+\. )?" + re.escape(name) + r"\(", line)]
    result = []
    for line in lines:
        if "Overloaded function" in doc and not re.match(r"^\d+\. ", line):
            continue
        inside = line[line.index("(") + 1:line.rindex(") ->") if ") ->" in line else None]
        params, depth, current = [], 0, ""
        for ch in inside:
            depth += ch in "([{"
            depth -= ch in ")]}"
            if ch == "," and depth == 0:
                params.append(current)
                current = ""
            else:
                current += ch
        params.append(current)
        names = [p.split(":")[0].split("=")[0].strip() for p in params]
        names = [n for n in names if n and n not in ("*", "self", "/")]
        result.append(names)
    return result or None


def module_names(module):
    return {n for n in vars(module) if public(n) and not n.startswith("__")} | (
        {"__version__"} if hasattr(module, "__version__") else set())


def compared_modules():
    found = [recode]
    for value in vars(recode).values():
        if isinstance(value, types.ModuleType) and value.__name__.startswith("recode."):
            found.append(value)
    return found


def check_parameters(where, runtime, stub_nodes, problems):
    runtime_sigs = signatures(runtime)
    if runtime_sigs is None:
        return
    stub_sigs = [stub_parameters(n) for n in stub_nodes]
    for sig in runtime_sigs:
        if sig not in stub_sigs:
            problems.append(f"{where}: the module's parameters {sig}, the stubs' {stub_sigs}")


def differences(module):
    prefix = "" if module is recode else module.__name__.split(".", 1)[1] + "."
    path = stub_file(module.__name__)
    if not path.is_file():
        if prefix.rstrip(".") in PENDING:
            return []
        return [f"{module.__name__}: no stub file {path}"]
    functions, classes, others = parse_stub(path)
    problems = []
    runtime = module_names(module)
    submodules = {n for n in runtime if isinstance(getattr(module, n), types.ModuleType)}
    stubbed = set(functions) | set(classes) | others
    for name in sorted(runtime - submodules - stubbed):
        if prefix + name not in PENDING:
            problems.append(f"{module.__name__}.{name} is not in {path.name}")
    for name in sorted(stubbed - runtime):
        problems.append(f"{path.name} has {name}, the module has not")
    for name in sorted(stubbed & pending_under(prefix)):
        problems.append(f"{prefix}{name} is in PENDING and in {path.name}: drop it from PENDING")
    for name, nodes in functions.items():
        if name in runtime:
            check_parameters(f"{module.__name__}.{name}", getattr(module, name), nodes, problems)
    for name, stub in classes.items():
        cls = getattr(module, name, None)
        if not isinstance(cls, type):
            continue
        if issubclass(cls, BaseException):
            continue  # an exception: its members are Python's
        members = {n for n in vars(cls) if public(n)}
        init = vars(cls).get("__init__")
        if init is not None and type(init).__name__ != "instancemethod":
            members.discard("__init__")  # no constructor bound: not constructible from Python
        for member in sorted(members - set(stub.members)):
            if f"{prefix}{name}.{member}" not in PENDING:
                problems.append(f"{module.__name__}.{name}.{member} is not in {path.name}")
        for member in sorted(set(stub.members) - members):
            problems.append(f"{path.name} has {name}.{member}, the module has not")
        for member in sorted(set(stub.members) & pending_under(prefix + name + ".")):
            problems.append(f"{prefix}{name}.{member} is in PENDING and in {path.name}: drop it "
                            "from PENDING")
        for member in sorted(members & set(stub.members)):
            value = vars(cls)[member]
            where = f"{module.__name__}.{name}.{member}"
            if isinstance(value, property):
                if (value.fset is not None) != stub.writable(member):
                    problems.append(f"{where}: writable {value.fset is not None} in the module, "
                                    f"{stub.writable(member)} in the stubs")
            else:
                target = value.__func__ if isinstance(value, staticmethod) else value
                check_parameters(where, target, [n for n in stub.members[member]
                                                 if isinstance(n, ast.FunctionDef)], problems)
    return problems


@pytest.mark.parametrize("module", compared_modules(), ids=lambda m: m.__name__)
def test_the_stubs_and_the_module_agree(module):
    problems = differences(module)
    assert not problems, "\n".join(problems)


def test_every_stub_file_parses_and_names_a_module():
    for path in STUBS.glob("*.pyi"):
        ast.parse(path.read_text(), str(path))
        if path.name != "__init__.pyi":
            assert hasattr(recode, path.stem), f"{path.name}: the module has no {path.stem}"


def test_the_check_sees_a_drift(tmp_path, monkeypatch):
    # Break it, run it: a stub without collide() and with a name the module lacks, a parameter
    # renamed and a read-only property made writable are each reported.
    text = (STUBS / "__init__.pyi").read_text()
    text = text.replace("def collide(a: CollisionObject", "def collide_(a: CollisionObject")
    text = text.replace("def add(self, object: CollisionObject)", "def add(self, obj: CollisionObject)")
    text = text.replace("    @property\n    def block_count(self) -> int: ...",
                        "    block_count: int")
    (tmp_path / "__init__.pyi").write_text(text)
    monkeypatch.setattr(sys.modules[__name__], "STUBS", tmp_path)
    problems = "\n".join(differences(recode))
    assert "recode.collide is not in __init__.pyi" in problems
    assert "__init__.pyi has collide_, the module has not" in problems
    assert "recode.CollisionManager.add: the module's parameters ['object']" in problems
    assert "recode.CollisionGeometry.block_count: writable False in the module, True" in problems


def mypy(tmp_path, program):
    """mypy --strict on `program` with the stubs as the package recode; its output."""
    shutil.copytree(STUBS, tmp_path / "stubs" / "recode")
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                           "--cache-dir", str(tmp_path / "cache"), str(program)],
                          capture_output=True, text=True, cwd=tmp_path,
                          env={**os.environ, "MYPYPATH": str(tmp_path / "stubs")})
    return done.returncode, done.stdout + done.stderr


needs_mypy = pytest.mark.skipif(importlib.util.find_spec("mypy") is None,
                                reason="no mypy for this interpreter (Debian: mypy)")


@needs_mypy
def test_mypy_accepts_the_stubs_and_a_typical_program(tmp_path):
    code, out = mypy(tmp_path, pathlib.Path(__file__).with_name("stubs_usage.py"))
    assert code == 0, out


@needs_mypy
def test_mypy_reports_wrong_calls(tmp_path):
    program = tmp_path / "wrong.py"
    program.write_text(
        "import recode\n"
        "recode.collide(recode.CollisionObject(recode.box(1, 1, 1)), 'b')\n"
        "recode.CollisionRequest(pixel_sise=0.1)\n"
        "x: str = recode.devices()[0]['available']\n")
    code, out = mypy(tmp_path, program)
    assert code == 1
    assert 'Argument 2 to "collide" has incompatible type "str"' in out
    assert 'Unexpected keyword argument "pixel_sise"' in out
    assert 'expression has type "bool", variable has type "str"' in out
