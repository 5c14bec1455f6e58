/* Internal to the basins files (basins_mapper.c, basins_attractor.c, basins_run.c): the mapper's
 * definition, its tessellation and the classification of a found attractor. */
#ifndef GD_BASINS_INTERNAL_H
#define GD_BASINS_INTERNAL_H

#include "geardyn/gd_basins.h"

/* The tessellation's cells hold 0 (nothing yet), 2 a + 2 (a cell of attractor a), 2 a + 3 (the
 * initial cell of a state that went to attractor a) or a gd_basin_label (< 0: the initial cell of a
 * state with that outcome). */
#define BASIN_CELL_ATT(a) (2 * (a) + 2)
#define BASIN_CELL_BASIN(a) (2 * (a) + 3)

struct gd_basin_mapper {
    gd_model m;
    gd_solver_opts o;
    gd_basin_section sec;
    gd_basin_opts bo;
    int mx, my;              /* margin cells on each side */
    int tx, ty;              /* the tessellation: cells[0] + 2 mx by cells[1] + 2 my */
    double du, dv;           /* a cell's size in the section coordinates */
    double state_cell;       /* the largest change of a state component across one cell (max-norm) */
    int basin_hits;
    int *cell;               /* tx * ty, index (j + my) tx + (i + mx) for grid cell (i, j) */
    int natt, att_cap;
    gd_attractor *att;
    int **att_cells;         /* the tessellation cells of each attractor */
    int *att_ncells;
    long periods;
};

/* The tessellation cell of state y, or -1 outside it. */
int gd_basin_cell_of(const gd_basin_mapper *mp, const double *y);
/* max_k |a_k - b_k| / (1 + max_k |b_k|) over n components */
double gd_basin_state_distance(const double *a, const double *b, int n);

/* The attractor a trajectory found: s is its simulation at a period boundary on the attractor (the
 * last nhist points of the map in hist, oldest first, n each). Periodic when shooting from the
 * state converges to a stable orbit of at most opts.max_period periods near those points; else its
 * largest Lyapunov exponent over opts.lyapunov_periods. *cells (malloc'd, *ncells of them): its
 * tessellation cells; *periods: mesh periods integrated. */
gd_status gd_basin_classify(const gd_basin_mapper *mp, const double *y, const double *hist, int nhist,
                            gd_attractor *a, int **cells, int *ncells, long *periods, gd_error *err);
/* Whether candidate c (cells, ncells) is attractor index k of the mapper. */
int gd_basin_same(const gd_basin_mapper *mp, const gd_attractor *c, const int *cells, int ncells, int k);
/* The name of an attractor from its kind and period ("period-3", "chaotic"). */
void gd_basin_name(gd_attractor *a);

/* ---- the analysis of a case (basins_run.c, basins_match.c) ---- */
/* The model at the section's phase and the base state at parameter value v (NaN: the case's values), the
 * working copy cc of case c moved to v. */
gd_status gd_basins_model_at(gd_case *cc, const gd_case *c, double v, gd_model *m, double *base, gd_error *err);
/* The case's section of model m through base. */
gd_status gd_basins_section_at(const gd_case *c, const gd_model *m, const double *base, gd_basin_section *s,
                               gd_error *err);
/* The mapper's options from the case's keys and the hooks. */
void gd_basins_opts_of(const gd_case *c, const gd_basins_hooks *h, gd_basin_opts *bo);
/* The mapper's attractors copied into point p (the counts of those p had kept). */
gd_status gd_basins_point_take(gd_basins_point *p, const gd_basin_mapper *mp, gd_error *err);
/* The continuation's orbits through value v (the working case cc already at v) into p->orbits; *failed:
 * those whose shooting did not converge. */
gd_status gd_basins_orbits_at(const gd_case *c, gd_case *cc, const gd_basins_known *known, double v,
                              const gd_solver_opts *o, const gd_basin_opts *bo, gd_basins_point *p, int *failed,
                              gd_error *err);
/* p's stable continuation orbits mapped as seeds into mp. */
gd_status gd_basins_seed_orbits(gd_basin_mapper *mp, const gd_basins_point *p, gd_error *err);

#endif
