#!/usr/bin/env bash
# scripts/mutate.sh end to end on a project of one library and one test program (made here, in
# WORK_DIR, a git repository of its own, with copies of the two scripts): `--changed HEAD` on a
# known one-line change lists that line's mutants and no other, runs them and records each one's
# status; the source is left with its bytes and time stamp; and a run interrupted (SIGINT to
# its process group, as Ctrl-C sends it) while a mutant is in the source restores it too.
#
#   tests/scripts/mutate_changed_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
rm -rf "$work"
mkdir -p "$work/project/scripts" "$work/project/src" "$work/project/tests/core"
cd "$work/project"
cp "$source_dir/scripts/mutate.sh" "$source_dir/scripts/mutants.py" scripts/
fail() { echo "mutate-changed: FAIL: $*" >&2; exit 1; }

cat > CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(bucket CXX)
add_library(bucket STATIC src/bucket.cpp)
target_include_directories(bucket PUBLIC src)
add_subdirectory(tests/core)
CMAKE
cat > tests/core/CMakeLists.txt <<'CMAKE'
add_executable(bucket_tests bucket_test.cpp)
target_link_libraries(bucket_tests PRIVATE bucket)
CMAKE
cat > src/bucket.hpp <<'CPP'
int bucket(int x);
int twice(int x);
CPP
cat > src/bucket.cpp <<'CPP'
#include "bucket.hpp"

int bucket(int x) {
  if (x <= 9)
    return 0;
  return 1;
}

int twice(int x) { return x * 2; }
CPP
# The test checks 9 and 20, not the edge at 10: the mutants that move the edge survive.
cat > tests/core/bucket_test.cpp <<'CPP'
#include "bucket.hpp"
int main() { return bucket(9) == 0 && bucket(20) == 1 && twice(3) == 6 ? 0 : 1; }
CPP
git init -q .
git add -A
git -c user.name=test -c user.email=test@localhost commit -qm base

# The known change: line 4 written another way.
sed -i 's/  if (x <= 9)/  if (x < 10)/' src/bucket.cpp
cp -p src/bucket.cpp "$work/bucket.cpp.changed"
stamp=$(stat -c %y src/bucket.cpp)
export MUTATE_LOCK="$work/build.lock"

listed=$(scripts/mutate.sh --changed HEAD --list src)
expected=$'src/bucket.cpp\t4\t8\tcomparison\t<\t<=\nsrc/bucket.cpp\t4\t10\tconstant\t10\t11\nsrc/bucket.cpp\t4\t5\tnegation\t(x < 10)\t(!(x < 10))'
[ "$(sort <<< "$listed")" = "$(sort <<< "$expected")" ] ||
  fail "--changed HEAD --list gave"$'\n'"$listed"$'\n'"expected"$'\n'"$expected"

# A compiler launcher that waits while $work/slow exists: the interrupted run below stops
# while a mutant is being compiled.
cat > "$work/slow.sh" <<SH
#!/bin/sh
while [ -f "$work/slow" ]; do sleep 0.2; done
exec "\$@"
SH
chmod +x "$work/slow.sh"
export CMAKE_CXX_COMPILER_LAUNCHER="$work/slow.sh"

scripts/mutate.sh --changed HEAD --build "$work/build" --out "$work/out" src > "$work/run.log" 2>&1 ||
  { cat "$work/run.log" >&2; fail "the run failed"; }
results=$(echo "$work"/out/*/results.tsv)
statuses() {  # STATUS: the key columns of the results' rows with that status
  python3 scripts/mutants.py with-status "$1" < "$results" | python3 scripts/mutants.py keys |
    sort
}
[ "$(statuses survived)" = "$(sed -n 1,2p <<< "$expected" | sort)" ] ||
  fail "survived: $(statuses survived)"
[ "$(statuses killed)" = "$(sed -n 3p <<< "$expected")" ] || fail "killed: $(statuses killed)"
[ "$(grep -vc '^#' "$results")" = 3 ] || fail "$(cat "$results")"
cmp -s src/bucket.cpp "$work/bucket.cpp.changed" || fail "the source differs after the run"
[ "$(stat -c %y src/bucket.cpp)" = "$stamp" ] || fail "the source's time stamp moved"

# Interrupted while the first mutant is in the source, its object being compiled. Job control
# (set -m) starts the run in a process group of its own, SIGINT not ignored (a script's other
# background commands ignore it), as a terminal's foreground job.
touch "$work/slow"
set -m
scripts/mutate.sh --changed HEAD --build "$work/build" --out "$work/out" src \
  > "$work/interrupted.log" 2>&1 &
run=$!
set +m
for _ in $(seq 600); do
  cmp -s src/bucket.cpp "$work/bucket.cpp.changed" || break
  sleep 0.1
done
! cmp -s src/bucket.cpp "$work/bucket.cpp.changed" || fail "no mutant was applied in 60 s"
sleep 0.5   # the compiler waits in the launcher
kill -INT -- "-$run"
rc=0
wait "$run" || rc=$?
rm -f "$work/slow"
[ "$rc" = 130 ] || { cat "$work/interrupted.log" >&2; fail "the interrupted run exited $rc"; }
cmp -s src/bucket.cpp "$work/bucket.cpp.changed" || fail "the source differs after Ctrl-C"
[ "$(stat -c %y src/bucket.cpp)" = "$stamp" ] || fail "the time stamp moved after Ctrl-C"
flock -n "$MUTATE_LOCK" true || fail "the build lock is still held"
# The next build compiles the source again (the mutant's object was deleted).
cmake --build "$work/build" --target tests/core/bucket_tests > /dev/null
(cd "$work/build/tests/core" && ./bucket_tests) || fail "the test program fails after Ctrl-C"
echo "mutate-changed: OK: 3 mutants of the changed line (2 survived, 1 killed), the source" \
  "restored after the run and after Ctrl-C"
