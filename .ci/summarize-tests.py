#!/usr/bin/env python3
"""Adds up the Surefire reports of all modules into one line: 'N passed, N failed, N skipped'.

Usage: summarize-tests.py [REPOSITORY_ROOT]. Reads **/target/surefire-reports/TEST-*.xml under the root (default: the
current directory). Exits 1 if any test failed or errored, or if no test ran at all.
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

root = sys.argv[1] if len(sys.argv) > 1 else "."
totals = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
# Modules may be nested (examples/*), so the reports are searched at any depth.
for report in sorted(glob.glob(os.path.join(root, "**", "target", "surefire-reports", "TEST-*.xml"), recursive=True)):
    try:
        suites = ET.parse(report).getroot().iter("testsuite")
    except ET.ParseError as error:
        print(f"unreadable report {report}: {error}", file=sys.stderr)
        totals["errors"] += 1
        continue
    for suite in suites:
        for key in totals:
            totals[key] += int(suite.get(key, "0"))

failed = totals["failures"] + totals["errors"]
passed = totals["tests"] - totals["failures"] - totals["errors"] - totals["skipped"]
if totals["tests"] == 0:
    print("no tests ran: no **/target/surefire-reports/TEST-*.xml with tests", file=sys.stderr)
print(f"{passed} passed, {failed} failed, {totals['skipped']} skipped")
sys.exit(1 if failed > 0 or totals["tests"] == 0 else 0)
