#!/usr/bin/env bash
# Mutation testing of the reference (docs/verification.md, "Mutation testing").
#
#   scripts/mutate.sh [options] [FILE_OR_FOLDER...]
#
# Makes mutants of the reference's own code (by default raster/src, core/pair/src,
# core/refine/src, core/sim/src, core/geometry/src/exact_predicates.cpp and the convex hull's
# sources), one textual change of one line at a time (scripts/mutants.py lists the operators),
# and for each: applies it in the working tree, rebuilds only the changed object and the test
# programs that link its library in a build folder of its own, runs those programs with a time
# limit, restores the source byte for byte and classifies the mutant:
#
#   killed        a test program failed
#   survived      every test program passed
#   timeout       a test program ran past the limit (counted as killed)
#   equivalent    the compiler made the same object (code, data, relocations) as from the source
#   argued        known not to change any output, not built: a call that only changes a
#                 container's capacity removed, or a row of scripts/mutation-equivalents.tsv
#                 (the file, the line's text, the change and the argument)
#   build-failed  the mutant does not compile (-Werror included): the compiler rejected it
#   not-reached   no test enters the function holding the line (gcov's function counts, from
#                 one run of the test programs on the unchanged build): not built, not run
#
# Options:
#   --changed BASE   only the mutants of lines that differ from git BASE (working tree)
#   --sample N       N mutants, each file its share by lines (--seed S fixes the choice; 1)
#   --seed S
#   --limit-factor F a test program may run F times its time on the unchanged build (5), and
#                    never less than --limit-min seconds (20)
#   --limit-min S
#   --build DIR      the build folder (build-mutate); configured once, like scripts/build.sh
#                    (Release, Ninja, -Werror) with --coverage added
#   --out DIR        where results.tsv and report.md go (DIR/<time>; default
#                    build-mutate/mutation-reports)
#   -j N             build jobs (1)
#   --list           only list the mutants (after --changed/--sample), build nothing
#   --mutants TSV    run the mutants of TSV (rows as --list prints them, or a results.tsv, e.g.
#                    its survivors: awk -F'\t' '$7 == "survived"' results.tsv) instead of
#                    making them
#
# The test programs are those of tests/core and tests/raster that link the changed object's
# library (MUTATE_TESTS, a regular expression on their build path, widens or narrows that).
# While a mutant is in the source, the build lock /tmp/recode-build.lock (MUTATE_LOCK) is held,
# so that no build of another folder from the same tree compiles it; the source is restored
# with its original bytes and time stamp before the lock is released, also on Ctrl-C or an
# error, and the mutated object is removed from the mutation build.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
helper="$root/scripts/mutants.py"

build="build-mutate"
out=""
base=""
sample=""
seed=1
factor=5
limit_min=20
jobs=1
list_only=0
given=""
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --changed) base=$2; shift 2 ;;
    --sample) sample=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --limit-factor) factor=$2; shift 2 ;;
    --limit-min) limit_min=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -j) jobs=$2; shift 2 ;;
    -j*) jobs=${1#-j}; shift ;;
    --list) list_only=1; shift ;;
    --mutants) given=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "mutate.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
if [ ${#targets[@]} -eq 0 ]; then
  targets=(raster/src core/pair/src core/refine/src core/sim/src
           core/geometry/src/exact_predicates.cpp core/geometry/src/convex_hull.cpp
           core/geometry/src/convex_hull_block.cpp core/geometry/src/convex_hull_facets.cpp
           core/geometry/src/convex_hull_quick.cpp)
fi
files=()
for t in "${targets[@]}"; do
  if [ -d "$t" ]; then
    while IFS= read -r f; do files+=("$f"); done < <(find "$t" -name '*.cpp' | sort)
  elif [ -f "$t" ]; then
    files+=("$t")
  else
    echo "mutate.sh: no such file or folder: $t" >&2; exit 2
  fi
done

work=$(mktemp -d /tmp/recode-mutate.XXXXXX)
mutants="$work/mutants.tsv"
if [ -n "$given" ]; then
  # List rows, or a results.tsv's rows (their first six fields).
  grep -v '^#' "$given" | cut -f1-6 > "$mutants"
else
  python3 "$helper" list "${files[@]}" > "$mutants"
fi
if [ -n "$base" ]; then
  python3 "$helper" changed "$base" "${files[@]}" > "$work/changed.tsv"
  awk -F'\t' 'NR==FNR { keep[$1 "\t" $2] = 1; next } ($1 "\t" $2) in keep' \
    "$work/changed.tsv" "$mutants" > "$work/m" && mv "$work/m" "$mutants"
fi
if [ -n "$sample" ]; then
  python3 "$helper" sample "$sample" "$seed" < "$mutants" > "$work/m" && mv "$work/m" "$mutants"
fi
count=$(wc -l < "$mutants")
if [ "$list_only" = 1 ]; then
  cat "$mutants"
  rm -rf "$work"
  exit 0
fi
echo "mutate.sh: $count mutants in $(cut -f1 "$mutants" | sort -u | wc -l) files" >&2
[ "$count" -gt 0 ] || { rm -rf "$work"; exit 0; }

# The mutation build: configured once, with --coverage, from the same options as build.sh.
if [ ! -f "$build/build.ninja" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRECODE_WERROR=ON \
    -DCMAKE_CXX_FLAGS=--coverage -DCMAKE_EXE_LINKER_FLAGS=--coverage >/dev/null
fi
stamp=$(date -u +%Y%m%dT%H%M%SZ)
out=${out:-$build/mutation-reports}/$stamp
mkdir -p "$out"
results="$out/results.tsv"
printf '#file\tline\tcolumn\toperator\toriginal\tmutant\tstatus\tseconds\ttests\tnote\n' > "$results"

lock=${MUTATE_LOCK-/tmp/recode-build.lock}
applied=""   # the source a mutant is in now
backup="$work/backup"
restore() {
  if [ -n "$applied" ]; then
    cp -p "$backup" "$applied"   # the original bytes and time stamp
    applied=""
    # Built from the mutant and newer than the source: deleted, so that the next build
    # compiles the source again.
    rm -f "$build/$obj"
  fi
}
cleanup() {
  restore
  [ -n "${lock_fd:-}" ] && exec {lock_fd}>&- || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

build_targets() {  # targets... : nice'd, -j$jobs, output to $work/build.log
  nice -n 10 cmake --build "$build" --target "$@" -j "$jobs" > "$work/build.log" 2>&1
}
text_of() {  # the object's code, data and relocations, without gcov's per-compile stamp
  local o=$1 s
  {
    objdump -r "$o" | tail -n +3
    for s in $(objdump -h "$o" |
               awk '$2 ~ /^\./ && $2 != ".data.rel" && $2 != ".comment" {print $2}'); do
      objdump -s -j "$s" "$o" | tail -n +4
    done
  } | md5sum | cut -d' ' -f1
}

declare -A tests_of baseline_s code_of never
current=""
baseline_of=""   # the test programs whose unchanged run the .gcda files hold
while IFS=$'\t' read -r -u 3 file line col op old new; do
  if [ "$file" != "$current" ]; then
    # A new file: its object, its test programs, the unchanged build, their times and coverage.
    current=$file
    mapfile -t found < <(python3 "$helper" objects "$build" "$root/$file")
    obj=${found[0]}
    progs=("${found[@]:1}")
    tests_of[$file]="${progs[*]}"
    echo "mutate.sh: $file: ${#progs[@]} test programs: ${progs[*]}" >&2
    build_targets "$obj" "${progs[@]}" || { cat "$work/build.log" >&2; exit 1; }
    code_of[$file]=$(text_of "$build/$obj")
    # The unchanged build's run (times and coverage) serves every file whose test programs
    # are the same: the mutants' runs write their coverage elsewhere (GCOV_PREFIX), so the
    # .gcda files still hold that run, and this file's object is the one it counted.
    if [ "${progs[*]}" != "$baseline_of" ]; then
      find "$build" -name '*.gcda' -delete
      for p in "${progs[@]}"; do
        t0=$(date +%s.%N)
        (cd "$build/$(dirname "$p")" && "./$(basename "$p")" > "$work/run.log" 2>&1) ||
          { echo "mutate.sh: $p fails on the unchanged source" >&2
            tail -20 "$work/run.log" >&2
            exit 1; }
        baseline_s[$p]=$(echo "$(date +%s.%N) - $t0" | bc)
      done
      baseline_of="${progs[*]}"
    fi
    { read -r _executed; read -r unexecuted; } < <(python3 "$helper" covered "$build" "$root/$file")
    never[$file]=" $unexecuted "
  fi
  t0=$(date +%s.%N)
  status=""
  rc=0
  note=$(python3 "$helper" argued "$file" "$line" "$col" "$old" "$new") || rc=$?
  [ "$rc" -le 1 ] || exit 1   # the equivalents file is malformed (mutants.py said where)
  if [ "$rc" = 0 ]; then
    status=argued
  elif [ -z "${tests_of[$file]}" ] || [[ "${never[$file]}" == *" $line "* ]]; then
    status=not-reached
  else
    if [ -n "$lock" ]; then
      exec {lock_fd}>"$lock"
      flock "$lock_fd"
    fi
    cp -p "$file" "$backup"
    applied=$file
    python3 "$helper" apply "$file" "$line" "$col" "$old" "$new"
    if ! build_targets "$obj"; then
      status="build-failed"
    elif [ "$(text_of "$build/$obj")" = "${code_of[$file]}" ]; then
      status=equivalent
    elif ! build_targets ${tests_of[$file]}; then
      status="build-failed"
    fi
    restore
    if [ -n "$lock" ]; then exec {lock_fd}>&-; unset lock_fd; fi
    if [ -z "$status" ]; then
      status=survived
      for p in ${tests_of[$file]}; do
        limit=$(echo "x = ${baseline_s[$p]} * $factor; if (x < $limit_min) x = $limit_min; x" | bc)
        rc=0
        (cd "$build/$(dirname "$p")" &&
          GCOV_PREFIX="$work/gcov" timeout "$limit" "./$(basename "$p")" --abort \
            > "$work/run.log" 2>&1) || rc=$?
        if [ "$rc" = 124 ]; then status=timeout; note=$p; break; fi
        if [ "$rc" != 0 ]; then
          status=killed
          # Catch2 prints the failing test case's name between the first two rules of dashes
          # (written out: mawk, Debian's awk, has no {n,} intervals).
          note="$p: $(awk '/^--------------------+$/ { n++; next } n == 1 { print; exit }' "$work/run.log")"
          break
        fi
      done
    fi
  fi
  seconds=$(echo "$(date +%s.%N) - $t0" | bc)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.1f\t%s\t%s\n' "$file" "$line" "$col" "$op" "$old" "$new" \
    "$status" "$seconds" "${tests_of[$file]}" "${note//$'\t'/ }" >> "$results"
  printf 'mutate.sh: %s:%s %s %s -> %s: %s (%.0f s)\n' "$file" "$line" "$op" "$old" "$new" \
    "$status" "$seconds" >&2
done 3< "$mutants"

# Leave the mutation build as the source is.
if [ -n "$current" ]; then
  # shellcheck disable=SC2046  # the programs' paths, one word each
  build_targets $(for f in "${!tests_of[@]}"; do echo ${tests_of[$f]}; done | sort -u) || true
fi
python3 "$helper" report "$results" "$out/report.md"
echo "mutate.sh: $out/report.md" >&2
cat "$out/report.md"
