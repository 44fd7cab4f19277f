#!/usr/bin/env python3
"""The mutation runner's helper (scripts/mutate.sh runs it; see docs/verification.md).

Subcommands:
  list FILE...             every mutant of the files, one row each (the key columns)
  operators                the mutation operators, one a line: its name and what it changes
  header [keys]            the header line of a results file (COLUMNS), or with `keys` of a
                           list (KEY_COLUMNS)
  row NAME=VALUE...        one results row, the values named by their column (every column once)
  keys                     reads rows (list rows or a results file) on stdin and prints their key
                           columns: the mutants they name, as list prints them
  with-status STATUS...    reads a results file on stdin and prints its header and the rows with
                           one of the statuses (e.g. `with-status survived < results.tsv`)
  files                    reads rows on stdin and prints their files, each once
  sample N SEED            reads list rows on stdin, keeps N of them, each file its share by
                           lines (the seed and the rows fix the choice, not the rows' order)
  changed BASE             reads list rows on stdin and keeps those on lines of their file that
                           differ from git BASE (the working tree included)
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
  report TSV OUT_MD        the markdown summary of a results file, per folder

A mutant is one textual change of one line: OLD at column COL (0-based) becomes NEW. The
operators (OPERATORS) work on clang-formatted C++ (binary operators have a space on each side),
in the code part of a line (not in comments, string literals or preprocessor lines).

Rows are tab-separated, one a line, their columns those of COLUMNS in that order; a list row has
the key columns alone (KEY_COLUMNS, the first six), a results row all of them. Lines starting
with "#" (the header) are not rows.
"""

import json
import math
import os
import random
import re
import subprocess
import sys
from collections import defaultdict, namedtuple

# A results row's columns. The first six name the mutant (a list row is those alone); mutate.sh
# names the others when it records a mutant's outcome (`row`).
COLUMNS = ("file", "line", "column", "operator", "original", "mutant",
           "status", "seconds", "tests", "note")
KEY_COLUMNS = COLUMNS[:6]

# The outcomes of a mutant, in the report's column order. `built`: its object was compiled (the
# report's times count those); `counts_as`: "killed" or "survived" for the mutants the score
# judges (a timeout is a kill), None for those it leaves out.
Status = namedtuple("Status", "name heading built counts_as")
STATUSES = (
    Status("killed", "killed", True, "killed"),
    Status("timeout", "timed out", True, "killed"),
    Status("survived", "survived", True, "survived"),
    Status("build-failed", "build failed", True, None),
    Status("equivalent", "equivalent", True, None),
    Status("argued", "argued", False, None),
    Status("not-reached", "not reached", False, None),
)
STATUS_NAMES = tuple(s.name for s in STATUSES)

COMPARISONS = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "=="}
ARITHMETIC = {"+": "-", "-": "+", "*": "/", "/": "*", "&&": "||", "||": "&&",
              "+=": "-=", "-=": "+="}
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
    """The literal moved by one (integers) or by its last bit (doubles); None when it is not
    moved (an octal integer, a float or long double literal)."""
    if re.fullmatch(r"\d+", text):
        if len(text) > 1 and text.startswith("0"):
            return None  # octal
        return str(int(text) + 1) + suffix
    if suffix:
        return None  # a float or long double literal: its last bit is not a double's
    return repr(math.nextafter(float(text), math.inf))


# The operators. Each takes a line's code part (code_part) and the code part of the last line
# before it that has code (";" before the first) and returns its mutants of the line as (column,
# the text replaced, its replacement); its name (`_` written `-`) is the results' operator.

BINARY = re.compile(r" (<=|>=|==|!=|<|>|&&|\|\||\+|-|\*|/|\+=|-=) ")


def binary(code, changes):
    """The binary operators of the line that `changes` has, each replaced by its partner."""
    return [(m.start(1), m.group(1), changes[m.group(1)]) for m in BINARY.finditer(code)
            if m.group(1) in changes]


def comparison(code, previous):
    """`<` <-> `<=`, `>` <-> `>=`, `==` <-> `!=`"""
    return binary(code, COMPARISONS)


def arithmetic(code, previous):
    """`+` <-> `-`, `*` <-> `/`, `+=` <-> `-=`, `&&` <-> `||`"""
    return binary(code, ARITHMETIC)


def constant(code, previous):
    """an integer moved by one; a double literal moved by its last bit (the next double up)"""
    moved = ((m, moved_constant(m.group(1), m.group(2))) for m in NUMBER.finditer(code))
    return [(m.start(), m.group(0), new) for m, new in moved if new]


def rounding(code, previous):
    """a `+ (... & 1u)` term or a `+ 0.5` / `- 0.5` dropped"""
    return [(m.start(), m.group(0), "")
            for m in re.finditer(r" \+ \([^()]*& 1u?\)| [+-] 0\.5(?![\d.])", code)]


def negation(code, previous):
    """the condition of an `if` or `while` negated (when it closes on the same line)"""
    found = []
    for m in re.finditer(r"\b(if|while) \(", code):
        open_at = m.end() - 1
        close = matching_paren(code, open_at)
        if close > open_at:
            cond = code[open_at + 1:close]
            found.append((open_at, "(" + cond + ")", "(!(" + cond + "))"))
    return found


def starts_statement(previous):
    """Whether the line after `previous` starts a statement (is not the rest of one)."""
    return not previous.strip() or previous.rstrip().endswith((";", "{", "}", ":"))


def call_ignored(code, previous):
    """`x = f(...);` becomes `(void)f(...);` (x keeps its old value)"""
    m = re.fullmatch(r"(\s*)([A-Za-z_][\w.\[\]>-]*) = ([A-Za-z_][\w:.]*\(.*\));\s*", code)
    if not m or m.group(2) in CONTROL or not starts_statement(previous):
        return []
    return [(len(m.group(1)), code.strip(), "(void)" + m.group(3) + ";")]


def statement(code, previous):
    """a whole assignment, increment or call statement removed (when one line holds it)"""
    m = re.fullmatch(
        r"(\s*)((?:\+\+|--)?[A-Za-z_][\w.\[\]>:-]*"
        r"(?: (?:=|\+=|-=|\*=|/=|\|=|&=) .*|\(.*\)|\+\+|--));\s*", code)
    if (not m or m.group(2).split("(")[0].split(" ")[0].lstrip("+-") in CONTROL
            or not starts_statement(previous)):
        return []
    return [(len(m.group(1)), m.group(2) + ";", ";")]


OPERATORS = [comparison, arithmetic, constant, rounding, negation, call_ignored, statement]


def operator_name(operator):
    return operator.__name__.replace("_", "-")


def mutable(code):
    """Whether a line's code part is one the operators change: not blank, not a preprocessor
    line, not a static_assert (its conditions are checked by the compiler, not the tests)."""
    stripped = code.strip()
    return bool(stripped) and not stripped.startswith(("#", "static_assert"))


def list_mutants(files):
    """Every mutant of the files: (file, line, column, operator, original, mutant)."""
    rows = []
    for path in files:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        previous = ";"
        for number, line in enumerate(lines, start=1):
            code = code_part(line)
            if mutable(code):
                for operator in OPERATORS:
                    for col, old, new in operator(code, previous):
                        if line[col:col + len(old)] == old:  # not blanked text (a literal's)
                            rows.append((path, number, col, operator_name(operator), old, new))
            if code.strip():
                previous = code
    return rows


def cmd_operators():
    for operator in OPERATORS:
        doc = " ".join(operator.__doc__.split())
        print(f"{operator_name(operator):<14}{doc}")


def tsv(fields):
    return "\t".join(str(f).replace("\t", " ").replace("\n", " ") for f in fields)


def read_rows(stream, results=False):
    """The rows of a list or results file as dicts by column name. With `results`, every row
    must have all the columns and a known status."""
    rows = []
    name = getattr(stream, "name", "<stdin>")
    for number, line in enumerate(stream, start=1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.rstrip("\n").split("\t")
        widths = (len(COLUMNS),) if results else (len(KEY_COLUMNS), len(COLUMNS))
        if len(fields) not in widths:
            sys.exit(f"mutants.py: {name}:{number}: {len(fields)} tab-separated fields; a list "
                     f"row has {len(KEY_COLUMNS)} ({', '.join(KEY_COLUMNS)}), a results row "
                     f"{len(COLUMNS)} (those, {', '.join(COLUMNS[len(KEY_COLUMNS):])})"
                     + (", and a results row is needed here" if results else ""))
        row = dict(zip(COLUMNS, fields))
        if results and row["status"] not in STATUS_NAMES:
            sys.exit(f"mutants.py: {name}:{number}: status {row['status']!r} is none of "
                     f"{', '.join(STATUS_NAMES)}")
        rows.append(row)
    return rows


def row_text(row):
    """A row (all columns, or the key columns alone) as a line of a TSV file."""
    return tsv(row[c] for c in COLUMNS if c in row)


def cmd_list(files):
    for row in list_mutants(files):
        print(tsv(row))


def cmd_header(which=()):
    if list(which) not in ([], ["keys"]):
        sys.exit(f"mutants.py header: {' '.join(which)}: expected nothing or `keys`")
    print("#" + "\t".join(KEY_COLUMNS if which else COLUMNS))


def cmd_row(assignments):
    values = {}
    for assignment in assignments:
        name, equals, value = assignment.partition("=")
        if not equals or name not in COLUMNS or name in values:
            sys.exit(f"mutants.py row: {assignment!r}: expected NAME=VALUE, NAME one of "
                     f"{', '.join(COLUMNS)}, each once")
        values[name] = value
    missing = [c for c in COLUMNS if c not in values]
    if missing:
        sys.exit(f"mutants.py row: no value for {', '.join(missing)}")
    if values["status"] not in STATUS_NAMES:
        sys.exit(f"mutants.py row: status {values['status']!r} is none of "
                 f"{', '.join(STATUS_NAMES)}")
    print(row_text(values))


def cmd_keys():
    for row in read_rows(sys.stdin):
        print(tsv(row[c] for c in KEY_COLUMNS))


def cmd_with_status(statuses):
    unknown = [s for s in statuses if s not in STATUS_NAMES]
    if not statuses or unknown:
        sys.exit(f"mutants.py with-status: {' '.join(unknown) or 'no status'}: expected one or "
                 f"more of {', '.join(STATUS_NAMES)}")
    cmd_header()
    for row in read_rows(sys.stdin, results=True):
        if row["status"] in statuses:
            print(row_text(row))


def cmd_files():
    for path in dict.fromkeys(row["file"] for row in read_rows(sys.stdin)):
        print(path)


def cmd_sample(n, seed):
    """Each file's share of N by its code lines. A file's mutants are drawn from in (line,
    column, operator, original, mutant) order, so the choice depends on the seed and the set of
    mutants only, not on the order the rows come in."""
    by_file = defaultdict(list)
    for row in read_rows(sys.stdin):
        by_file[row["file"]].append(row)
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

    def place(r):
        return (int(r["line"]), int(r["column"]), r["operator"], r["original"], r["mutant"])

    for p in sorted(by_file):
        for row in sorted(rng.sample(sorted(by_file[p], key=place), counts[p]), key=place):
            print(row_text(row))


def changed_lines(base, path):
    """The lines of the file (as it is now) that differ from git BASE."""
    diff = subprocess.run(["git", "diff", "-U0", base, "--", path], capture_output=True,
                          text=True)
    if diff.returncode != 0:
        sys.exit(f"mutants.py changed: git diff -U0 {base} -- {path}: {diff.stderr.strip()}")
    for m in re.finditer(r"^@@ -\S+ \+(\d+)(?:,(\d+))? @@", diff.stdout, re.M):
        start, count = int(m.group(1)), int(m.group(2) or "1")
        yield from range(start, start + count)


def cmd_changed(base):
    rows = read_rows(sys.stdin)
    changed = {(path, line) for path in dict.fromkeys(row["file"] for row in rows)
               for line in changed_lines(base, path)}
    for row in rows:
        if (row["file"], int(row["line"])) in changed:
            print(row_text(row))


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


def object_of(builds, source):
    """The object compiled from the source (an absolute path), None when there is none."""
    return next((outs[0] for outs, rule, explicit, _ in builds
                 if rule.startswith("CXX_COMPILER") and source in explicit), None)


def cmd_objects(build_dir, source):
    source = os.path.abspath(source)
    builds = list(ninja_builds(build_dir))
    obj = object_of(builds, source)
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
    obj = object_of(list(ninja_builds(build_dir)), source)
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


def score_row(name, counts):
    """One table row: the mutants made, their count for each status, and the score: killed
    (timeouts included) over the mutants judged (killed, timed out or survived; those not
    built, not compiled or compiled to the same object are left out)."""
    made = sum(counts.values())
    judged = {kind: sum(counts[s.name] for s in STATUSES if s.counts_as == kind)
              for kind in ("killed", "survived")}
    scored = judged["killed"] + judged["survived"]
    score = f"{100.0 * judged['killed'] / scored:.0f} %" if scored else "-"
    cells = [name, made] + [counts[s.name] for s in STATUSES] + [score]
    return "| " + " | ".join(str(cell) for cell in cells) + " |\n"


def cmd_report(results, out_md):
    with open(results, encoding="utf-8") as f:
        rows = read_rows(f, results=True)
    built = {s.name for s in STATUSES if s.built}
    folders = defaultdict(lambda: defaultdict(int))
    total = defaultdict(int)
    times = []
    for row in rows:
        folders[os.path.dirname(row["file"])][row["status"]] += 1
        total[row["status"]] += 1
        if row["status"] in built:
            times.append(float(row["seconds"]))
    headings = ["folder", "made"] + [s.heading for s in STATUSES] + ["score"]
    with open(out_md, "w", encoding="utf-8") as f:
        f.write("# Mutation run\n\n")
        f.write("| " + " | ".join(headings) + " |\n|" + "---|" * len(headings) + "\n")
        for folder in sorted(folders):
            f.write(score_row(folder, folders[folder]))
        f.write(score_row("all", total))
        if times:
            f.write(f"\n{len(times)} mutants built and judged, {sum(times):.0f} s in all,"
                    f" {sum(times) / len(times):.0f} s each on average.\n")
        for status, title in (("survived", "Survivors"), ("argued", "Argued equivalent")):
            listed = [row for row in rows if row["status"] == status]
            if listed:
                f.write(f"\n## {title}\n\n")
                for r in listed:
                    why = f": {r['note']}" if status == "argued" else ""
                    f.write(f"- `{r['file']}:{r['line']}` ({r['operator']}): `{r['original']}`"
                            f" -> `{r['mutant']}`{why}\n")


# Each subcommand: its function and how its arguments are read (None: all of them, as strings).
SUBCOMMANDS = {
    "list": (cmd_list, None),
    "operators": (cmd_operators, ()),
    "header": (cmd_header, None),
    "row": (cmd_row, None),
    "keys": (cmd_keys, ()),
    "with-status": (cmd_with_status, None),
    "files": (cmd_files, ()),
    "sample": (cmd_sample, (int, int)),
    "changed": (cmd_changed, (str,)),
    "apply": (cmd_apply, (str, int, int, str, str)),
    "objects": (cmd_objects, (str, str)),
    "covered": (cmd_covered, (str, str)),
    "argued": (cmd_argued, (str, int, int, str, str)),
    "report": (cmd_report, (str, str)),
}


def main(argv):
    if not argv or argv[0] not in SUBCOMMANDS:
        sys.exit(__doc__)
    function, types = SUBCOMMANDS[argv[0]]
    args = argv[1:]
    if types is None:
        return function(args)
    if len(args) != len(types):
        sys.exit(f"mutants.py {argv[0]}: expected {len(types)} arguments, got {len(args)}\n\n"
                 + __doc__)
    return function(*(t(a) for t, a in zip(types, args)))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
