"""What the outside judges share: in CI (CI=true) a missing tool or file fails the judge; elsewhere it skips (77)."""
import json
import os
import subprocess
import sys

CI = os.environ.get("CI") == "true"


def skip_or_fail(message):
    if CI:
        print("FAIL: " + message, file=sys.stderr)
        sys.exit(1)
    print("SKIP: " + message, file=sys.stderr)
    sys.exit(77)


# The checks a judge makes: each prints "ok - ..." or "FAIL - ..."; finish() exits 1 when one failed.
_failed = False
_voxmod = None


def check(ok, what):
    global _failed
    _failed |= not ok
    print(("ok" if ok else "FAIL") + " - " + what)


def finish():
    sys.exit(1 if _failed else 0)


def use_voxmod(path):
    global _voxmod
    _voxmod = path


def voxmod(*args):
    """Runs the voxmod given to use_voxmod with --json; its report, or RuntimeError naming the command."""
    run = subprocess.run([_voxmod, *args, "--json"], capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"voxmod {' '.join(args)}: exit {run.returncode}: {run.stderr}")
    return json.loads(run.stdout)


def close(a, b, tol=1e-9):
    """Every component of a within a relative tol of b's."""
    return all(abs(x - y) <= tol * max(1.0, abs(y)) for x, y in zip(a, b))
