/* The table of analyses: every value of [scene] analysis is one row, naming the checks of the
 * analysis's own keys. A case is resolved in three steps, always in this order: the cross-key
 * checks that need no physics (gd_case_check), the scene (gd_scene_resolve: geometry and what
 * follows from it) and the row's own checks. The command line dispatches `run` by the same rows
 * (src/cli/cmd_run_dispatch.c); docs/architecture.md says how to add one. */
#ifndef GD_ANALYSIS_H
#define GD_ANALYSIS_H

#include "geardyn/gd_case.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gd_analysis_type {
    int id;                  /* gd_analysis, the value of scene.analysis */
    const char *name;        /* as the case file writes it */
    const char *what;        /* one line */
    /* The checks and derived defaults of the analysis's own keys, after the scene is resolved;
     * NULL when it has none. Messages name the case file line. */
    gd_status (*check_case)(gd_case *c, gd_error *err);
} gd_analysis_type;

/* All rows, in the order of the gd_analysis values. */
GD_API const gd_analysis_type *gd_analysis_types(size_t *n);
/* The row of an analysis, or NULL when this build has none. */
GD_API const gd_analysis_type *gd_analysis_find(int id);

/* Fill the derived values (unless pinned) and check consistency and ranges across keys: the
 * case's own checks, the scene, the analysis's. Call once after load and sets. */
GD_API gd_status gd_case_resolve(gd_case *c, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
