#!/usr/bin/python3
"""The WebAssembly build of the reference gives the native build's bits.

Under Node, the module (wasm/, scripts/build-wasm.sh) replays every committed golden vector
(data/golden) and must match each expected buffer exactly; and it runs `recode pair` on the
built-in pair in every mode and option, on the first two objects of every scene of data/scenes,
on block pairs of the built-in scenes and on the generated pair suite (both written as scenes
by `recode verify --save-scenes`),
and each answer must be byte for byte what the native `recode pair --json --no-timing` prints.

Usage: check_wasm_same_bytes.py RECODE MODULE.js WORKDIR [SUITE_COUNT]
Exit status 0: passed; 1: failed; 77: skipped (no Node or no module).
"""

import glob
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.normpath(os.path.join(HERE, "..", "..", "data"))

# `recode run`'s built-in experiments (data/scenes), whose objects are mostly groups of blocks.
BUILTIN_SCENES = ["comb-translate-aligned", "comb-translate-offset", "comb-rotate-aligned",
                  "comb-rotate-offset", "random-cones", "random-shapes", "hand-grasp",
                  "hierarchy-9"]
BLOCK_PAIRS_PER_SCENE = 12

# The built-in pair: every mode and option `recode pair` has that the module takes.
BUILTIN_CASES = [
    {},
    {"mode": "adaptive"},
    {"mode": "conservative"},
    {"mode": "skip-apart"},
    {"pixel": "128,128"},
    {"normal": True},
    {"mor": "max"},
    {"mor": "full", "resolution": "96"},
    {"view_axis": "adaptive"},
    {"resolution": "200x120"},
    {"pixel_size": 0.05},
    {"box_test": False},
    {"contact": False},
]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def cli_args(case):
    """The `recode pair` arguments of a case."""
    args = [case["scene"]] if case.get("scene") else []
    args += ["--json", "--no-timing"]
    for key, option in (("mode", "--mode"), ("pixel", "--pixel"), ("mor", "--mor"),
                        ("view_axis", "--view-axis"), ("resolution", "--resolution")):
        if key in case:
            args += [option, case[key]]
    if "pixel_size" in case:
        args += ["--pixel-size", repr(case["pixel_size"])]
    if case.get("normal"):
        args.append("--normal")
    if case.get("box_test") is False:
        args.append("--no-box-test")
    if case.get("contact") is False:
        args.append("--no-contact")
    return args


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    recode, module, work = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    suite_count = int(sys.argv[4]) if len(sys.argv) > 4 else 504
    node = shutil.which("node") or shutil.which("nodejs")
    if not node:
        print("SKIP: no node")
        return 77
    if not os.path.exists(module):
        print("SKIP: no module at " + module + " (scripts/build-wasm.sh)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    suite = os.path.join(work, "suite")
    subprocess.run([recode, "verify", "--suite", "--count", str(suite_count), "--width", "64",
                    "--save-scenes", suite], check=True, stdout=subprocess.DEVNULL)

    # The built-in scenes' block pairs at frame 0, as `recode verify SCENE` checks them: up to
    # BLOCK_PAIRS_PER_SCENE of each, evenly spaced.
    block_pairs = []
    for name in BUILTIN_SCENES:
        out = os.path.join(work, "scene-" + name)
        subprocess.run([recode, "verify", os.path.join(DATA, "scenes", name + ".json"),
                        "--save-scenes", out], check=True, stdout=subprocess.DEVNULL)
        written = sorted(glob.glob(os.path.join(out, "pair-*.json")))
        step = max(1, len(written) // BLOCK_PAIRS_PER_SCENE)
        block_pairs += written[::step][:BLOCK_PAIRS_PER_SCENE]

    pair_cases = [dict(c) for c in BUILTIN_CASES]
    pair_cases += [{"scene": p} for p in sorted(glob.glob(os.path.join(DATA, "scenes", "*.json")))]
    pair_cases += [{"scene": p} for p in block_pairs]
    suite_scenes = sorted(glob.glob(os.path.join(suite, "pair-*.json")))
    pair_cases += [{"scene": p} for p in suite_scenes]
    # The adaptive mode's finer frames on every eighth suite pair.
    pair_cases += [{"scene": p, "mode": "adaptive"} for p in suite_scenes[::8]]
    goldens = sorted(glob.glob(os.path.join(DATA, "golden", "**", "*.json"), recursive=True))
    if len(suite_scenes) != suite_count or not goldens:
        fail("expected %d suite scenes and some golden vectors, found %d and %d"
             % (suite_count, len(suite_scenes), len(goldens)))

    cases, refused, layered = [], [], []
    for i, case in enumerate(pair_cases):
        # Each run also writes its case map (--dump-cases), compared byte for byte too.
        native_cases = os.path.join(work, "case-%04d.native.pgm" % i)
        native = subprocess.run([recode, "pair"] + cli_args(case) + ["--dump-cases", native_cases],
                                capture_output=True, text=True)
        dump_cases = True
        if native.returncode != 0:
            # A pair with a closed mesh has no case map (it is decided by layers) and refuses
            # --dump-cases: its JSON answer is compared without one.
            plain = subprocess.run([recode, "pair"] + cli_args(case), capture_output=True, text=True)
            if plain.returncode == 0:
                native, dump_cases = plain, False
        expected = os.path.join(work, "case-%04d.native.json" % i)
        with open(expected, "w") as f:
            if native.returncode == 0:
                f.write(native.stdout)
            else:  # a refusal (a scene whose first object is a group): the same message
                message = native.stderr.strip()
                prefix = "recode: error: "
                if not message.startswith(prefix):
                    fail("native recode pair %s: %s" % (" ".join(cli_args(case)), message))
                f.write(json.dumps({"error": message[len(prefix):]}, separators=(",", ":"), ensure_ascii=False) + "\n")
                refused.append(case)
        request = dict(case)
        request["timing"] = False
        wasm_cases = os.path.join(work, "case-%04d.wasm.pgm" % i)
        if dump_cases:
            request["dump_cases"] = wasm_cases
        else:
            layered.append(case)
        cases.append({"kind": "pair", "request": request, "expected": expected,
                      "out": os.path.join(work, "case-%04d.wasm.json" % i),
                      "cases": (native_cases, wasm_cases),
                      "what": "recode pair " + " ".join(cli_args(case))})
    for i, path in enumerate(goldens):
        cases.append({"kind": "golden", "path": path, "what": os.path.relpath(path, DATA),
                      "out": os.path.join(work, "golden-%04d.wasm.json" % i)})
    spec = os.path.join(work, "cases.json")
    with open(spec, "w") as f:
        json.dump({"mounts": [DATA, work], "cases": cases}, f)
    run = subprocess.run([node, os.path.join(HERE, "wasm_runner.cjs"), module, spec],
                         capture_output=True, text=True)
    print(run.stdout.strip())
    if run.returncode != 0:
        fail("node: " + run.stderr.strip()[-2000:])

    different, golden_failed = [], []
    case_maps = 0
    for c in cases:
        with open(c["out"]) as f:
            got = f.read()
        if c["kind"] == "pair":
            with open(c["expected"]) as f:
                same = got == f.read()
            native_map, wasm_map = c["cases"]
            if os.path.exists(native_map) != os.path.exists(wasm_map):
                same = False
            elif os.path.exists(native_map):
                with open(native_map, "rb") as a, open(wasm_map, "rb") as b:
                    same = same and a.read() == b.read()
                case_maps += 1
            if not same:
                different.append(c)
        else:
            answer = json.loads(got)
            if answer.get("error") or answer["depth_pixels"] or answer["stencil_pixels"]:
                golden_failed.append((c["what"], answer))
    for c in different[:5]:
        print("different: %s (diff %s %s; cmp %s %s)"
              % ((c["what"], c["expected"], c["out"]) + c["cases"]))
    for what, answer in golden_failed[:5]:
        print("golden vector failed: %s: %s" % (what, json.dumps(answer)))
    if different or golden_failed:
        fail("%d of %d pair outputs differ, %d of %d golden vectors fail"
             % (len(different), len(pair_cases), len(golden_failed), len(goldens)))
    scene_files = len(pair_cases) - len(BUILTIN_CASES) - len(block_pairs) - len(suite_scenes) \
        - len(suite_scenes[::8])
    print("wasm same bytes OK: %d pair outputs and %d case maps identical (%d built-in pair, %d scene files, "
          "%d block pairs of the built-in scenes, %d suite pairs, %d in the adaptive mode; %d "
          "of them the same refusal, %d pairs with a closed mesh without a case map); "
          "%d golden vectors pass"
          % (len(pair_cases), case_maps, len(BUILTIN_CASES), scene_files, len(block_pairs),
             len(suite_scenes), len(suite_scenes[::8]), len(refused), len(layered), len(goldens)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
