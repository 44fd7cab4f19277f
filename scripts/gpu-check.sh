#!/usr/bin/env bash
# The GPU check: on a machine with a GPU driver (a Vulkan ICD and an EGL vendor library), are the
# exact devices still the reference bit for bit, and how fast are they? Runs
#   1. recode conform on the exact Vulkan, GL, 32-bit Vulkan and compute Vulkan devices (every
#      committed golden vector),
#   2. recode verify --suite at 800 pixels on the exact Vulkan and GL devices, and on the compute
#      device (per-command parity of 504 pairs, then the same pairs as one batch against the
#      reference),
#   3. recode run on every built-in scene (two with QUICK) on the compute device (posed blocks: the vertex stage
#      runs on the GPU) against the CPU device, byte for byte, and the compute device's own tests
#      (the kit's vertex-stage vectors among them) when the build has them,
#   4. recode bench table2 figure8 with the GPU columns (the CGAL judge, recode-cpu, the exact
#      devices batched, Vulkan pair by pair, with speculative contact passes, the same concluded
#      from 64-byte summaries made by a compute shader, and that on 16 devices a frame size
#      (waves), the 32-bit Vulkan device, the compute device, FCL GJK, Bullet),
#   5. recode conform on the native pipelines, the fixed-function GL device (gl) and Vulkan's own
#      rasterizer and depth (vulkan-native): the driver's departures from the contract, with the
#      freedoms of the APIs it takes (the fingerprint), reported and never judged,
# and prints a summary. Exit status 0 when every correctness check passed (the bench's times and
# the native pipelines' failing vectors are reported, never judged; a native conform that ends in
# an error, a crash rather than a verdict, fails the check).
#
# Usage: scripts/gpu-check.sh [OUT]          (default OUT: gpu-check)
# Environment: RECODE   the recode binary (default build/apps/recode)
#              QUICK=1  the bench's smallest levels only (--quick), to try the script on
#                       lavapipe and Mesa's EGL first
# On a lent machine without the loaders, see docs/backends.md ("Running on a GPU").
set -uo pipefail

recode=${RECODE:-build/apps/recode}
out=${1:-gpu-check}
quick=${QUICK:+--quick}
mkdir -p "$out"
[[ -x $recode ]] || { echo "gpu-check: no recode binary at $recode (set RECODE)" >&2; exit 2; }

failed=()
step() {  # step NAME LOG COMMAND...: runs it, keeps its output, records a failure
  local name=$1 log=$2
  shift 2
  local start=$SECONDS
  if "$@" >"$out/$log" 2>&1; then
    printf '%-34s passed  (%d s)\n' "$name" $((SECONDS - start))
  else
    printf '%-34s FAILED  (%d s; see %s)\n' "$name" $((SECONDS - start)) "$out/$log"
    failed+=("$name")
  fi
}

echo "gpu-check: $recode, writing into $out"
step "conform --device vulkan" conform-vulkan.json "$recode" conform --device vulkan --json
step "conform --device gl-exact" conform-gl-exact.json "$recode" conform --device gl-exact --json
step "conform --device vulkan-32" conform-vulkan-32.json "$recode" conform --device vulkan-32 --json
step "conform --device vulkan-compute" conform-vulkan-compute.json \
  "$recode" conform --device vulkan-compute --json
step "verify --suite --width 800" verify-800.json \
  "$recode" verify --suite --width 800 --vulkan --gl-exact --gl-platform egl --json
step "verify --suite --vulkan-compute" verify-800-compute.json \
  "$recode" verify --suite --width 800 --vulkan-compute --json
same_runs() {  # each built-in scene's `recode run --json --no-timing`, cpu against vulkan-compute
  local scene status=0 scenes
  if [[ -n $quick ]]; then
    scenes="hand-grasp random-shapes"  # lavapipe's compute device is slow: two scenes
  else
    scenes=$("$recode" run --list | awk 'NR > 1 {print $1}')
  fi
  for scene in $scenes; do
    "$recode" run "$scene" --json --no-timing > "$out/run-$scene-cpu.json" || status=1
    "$recode" run "$scene" --json --no-timing --device vulkan-compute \
      > "$out/run-$scene-vulkan-compute.json" || status=1
    if cmp -s "$out/run-$scene-cpu.json" "$out/run-$scene-vulkan-compute.json"; then
      echo "$scene: same bytes"
    else
      echo "$scene: DIFFERENT"
      status=1
    fi
  done
  return $status
}
step "run --device vulkan-compute (posed)" run-vulkan-compute.log same_runs
compute_tests=$(dirname "$recode")/../tests/backends/recode_backends_vulkan_compute_tests
if [[ -x $compute_tests ]]; then
  step "vulkan-compute device tests" vulkan-compute-tests.log "$compute_tests"
fi
native() {  # native DEVICE: recode conform --json on a native pipeline, its vectors reported
  local device=$1 start=$SECONDS status
  "$recode" conform --device "$device" --json >"$out/conform-$device.json" 2>"$out/conform-$device.log"
  status=$?
  if ((status == 0 || status == 2)); then  # 2: vectors failed, the driver's own answers
    printf '%-34s reported (%d s; see %s)\n' "conform --device $device" $((SECONDS - start)) \
      "$out/conform-$device.json"
  else
    printf '%-34s FAILED  (%d s; see %s)\n' "conform --device $device" $((SECONDS - start)) \
      "$out/conform-$device.log"
    failed+=("conform --device $device")
  fi
}
native gl
native vulkan-native
step "bench table2 figure8" bench.log \
  "$recode" bench table2 figure8 $quick --out "$out/bench" \
  --algorithms recode-cpu,recode-gl-exact,recode-vulkan,recode-vulkan-per-pair,recode-vulkan-speculative,recode-vulkan-summaries,recode-vulkan-waves,recode-vulkan-32,recode-vulkan-compute,fcl-gjk,bullet

echo
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]

def load(name):
    try:
        with open(os.path.join(out, name)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None

for device in ("vulkan", "gl-exact", "vulkan-32", "vulkan-compute"):
    c = load(f"conform-{device}.json")
    if c:
        print(f"conform {device}: {c.get('passed', '?')} of {c.get('vectors', '?')} vectors passed")
for device in ("gl", "vulkan-native"):  # native pipelines: where the driver departs, and how
    c = load(f"conform-{device}.json")
    if not c:
        continue
    failing = [r for r in c.get("results", []) if not r.get("passed")]
    stages, families = {}, {}
    for r in failing:
        stages[r.get("stage", "?")] = stages.get(r.get("stage", "?"), 0) + 1
        family = r.get("file", "?").rsplit(".", 1)[0].rstrip("0123456789").rstrip("_")
        families[family] = families.get(family, 0) + 1
    forbidden = sum(1 for r in failing if r.get("api", {}).get("forbidden_pixels", 0) > 0)
    print(f"conform {device} (native): {c.get('passed', '?')} of {c.get('vectors', '?')} vectors"
          f" give the contract's bits; {forbidden} failing vectors with pixels the APIs forbid")
    print("  failing by stage: " + ", ".join(f"{k} {v}" for k, v in sorted(stages.items())))
    print("  failing by family: " + ", ".join(f"{k} {v}" for k, v in sorted(families.items())))
    for f in c.get("fingerprint", []):
        print(f"  {f.get('freedom', '?')}: {f.get('verdict', '?')}")
for name, keys in (("verify-800.json", ("vulkan", "gl_exact")),
                   ("verify-800-compute.json", ("vulkan",))):
    v = load(name)
    for key in keys if v else ():
        d = v.get(key, {})
        b = d.get("batch", {})
        label = d.get("device", key)
        print(f"verify {label}: {d.get('pixels', 0):,} pixels, {d.get('different', '?')} different;"
              f" batched {b.get('pairs', 0)} pairs, {b.get('different', '?')} different,"
              f" {b.get('submissions', '?')} submissions")
path = os.path.join(out, "bench", "bench.csv")
if os.path.exists(path):
    rows = list(csv.DictReader(open(path)))
    columns = ["recode-cpu", "recode-gl-exact", "recode-vulkan", "recode-vulkan-per-pair",
               "recode-vulkan-speculative", "recode-vulkan-summaries", "recode-vulkan-waves",
               "recode-vulkan-32", "recode-vulkan-compute", "fcl-gjk"]
    print("\nmean ms a frame (submissions a frame, read-back bytes a pair test, ms of the frame"
          " spent waiting for the device):")
    print("| scene | triangles | " + " | ".join(columns) + " |")
    keys = sorted({(r["experiment"], r["scene"], int(r["triangles"])) for r in rows})
    for e, s, t in keys:
        cells = []
        for c in columns:
            r = next((r for r in rows if (r["experiment"], r["scene"], int(r["triangles"]),
                                          r["algorithm"]) == (e, s, t, c)), None)
            if r is None:
                cells.append("-")
            elif r["submissions_per_frame"] and float(r["submissions_per_frame"]) > 0:
                tests = int(r["pair_tests"]) or 1
                per_test = float(r["readback_bytes_per_frame"]) * int(r["frames"]) / tests
                cells.append(f"{float(r['mean_ms']):.3f} ({float(r['submissions_per_frame']):.1f},"
                             f" {per_test:.0f} B, {float(r['device_wait_ms_per_frame']):.3f})")
            else:
                cells.append(f"{float(r['mean_ms']):.3f}")
        print(f"| {s} | {t:,} | " + " | ".join(cells) + " |")
    recode_columns = [c for c in columns if c.startswith("recode-")]
    print("\nhost ms a frame (host_ms_per_frame: the frame minus the wait for the device, the"
          " host's own work, which no GPU makes faster):")
    print("| scene | triangles | " + " | ".join(recode_columns) + " |")
    for e, s, t in keys:
        cells = []
        for c in recode_columns:
            r = next((r for r in rows if (r["experiment"], r["scene"], int(r["triangles"]),
                                          r["algorithm"]) == (e, s, t, c)), None)
            cells.append(f"{float(r['host_ms_per_frame']):.3f}"
                         if r is not None and r["host_ms_per_frame"] else "-")
        print(f"| {s} | {t:,} | " + " | ".join(cells) + " |")
    stages = ("vertex", "setup", "binning", "raster", "reads")
    print("\nrecode-vulkan-compute, where its device time goes (ms a frame, from timestamps;"
          " dispatches and submissions a frame):")
    print("| scene | triangles | " + " | ".join(stages) + " | dispatches | submissions |")
    for e, s, t in keys:
        r = next((r for r in rows if (r["experiment"], r["scene"], int(r["triangles"]),
                                      r["algorithm"]) == (e, s, t, "recode-vulkan-compute")), None)
        if r is None or not r.get("dispatches_per_frame"):
            continue
        cells = [f"{float(r['stage_ms_' + k]):.3f}" for k in stages]
        print(f"| {s} | {t:,} | " + " | ".join(cells) +
              f" | {float(r['dispatches_per_frame']):.1f} | {float(r['submissions_per_frame']):.1f} |")
PY

if ((${#failed[@]})); then
  echo "gpu-check: FAILED: ${failed[*]}"
  exit 1
fi
echo "gpu-check: every correctness check passed"
