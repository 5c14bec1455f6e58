#!/usr/bin/env bash
# Regenerate every figure of docs/figures/ from the shipped cases, with the commands the docs name
# beside each figure (docs/guide.md, docs/continuation.md, docs/paper-reproduction.md,
# docs/optimisation.md, docs/accuracy.md, docs/basins.md), and copy each picture over its figure.
#
#   bash scripts/figures.sh [GEARDYN [WORKDIR]]
#
# GEARDYN: the executable (default build/src/cli/geardyn); WORKDIR: where the runs go (default a new
# directory under /tmp, kept: its results hold every table a figure was drawn from). ONLY=REGEX
# regenerates the figures whose names match (ONLY='^wp-' the work-precision diagrams). Prints one
# line per figure and the time each run took. The optimiser comparisons on the gear are the long
# runs (tens of minutes of CPU each), then the work-precision studies (45 s to 8 min each).
set -euo pipefail
cd "$(dirname "$0")/.."
REPO=$(pwd)
G=${1:-build/src/cli/geardyn}
case "$G" in /*) ;; *) G="$REPO/$G" ;; esac
[ -x "$G" ] || { echo "figures: not an executable: $G" >&2; exit 2; }
W=${2:-$(mktemp -d /tmp/geardyn-figures.XXXXXX)}
mkdir -p "$W"
W=$(cd "$W" && pwd)
ONLY=${ONLY:-.}
FIG="$REPO/docs/figures"

wanted() { # any of the figure names matches ONLY
    local f
    for f in "$@"; do [[ $f =~ $ONLY ]] && return 0; done
    return 1
}

# run OUT CASE [ARGS...]: geardyn run CASE ARGS --out WORKDIR/OUT, from the repository (the cases'
# relative paths, and an overlay sweep named relative to it)
run() {
    local out=$1 case=$2
    shift 2
    local t0=$SECONDS
    "$G" run "$case" "$@" --out "$W/$out" --quiet
    echo "  $case $* -> $W/$out ($((SECONDS - t0)) s)"
}

# fig NAME PICTURE: copy WORKDIR/PICTURE over docs/figures/NAME.png
fig() {
    cp "$W/$2" "$FIG/$1.png"
    echo "docs/figures/$1.png <- $2"
}

# docs/guide.md: the spur pair's response and speed sweep
if wanted guide-spur-response; then
    run spur cases/guide/spur.ini
    fig guide-spur-response spur/response.png
fi
if wanted guide-spur-sweep; then
    run spur-sweep cases/guide/spur-sweep.ini --threads 2
    fig guide-spur-sweep spur-sweep/bifurcation.png
fi

# docs/guide.md section 13: the NASA Glenn spur pair's speed sweep, and its continuation with the
# sweep over it (the case names the sweep's directory results/nasa-grc-spur-sweep)
if wanted guide-nasa-sweep guide-nasa-continuation; then
    run nasa-grc-spur-sweep cases/guide/nasa-grc-spur-sweep.ini --threads 2
    fig guide-nasa-sweep nasa-grc-spur-sweep/bifurcation.png
fi
if wanted guide-nasa-continuation; then
    run nasa-grc-spur-continuation cases/guide/nasa-grc-spur-continuation.ini \
        --set continuation.overlay_sweep="$W/nasa-grc-spur-sweep"
    fig guide-nasa-continuation nasa-grc-spur-continuation/continuation.png
fi

# docs/continuation.md: Kahraman & Singh by continuation
if wanted continuation-kahraman-singh; then
    run kahraman-singh cases/continuation/kahraman-singh.ini
    fig continuation-kahraman-singh kahraman-singh/continuation.png
fi
if wanted continuation-curves-kahraman-singh; then
    run kahraman-singh-curves cases/continuation/kahraman-singh-curves.ini
    fig continuation-curves-kahraman-singh kahraman-singh-curves/curves.png
fi
if wanted continuation-curves-kahraman-singh-cusp; then
    run kahraman-singh-cusp cases/continuation/kahraman-singh-cusp.ini
    fig continuation-curves-kahraman-singh-cusp kahraman-singh-cusp/curves.png
fi
# the curves in (Omega, F_a) over a regime map of the same plane, 41 x 31 points both ways
if wanted continuation-curves-kahraman-singh-map; then
    run kahraman-singh-map cases/continuation/kahraman-singh-curves.ini --set scene.analysis=sweep \
        --set sweep.parameter=operating.speed_rpm --set sweep.from=1591.5494309189 --set sweep.to=4774.6482927569 \
        --set sweep.points=41 --set sweep.parameter2=excitation.ste_amplitude_um --set sweep.from2=0.5 \
        --set sweep.to2=2 --set sweep.points2=31 --set sweep.direction=both --set run.lyapunov_exponents=0 \
        --set output.plots=off --threads 2
    run kahraman-singh-curves-map cases/continuation/kahraman-singh-curves.ini \
        --set continuation.overlay_map="$W/kahraman-singh-map"
    fig continuation-curves-kahraman-singh-map kahraman-singh-curves-map/curves.png
fi
# the curves in (Omega, F_a) at mesh damping ratio 0.07 beside those at 0.05
if wanted continuation-curves-kahraman-singh-damping; then
    run kahraman-singh-curves-005 cases/continuation/kahraman-singh-curves.ini --set output.plots=off
    run kahraman-singh-curves-007 cases/continuation/kahraman-singh-curves.ini --set damping.mesh_damping_ratio=0.07 \
        --set continuation.overlay_curves="$W/kahraman-singh-curves-005" \
        --set "scene.title=Kahraman & Singh oscillator: zeta 0.07 beside 0.05, F_m 0.1, constant stiffness, curves in (Omega, F_a)"
    fig continuation-curves-kahraman-singh-damping kahraman-singh-curves-007/curves.png
fi
if wanted continuation-curves-kahraman-singh-mean-force; then
    run kahraman-singh-mean-force cases/continuation/kahraman-singh-mean-force.ini
    fig continuation-curves-kahraman-singh-mean-force kahraman-singh-mean-force/curves.png
fi
# docs/continuation.md section 8: the paper's pair in (speed, torque) and (speed, backlash), modified and
# unmodified (the torque planes are the long runs: LTCA at every new torque)
for v in modified unmodified; do
    set_mod=()
    [ $v = unmodified ] && set_mod=(--set modification.apply=off)
    if wanted continuation-curves-paper-torque-$v; then
        run paper-curves-torque-$v cases/continuation/paper-curves-torque.ini "${set_mod[@]}" \
            --set "scene.title=The paper's pair, $v: curves in speed and torque"
        fig continuation-curves-paper-torque-$v paper-curves-torque-$v/curves.png
    fi
    if wanted continuation-curves-paper-backlash-$v; then
        run paper-curves-backlash-$v cases/continuation/paper-curves-backlash.ini "${set_mod[@]}" \
            --set "scene.title=The paper's pair, $v: curves in speed and backlash"
        fig continuation-curves-paper-backlash-$v paper-curves-backlash-$v/curves.png
    fi
done

# docs/paper-reproduction.md: the speed sweeps, and the sweep beside its continuation
if wanted paper-speed-100-8000rpm-modified; then
    run sweep-speed cases/paper/sweep-speed.ini --threads 2
    fig paper-speed-100-8000rpm-modified sweep-speed/bifurcation.png
fi
if wanted paper-speed-1000-3400rpm-modified; then
    run sweep-speed-1000-3400 cases/paper/sweep-speed.ini --set sweep.from=1000 --set sweep.to=3400 \
        --set sweep.points=49 --threads 2
    fig paper-speed-1000-3400rpm-modified sweep-speed-1000-3400/bifurcation.png
fi
if wanted paper-speed-sweep-3000-5500rpm paper-speed-continuation-3000-5500rpm; then
    run sweep-3000-5500 cases/paper/sweep-speed.ini --set sweep.from=3000 --set sweep.to=5500 --set sweep.points=26 \
        --set run.lyapunov_exponents=0 --threads 2
    run paper-speed cases/continuation/paper-speed.ini --set continuation.overlay_sweep="$W/sweep-3000-5500"
    fig paper-speed-sweep-3000-5500rpm sweep-3000-5500/bifurcation.png
    fig paper-speed-continuation-3000-5500rpm paper-speed/continuation.png
fi

# docs/optimisation.md: ALO on the gear, the optimisers on the gear at two budgets and on the test
# functions
if wanted opt-alo-lte opt-alo-load-distribution opt-alo-convergence; then
    run optimize-alo cases/paper/optimize-alo.ini --threads 2
    fig opt-alo-lte optimize-alo/lte.png
    fig opt-alo-load-distribution optimize-alo/optimum/load_distribution.png
    fig opt-alo-convergence optimize-alo/convergence.png
fi
if wanted opt-gear400-convergence opt-gear400-ecdf; then
    run compare-optimizers cases/paper/compare-optimizers.ini --threads 2
    fig opt-gear400-convergence compare-optimizers/convergence.png
    fig opt-gear400-ecdf compare-optimizers/ecdf.png
fi
if wanted opt-gear3030-convergence; then
    run compare-optimizers-3030 cases/paper/compare-optimizers.ini \
        --set optimize.optimizers=alo,gn_esch,gn_crs2_lm,gn_direct_l,random --set optimize.runs=5 \
        --set optimize.budget_evals=3030 --set optimize.population=30 --threads 2
    fig opt-gear3030-convergence compare-optimizers-3030/convergence.png
fi
# docs/optimisation.md section 12: the dynamic objective over load and speed (1240 evaluations of
# three LTCAs and continuations: tens of minutes of CPU), section 13: the two-objective optimisers
# on the gear
if wanted opt-dyn-convergence opt-dyn-response opt-dyn-harris opt-dyn-load-optimum opt-dyn-load-case; then
    run optimize-dynamic cases/paper/optimize-dynamic.ini --threads 2
    fig opt-dyn-convergence optimize-dynamic/convergence.png
    fig opt-dyn-response optimize-dynamic/response_over_speed.png
    fig opt-dyn-harris optimize-dynamic/lte_over_torque.png
    fig opt-dyn-load-optimum optimize-dynamic/optimum/load_distribution.png
    fig opt-dyn-load-case optimize-dynamic/case/load_distribution.png
fi
if wanted opt-pareto-gear; then
    run pareto-lte-dynamic cases/paper/pareto-lte-dynamic.ini --threads 2
    fig opt-pareto-gear pareto-lte-dynamic/pareto.png
fi
if wanted opt-two-gear-convergence opt-two-gear-ecdf; then
    run compare-two-objectives-gear cases/paper/compare-two-objectives-gear.ini --threads 1
    fig opt-two-gear-convergence compare-two-objectives-gear/convergence.png
    fig opt-two-gear-ecdf compare-two-objectives-gear/ecdf.png
fi
if wanted opt-testfn-ecdf; then
    run compare-test-functions cases/optimize/compare-test-functions.ini --threads 2
    fig opt-testfn-ecdf compare-test-functions/ecdf.png
fi

# docs/basins.md: Kahraman & Singh at Omega 0.65 and over Omega with the continuation's orbits, the
# paper's pair at 4750 rpm at 40 x 40 cells and 400 states
if wanted basins-kahraman-singh basins-kahraman-singh-fractions; then
    [ -d "$W/kahraman-singh" ] || run kahraman-singh cases/continuation/kahraman-singh.ini
fi
if wanted basins-kahraman-singh; then
    run basins-ks cases/basins/ks-hysteresis.ini --set basins.continuation="$W/kahraman-singh" --threads 2
    fig basins-kahraman-singh basins-ks/basins.png
fi
if wanted basins-kahraman-singh-fractions; then
    run basins-ks-fractions cases/basins/ks-fractions.ini --set basins.continuation="$W/kahraman-singh" --threads 2
    fig basins-kahraman-singh-fractions basins-ks-fractions/fractions.png
fi
if wanted basins-paper-4750rpm; then
    run basins-paper cases/basins/paper-4750rpm.ini --threads 2
    fig basins-paper-4750rpm basins-paper/basins.png
fi

# docs/accuracy.md: the work-precision diagrams of the five scenes
for s in period1-7000rpm periodn-2000rpm chaotic-1500rpm rattle-4000rpm stiff-supports; do
    if wanted "wp-$s"; then
        run "wp-$s" "cases/accuracy/$s.ini"
        fig "wp-$s" "wp-$s/work_precision.png"
    fi
done
echo "results in $W"
