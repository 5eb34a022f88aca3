# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Studies that run or read many runs: the integrators' order
(integrator_order), the grid study (grid_study), the PIMPLE study's table
(pimple_study), the quasi-steady model's sweeps, calibration, integrators and
the drones' flights on one figure (qs_sweep, qs_calibrate, qs_integrators,
qs_flights), the controller's gain sweeps
(gain_sweep), CFD against QS (compare_models), the production ascent
(ascent), bench/forwardDynamics' table (forward_dynamics_table), and
designed flight on the QS model: a periodic flight's trim (trim), its
Floquet modes (floquet), a flown flight's cycle-to-cycle modes
(flight_modes), on the one-cycle map of a case (cycle_map; qs_case: the
studies' way to set a case up and run rigidBodySimulate).
"""
