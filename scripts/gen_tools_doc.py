#!/usr/bin/env python3
"""Writes docs/tools.md, the tools' options, from each tool's own --help, so
the page and the programs cannot drift apart.

usage: gen_tools_doc.py BUILD_TOOLS_DIR [--check]
  BUILD_TOOLS_DIR  the directory holding the built mjbuoy-* programs
  --check          compare with docs/tools.md instead of writing it: exit 1,
                   naming the first differing line, when the page is stale
                   (regenerate with the same command without --check)"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "tools.md")

# (program, subcommands, what it is for): the --help text says the rest
TOOLS = [
  ("mjbuoy-sim", [], "Runs a model headless: a summary on stdout, a CSV of "
   "the motions, clips, stills and plots. The CSV has a header row: `time`, then for "
   "every body with a free joint `<body>.x,<body>.y,<body>.z` (the body frame origin, m) "
   "and `<body>.roll,<body>.pitch,<body>.yaw` (degrees, R = Rz(yaw) Ry(pitch) Rx(roll)); "
   "then every other joint by its name (slide: m, hinge: degrees, ball: `.qw,.qx,.qy,.qz`); "
   "then every sensor by its name (`<sensor>.0`, `.1`, ... when it has several values)."),
  ("mjbuoy-view", [], "An interactive window (GLFW, X11) with the sea drawn live; "
   "physics runs in real time on its own thread. Keys: Space pause, Right arrow one step, "
   "Backspace reset, `-` / `+` slower / faster, Up / Down the chosen actuator's control "
   "(a twentieth of its ctrlrange a press), `[` / `]` the previous / next actuator, 0 every "
   "control to 0, F force arrows, W wet part, H help; double-click selects a body, Ctrl + "
   "drag pulls or turns it. The overlay names the sea (its components by kind, Gerstner or "
   "linear, and its spectra), the wind, the radiation and the real-time factor the physics "
   "keeps; when the physics falls behind the clock, drawing yields to it. Headless, run it "
   "under `xvfb-run -a`."),
  ("mjbuoy-hydro", [], "Prints the radiation coefficients the panel solver finds for "
   "each hull body and fills the radiation cache."),
  ("mjbuoy-scenario", [], "Runs scenario files: a model, a sea and checks on the "
   "motion, with JUnit output ([Scenario files](scenarios.md))."),
  ("mjbuoy-sweep", ["run", "case", "estimate", "slurm", "list", "merge"],
   "Runs a sweep of scenarios locally or on Slurm and merges the results "
   "([Sweeps](sweeps.md), [An RAO sweep](howto-rao.md))."),
  ("mjbuoy-bench", [], "Measures the cost of a step over a grid of boats and hull "
   "resolutions, or of one scene as it is with `--scene` (hydro, full step and the "
   "real-time factor) ([Benchmarks](benchmarks.md))."),
  ("mjbuoy-hullgen", [], "Writes Wigley hull meshes (OBJ) of a given resolution."),
]


def helptext(tools, prog, sub):
  cmd = [os.path.join(tools, prog)] + ([sub] if sub else []) + ["--help"]
  out = subprocess.run(cmd, capture_output=True, text=True, timeout=60).stdout
  # the usage line names the program as it was called: use its installed name
  return out.replace(os.path.join(tools, prog), prog).rstrip() + "\n"


def page(tools):
  out = ["# Tools\n",
         "The command-line programs, built into `build/tools/` and installed into `bin/`. "
         "Every program has `--version`, checks its numeric options when it parses them "
         "(a value out of range is an error naming the option, the value and the range), "
         "and writes every output to a temporary file beside it, renamed into place only "
         "when the run succeeds; an output that is an input or another output is refused "
         "([Errors and limits](robustness.md)).\n",
         "Every program that attaches a model with radiation on says on stderr, as the attach "
         "goes, what the panel solver solves for each distinct hull (the body, its body and lid "
         "panels and mirror planes, the frequencies, the headings and an estimated time), which "
         "bodies take the solution of an identical hull, and which solutions the radiation cache "
         "answers (the file read).\n",
         "This page is generated from the programs' `--help` by "
         "`python3 scripts/gen_tools_doc.py build/tools`; the test `docs.tools` fails "
         "when it is stale.\n"]
  for prog, subs, what in TOOLS:
    out.append("## %s\n" % prog)
    out.append(what + "\n")
    out.append("```text\n" + helptext(tools, prog, None) + "```\n")
    for sub in subs:
      out.append("### %s %s\n" % (prog, sub))
      out.append("```text\n" + helptext(tools, prog, sub) + "```\n")
  return "\n".join(out)


def main():
  args = [a for a in sys.argv[1:] if a != "--check"]
  if len(args) != 1:
    print(__doc__)
    return 2
  text = page(args[0])
  if "--check" in sys.argv:
    old = open(PAGE, encoding="utf-8").read() if os.path.exists(PAGE) else ""
    if old == text:
      print("gen_tools_doc: docs/tools.md matches the tools' --help")
      return 0
    a, b = old.splitlines(), text.splitlines()
    n = next((i for i in range(min(len(a), len(b))) if a[i] != b[i]), min(len(a), len(b)))
    print("FAIL docs/tools.md is stale at line %d:\n  page: %s\n  tool: %s\n"
          "regenerate: python3 scripts/gen_tools_doc.py BUILD/tools" %
          (n + 1, a[n] if n < len(a) else "(end)", b[n] if n < len(b) else "(end)"))
    return 1
  with open(PAGE + ".tmp", "w", encoding="utf-8") as f:
    f.write(text)
  os.replace(PAGE + ".tmp", PAGE)
  print("gen_tools_doc: wrote docs/tools.md")
  return 0


if __name__ == "__main__":
  sys.exit(main())
