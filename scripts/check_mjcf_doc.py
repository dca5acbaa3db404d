#!/usr/bin/env python3
"""docs/mjcf.md against the tables the MJCF parser uses, so the reference
cannot drift from the code: every field of mjbuoy/api/config.cc's
kSeaFields and kHullFields and of mjbuoy/api/seaconfig.cc's spectrum and
wind tables has its row in docs/mjcf.md, and that row's range names the
table's finite bounds; every mjbuoy.radiation.* entry
mjbuoy/api/radconfig.cc accepts is documented.

usage: check_mjcf_doc.py [--root DIR]   exit 0: consistent; 1: each
mismatch printed with FAIL, naming the field, the code's value and the row.
       check_mjcf_doc.py --self-test     the check finds a wrong bound and a
                                         missing row in a doctored page"""
import math
import os
import re
import sys

FIELD = re.compile(r'\{"([a-z_]+)",\s*(\d+),\s*([^,]+),\s*([^,]+),')


def number(text):
  text = text.strip()
  if "INFINITY" in text:
    return math.inf if not text.startswith("-") else -math.inf
  try:
    return float(text)
  except ValueError:
    return None  # a named constant: not checked


def table(src, name):
  # the brace block after "name[] = {" (or "name = {"), its {"field", n, lo, hi rows
  i = src.index(name)
  j = src.index("};", i)
  return [(m.group(1), number(m.group(3)), number(m.group(4))) for m in FIELD.finditer(src[i:j])]


def blocks(src):
  # seaconfig.cc: the spectrum table comes first, then the wind table
  i = src.index('{"hs"')
  j = src.index("};", i)
  k = src.index('{"speed"')
  l = src.index("};", k)
  rows = lambda a, b: [(m.group(1), number(m.group(3)), number(m.group(4)))
                       for m in FIELD.finditer(src[a:b])]
  return rows(i, j), rows(k, l)


def numbers_in(cell):
  cell = cell.replace("2^53", "9007199254740992")
  return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", cell)]


def section(doc, title):
  i = doc.index(title)
  j = doc.find("\n## ", i + 1)
  return doc[i:j if j > 0 else len(doc)]


def row(text, key):
  for line in text.splitlines():
    if line.startswith("| `%s`" % key):
      return [c.strip() for c in line.strip().strip("|").split("|")]
  return None


def check_bounds(fails, what, cells, lo, hi):
  nums = numbers_in(" ".join(cells))
  for b in (lo, hi):
    if b is None or math.isinf(b) or (b == 0 and lo == hi):
      continue
    if not any(abs(x - b) <= 1e-12 * max(1, abs(b)) for x in nums):
      fails.append("FAIL %s: the parser's bound %g is not in its row: %s" % (what, b, " | ".join(cells)))


def check(root, doc):
  fails = []
  api = os.path.join(root, "mjbuoy", "api")
  config = open(os.path.join(api, "config.cc")).read()
  seacfg = open(os.path.join(api, "seaconfig.cc")).read()
  radcfg = open(os.path.join(api, "radconfig.cc")).read()
  entries = section(doc, "## 2. Entries")
  for name, lo, hi in table(config, "kSeaFields[]"):
    r = row(entries, "mjbuoy.sea.%s" % name)
    if r is None:
      fails.append("FAIL mjbuoy.sea.%s: no row in docs/mjcf.md section 2" % name)
    elif lo != hi:
      check_bounds(fails, "mjbuoy.sea.%s" % name, r[5:6], lo, hi)
  hulls = entries[entries.index("**Hull parameters.**"):]  # their table, in section 2
  for name, lo, hi in table(config, "kHullFields[]"):
    r = row(hulls, name)
    if r is None:
      fails.append("FAIL mjbuoy.hull.%s: no row in docs/mjcf.md section 2" % name)
    elif lo != hi:
      check_bounds(fails, "mjbuoy.hull.%s" % name, r[4:5], lo, hi)
  spectrum, wind = blocks(seacfg)
  for title, prefix, fields in (("## 8. Irregular seas", "mjbuoy.spectrum.<label>", spectrum),
                                ("## 9. Wind", "mjbuoy.wind", wind)):
    text = section(doc, title)
    for name, lo, hi in fields:
      r = row(text, name)
      if r is None:
        fails.append("FAIL %s.%s: no row in docs/mjcf.md %s" % (prefix, name, title[3:]))
      else:
        check_bounds(fails, "%s.%s" % (prefix, name), r[5:6], lo, hi)
  for name in sorted(set(re.findall(r"mjbuoy\.radiation\.([a-z]+)", radcfg))):
    if "`mjbuoy.radiation.%s" % name not in doc:
      fails.append("FAIL mjbuoy.radiation.%s: accepted by radconfig.cc, not in docs/mjcf.md" % name)
  return fails


def self_test(root):
  doc = open(os.path.join(root, "docs", "mjcf.md")).read()
  bad = doc.replace("| 1 to 1e5 | water density rho |", "| 1 to 1e4 | water density rho |")
  bad = re.sub(r"\n\| `vref` \| 1 \|[^\n]*", "", bad)
  fails = check(root, bad)
  want = ["mjbuoy.sea.density", "mjbuoy.hull.vref"]
  ok = len(fails) == 2 and all(any(w in f for f in fails) for w in want)
  print("\n".join(fails))
  print("check_mjcf_doc self-test: %s (want 2 failures: density's bound, vref's row)" %
        ("ok" if ok else "FAIL"))
  return 0 if ok else 1


def main():
  root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
  if "--root" in sys.argv:
    root = sys.argv[sys.argv.index("--root") + 1]
  if "--self-test" in sys.argv:
    return self_test(root)
  fails = check(root, open(os.path.join(root, "docs", "mjcf.md")).read())
  for f in fails:
    print(f)
  print("check_mjcf_doc: %s" % ("docs/mjcf.md matches the parser's tables" if not fails else
                                "%d mismatches" % len(fails)))
  return 1 if fails else 0


if __name__ == "__main__":
  sys.exit(main())
