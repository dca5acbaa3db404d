#!/usr/bin/env python3
"""The library's house rules (docs/architecture.md): which subsystem folder
of mjbuoy/ may include which, and that tools/ reaches the library's api/
only through the public header. Exits 1 naming each include that breaks a
rule, 0 when the tree is as drawn.

  python3 scripts/check_layout.py [--root DIR]
  python3 scripts/check_layout.py --self-test   (a tree with a broken include fails)
"""
import argparse
import os
import re
import sys
import tempfile

# folder -> the folders its files may include (besides its own); the
# public header mjbuoy.h (plain C types and the API's declarations) may be
# included from anywhere
MAY_USE = {
    'util': set(),
    'sea': {'util'},
    'hull': {'sea', 'util'},
    'cpu': {'hull', 'sea', 'util'},
    'gl': {'hull', 'sea', 'util'},
    'radiation': {'hull', 'sea', 'util'},
    'mooring': {'sea', 'util'},
    'api': {'cpu', 'gl', 'radiation', 'mooring', 'hull', 'sea', 'util'},
}
PUBLIC = {'mjbuoy.h', 'mjbuoy_version.h'}
# includes that still break a rule, as (file, include) pairs: empty, and
# to stay so. A new break fails the check, and so does a listed pair that
# is gone (remove it here)
KNOWN = set()
# tools/ files that still include an internal header of mjbuoy/api/ (the
# public API, mjbuoy.h, has no query for what they read yet), as (file,
# include) pairs; a new one fails the check, and so does a listed pair
# that is gone
TOOLS_KNOWN = {
    ('tools/bench/bench.cc', 'api/buoy.h'),
    ('tools/common/seadraw.cc', 'api/config.h'),
    ('tools/hydro/hydro.cc', 'api/buoy.h'),
    ('tools/hydro/hydro.cc', 'api/coefexport.h'),
    ('tools/sweep/sweep_run.cc', 'api/buoy.h'),
    ('tools/view/view_text.cc', 'api/config.h'),
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def includes(path):
    """(line number, quoted include) of each #include "..." in path"""
    with open(path, encoding='utf-8') as fh:
        for n, line in enumerate(fh, 1):
            m = INCLUDE.match(line)
            if m:
                yield n, m.group(1)


def check(root):
    lib = os.path.join(root, 'mjbuoy')
    bad = []
    seen = set()
    folders = sorted(d for d in os.listdir(lib) if os.path.isdir(os.path.join(lib, d)))
    for d in folders:
        if d not in MAY_USE:
            bad.append('mjbuoy/%s/: a folder the rules do not know; add it to MAY_USE in '
                       'scripts/check_layout.py and to docs/architecture.md' % d)
    for name in sorted(os.listdir(lib)):
        p = os.path.join(lib, name)
        if os.path.isfile(p) and name.endswith(('.cc', '.h')) and name not in PUBLIC:
            bad.append('mjbuoy/%s: library sources live in a subsystem folder' % name)
    for d in folders:
        allowed = MAY_USE.get(d, set()) | {d}
        for dp, _, files in os.walk(os.path.join(lib, d)):
            for f in sorted(files):
                if not f.endswith(('.cc', '.h', '.inc')):
                    continue
                path = os.path.join(dp, f)
                rel = os.path.relpath(path, root)
                for n, inc in includes(path):
                    if inc in PUBLIC:
                        continue
                    if '/' not in inc:
                        if os.path.exists(os.path.join(dp, inc)):
                            bad.append('%s:%d: #include "%s": name it from mjbuoy/, '
                                       'as "%s/%s"' % (rel, n, inc, d, inc))
                        continue  # shaders/ and generated headers
                    top = inc.split('/')[0]
                    if top not in MAY_USE:
                        continue
                    if top not in allowed and (rel, inc) in KNOWN:
                        seen.add((rel, inc))
                    elif top not in allowed:
                        uses = ', '.join(sorted(MAY_USE[d])) or 'nothing else'
                        bad.append('%s:%d: #include "%s": %s/ may use only %s '
                                   '(docs/architecture.md)' % (rel, n, inc, d, uses))
    for rel, inc in sorted(KNOWN - seen):
        bad.append('%s: no longer includes "%s": remove it from KNOWN in '
                   'scripts/check_layout.py' % (rel, inc))
    return bad + check_tools(root)


def check_tools(root):
    """tools/ may include mjbuoy.h, not mjbuoy/api/ (save TOOLS_KNOWN)"""
    bad = []
    seen = set()
    tools = os.path.join(root, 'tools')
    for dp, _, files in os.walk(tools):
        for f in sorted(files):
            if not f.endswith(('.cc', '.h')):
                continue
            path = os.path.join(dp, f)
            rel = os.path.relpath(path, root)
            for n, inc in includes(path):
                if not inc.startswith('api/'):
                    continue
                if (rel, inc) in TOOLS_KNOWN:
                    seen.add((rel, inc))
                else:
                    bad.append('%s:%d: #include "%s": tools use the public API, mjbuoy.h; '
                               'add the query they need there (docs/architecture.md, '
                               'Tools)' % (rel, n, inc))
    for rel, inc in sorted(TOOLS_KNOWN - seen):
        if os.path.isdir(tools):
            bad.append('%s: no longer includes "%s": remove it from TOOLS_KNOWN in '
                       'scripts/check_layout.py' % (rel, inc))
    return bad


def self_test():
    """a sea/ file that includes hull/ and a loose source must both be named"""
    with tempfile.TemporaryDirectory() as t:
        for d in MAY_USE:
            os.makedirs(os.path.join(t, 'mjbuoy', d))
        with open(os.path.join(t, 'mjbuoy', 'sea', 'bad.cc'), 'w') as f:
            f.write('#include "mjbuoy.h"\n#include "util/fmt.h"\n#include "hull/hull.h"\n')
        with open(os.path.join(t, 'mjbuoy', 'loose.cc'), 'w') as f:
            f.write('\n')
        os.makedirs(os.path.join(t, 'tools', 'sim'))
        with open(os.path.join(t, 'tools', 'sim', 'sim.cc'), 'w') as f:
            f.write('#include "mjbuoy.h"\n#include "api/buoy.h"\n')
        global KNOWN, TOOLS_KNOWN
        KNOWN = set()
        TOOLS_KNOWN = set()
        bad = check(t)
    want = ['mjbuoy/loose.cc: library sources live in a subsystem folder',
            'mjbuoy/sea/bad.cc:3: #include "hull/hull.h": sea/ may use only util',
            'tools/sim/sim.cc:2: #include "api/buoy.h": tools use the public API']
    ok = len(bad) == 3 and all(any(b.startswith(w) for b in bad) for w in want)
    print('\n'.join(bad))
    print('check_layout self-test: %s' % ('ok' if ok else 'FAIL the check missed a break'))
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--root', default=os.path.join(os.path.dirname(__file__), '..'))
    ap.add_argument('--self-test', action='store_true', help='check the checker on a broken tree')
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    bad = check(os.path.abspath(a.root))
    for b in bad:
        print('FAIL ' + b)
    if bad:
        print('check_layout: %d include(s) break the house rules' % len(bad))
        return 1
    if KNOWN:
        print('check_layout: no new break of the house rules; %d known break(s) still listed '
              'in KNOWN' % len(KNOWN))
    else:
        print('check_layout: every include of mjbuoy/ follows the house rules')
    print('check_layout: tools/ reaches mjbuoy/api/ only through mjbuoy.h, save %d include(s) '
          'listed in TOOLS_KNOWN' % len(TOOLS_KNOWN))
    return 0


if __name__ == '__main__':
    sys.exit(main())
