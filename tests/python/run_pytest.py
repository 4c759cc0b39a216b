"""Runs one pytest file as one ctest entry (python/CMakeLists.txt registers them).

Exit status: 0 when every test passed; 1 when one failed or none was collected; 77 (ctest's
SKIP_RETURN_CODE, as in tests/skip.hpp) when pytest or numpy cannot be imported, or when no
test failed but at least one was skipped: an entry that did not check everything is
reported skipped, never passed (the skipped tests and why are printed).
"""
import sys

SKIP = 77


def main(argv):
    if len(argv) != 2:
        print("usage: run_pytest.py TEST_FILE", file=sys.stderr)
        return 2
    missing = []
    for name in ("pytest", "numpy"):
        try:
            __import__(name)
        except ImportError as e:
            missing.append(f"{name} ({e})")
    if missing:
        print(f"SKIPPED: {argv[1]}: {sys.executable} cannot import {', '.join(missing)}")
        return SKIP
    try:  # the module itself must import: a broken build fails, it does not skip
        import cmx
    except ImportError as e:
        print(f"FAILED: {argv[1]}: cannot import the cmx module ({e}); is it built (target cmx_python)?")
        return 1
    print(f"cmx {cmx.__version__} from {cmx.__file__}")
    import pytest

    class Outcomes:
        def __init__(self):
            self.passed, self.failed, self.skipped = 0, 0, []

        def pytest_runtest_logreport(self, report):
            if report.failed:
                self.failed += 1
            elif report.skipped:
                self.skipped.append(report.nodeid)
            elif report.passed and report.when == "call":
                self.passed += 1

        def pytest_collectreport(self, report):  # a whole module skipped (pytest.importorskip)
            if report.failed:
                self.failed += 1
            elif report.skipped:
                self.skipped.append(report.nodeid)

    outcomes = Outcomes()
    code = pytest.main([argv[1], "-q", "-rs", "-p", "no:cacheprovider"], plugins=[outcomes])
    if code not in (0, 5) or outcomes.failed:
        return 1
    if outcomes.passed == 0 and not outcomes.skipped:
        print(f"FAILED: {argv[1]}: no test ran")
        return 1
    if outcomes.skipped:
        print(f"SKIPPED: {argv[1]}: {len(outcomes.skipped)} test(s) skipped ({', '.join(outcomes.skipped)}); "
              f"{outcomes.passed} passed")
        return SKIP
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
