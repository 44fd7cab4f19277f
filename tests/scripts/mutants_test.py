#!/usr/bin/env python3
"""scripts/mutants.py, the mutation runner's helper: the mutants each operator makes of a small
C++ snippet (written out by hand), the results' columns from `header` and `row` read back by
name, the report's table, and a sample that does not depend on the order of its rows."""

import contextlib
import importlib.util
import io
import os
import random
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                      "mutants.py")
spec = importlib.util.spec_from_file_location("mutants", SCRIPT)
mutants = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mutants)

SNIPPET = """#define LIMIT 3
static_assert(2 > 1);
int clampSum(int a, int b) {
  if (a < b && b != 0)
    a = combine(a, b);
  total += a * 2;
  a = combine(a, b);
  double h = a + 0.5;
  float k = 1.0f * 3u;
  return (a + (b & 1u)) / 2 + 010;
  while (n > 0) --n;
  count++;
  log("a * b 7");
  int r =
      g(a);
  // 5 < 6
}
"""

# (line, column, operator, original, mutant). Lines 1-3, 5 (the body of an `if` without braces:
# the rest of a statement), 13 (a string literal), 14-15 (one statement on two lines), 16 (a
# comment) and 17 have none; 010 (octal) and 1.0f (a float) are not moved.
EXPECTED = {
    (4, 8, "comparison", "<", "<="),
    (4, 17, "comparison", "!=", "=="),
    (4, 12, "arithmetic", "&&", "||"),
    (4, 20, "constant", "0", "1"),
    (4, 5, "negation", "(a < b && b != 0)", "(!(a < b && b != 0))"),
    (6, 8, "arithmetic", "+=", "-="),
    (6, 13, "arithmetic", "*", "/"),
    (6, 15, "constant", "2", "3"),
    (6, 2, "statement", "total += a * 2;", ";"),
    (7, 2, "call-ignored", "a = combine(a, b);", "(void)combine(a, b);"),
    (7, 2, "statement", "a = combine(a, b);", ";"),
    (8, 15, "arithmetic", "+", "-"),
    (8, 17, "constant", "0.5", "0.5000000000000001"),
    (8, 14, "rounding", " + 0.5", ""),
    (9, 17, "arithmetic", "*", "/"),
    (9, 19, "constant", "3u", "4u"),
    (10, 12, "arithmetic", "+", "-"),
    (10, 24, "arithmetic", "/", "*"),
    (10, 28, "arithmetic", "+", "-"),
    (10, 19, "constant", "1u", "2u"),
    (10, 26, "constant", "2", "3"),
    (10, 11, "rounding", " + (b & 1u)", ""),
    (11, 11, "comparison", ">", ">="),
    (11, 13, "constant", "0", "1"),
    (11, 8, "negation", "(n > 0)", "(!(n > 0))"),
    (12, 2, "statement", "count++;", ";"),
}


def run(*args, stdin=""):
    """The subcommand's exit status, output and error output (run in this process: a Python
    start costs more than most of these tests)."""
    out, err = io.StringIO(), io.StringIO()
    saved_stdin, sys.stdin = sys.stdin, io.StringIO(stdin)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            rc = mutants.main(list(args)) or 0
    except SystemExit as e:
        rc = e.code if isinstance(e.code, int) else 1
        err.write("" if isinstance(e.code, int) or e.code is None else str(e.code))
    finally:
        sys.stdin = saved_stdin
    return rc, out.getvalue(), err.getvalue()


def run_program(*args, stdin=""):
    """The same as a program, as scripts/mutate.sh runs it."""
    done = subprocess.run([sys.executable, SCRIPT, *args], input=stdin, capture_output=True,
                          text=True)
    return done.returncode, done.stdout, done.stderr


class Operators(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.path = os.path.join(self.dir.name, "snippet.cpp")
        with open(self.path, "w", encoding="utf-8") as f:
            f.write(SNIPPET)

    def tearDown(self):
        self.dir.cleanup()

    def test_the_snippets_mutants_are_the_hand_written_ones(self):
        rc, out, err = run("list", self.path)
        self.assertEqual(rc, 0, err)
        rows = [line.split("\t") for line in out.splitlines()]
        self.assertTrue(all(r[0] == self.path for r in rows))
        got = [(int(r[1]), int(r[2]), r[3], r[4], r[5]) for r in rows]
        self.assertEqual(len(got), len(set(got)), "a mutant listed twice")
        self.assertEqual(set(got), EXPECTED)

    def test_each_operator_is_listed_with_what_it_changes(self):
        rc, out, _ = run("operators")
        self.assertEqual(rc, 0)
        names = [line.split()[0] for line in out.splitlines()]
        self.assertEqual(names, ["comparison", "arithmetic", "constant", "rounding", "negation",
                                 "call-ignored", "statement"])

    def test_a_statement_is_removed_only_from_the_line_that_starts_it(self):
        for previous, starts in ((";", True), ("  x = 1;", True), ("  {", True), ("  }", True),
                                 ("  case 2:", True), ("", True), ("  if (a)", False),
                                 ("  int r =", False), ("  f(a,", False)):
            got = mutants.statement("  a = combine(a, b);", previous)
            self.assertEqual(bool(got), starts, previous)
            got = mutants.call_ignored("  a = combine(a, b);", previous)
            self.assertEqual(bool(got), starts, previous)

    def test_a_sample_does_not_depend_on_the_order_of_its_rows(self):
        _, out, _ = run("list", self.path)
        rows = out.splitlines()
        shuffled = rows[:]
        random.Random(5).shuffle(shuffled)
        self.assertNotEqual(rows, shuffled)
        first = run("sample", "7", "3", stdin="\n".join(rows) + "\n")
        second = run("sample", "7", "3", stdin="\n".join(shuffled) + "\n")
        self.assertEqual(first[0], 0, first[2])
        self.assertEqual(len(first[1].splitlines()), 7)
        self.assertEqual(first[1], second[1])


ROW = {"file": "core/a/src/x.cpp", "line": "12", "column": "4", "operator": "constant",
       "original": "2", "mutant": "3", "status": "killed", "seconds": "3.5",
       "tests": "tests/core/a_tests tests/core/b_tests", "note": "tests/core/a_tests: a case"}


class Rows(unittest.TestCase):
    def test_a_row_written_by_name_reads_back_by_name(self):
        # Named in another order than the columns'.
        rc, row, err = run_program("row", *(f"{k}={v}" for k, v in reversed(list(ROW.items()))))
        self.assertEqual(rc, 0, err)
        rc, header, _ = run_program("header")
        self.assertEqual(header.rstrip("\n").lstrip("#").split("\t"), list(ROW))
        rows = mutants.read_rows(iter([header, row]), results=True)
        self.assertEqual(rows, [ROW])

    def test_keys_are_a_results_rows_mutant_as_list_prints_it(self):
        _, header, _ = run("header")
        _, row, _ = run("row", *(f"{k}={v}" for k, v in ROW.items()))
        rc, keys, _ = run("keys", stdin=header + row)
        self.assertEqual(rc, 0)
        self.assertEqual(keys, "core/a/src/x.cpp\t12\t4\tconstant\t2\t3\n")
        _, key_header, _ = run("header", "keys")
        self.assertEqual(key_header, "#file\tline\tcolumn\toperator\toriginal\tmutant\n")

    def test_with_status_keeps_the_rows_of_those_statuses(self):
        _, header, _ = run("header")
        lines = [run("row", *(f"{k}={v}" for k, v in dict(ROW, line=str(n), status=s).items()))[1]
                 for n, s in ((1, "killed"), (2, "survived"), (3, "not-reached"))]
        rc, out, _ = run("with-status", "survived", "not-reached", stdin=header + "".join(lines))
        self.assertEqual(rc, 0)
        self.assertEqual(out, header + lines[1] + lines[2])

    def test_a_row_with_a_column_missing_twice_or_unknown_is_refused(self):
        named = [f"{k}={v}" for k, v in ROW.items()]
        for args, says in ((named[:-1], "no value for note"),
                           (named + ["note=again"], "'note=again'"),
                           (named[:6] + ["status=lost"] + named[7:], "status 'lost'")):
            rc, out, err = run("row", *args)
            self.assertNotEqual(rc, 0)
            self.assertEqual(out, "")
            self.assertIn(says, err)

    def test_a_results_row_of_the_wrong_width_names_its_line(self):
        rc, _, err = run("with-status", "killed",
                         stdin="#header\n" + "\t".join(ROW.values()) + "\nshort\trow\n")
        self.assertNotEqual(rc, 0)
        self.assertIn("<stdin>:3: 2 tab-separated fields", err)


class Report(unittest.TestCase):
    def test_the_table_counts_each_status_and_scores_the_judged(self):
        with tempfile.TemporaryDirectory() as d:
            results = os.path.join(d, "results.tsv")
            statuses = ["killed", "killed", "timeout", "survived", "argued", "not-reached",
                        "build-failed", "equivalent"]
            with open(results, "w", encoding="utf-8") as f:
                f.write(run("header")[1])
                for n, status in enumerate(statuses):
                    f.write(run("row", *(f"{k}={v}" for k, v in
                                         dict(ROW, line=str(n), status=status).items()))[1])
            rc, _, err = run("report", results, os.path.join(d, "report.md"))
            self.assertEqual(rc, 0, err)
            with open(os.path.join(d, "report.md"), encoding="utf-8") as f:
                lines = f.read().splitlines()
        self.assertIn("| folder | made | killed | timed out | survived | build failed |"
                      " equivalent | argued | not reached | score |", lines)
        # 3 killed (a timeout counts) of 4 judged.
        self.assertIn("| core/a/src | 8 | 2 | 1 | 1 | 1 | 1 | 1 | 1 | 75 % |", lines)
        self.assertIn("| all | 8 | 2 | 1 | 1 | 1 | 1 | 1 | 1 | 75 % |", lines)
        # Built and judged: all but the argued and the not reached, 3.5 s each.
        self.assertIn("6 mutants built and judged, 21 s in all, 4 s each on average.", lines)


if __name__ == "__main__":
    unittest.main()
