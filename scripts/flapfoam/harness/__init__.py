# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The test harness: the PASS/FAIL lines every check prints (checklist), the
scenario runner of the test folders (scenarios, its table format in
scenario_table), the runner of the docs' commands (doc_commands) and the
synthetic flight data of the qsCalibrate test (synthetic_flight_data).
"""
