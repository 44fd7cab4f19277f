#!/usr/bin/env bash
# Mutation testing of the reference (docs/verification.md, "Mutation testing").
#
#   scripts/mutate.sh [options] [FILE_OR_FOLDER...]
#
# Makes mutants of the reference's own code (by default raster/src, core/pair/src,
# core/refine/src, core/sim/src, core/geometry/src/exact_predicates.cpp and the convex hull's
# sources), one textual change of one line at a time (the operators are listed at the end),
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
#                    its survivors: scripts/mutants.py with-status survived < results.tsv)
#                    instead of making them
#
# The test programs are those of tests/core and tests/raster that link the changed object's
# library (MUTATE_TESTS, a regular expression on their build path, widens or narrows that).
# While a mutant is in the source, the build lock /tmp/recode-build.lock (MUTATE_LOCK) is held,
# so that no build of another folder from the same tree compiles it; the source is restored
# with its original bytes and time stamp before the lock is released, also on Ctrl-C or an
# error, and the mutated object is removed from the mutation build.
#
# results.tsv has a header line and one row a mutant; scripts/mutants.py (its COLUMNS) names
# the columns and writes the rows, and its subcommands read them by name (`header`, `keys`,
# `with-status`, `report`).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
helper="$root/scripts/mutants.py"

usage() {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
  echo
  echo "Operators (scripts/mutants.py operators):"
  echo
  python3 "$helper" operators | sed 's/^/  /'
}

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
    -h|--help) usage; exit 0 ;;
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

# What the exit trap reads, and nothing else: the scratch folder, the build lock's descriptor
# while it is held, and the source a mutant is in now (applied, empty when none) with its
# original (applied_backup) and the object built from the mutant (applied_obj), all three set
# together by build_mutant and cleared by restore.
work=$(mktemp -d /tmp/recode-mutate.XXXXXX)
lock_fd=""
applied=""
applied_backup=""
applied_obj=""
restore() {
  if [ -n "$applied" ]; then
    cp -p "$applied_backup" "$applied"   # the original bytes and time stamp
    # Built from the mutant and newer than the source: deleted, so that the next build
    # compiles the source again.
    rm -f "$applied_obj"
    applied=""
  fi
}
cleanup() {
  restore
  if [ -n "$lock_fd" ]; then exec {lock_fd}>&-; fi
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

mutants="$work/mutants.tsv"
if [ -n "$given" ]; then
  python3 "$helper" keys < "$given" > "$mutants"   # list rows, or a results file's mutants
else
  python3 "$helper" list "${files[@]}" > "$mutants"
fi
# (Each filter a command of its own: its failure stops the run, under set -e.)
if [ -n "$base" ]; then
  python3 "$helper" changed "$base" < "$mutants" > "$work/m"
  mv "$work/m" "$mutants"
fi
if [ -n "$sample" ]; then
  python3 "$helper" sample "$sample" "$seed" < "$mutants" > "$work/m"
  mv "$work/m" "$mutants"
fi
count=$(wc -l < "$mutants")
if [ "$list_only" = 1 ]; then
  cat "$mutants"
  exit 0
fi
echo "mutate.sh: $count mutants in $(python3 "$helper" files < "$mutants" | wc -l) files" >&2
[ "$count" -gt 0 ] || exit 0

# The mutation build: configured once, with --coverage, from the same options as build.sh.
if [ ! -f "$build/build.ninja" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRECODE_WERROR=ON \
    -DCMAKE_CXX_FLAGS=--coverage -DCMAKE_EXE_LINKER_FLAGS=--coverage >/dev/null
fi
stamp=$(date -u +%Y%m%dT%H%M%SZ)
out=${out:-$build/mutation-reports}/$stamp
mkdir -p "$out"
results="$out/results.tsv"
python3 "$helper" header > "$results"
lock=${MUTATE_LOCK-/tmp/recode-build.lock}

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
seconds_since() {  # T0 (date +%s.%N): the seconds since, one decimal
  printf '%.1f' "$(echo "$(date +%s.%N) - $1" | bc)"
}

# What prepare_file learns of each file (by its path) and of each test program, for its mutants.
declare -A object_of tests_of code_of never baseline_s
baseline_of=""   # the test programs whose unchanged run the .gcda files hold

prepare_file() {  # FILE: its object and test programs built from the unchanged source and run
  local file=$1 listing found progs p t0 unexecuted
  listing=$(python3 "$helper" objects "$build" "$root/$file") || exit 1
  mapfile -t found <<< "$listing"
  object_of[$file]=${found[0]}
  progs=("${found[@]:1}")
  tests_of[$file]="${progs[*]}"
  echo "mutate.sh: $file: ${#progs[@]} test programs: ${progs[*]}" >&2
  build_targets "${object_of[$file]}" "${progs[@]}" || { cat "$work/build.log" >&2; exit 1; }
  code_of[$file]=$(text_of "$build/${object_of[$file]}")
  # The unchanged build's run (times and coverage) serves every file whose test programs are
  # the same: the mutants' runs write their coverage elsewhere (GCOV_PREFIX), so the .gcda
  # files still hold that run, and this file's object is the one it counted.
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
}

lock_source() {  # the build lock (MUTATE_LOCK), so that no other build compiles a mutant
  if [ -n "$lock" ]; then
    exec {lock_fd}>"$lock"
    flock "$lock_fd"
  fi
}
unlock_source() {
  if [ -n "$lock_fd" ]; then exec {lock_fd}>&-; lock_fd=""; fi
}

build_mutant() {  # FILE LINE COL OLD NEW: sets status to build-failed or equivalent, or leaves
                  # it empty when the test programs are built from the mutant
  local file=$1 obj=${object_of[$1]} progs
  read -r -a progs <<< "${tests_of[$file]}"
  lock_source
  cp -p "$file" "$work/backup"
  applied_backup="$work/backup"
  applied_obj="$build/$obj"
  applied=$file
  python3 "$helper" apply "$@"
  if ! build_targets "$obj"; then
    status="build-failed"
  elif [ "$(text_of "$build/$obj")" = "${code_of[$file]}" ]; then
    status=equivalent
  elif ! build_targets "${progs[@]}"; then
    status="build-failed"
  fi
  restore
  unlock_source
}

run_tests() {  # FILE: runs its test programs (built from the mutant); sets status and note
  local p progs limit rc
  read -r -a progs <<< "${tests_of[$1]}"
  status=survived
  for p in "${progs[@]}"; do
    limit=$(echo "x = ${baseline_s[$p]} * $factor; if (x < $limit_min) x = $limit_min; x" | bc)
    rc=0
    (cd "$build/$(dirname "$p")" &&
      GCOV_PREFIX="$work/gcov" timeout "$limit" "./$(basename "$p")" --abort \
        > "$work/run.log" 2>&1) || rc=$?
    if [ "$rc" = 124 ]; then status=timeout; note=$p; return; fi
    if [ "$rc" != 0 ]; then
      status=killed
      # Catch2 prints the failing test case's name between the first two rules of dashes
      # (written out: mawk, Debian's awk, has no {n,} intervals).
      note="$p: $(awk '/^--------------------+$/ { n++; next } n == 1 { print; exit }' \
                    "$work/run.log")"
      return
    fi
  done
}

judge_mutant() {  # FILE LINE COL OLD NEW: sets status and note
  local file=$1 line=$2 rc=0
  status=""
  note=$(python3 "$helper" argued "$@") || rc=$?
  [ "$rc" -le 1 ] || exit 1   # the equivalents file is malformed (mutants.py said where)
  if [ "$rc" = 0 ]; then
    status=argued
  elif [ -z "${tests_of[$file]}" ] || [[ "${never[$file]}" == *" $line "* ]]; then
    status=not-reached
  else
    build_mutant "$@"
    [ -n "$status" ] || run_tests "$file"
  fi
}

# The mutant being judged, by column name (mutants.py's KEY_COLUMNS).
IFS=$'\t' read -r -a key_columns <<< "$(python3 "$helper" header keys)"
key_columns[0]=${key_columns[0]#\#}
declare -A row
read_row() {  # reads the next row of fd 3 into row; false at the end
  local text name
  IFS= read -r -u 3 text || return 1
  row=()
  for name in "${key_columns[@]}"; do
    # Split at each tab (read -a would take a run of tabs as one: an empty field lost).
    row[$name]=${text%%$'\t'*}
    if [[ "$text" == *$'\t'* ]]; then text=${text#*$'\t'}; else text=""; fi
  done
}
record_row() {  # the mutant in row, with status, note and SECONDS, into the results
  local args=() name
  for name in "${!row[@]}"; do args+=("$name=${row[$name]}"); done
  python3 "$helper" row "${args[@]}" status="$status" seconds="$1" \
    tests="${tests_of[${row[file]}]}" note="$note" >> "$results"
}

current=""
while read_row; do
  if [ "${row[file]}" != "$current" ]; then
    current=${row[file]}
    prepare_file "$current"
  fi
  t0=$(date +%s.%N)
  judge_mutant "${row[file]}" "${row[line]}" "${row[column]}" "${row[original]}" "${row[mutant]}"
  seconds=$(seconds_since "$t0")
  record_row "$seconds"
  echo "mutate.sh: ${row[file]}:${row[line]} ${row[operator]} ${row[original]} ->" \
    "${row[mutant]}: $status ($seconds s)" >&2
done 3< "$mutants"

# Leave the mutation build as the source is.
if [ -n "$current" ]; then
  # shellcheck disable=SC2046  # the programs' paths, one word each
  build_targets $(printf '%s\n' "${tests_of[@]}" | tr ' ' '\n' | sort -u) || true
fi
python3 "$helper" report "$results" "$out/report.md"
echo "mutate.sh: $out/report.md" >&2
cat "$out/report.md"
