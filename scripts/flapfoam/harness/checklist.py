# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
PASS/FAIL lines of the checks: one line a check, "PASS <text>" or
"FAIL <text>".
"""

import json


def report(ok, text):
    """Print the line; 0 if ok, else 1 (to be or-ed into an exit status)."""
    print("%s %s" % ("PASS" if ok else "FAIL", text))
    return 0 if ok else 1


class Checks:
    """A series of checks that remembers whether all passed, and writes
    the results as json at the end."""

    def __init__(self):
        self.ok = True

    def __call__(self, passed, text):
        """Print the line; passed."""
        self.ok = self.ok and passed
        report(passed, text)
        return passed

    def finish(self, path, results):
        """Write results to path (if given); the exit status."""
        if path:
            with open(path, "w") as fh:
                json.dump(results, fh, indent=2)
        return 0 if self.ok else 1
