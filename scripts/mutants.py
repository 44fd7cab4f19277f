#!/usr/bin/env python3
"""The mutation runner's helper (scripts/mutate.sh runs it; see docs/verification.md).

Subcommands:
  list FILE...             every mutant of the files, one TSV row each
  sample N SEED            reads list rows on stdin, keeps N of them, each file its share by
                           lines (the seed fixes the choice)
  changed BASE FILE...     the lines of the files that differ from git BASE, "FILE<TAB>LINE"
  apply FILE LINE COL OLD NEW
                           replaces OLD at column COL of line LINE by NEW (in place)
  objects BUILD_DIR FILE   the object of FILE in BUILD_DIR's build.ninja and the test programs
                           that link the library holding it, one path a line (object first)
  covered BUILD_DIR FILE   the lines of FILE that tests reached, then (second line) those they
                           did not, from BUILD_DIR's .gcda files (gcov; see cmd_covered)
  argued FILE LINE COL OLD NEW
                           prints why the mutant cannot change any output and exits 0 when it
                           is known to be equivalent (a capacity-only call removed, or a row of
                           scripts/mutation-equivalents.tsv); exits 1 otherwise
  report TSV OUT_MD        the markdown summary of a result TSV, per folder

A mutant is one textual change of one line: OLD at column COL (0-based) becomes NEW. The
operators work on clang-formatted C++ (binary operators have a space on each side), in the code
part of a line (not in comments, string literals or preprocessor lines).
"""

import json
import math
import os
import random
import re
import subprocess
import sys
from collections import defaultdict

COMPARISONS = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "=="}
ARITHMETIC = {"+": "-", "-": "+", "*": "/", "/": "*", "&&": "||", "||": "&&"}
ASSIGN_OPS = {"+=": "-=", "-=": "+="}
CONTROL = ("if", "while", "for", "switch", "return", "case", "default", "else", "do", "break",
           "continue", "throw", "goto", "delete", "using", "namespace", "template", "typedef")


def code_part(line):
    """The line with comments and string/char literal contents blanked (same length)."""
    out = []
    i, n = 0, len(line)
    while i < n:
        c = line[i]
        if line.startswith("//", i):
            out.append(" " * (n - i))
            break
        if c in "\"'":
            j = i + 1
            while j < n and line[j] != c:
                j += 2 if line[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)[:n]


def matching_paren(code, open_at):
    depth = 0
    for k in range(open_at, len(code)):
        if code[k] == "(":
            depth += 1
        elif code[k] == ")":
            depth -= 1
            if depth == 0:
                return k
    return -1


NUMBER = re.compile(r"(?<![\w.])(\d+\.\d*(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+|\d+)([uUlL]*)(?![\w.])")


def moved_constant(text, suffix):
    """The literal moved by one (integers) or by its last bit (doubles)."""
    if re.fullmatch(r"\d+", text):
        if len(text) > 1 and text.startswith("0"):
            return None  # octal
        return [str(int(text) + 1) + suffix]
    if suffix:
        return None  # a float or long double literal: its last bit is not a double's
    value = float(text)
    up = math.nextafter(value, math.inf)
    return [repr(up)]


def mutants_of_line(code):
    """(col, old, new, operator) for every mutant of one code line."""
    found = []
    stripped = code.strip()
    if not stripped or stripped.startswith("#") or stripped.startswith("static_assert"):
        return found
    # Comparisons and arithmetic: binary operators with a space each side.
    for m in re.finditer(r" (<=|>=|==|!=|<|>|&&|\|\||\+|-|\*|/|\+=|-=) ", code):
        op = m.group(1)
        col = m.start(1)
        if op in COMPARISONS:
            found.append((col, op, COMPARISONS[op], "comparison"))
        elif op in ARITHMETIC:
            found.append((col, op, ARITHMETIC[op], "arithmetic"))
        elif op in ASSIGN_OPS:
            found.append((col, op, ASSIGN_OPS[op], "arithmetic"))
    # Constants: moved by one, or by their last bit.
    for m in NUMBER.finditer(code):
        moved = moved_constant(m.group(1), m.group(2))
        if moved:
            old = m.group(0)
            for new in moved:
                found.append((m.start(), old, new, "constant"))
    # Rounding terms: "+ (... & 1u)" and "+ 0.5" / "- 0.5" dropped.
    for m in re.finditer(r" \+ \([^()]*& 1u?\)| [+-] 0\.5(?![\d.])", code):
        found.append((m.start(), m.group(0), "", "rounding"))
    # Conditions negated: if (...) / while (...) with the condition on this line.
    for m in re.finditer(r"\b(if|while) \(", code):
        open_at = m.end() - 1
        close = matching_paren(code, open_at)
        if close > open_at:
            cond = code[open_at + 1:close]
            found.append((open_at, "(" + cond + ")", "(!(" + cond + "))", "negation"))
    # A call's result ignored: "x = f(...);" keeps x's old value.
    m = re.fullmatch(r"(\s*)([A-Za-z_][\w.\[\]>-]*) = ([A-Za-z_][\w:.]*\(.*\));\s*", code)
    if m and m.group(2) not in CONTROL:
        found.append((len(m.group(1)), code.strip(), "(void)" + m.group(3) + ";", "call-ignored"))
    # A statement removed: a whole simple statement on this line (an assignment, an increment
    # or a call), not a declaration, jump or return.
    m = re.fullmatch(
        r"(\s*)((?:\+\+|--)?[A-Za-z_][\w.\[\]>:-]*"
        r"(?: (?:=|\+=|-=|\*=|/=|\|=|&=) .*|\(.*\)|\+\+|--));\s*", code)
    if m and m.group(2).split("(")[0].split(" ")[0].lstrip("+-") not in CONTROL:
        found.append((len(m.group(1)), m.group(2) + ";", ";", "statement"))
    return found


def list_mutants(files):
    rows = []
    for path in files:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        previous = ";"
        for number, line in enumerate(lines, start=1):
            code = code_part(line)
            for col, old, new, op in mutants_of_line(code):
                if line[col:col + len(old)] != old:
                    continue  # blanked text: a literal's contents
                # A statement removed only when the line starts it.
                if op in ("statement", "call-ignored") and not previous.rstrip().endswith(
                        (";", "{", "}", ":")) and previous.strip():
                    continue
                rows.append((path, number, col, op, old, new))
            if code.strip():
                previous = code
    return rows


def tsv(fields):
    return "\t".join(str(f).replace("\t", " ").replace("\n", " ") for f in fields)


def cmd_list(files):
    for row in list_mutants(files):
        print(tsv(row))


def cmd_sample(n, seed):
    rows = [line.rstrip("\n").split("\t") for line in sys.stdin if line.strip()]
    by_file = defaultdict(list)
    for r in rows:
        by_file[r[0]].append(r)
    sizes = {}
    for path in by_file:
        with open(path, encoding="utf-8") as f:
            sizes[path] = sum(1 for line in f if code_part(line).strip())
    total = sum(sizes.values()) or 1
    rng = random.Random(seed)
    # Each file's share by lines (largest remainders), never more than it has.
    shares = {p: n * sizes[p] / total for p in by_file}
    counts = {p: min(len(by_file[p]), int(shares[p])) for p in by_file}
    for p in sorted(by_file, key=lambda p: shares[p] - int(shares[p]), reverse=True):
        if sum(counts.values()) >= n:
            break
        if counts[p] < len(by_file[p]):
            counts[p] += 1
    for p in sorted(by_file):
        for r in sorted(rng.sample(by_file[p], counts[p]), key=lambda r: (int(r[1]), int(r[2]))):
            print("\t".join(r))


def cmd_changed(base, files):
    for path in files:
        diff = subprocess.run(["git", "diff", "-U0", base, "--", path], capture_output=True,
                              text=True, check=True).stdout
        for m in re.finditer(r"^@@ -\S+ \+(\d+)(?:,(\d+))? @@", diff, re.M):
            start, count = int(m.group(1)), int(m.group(2) or "1")
            for line in range(start, start + count):
                print(f"{path}\t{line}")


def cmd_apply(path, line, col, old, new):
    with open(path, encoding="utf-8", newline="") as f:
        lines = f.read().split("\n")
    text = lines[line - 1]
    if text[col:col + len(old)] != old:
        sys.exit(f"mutants.py: {path}:{line}:{col} does not read {old!r}")
    lines[line - 1] = text[:col] + new + text[col + len(old):]
    with open(path, "w", encoding="utf-8", newline="") as f:
        f.write("\n".join(lines))


def ninja_builds(build_dir):
    """(outputs, rule, explicit inputs, all inputs) of every build statement."""
    with open(os.path.join(build_dir, "build.ninja"), encoding="utf-8") as f:
        text = f.read().replace("$\n", "")
    for line in text.split("\n"):
        if not line.startswith("build "):
            continue
        head, _, rest = line[6:].partition(": ")
        parts = rest.split()
        if not parts:
            continue
        inputs = [p for p in parts[1:] if p not in ("|", "||")]
        explicit = []
        for p in parts[1:]:
            if p in ("|", "||"):
                break
            explicit.append(p)
        yield head.split(), parts[0], explicit, inputs


def cmd_objects(build_dir, source):
    source = os.path.abspath(source)
    builds = list(ninja_builds(build_dir))
    obj = next((outs[0] for outs, rule, explicit, _ in builds
                if rule.startswith("CXX_COMPILER") and source in explicit), None)
    if obj is None:
        sys.exit(f"mutants.py: no object for {source} in {build_dir}")
    lib = next((outs[0] for outs, rule, explicit, _ in builds
                if rule.startswith("CXX_STATIC_LIBRARY_LINKER") and obj in explicit), None)
    print(obj)
    pattern = re.compile(os.environ.get("MUTATE_TESTS", r"^tests/(core|raster)/.*_tests$"))
    for outs, rule, explicit, inputs in builds:
        if rule.startswith("CXX_EXECUTABLE_LINKER") and pattern.search(outs[0]) and (
                obj in inputs or (lib and lib in inputs)):
            print(outs[0])


def cmd_covered(build_dir, source):
    """Lines reached / lines not reached, by gcov on the object's .gcda (JSON format).

    In an optimised build neither of gcov's counts is exact alone: a line can read 0 while it
    ran (its code merged into the lines of a callee inlined into it), and so can a function
    (inlined early, before the counters were placed, its counts land in its callers). A line
    is reached when its own count or its innermost function's (a lambda is its own) is above
    0, or when it lies in no function; not reached when both are 0."""
    source = os.path.abspath(source)
    build_dir = os.path.abspath(build_dir)
    builds = list(ninja_builds(build_dir))
    obj = next((outs[0] for outs, rule, explicit, _ in builds
                if rule.startswith("CXX_COMPILER") and source in explicit), None)
    gcda = os.path.join(build_dir, obj[:-2] + ".gcda") if obj else ""
    if not obj or not os.path.exists(gcda):
        # Nothing known: every line counts as reached.
        print(f"mutants.py: no coverage data for {source}", file=sys.stderr)
        print("\n")
        return
    out = subprocess.run(["gcov", "--json-format", "--stdout", gcda], capture_output=True,
                         text=True, check=True, cwd=build_dir).stdout
    ranges = defaultdict(int)  # (first, last) -> runs, template instances summed
    line_runs = defaultdict(int)
    for doc in out.splitlines():
        if not doc.strip().startswith("{"):
            continue
        for f in json.loads(doc).get("files", []):
            if os.path.abspath(os.path.join(build_dir, f["file"])) != source:
                continue
            for fn in f.get("functions", []):
                ranges[(fn["start_line"], fn["end_line"])] += fn["execution_count"]
            for ln in f.get("lines", []):
                line_runs[ln["line_number"]] += ln["count"]
    with open(source, encoding="utf-8") as f:
        count = sum(1 for _ in f)
    executed, never = [], []
    for line in range(1, count + 1):
        around = [r for r in ranges if r[0] <= line <= r[1]]
        if not around:
            continue
        inner = min(around, key=lambda r: r[1] - r[0])
        ran = ranges[inner] > 0 or line_runs[line] > 0
        (executed if ran else never).append(line)
    print(" ".join(str(n) for n in executed))
    print(" ".join(str(n) for n in never))


# Calls that change only a container's capacity: removing one cannot change any value.
CAPACITY_ONLY = re.compile(r"^[\w.\[\]>-]+\.(reserve|shrink_to_fit)\(.*\);$")
EQUIVALENTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mutation-equivalents.tsv")


def equivalents():
    """Rows of mutation-equivalents.tsv: (file, line text, column in it, old, new) -> why.

    A mutant is named by its line's text (stripped), not its number, so that the entry holds
    while lines above it come and go; the column counts from the text's first character."""
    known = {}
    if not os.path.exists(EQUIVALENTS):
        return known
    with open(EQUIVALENTS, encoding="utf-8") as f:
        for number, row in enumerate(f, start=1):
            if not row.strip() or row.startswith("#"):
                continue
            fields = row.rstrip("\n").split("\t")
            if len(fields) != 6 or not fields[2].isdigit():
                print(f"{EQUIVALENTS}:{number}: expected 6 tab-separated fields (file, line "
                      f"text, column, old, new, why), got {len(fields)}", file=sys.stderr)
                sys.exit(2)
            known[tuple(fields[:2]) + (int(fields[2]),) + tuple(fields[3:5])] = fields[5]
    return known


def cmd_argued(path, line, col, old, new):
    if old.endswith(";") and new == ";" and CAPACITY_ONLY.match(old):
        print("only a container's capacity changes")
        return 0
    with open(path, encoding="utf-8") as f:
        text = f.read().split("\n")[line - 1]
    indent = len(text) - len(text.lstrip())
    why = equivalents().get((path, text.strip(), col - indent, old, new))
    if why:
        print(why)
        return 0
    return 1


def score_row(name, c):
    """One table row: the counts, and killed (timeouts included) over the mutants judged
    (made less those never run: equivalent, argued, not reached, not compiled)."""
    made = sum(c.values())
    judged = made - c["equivalent"] - c["argued"] - c["not-reached"] - c["build-failed"]
    score = f"{100.0 * (c['killed'] + c['timeout']) / judged:.0f} %" if judged else "-"
    return (f"| {name} | {made} | {c['killed']} | {c['timeout']} | {c['survived']} |"
            f" {c['build-failed']} | {c['equivalent']} | {c['argued']} | {c['not-reached']} |"
            f" {score} |\n")


def cmd_report(results, out_md):
    rows = [line.rstrip("\n").split("\t") for line in open(results, encoding="utf-8")
            if line.strip() and not line.startswith("#")]
    folders = defaultdict(lambda: defaultdict(int))
    total = defaultdict(int)
    times = []
    for r in rows:
        path, status, seconds = r[0], r[6], float(r[7])
        folders[os.path.dirname(path)][status] += 1
        total[status] += 1
        if status not in ("not-reached", "argued"):
            times.append(seconds)
    with open(out_md, "w", encoding="utf-8") as f:
        f.write("# Mutation run\n\n")
        f.write("| folder | made | killed | timed out | survived | build failed | equivalent |"
                " argued | not reached | score |\n|---|---|---|---|---|---|---|---|---|---|\n")
        for folder in sorted(folders):
            f.write(score_row(folder, folders[folder]))
        f.write(score_row("all", total))
        if times:
            f.write(f"\n{len(times)} mutants built and judged, {sum(times):.0f} s in all,"
                    f" {sum(times) / len(times):.0f} s each on average.\n")
        for status, title in (("survived", "Survivors"), ("argued", "Argued equivalent")):
            listed = [r for r in rows if r[6] == status]
            if listed:
                f.write(f"\n## {title}\n\n")
                for r in listed:
                    why = f": {r[9]}" if status == "argued" and len(r) > 9 else ""
                    f.write(f"- `{r[0]}:{r[1]}` ({r[3]}): `{r[4]}` -> `{r[5]}`{why}\n")


def main(argv):
    if not argv:
        sys.exit(__doc__)
    cmd, args = argv[0], argv[1:]
    if cmd == "list":
        cmd_list(args)
    elif cmd == "sample":
        cmd_sample(int(args[0]), int(args[1]))
    elif cmd == "changed":
        cmd_changed(args[0], args[1:])
    elif cmd == "apply":
        cmd_apply(args[0], int(args[1]), int(args[2]), args[3], args[4])
    elif cmd == "objects":
        cmd_objects(args[0], args[1])
    elif cmd == "covered":
        cmd_covered(args[0], args[1])
    elif cmd == "argued":
        sys.exit(cmd_argued(args[0], int(args[1]), int(args[2]), args[3], args[4]))
    elif cmd == "report":
        cmd_report(args[0], args[1])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
