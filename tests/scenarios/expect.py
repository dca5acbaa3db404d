#!/usr/bin/env python3
"""Run mjbuoy-scenario on one scenario file and check what it reports.

expect.py TOOL SCENARIO.xml

The scenario file states what to expect in its leading comment:

    expect exit N              (default 0)
    expect output: REGEX       (any number; each must match a line of the
                                combined stdout and stderr, re.MULTILINE)

The JUnit file written with --junit is checked too: it parses, has one
<testsuite>, and counts the same failures as the FAIL lines of the output
(exit 0, 1) or one <error> (exit 2).
"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    tool, scenario = sys.argv[1], sys.argv[2]
    with open(scenario) as f:
        text = f.read()
    want_exit = 0
    patterns = []
    for line in text.splitlines():
        m = re.match(r"\s*(?:<!--)?\s*expect exit (\d+)", line)
        if m:
            want_exit = int(m.group(1))
        m = re.match(r"\s*(?:<!--)?\s*expect output: (.*?)\s*$", line)
        if m:
            patterns.append(m.group(1))

    with tempfile.TemporaryDirectory() as tmp:
        junit = os.path.join(tmp, "junit.xml")
        run = subprocess.run([tool, scenario, "--junit", junit], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        out = run.stdout
        sys.stdout.write(out)
        bad = []
        if run.returncode != want_exit:
            bad.append("exit status %d, expected %d" % (run.returncode, want_exit))
        for p in patterns:
            if not re.search(p, out, re.MULTILINE):
                bad.append("no line of the output matches: %s" % p)
        try:
            root = ET.parse(junit).getroot()
            suites = root.findall("testsuite")
            fails = len(root.findall("testsuite/testcase/failure"))
            errors = len(root.findall("testsuite/testcase/error"))
            nfail = len(re.findall(r"^FAIL ", out, re.MULTILINE))
            if root.tag != "testsuites" or len(suites) != 1:
                bad.append("JUnit: expected <testsuites> with one <testsuite>")
            elif run.returncode == 2 and errors != 1:
                bad.append("JUnit: %d <error>, expected 1" % errors)
            elif run.returncode != 2 and fails != nfail:
                bad.append("JUnit: %d <failure>, the output has %d FAIL lines" % (fails, nfail))
            elif run.returncode != 2 and suites[0].get("failures") != str(nfail):
                bad.append("JUnit: testsuite failures=%s, expected %d"
                           % (suites[0].get("failures"), nfail))
        except (ET.ParseError, OSError) as e:
            bad.append("JUnit: %s" % e)
    for b in bad:
        print("expect.py: %s: %s" % (scenario, b))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
