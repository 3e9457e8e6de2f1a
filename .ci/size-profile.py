#!/usr/bin/env python3
"""Size profile of the Kotlin main sources: files over 300 lines, functions over 40 lines.

A function is a line starting with `fun` (after modifiers) at any indentation; it ends where its body ends: the
matching `}` of a block body, or, for an expression body, the last line before the next line indented no deeper
than the `fun` (blank lines and the closing `)` of a multi-line expression included).
Usage: size-profile [DIR ...]   (default: every `src/main/kotlin` below the current folder)
"""
import os, re, sys

FUN = re.compile(r"^(\s*)((public|private|internal|protected|override|suspend|inline|operator|infix|tailrec|open|abstract|actual|expect)\s+)*fun\s+([^\s(]+)")

def sources(roots):
    for root in roots:
        for d, dirs, files in os.walk(root):
            dirs[:] = [x for x in dirs if x not in ("target", "build", "node_modules", ".git")]
            if "src/main/kotlin" not in d.replace(os.sep, "/") and "src/main/kotlin" not in root:
                continue
            for f in files:
                if f.endswith(".kt"):
                    yield os.path.join(d, f)

def functions(lines):
    for i, line in enumerate(lines):
        m = FUN.match(line)
        if not m:
            continue
        indent = len(m.group(1))
        end = i
        for j in range(i + 1, len(lines)):
            text = lines[j]
            if not text.strip():
                continue
            if len(text) - len(text.lstrip()) <= indent:
                end = j if text.strip().startswith((")", "}")) else end
                break
            end = j
        yield m.group(4), i + 1, end - i + 1

def main():
    roots = sys.argv[1:] or ["."]
    files = sorted(set(sources(roots)))
    big_files, long_functions, total_functions = [], [], 0
    for path in files:
        with open(path, encoding="utf-8") as handle:
            lines = handle.read().splitlines()
        if len(lines) > 300:
            big_files.append((len(lines), path))
        for name, start, length in functions(lines):
            total_functions += 1
            if length > 40:
                long_functions.append((length, f"{path}:{start} {name}"))
    print(f"{len(files)} files, {total_functions} functions")
    print(f"files > 300 lines: {len(big_files)}")
    for n, p in sorted(big_files, reverse=True):
        print(f"  {n:5d} {p}")
    print(f"functions > 40 lines: {len(long_functions)}")
    for n, p in sorted(long_functions, reverse=True):
        print(f"  {n:5d} {p}")

main()
