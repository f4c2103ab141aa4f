#!/usr/bin/env python3
"""The layer check: every #include "..." of kernels/, include/ and src/<folder>/
must point to the same folder or to one the folder may use (cmake/layers.txt,
read with the dependencies' own dependencies: a layer may use everything
below the layers it names); the folders' include graph must have no cycle;
and the include closure of the certificate checker (its files named in the
table) must not reach the folders the table forbids it.

    python3 scripts/check_layers.py [--quiet] [ROOT]   # exit 0 clean, 1 violations

--quiet prints the errors only (the build runs it so).

An include is resolved as the compiler does here (the including file's
folder, then the include directories: the repository root and include/);
includes of files outside the repository (the standard library, CGAL, ...)
are not checked.  Known exceptions are listed in the table with the reason
they remain (an excepted include is also not followed into the checker's
closure); an exception that no longer occurs is itself an error, so that
the list only shrinks.
"""
import collections, os, re, sys

INCLUDE = re.compile(r'\s*#\s*include\s*"([^"]+)"')
SOURCE_SUFFIXES = (".cpp", ".h", ".hpp")


def folder(path):
    parts = path.split("/")
    return "/".join(parts[:2]) if parts[0] == "src" and len(parts) > 2 else parts[0]


def read_table(path):
    """layers, checker files, checker's forbidden folders, exceptions."""
    layers, checker, forbidden, exceptions = {}, [], [], {}
    with open(path, encoding="utf-8") as fh:
        for n, raw in enumerate(fh, 1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            key, sep, rest = line.partition(":")
            if not sep:
                raise SystemExit(f"{path}:{n}: expected 'name: values'")
            key, values = key.strip(), rest.split()
            if key == "checker":
                checker += values
            elif key == "checker-forbidden":
                forbidden += values
            elif key == "exception":
                if len(values) != 3 or values[1] != "->":
                    raise SystemExit(f"{path}:{n}: expected 'exception: FILE -> INCLUDED'")
                exceptions[(values[0], values[2])] = n
            else:
                if key in layers:
                    raise SystemExit(f"{path}:{n}: {key} listed twice")
                layers[key] = values
    for key, deps in layers.items():
        for d in deps:
            if d not in layers:
                raise SystemExit(f"{path}: {key} uses {d}, which is not a layer of the table")
    return layers, checker, forbidden, exceptions


def allowed_closure(layers):
    closure = {}

    def visit(name, stack):
        if name in closure:
            return closure[name]
        if name in stack:
            raise SystemExit("cmake/layers.txt: the layers form a cycle: " + " -> ".join(stack + [name]))
        out = set()
        for d in layers[name]:
            out.add(d)
            out |= visit(d, stack + [name])
        closure[name] = out
        return out

    for name in layers:
        visit(name, [])
    return closure


def main():
    args = sys.argv[1:]
    quiet = "--quiet" in args
    args = [a for a in args if a != "--quiet"]
    root = os.path.abspath(args[0] if args else os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    table = os.path.join(root, "cmake", "layers.txt")
    layers, checker, forbidden, exceptions = read_table(table)
    may_use = allowed_closure(layers)

    files = []
    for top in ("kernels", "include", "src"):
        for dp, _, names in os.walk(os.path.join(root, top)):
            files += [os.path.relpath(os.path.join(dp, f), root) for f in names if f.endswith(SOURCE_SUFFIXES)]
    files.sort()
    fileset = set(files)

    includes = {}
    for f in files:
        out = []
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as fh:
            for n, line in enumerate(fh, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                inc = m.group(1)
                for c in (os.path.normpath(os.path.join(os.path.dirname(f), inc)), inc, "include/" + inc):
                    if c in fileset:
                        out.append((n, c))
                        break
        includes[f] = out

    errors = []
    used_exceptions = set()
    graph = collections.defaultdict(set)  # every folder edge
    known = collections.defaultdict(set)  # the edges the table allows or excepts
    for f in files:
        a = folder(f)
        if a not in layers:
            errors.append(f"{f}: folder {a} is not in cmake/layers.txt")
            continue
        for n, c in includes[f]:
            b = folder(c)
            if b == a:
                continue
            graph[a].add(b)
            if b in may_use[a]:
                known[a].add(b)
            elif (f, c) in exceptions:
                used_exceptions.add((f, c))
                known[a].add(b)
            else:
                errors.append(f"{f}:{n}: includes {c}: {a} may not use {b}")

    # Folder-level cycles.  The edges the table allows all point down, so a
    # cycle goes through an exception (listed as known) or a violation (an
    # error).
    def reaches(g, x, y):
        seen, todo = set(), [x]
        while todo:
            n = todo.pop()
            if n == y:
                return True
            if n not in seen:
                seen.add(n)
                todo += g[n]
        return False

    notes = []
    for a in sorted(graph):
        for b in sorted(graph[a]):
            if reaches(graph, b, a):
                if b in known[a] and reaches(known, b, a):
                    notes.append(f"known cycle (through an exception): {a} -> {b} -> ... -> {a}")
                else:
                    errors.append(f"cycle: {a} -> {b} -> ... -> {a}")

    # The checker's include closure: its files, what they include, and the
    # implementation (.cpp beside the header) of every checker header it includes.
    checker_set = set(checker)
    for f in checker:
        if f not in fileset:
            errors.append(f"cmake/layers.txt: checker file {f} does not exist")
    seen, todo, parent = set(), [f for f in checker if f in fileset], {}
    while todo:
        f = todo.pop()
        if f in seen:
            continue
        seen.add(f)
        for _, c in includes[f]:
            if (f, c) in exceptions:
                used_exceptions.add((f, c))
                continue
            if c not in seen:
                parent.setdefault(c, f)
                todo.append(c)
            impl = os.path.splitext(c)[0] + ".cpp"
            if impl in checker_set and impl not in seen:
                todo.append(impl)
    for f in sorted(seen):
        if folder(f) in forbidden:
            chain, g = [f], f
            while g in parent:
                g = parent[g]
                chain.append(g)
            errors.append("the checker reaches " + folder(f) + ": " + " <- ".join(chain))

    for (f, c), n in sorted(exceptions.items(), key=lambda e: e[1]):
        if (f, c) not in used_exceptions:
            errors.append(f"cmake/layers.txt:{n}: exception {f} -> {c} no longer occurs; remove it")

    for e in ([] if quiet else notes) + errors:
        print(e)
    if quiet and not errors:
        return 0
    print(f"layers: {len(files)} files, {sum(len(v) for v in graph.values())} folder edges, "
          f"{len(used_exceptions)} known exceptions, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
