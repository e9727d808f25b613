#!/usr/bin/env bash
# Lists the functions in src/ (or the given folders) longer than LIMIT lines
# (default 60, the DEVELOPERS guide's bound), longest first:
#   scripts/long_functions.sh [LIMIT] [DIR...]
# A function runs from the first line of its declaration to its closing brace.
# A brace counter, not a parser: comments, strings, characters and
# preprocessor lines are blanked
# first; a brace opens a function body when only namespaces and classes
# enclose it and a ')' comes before it.
set -euo pipefail
cd "$(dirname "$0")/.."
limit="${1:-60}"
shift || true
[ $# -gt 0 ] || set -- src
/usr/bin/python3 - "$limit" "$@" <<'PY'
import pathlib, re, sys
limit = int(sys.argv[1])
files = sorted(p for d in sys.argv[2:] for p in pathlib.Path(d).rglob('*') if p.suffix in ('.cpp', '.hpp'))
blank = re.compile(r'^[ \t]*#(?:[^\n]*\\\n)*[^\n]*|//[^\n]*|/\*.*?\*/|R"(\w*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S | re.M)
found = []
for path in files:
    text = blank.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), path.read_text(encoding='utf-8'))
    stack, head = [], 0  # ('scope' | 'function' | 'block', first line, name)
    for i, c in enumerate(text):
        if c == '{':
            header = text[head:i]
            if re.search(r'\bnamespace\b', header) or (re.search(r'\b(class|struct|union|enum)\b', header) and ')' not in header):
                stack.append(('scope', 0, ''))
            elif all(k == 'scope' for k, _, _ in stack) and ')' in header and '=' not in header.split(')')[-1]:
                first = head + len(header) - len(header.lstrip())
                name = re.findall(r'([~\w:]+)\s*\(', header)
                stack.append(('function', text.count('\n', 0, first) + 1, name[0] if name else '?'))
            else:
                stack.append(('block', 0, ''))
            head = i + 1
        elif c == '}':
            kind, line, name = stack.pop() if stack else ('block', 0, '')
            n = text.count('\n', 0, i) + 2 - line
            if kind == 'function' and n > limit:
                found.append((n, f'{path}:{line}', name))
            head = i + 1
        elif c == ';':
            head = i + 1
for n, where, name in sorted(found, key=lambda f: (-f[0], f[1])):
    print(f'{n:4d} {where} {name}')
PY
