#!/usr/bin/env python3
"""Functions of mjbuoy/ longer than the style's limit (docs/architecture.md:
a function past about 80 lines is split along its concerns). Lists each
as file:line name lines, longest first; exits 1 when any is past --max.

  python3 scripts/func_lengths.py [--max 80] [--root DIR] [--all]

Functions in KNOWN (file, name) are the ones still to split: they are
listed but do not fail the check unless --all; a new long function fails
it, and so does a listed one that is no longer long (remove it here).

A function is a definition that starts at column 0 (MuJoCo's style keeps
namespace bodies unindented) and ends at its matching closing brace; its
length counts from the line of its name to that brace. Comments, strings
and character literals are blanked before braces are counted.
"""
import argparse
import os
import re
import sys

TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)
# a definition's head: not a control statement, a type or a namespace
HEAD = re.compile(r'^(?!(?:namespace|struct|class|enum|union|extern|typedef|using|if|for|while|'
                  r'switch|return|static_assert)\b)[A-Za-z_].*\)\s*(?:const\s*)?(?:noexcept\s*)?'
                  r'(?:->\s*[\w:<>*& ]+)?\s*\{\s*$')
NAME = re.compile(r'([~\w:]+)\s*\(')
# the functions past the limit still to split; the list may only shrink
KNOWN = set()


def blank(text):
    """text with comments and literals replaced by spaces (newlines kept)"""
    return TOKEN.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


def functions(path):
    """(line, name, length) of each column-0 function definition in path"""
    with open(path, encoding='utf-8') as f:
        lines = blank(f.read()).split('\n')
    out = []
    i = 0
    while i < len(lines):
        # a head may span lines: join up to 6 until a line ends with '{'
        if lines[i][:1].isalpha() or lines[i][:1] == '_':
            j = i
            head = lines[i].rstrip()
            while not head.endswith('{') and not head.endswith(';') and j + 1 < len(lines) \
                    and j - i < 6 and not head.endswith('}'):
                j += 1
                head += ' ' + lines[j].strip()
            if HEAD.match(head):
                names = NAME.findall(head.split('(')[0] + '(')
                name = names[-1] if names else '?'
                depth = 0
                k = i
                while k < len(lines):
                    depth += lines[k].count('{') - lines[k].count('}')
                    if depth <= 0 and k >= j:
                        break
                    k += 1
                out.append((i + 1, name, k - i + 1))
                i = k + 1
                continue
        i += 1
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--root', default=os.path.join(os.path.dirname(__file__), '..'))
    ap.add_argument('--max', type=int, default=80, help='longest function allowed [lines]')
    ap.add_argument('--all', action='store_true', help='fail on every long function, KNOWN too')
    a = ap.parse_args()
    lib = os.path.join(os.path.abspath(a.root), 'mjbuoy')
    long = []
    for dp, _, files in os.walk(lib):
        for f in sorted(files):
            if f.endswith(('.cc', '.h')):
                p = os.path.join(dp, f)
                rel = os.path.relpath(p, os.path.dirname(lib))
                long += [(n, rel, line, name) for line, name, n in functions(p) if n > a.max]
    bad = 0
    for n, rel, line, name in sorted(long, reverse=True):
        known = (rel, name) in KNOWN and not a.all
        bad += not known
        print('%s%s:%d %s %d lines%s' % ('' if known else 'FAIL ', rel, line, name, n,
                                         ' (known, to split)' if known else ''))
    if not a.all and a.max == 80:
        for rel, name in sorted(KNOWN - {(r, m) for _, r, _, m in long}):
            bad += 1
            print('FAIL %s %s: no longer past %d lines; remove it from KNOWN in '
                  'scripts/func_lengths.py' % (rel, name, a.max))
    print('func_lengths: %d function(s) of mjbuoy/ past %d lines, %d failing' %
          (len(long), a.max, bad))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
