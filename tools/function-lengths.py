#!/usr/bin/env python3
"""The longest C++ functions under some folders, by brace matching (no parser, no ctags).

Usage: tools/function-lengths.py [--top N] [--max LINES] [--exclude DIR ...] DIR|FILE ...

Prints the N longest (default 10) as `length  file:line  name`, longest first; with --max,
exits 1 when one is longer than LINES (and lists every such function). Length counts the lines
from the signature's first line to the closing brace, both included.

The heuristic: comments, string and character literals (raw strings too) and preprocessor lines
are blanked; a `{` opens a function when it is outside any function and the code before it
(back to the previous `;`, `{` or `}`) looks like a signature: it has a `(` and ends with `)`,
optionally followed by const, noexcept, override, final, mutable or a trailing `-> type`.
Lambdas and local classes count towards the function around them; a lambda at namespace scope
counts as a function of its own. Not recognised as functions (so not measured): constructors
whose initializer list ends in a brace initializer (`: a_{x} {`), and function-try-blocks.
"""
import argparse
import os
import re
import sys

EXTENSIONS = (".cpp", ".cc", ".cxx", ".h", ".hpp", ".hh", ".inl")
SIGNATURE_END = re.compile(
    r"\)\s*((const|noexcept(\s*\([^()]*\))?|override|final|mutable|&&?|->\s*[\w:<>,\s*&]+)\s*)*$")
LEADING_LABELS = re.compile(r"^\s*((public|private|protected)\s*:\s*)*")
NAME = re.compile(r"(~?[A-Za-z_][\w:~]*(\s*<[^()]*>)?|operator\s*[^\s(]+|operator\s*\(\))\s*\(")


def blank(text):
    """Comments, literals and preprocessor lines replaced by spaces; newlines kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A directive, with its continuation lines.
            j = i
            while j < n and not (text[j] == "\n" and text[j - 1] != "\\"):
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
            continue
        if c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        m = re.match(r'R"([^()\s\\]{0,16})\(', text[i:i + 20]) if c == "R" and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")) else None
        if m:
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2:j]))
            i = j
            continue
        if c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 digit separators
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * (j - i - 2) + c if j - i >= 2 else c)
            i = j
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


def functions(path):
    """(name, first line, length) of every function defined in the file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        code = blank(f.read())
    found = []
    depth = 0
    in_function = None  # (depth at its brace, name, first line) while inside one
    head_start = 0      # where the code since the last ; { } begins
    line_of = lambda pos: code.count("\n", 0, pos) + 1
    for i, c in enumerate(code):
        if c == "{":
            if in_function is None:
                head = code[head_start:i]
                label = LEADING_LABELS.match(head)
                start = head_start + (label.end() if label else 0)
                head = code[start:i].strip()
                if "(" in head and SIGNATURE_END.search(head) and not head.startswith(("namespace", "extern")):
                    m = NAME.search(head)
                    if head.find("[") >= 0 and (not m or head.find("[") < m.start()):  # auto f = [...](...) {
                        m = re.search(r"(\w+)\s*=\s*\[", head)
                    first = start + len(code[start:i]) - len(code[start:i].lstrip())
                    in_function = (depth, m.group(1).replace(" ", "") if m else "?", line_of(first))
            depth += 1
            head_start = i + 1
        elif c == "}":
            depth -= 1
            if in_function is not None and depth == in_function[0]:
                found.append((in_function[1], in_function[2], line_of(i) - in_function[2] + 1))
                in_function = None
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("paths", nargs="+", help="folders (searched recursively) or files")
    ap.add_argument("--top", type=int, default=10, help="how many to print (default 10)")
    ap.add_argument("--max", type=int, help="fail when a function is longer than this")
    ap.add_argument("--exclude", action="append", default=[], help="a folder to skip (repeatable)")
    a = ap.parse_args()
    excluded = [os.path.normpath(e) for e in a.exclude]
    files = []
    for p in a.paths:
        if os.path.isfile(p):
            files.append(p)
            continue
        if not os.path.isdir(p):
            sys.exit(f"function-lengths: {p}: no such file or folder")
        for root, dirs, names in os.walk(p):
            dirs[:] = sorted(d for d in dirs if os.path.normpath(os.path.join(root, d)) not in excluded)
            files += [os.path.join(root, f) for f in sorted(names) if f.endswith(EXTENSIONS)]
    rows = [(length, path, line, name) for path in files for name, line, length in functions(path)]
    rows.sort(key=lambda r: (-r[0], r[1], r[2]))
    rows = [(length, f"{path}:{line}", name) for length, path, line, name in rows]
    print(f"{len(rows)} functions in {len(files)} files; the {min(a.top, len(rows))} longest:")
    for length, where, name in rows[:a.top]:
        print(f"{length:6d}  {where}  {name}")
    if a.max is not None:
        over = [r for r in rows if r[0] > a.max]
        for length, where, name in over:
            print(f"function-lengths: {where}: {name} is {length} lines, more than {a.max}", file=sys.stderr)
        return 1 if over else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
