#------------------------------------------------------------------------------
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
#------------------------------------------------------------------------------
# The check of a bad-input run, shared by the Alltest scripts (sourced):
#
#     expectError WHAT RC LOG WORD...
#
# PASS "bad input WHAT" when RC is an error exit (not 0, not a timeout 124,
# not a signal >= 128) and LOG holds every WORD; else FAIL, naming the
# missing words, and the log is printed.  Uses the script's pass and fail.
#------------------------------------------------------------------------------

expectError()
{
    local what="$1" rc="$2" log="$3" missing="" w
    shift 3
    for w in "$@"
    do
        grep -qF -- "$w" "$log" || missing="$missing [$w]"
    done
    if [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && [ "$rc" -lt 128 ] \
    && [ -z "$missing" ]
    then
        pass "bad input $what (exit $rc)"
    else
        fail "bad input $what (exit $rc, message lacks:$missing; $log)"
        cat "$log"
    fi
}
