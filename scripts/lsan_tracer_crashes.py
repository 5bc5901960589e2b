#!/usr/bin/env python3
"""Whether every test that failed in a ctest JUnit report failed only because LeakSanitizer's
stop-the-world tracer crashed as the process exited (a fault of the sanitizer runtime, not a leak
and not the test's). Exit 0 and name them when so; exit 1 when any failure is something else, or
when nothing failed.

usage: lsan_tracer_crashes.py CTEST_JUNIT.xml
"""
import sys
import xml.etree.ElementTree as ET

SIGNATURE = ("Tracer caught signal", "LeakSanitizer has encountered a fatal error")


def main():
    failed = [case for case in ET.parse(sys.argv[1]).getroot().iter("testcase") if case.get("status") == "fail"]
    crashes = [case.get("name") for case in failed if all(s in (case.findtext("system-out") or "") for s in SIGNATURE)]
    for name in crashes:
        print(f"LeakSanitizer's tracer crashed at the exit of: {name}")
    others = [case.get("name") for case in failed if case.get("name") not in crashes]
    for name in others:
        print(f"failed otherwise: {name}")
    sys.exit(0 if failed and not others else 1)


if __name__ == "__main__":
    main()
