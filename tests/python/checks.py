"""Check helpers shared by the Python tests: count failures instead of stopping at the first."""
import sys

failures = 0


def check(cond, what):
    """Counts a failed condition and says what it was."""
    global failures
    if not cond:
        failures += 1
        print("CHECK failed: " + what, file=sys.stderr)


def raises(exc, fn, what):
    """Calls fn, expecting exc; returns the exception (None, counted as a failure, otherwise)."""
    try:
        fn()
    except exc as e:
        return e
    except Exception as e:  # noqa: BLE001
        check(False, "%s: raised %s (%s), expected %s" % (what, type(e).__name__, e, exc.__name__))
        return None
    check(False, "%s: did not raise %s" % (what, exc.__name__))
    return None
