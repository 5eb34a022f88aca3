# shellcheck shell=bash
#------------------------------------------------------------------------------
# flapFoam: shell functions of the drone cases' Alltest scripts (sourced,
# with the project's check functions, bin/tools/checkFunctions).  Each
# prints PASS/FAIL lines "PASS [label] ..." (a failure sets status=1):
# runAllrun, scenarios, motionCycle, climbed, cleanKeepsRuns, lockedFolder,
# plots, copiedCase, result, flightData, quasiSteady, vacuum.  Needs:
# python (Debian's python3) and flapfoam (etc/bashrc), the case folder as
# the working directory, testRuns (the folder of the checks' runs and
# logs, set by the Alltest).
#------------------------------------------------------------------------------

projectScripts="$(cd "${BASH_SOURCE[0]%/*}" && pwd -P)"
# shellcheck source=bin/tools/checkFunctions
. "$projectScripts/checkFunctions"

# Allrun options: tight linear solvers (p, pFinal, U, UFinal tolerance
# 1e-12, relTol 0: comparisons then measure what they compare, not the
# solver tolerance), laminar flow (exact restarts, see the single-wing
# drone's README)
tight=()
for s in p pFinal U UFinal
do
    tight+=(-set system/fvSolution "solvers/$s/tolerance" 1e-12
            -set system/fvSolution "solvers/$s/relTol" 0)
done
laminar=(-set constant/turbulenceProperties simulationType laminar)

# runAllrun [-each] <label> <Allrun options...>: the run's log in
# $testRuns/log.Alltest.<label>; one line for the run (completed, no orphan at
# any step when the case checks orphans) and the FAIL lines of its checks;
# with -each every PASS/FAIL line of the run instead, and a FAIL line if
# it does not complete
runAllrun()
{
    local each=false
    [ "$1" = -each ] && { each=true; shift; }
    local label="$1"
    shift
    local log="$testRuns/log.Alltest.$label"
    local t0=$SECONDS
    ./Allrun "$@" > "$log" 2>&1
    local rc=$?
    if $each
    then
        grep -E '^(PASS|FAIL) ' "$log" | sed -E "s/^(PASS|FAIL) /\1 [$label] /"
        if [ "$rc" -ne 0 ]
        then
            fail "[$label] ./Allrun $* exited $rc (see $log)"
        fi
        return
    fi
    local p f
    p=$(grep -c '^PASS ' "$log")
    f=$(grep -c '^FAIL ' "$log")
    grep -E '^FAIL ' "$log" | sed -E "s/^FAIL /FAIL [$label] /"
    if [ "$rc" -ne 0 ] || [ "$f" -gt 0 ] || \
       { [ -f scripts/oversetCheck.py ] && [ "$p" -eq 0 ]; }
    then
        fail "[$label] ./Allrun $* exited $rc, $p orphan checks" \
             "passed, $f failed (see $log)"
    elif [ -f scripts/oversetCheck.py ]
    then
        pass "[$label] run completed; no orphan at any of the $p" \
             "written steps ($((SECONDS - t0)) s)"
    else
        pass "[$label] run completed ($((SECONDS - t0)) s)"
    fi
}

# scenarios <table> [flapfoam scenarios options...]: the rows of the case's
# table (flapfoam scenarios) from the case folder, their logs in
# $testRuns/log.<row>; its variables testRuns, tight, laminar and builtFrom
# (the commit Allwmake stamped into the build)
scenarios()
{
    local builtFrom
    builtFrom=$(sed -n 's/^#define FLAPFOAM_COMMIT "\(.*\)"$/\1/p' \
        "$FLAPFOAM_PROJECT_DIR/platforms/$WM_OPTIONS/include/flapFoamCommit.H")
    flapfoam scenarios "$1" -dir "$testRuns" \
        -var testRuns="$testRuns" -var "tight=${tight[*]}" \
        -var "laminar=${laminar[*]}" -var "builtFrom=${builtFrom:-missing}" \
        "${@:2}" || status=1
}

# plots <label> <run folder> <PNG names...>: scripts/plotRun.py on the run
# folder (log $testRuns/log.plotRun); every PNG in <run folder>/plots, not empty
plots()
{
    local label="$1" dir="$2"
    shift 2
    "$python" scripts/plotRun.py -case "$dir" > "$testRuns/log.plotRun" 2>&1
    local p n=0 error
    for p in "$@"
    do
        [ -s "$dir/plots/$p.png" ] && n=$((n + 1))
    done
    error="$(grep -o 'max |q - analytic|/amplitude = [^ ]*' "$testRuns/log.plotRun")"
    [ "$n" -eq "$#" ]
    verdict $? "[$label] plots: $n PNGs in $dir/plots${error:+; $error}" \
        "[$label] plots: $n of $# PNGs (see $testRuns/log.plotRun)"
}

# motionCycle <label> <run folder> [Allrun options...]: the mesh motion
# without flow (Allrun -motionOnly, tiny mesh; a whole flapping cycle unless
# the options say otherwise): the overset assembly at every step
# (oversetMotionCheck: no zone with more than 25 % holes, no acceptor
# without donors)
motionCycle()
{
    local label="$1" dir="$2"
    shift 2
    local log="$testRuns/log.Alltest.$label"
    local t0=$SECONDS
    ./Allrun -clean -level tiny -motionOnly -noMeshCheck -case "$dir" "$@" \
        > "$log" 2>&1
    local rc=$?
    local steps
    steps=$(grep -h '^Steps: ' "$dir/log.oversetMotionCheck" 2>/dev/null)
    [ "$rc" -eq 0 ] && grep -q '^oversetMotionCheck: OK' "$log"
    verdict $? "[$label] the mesh motion to t = $(foamDictionary -entry endTime -value "$dir/system/controlDict"): $steps ($((SECONDS - t0)) s)" \
        "[$label] ./Allrun -motionOnly exited $rc: $(grep -h '^oversetMotionCheck: FAILED' "$log" | head -1) (see $log)"
}

# climbed <label> <run folder> <q_0> <q_1> <tol>: the last row of the
# run's joints.dat has heave q_0 and surge q_1 within tol [m] of these
climbed()
{
    local label="$1" dir="$2" z="$3" x="$4" tol="$5" last
    last=$(tail -n 1 "$dir"/postProcessing/eABAMeshMotion/*/joints.dat \
        2>/dev/null)
    awk -v z="$z" -v x="$x" -v tol="$tol" \
        '{ exit !(NF > 4 && ($2 - z)^2 <= tol^2 && ($5 - x)^2 <= tol^2) }' \
        <<< "$last"
    verdict $? "[$label] at t = ${last%% *} heave and surge within $tol m of $z and $x m" \
        "[$label] the last row of joints.dat, t q_0 ... q_1:  $(cut -d' ' -f1-5 <<< "$last") (expected q_0 $z, q_1 $x, within $tol)"
}

# cleanKeepsRuns <label>: the case's Allclean in a scratch copy with a
# generated file, a time folder and two runs: exit 0, says what it removed,
# keeps the runs (listed) until named or -runs
cleanKeepsRuns()
{
    local label="$1" copy out rc
    copy="$(mktemp -d "${TMPDIR:-/tmp}/flapFoam-clean-XXXXXX")" || return
    cp Allclean "$copy/" && mkdir -p "$copy/mesh" "$copy/0.0125" \
        "$copy/runs/coarse" "$copy/runs/ascent" || return
    out=$(cd "$copy" && ./Allclean 2>&1)
    rc=$?
    [ "$rc" -eq 0 ] && [ ! -e "$copy/mesh" ] && [ ! -e "$copy/0.0125" ] \
        && [ -d "$copy/runs/coarse" ] && [[ "$out" == *"removed mesh 0.0125"* ]] \
        && [[ "$out" == *"kept the runs runs/ascent runs/coarse"* ]] \
        && (cd "$copy" && ./Allclean runs/coarse > /dev/null) \
        && [ ! -e "$copy/runs/coarse" ] && [ -d "$copy/runs/ascent" ] \
        && (cd "$copy" && ./Allclean -runs > /dev/null) && [ ! -e "$copy/runs" ]
    verdict $? "[$label] Allclean exits 0, says what it removed, keeps runs/ until named or -runs" \
        "[$label] Allclean: exit $rc, '$out' (in $copy)"
    rm -rf "$copy"
}

# lockedFolder <label> <run folder>: a second Allrun on a run folder in
# use stops naming the running one and touches nothing (here -test, which
# cleans); a lock file left by a killed driver (kill -9: not locked) is no
# obstacle; Allrun under mpirun stops at once, making nothing
lockedFolder()
{
    local label="$1" dir="$2" out rc pid
    rm -rf "$dir"
    ./Allrun -test -case "$dir" > "$testRuns/log.Alltest.$label" 2>&1 &
    pid=$!
    for _ in $(seq 100)
    do
        [ -s "$dir/Allrun.lock" ] && break
        sleep 0.1
    done
    out=$(./Allrun -test -case "$dir" 2>&1)
    rc=$?
    if [ "$rc" -ne 0 ] && [[ "$out" == *"$dir is in use by another run ("*"Allrun -test -case $dir"* ]] \
        && wait "$pid" && [ -d "$dir/5e-05" ] && [ ! -e "$dir/Allrun.lock" ]
    then
        pass "[$label] a second Allrun on a folder in use: exit $rc, names" \
             "the running one; the first completes undisturbed"
    else
        wait "$pid"
        fail "[$label] a second Allrun on a folder in use: exit $rc," \
             "'$(tail -c 300 <<< "$out")'"
    fi
    echo "Allrun (PID 999999, killed)" > "$dir/Allrun.lock"
    ./Allrun -test -case "$dir" > "$testRuns/log.Alltest.$label.stale" 2>&1
    verdict $? "[$label] a lock file left by a killed driver: the next run starts" \
        "[$label] a stale lock file stopped Allrun (see $testRuns/log.Alltest.$label.stale)"
    out=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        timeout 60 mpirun -np 2 ./Allrun -test -case "$dir-mpirun" 2>&1)
    [[ "$out" == *"started under MPI (OMPI_COMM_WORLD_SIZE=2): run Allrun once"* ]] \
        && [ ! -e "$dir-mpirun" ]
    verdict $? "[$label] mpirun -np 2 ./Allrun: stops at once, nothing made" \
        "[$label] mpirun -np 2 ./Allrun: '$(tail -c 300 <<< "$out")'"
}

# copiedCase [-script NAME] <label> <case folder> <options...>: the case copied
# out of the project tree (without runs/) runs there with only flapFoam's
# etc/bashrc sourced in a clean environment; a copy without it stops with
# a message saying what to source
copiedCase()
{
    local script=Allrun
    [ "$1" = -script ] && { script="$2"; shift 2; }
    local label="$1" case="$2"
    shift 2
    local copy t0=$SECONDS rc
    copy="$(mktemp -d "${TMPDIR:-/tmp}/flapFoam-copiedCase-XXXXXX")" || return
    (cd "$case" && tar cf - --exclude=./runs --exclude='log.*' .) \
        | (cd "$copy" && tar xf -)
    env -i HOME="$HOME" PATH=/usr/bin:/bin bash -c \
        'a=("$@"); set --; . "$0/etc/bashrc" && exec nice -n 10 "${a[@]}"' \
        "$FLAPFOAM_PROJECT_DIR" "$copy/$script" "$@" \
        > "$testRuns/log.Alltest.$label" 2>&1
    rc=$?
    [ "$rc" -eq 0 ]
    verdict $? "[$label] a copy in $copy ran with only etc/bashrc: $script $* ($((SECONDS - t0)) s)" \
        "[$label] the copy's $script $* exited $rc (see $testRuns/log.Alltest.$label)"
    expectRefusal -dir "$copy" "$label environment not set" \
        "source it first" env -i PATH=/usr/bin:/bin "$copy/$script" "$@"
    rm -rf "$copy"
}

# result <label> <flapfoam check_run arguments...>
result()
{
    local label="$1"
    shift
    labelled "$label" flapfoam check_run "$@"
}

# flightData <label> <flapfoam flight_data arguments...>
flightData()
{
    local label="$1"
    shift
    labelled "$label" flapfoam flight_data "$@"
}

# quasiSteady <label> <run folder> <rows> <Allrun options...>: Allrun
# -model quasiSteady -noPlot -case <run folder> <options> completes (log
# $testRuns/log.Alltest.<label>); its flight data complete (<rows> rows,
# attributes level none, stencil none, model quasiSteady, every value
# finite after the start row) and the same times and q of every joint as
# rigidBodySimulate's joints.dat (15 digits: the HDF5 values written so,
# exactly equal)
quasiSteady()
{
    local label="$1" dir="$2" rows="$3"
    shift 3
    local t0=$SECONDS log="$testRuns/log.Alltest.$label"
    if ./Allrun -model quasiSteady -noPlot -case "$dir" "$@" > "$log" 2>&1
    then
        pass "[$label] Allrun -model quasiSteady $* completed" \
            "($((SECONDS - t0)) s: $(grep -o 'in [0-9.]* s of wall' "$log"))"
    else
        fail "[$label] Allrun -model quasiSteady $* failed (see $log)"
        return
    fi
    flightData "$label" check "$dir" -uniformStep -rows "$rows" -attr level=none \
        -attr stencil=none -attr model=quasiSteady
    labelled "$label" flapfoam result_checks \
        flight-data-joints "$dir"
}

# vacuum <label> <run folder> <tol>: rigidBodySimulate on a copy of the
# folder's dictionaries (a row per step) against its joints.dat
vacuum()
{
    local label="$1" run="$2" tol="$3"
    local rbs="$run-rigidBodySimulate"
    rm -rf "$rbs"
    mkdir -p "$rbs/constant"
    cp -r "$run/system" "$rbs/"
    cp "$run/constant/dynamicMeshDict" "$rbs/constant/"
    local entry
    for entry in "startFrom startTime" "writeControl timeStep" \
                 "writeInterval 1"
    do
        set -- $entry
        foamDictionary -precision 17 -entry "$1" -set "$2" \
            "$rbs/system/controlDict" > /dev/null
    done
    if rigidBodySimulate -case "$rbs" > "$rbs/log.rigidBodySimulate" 2>&1
    then
        result "$label" -name rigidBodySimulate rbs "$run" "$rbs" \
            -tol "$tol"
    else
        fail "[$label] rigidBodySimulate failed" \
             "(see $rbs/log.rigidBodySimulate)"
    fi
}

#------------------------------------------------------------------------------
