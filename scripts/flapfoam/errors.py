# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The package's error: a library function raises FlapFoamError with a
message that names the file, the entry, the value and what is allowed;
the tool's command layer (its main) turns it into that message and an
exit status.
"""


class FlapFoamError(Exception):
    """An error of the user's input or data, said in one message."""
