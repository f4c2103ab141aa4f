#!/usr/bin/env python3
"""Runs the commands shown in the documentation and compares their output.

    docs_commands.py REPOSITORY_ROOT BUILD_DIR

Reads README.md, docs/*.md and every examples/**/README.md.  In a fenced
block tagged `sh` (a line "```sh"):

- a line starting with "$ " is a command, run by /bin/sh from the repository
  root, where build/ is the actual build directory BUILD_DIR;
- the lines after it, up to the next "$ " line or the end of the block, are
  its expected stdout, compared line by line (trailing blanks ignored):
  a line ending in " ..." matches any line that starts with what precedes
  the " ..." (so a prefix may end in the middle of a word or a JSON
  line), and a line that is exactly "..." matches any number of lines;
- exit code: a line "# exit N" among the expected lines (not part of the
  output) says that the command exits with N; without one it must exit 0.

Blocks with other tags (or none), and lines of an `sh` block before its
first "$ " line, are not run: commands that need the network, root or a
package install (git clone, make demo, apt-get) are written without the
"$ " prompt or in such blocks.

The commands run in a fresh temporary directory holding a symbolic link to
every entry of the repository root (and `build` to BUILD_DIR), so files
they write (certificates) do not land in the repository.  Each command has
60 seconds.

On a mismatch it prints the file, line, command, expected and actual output.
Its last line is "N passed, M failed"; it exits 1 when anything failed (or
no command was found), 0 otherwise.  Python 3 standard library only.
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

TIMEOUT_SECONDS = 60
EXIT_LINE = re.compile(r"^# exit (\d+)$")


def documents(root):
    """The documentation files whose `sh` blocks are run, in a fixed order."""
    files = [os.path.join(root, "README.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    files += sorted(glob.glob(os.path.join(root, "examples", "**", "README.md"), recursive=True))
    return [f for f in files if os.path.isfile(f)]


class Command:
    def __init__(self, path, line, text):
        self.path = path      # the document
        self.line = line      # 1-based line of the "$ " line
        self.text = text      # the command
        self.expected = []    # expected stdout lines (patterns)
        self.exit_code = 0


def commands_of(path):
    """Every "$ " command of the `sh` blocks of one document."""
    out = []
    in_block = False
    runnable = False
    current = None
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, start=1):
            line = raw.rstrip("\n").rstrip()
            if line.lstrip().startswith("```"):
                if in_block:
                    in_block = False
                    current = None
                else:
                    in_block = True
                    runnable = line.strip() == "```sh"
                continue
            if not in_block or not runnable:
                continue
            if line.startswith("$ "):
                current = Command(path, number, line[2:])
                out.append(current)
            elif current is not None:
                m = EXIT_LINE.match(line)
                if m:
                    current.exit_code = int(m.group(1))
                else:
                    current.expected.append(line)
    return out


def line_matches(pattern, actual):
    if pattern.endswith(" ..."):
        return actual.startswith(pattern[:-4])
    return actual == pattern


def lines_match(patterns, actual):
    """Whether the actual lines match the expected patterns ("..." lines
    match any number of lines)."""
    # match[i][j]: patterns[i:] matches actual[j:]
    n, m = len(patterns), len(actual)
    match = [[False] * (m + 1) for _ in range(n + 1)]
    match[n][m] = True
    for i in range(n - 1, -1, -1):
        for j in range(m, -1, -1):
            if patterns[i] == "...":
                match[i][j] = match[i + 1][j] or (j < m and match[i][j + 1])
            else:
                match[i][j] = j < m and line_matches(patterns[i], actual[j]) and match[i + 1][j + 1]
    return match[0][0]


def sandbox(root, build):
    """A temporary directory linking to every entry of the repository root,
    with build -> BUILD_DIR."""
    work = tempfile.mkdtemp(prefix="tmcert-docs-")
    for entry in os.listdir(root):
        if entry == "build":
            continue
        os.symlink(os.path.join(root, entry), os.path.join(work, entry))
    os.symlink(build, os.path.join(work, "build"))
    return work


def main(argv):
    if len(argv) != 3:
        print("usage: docs_commands.py REPOSITORY_ROOT BUILD_DIR", file=sys.stderr)
        return 2
    root = os.path.abspath(argv[1])
    build = os.path.abspath(argv[2])
    commands = [c for path in documents(root) for c in commands_of(path)]
    work = sandbox(root, build)
    passed = failed = 0
    try:
        for c in commands:
            where = "%s:%d" % (os.path.relpath(c.path, root), c.line)
            try:
                run = subprocess.run(c.text, shell=True, cwd=work, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, timeout=TIMEOUT_SECONDS)
                stdout = run.stdout.decode("utf-8", "replace")
                stderr = run.stderr.decode("utf-8", "replace")
                code = run.returncode
            except subprocess.TimeoutExpired:
                stdout, stderr, code = "", "(timed out after %d s)" % TIMEOUT_SECONDS, None
            actual = [line.rstrip() for line in stdout.splitlines()]
            problems = []
            if code != c.exit_code:
                problems.append("exit code %s, expected %d" % (code, c.exit_code))
            if not lines_match(c.expected, actual):
                problems.append("stdout differs")
            if not problems:
                passed += 1
                continue
            failed += 1
            print("FAIL %s: $ %s" % (where, c.text))
            print("  " + "; ".join(problems))
            print("  expected:")
            for line in c.expected:
                print("    | " + line)
            print("  actual:")
            for line in actual:
                print("    | " + line)
            if stderr.strip():
                print("  stderr:")
                for line in stderr.splitlines()[:10]:
                    print("    | " + line)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if not commands:
        print("no commands found in the documentation")
        failed += 1
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
