#!/usr/bin/env python3
"""Checks the local links of Markdown files: every relative link names a
file that exists, and every #anchor names a heading of the page it points
to (slugs as GitHub and MyST make them). External links (http, https,
mailto) are not checked: the test machine has no network.

usage: check_links.py ROOT FILE_OR_DIR...   (paths relative to ROOT)
       check_links.py --self-test             (a page with one good link, a
                                               missing file and a missing anchor)
exit 0: all links resolve; 1: a broken link (each printed as file:line)."""
import os
import re
import sys

LINK = re.compile(r"(?<!\!)\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def slug(title):
  # GitHub's and MyST's heading anchors: lowercase, drop punctuation other
  # than - and _, spaces become -
  t = re.sub(r"`([^`]*)`", r"\1", title.strip()).lower()
  t = re.sub(r"[^\w\- ]", "", t)
  return t.replace(" ", "-")


def lines_outside_code(path):
  fenced = False
  with open(path, encoding="utf-8") as f:
    for no, line in enumerate(f, 1):
      if FENCE.match(line):
        fenced = not fenced
        continue
      if not fenced:
        yield no, re.sub(r"`[^`]*`", "", line)


def anchors(path, cache={}):
  if path not in cache:
    seen = {}
    out = set()
    for _, line in lines_outside_code(path):
      m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
      if m:
        s = slug(m.group(2))
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else "%s-%d" % (s, n))
      for a in re.findall(r"\(([\w\-]+)\)=", line):  # MyST targets: (name)=
        out.add(a)
    cache[path] = out
  return cache[path]


def check(path):
  bad = []
  for no, line in lines_outside_code(path):
    for target in LINK.findall(line):
      if re.match(r"^[a-z]+:", target):
        continue  # external: not checked
      file, _, anchor = target.partition("#")
      dest = os.path.normpath(os.path.join(os.path.dirname(path), file)) if file else path
      if not os.path.exists(dest):
        bad.append("%s:%d: %s: no file %s" % (path, no, target, dest))
      elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
        bad.append("%s:%d: %s: no heading with anchor #%s in %s" % (path, no, target, anchor, dest))
  return bad


def self_test():
  import tempfile
  with tempfile.TemporaryDirectory() as d:
    with open(os.path.join(d, "a.md"), "w") as f:
      f.write("# A page\n\n## Its part\n\n[ok](a.md#its-part) [ok](#a-page) [x](https://x.y/z)\n"
              "[missing](b.md) [anchor](a.md#no-such-part)\n```\n[in code](c.md)\n```\n")
    bad = check(os.path.join(d, "a.md"))
  want = ["no file", "no heading with anchor #no-such-part"]
  ok = len(bad) == 2 and all(w in b for w, b in zip(want, bad))
  print("\n".join(bad))
  print("check_links self-test: %s (want 2 broken links, found %d)" % ("ok" if ok else "FAIL", len(bad)))
  return 0 if ok else 1


def main():
  if sys.argv[1:] == ["--self-test"]:
    return self_test()
  if len(sys.argv) < 3:
    print(__doc__)
    return 2
  os.chdir(sys.argv[1])
  files = []
  for p in sys.argv[2:]:
    if os.path.isdir(p):
      files += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".md"))
    else:
      files.append(p)
  bad = []
  for f in files:
    bad += check(f)
  for b in bad:
    print(b)
  print("check_links: %d files, %d broken local links (external links not checked)" %
        (len(files), len(bad)))
  return 1 if bad else 0


if __name__ == "__main__":
  sys.exit(main())
