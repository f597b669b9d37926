"""Prints 'N passed, N failed' (the line tests/run counts) from a pytest JUnit XML report.

Usage: junit_summary.py JUNIT.xml PYTEST_EXIT_STATUS
"""
import sys
import xml.etree.ElementTree as ET

try:
    suite = ET.parse(sys.argv[1]).getroot()
    suite = suite if suite.tag == "testsuite" else suite.find("testsuite")
    n = {k: int(suite.get(k, 0)) for k in ("tests", "failures", "errors", "skipped")}
    failed = n["failures"] + n["errors"]
    if failed == 0 and sys.argv[2] != "0":
        failed = 1  # pytest failed outside the tests (collection, usage)
    print(f"{n['tests'] - failed - n['skipped']} passed, {failed} failed")
except (OSError, ET.ParseError, AttributeError):
    print("0 passed, 1 failed")  # pytest did not get as far as writing its report
