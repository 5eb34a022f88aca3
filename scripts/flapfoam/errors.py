# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The package's error: a library function raises FlapFoamError with a
message that names the file, the entry, the value and what is allowed;
the command layer (run_tool, every tool's main guard) turns it into that
message on stderr and exit status 1.
"""

import sys


class FlapFoamError(Exception):
    """An error of the user's input or data, said in one message."""


def run_tool(main, *args):
    """Runs a tool's main with args: its return value, or for a
    FlapFoamError the message on stderr and exit status 1."""
    try:
        return main(*args)
    except FlapFoamError as e:
        sys.exit(str(e))
