/* The ltca row: the LTCA of the case, then lte.csv, load_distribution.csv, pair_loads.csv and
 * summary.json. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_ltca.h"
#include "../output/output_internal.h"

#include <stdlib.h>

gd_status gd_row_ltca_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result, gd_error *err)
{
    (void)out;
    *result = NULL;
    gd_case c = *cp;
    gd_ltca_result *r = malloc(sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    const gd_pair pair = gd_pair_from_case(&c);
    gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    set.stop = gd_row_stop(env);
    gd_status st = gd_ltca_run(&pair, &set, r, err);
    if (st != GD_OK) {
        free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_ltca_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    return gd_ltca_write_tables(out, result, err);
}

gd_status gd_row_ltca_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    return gd_summary_write_ltca(out, c, result, err);
}

void gd_row_ltca_free(void *result)
{
    if (!result)
        return;
    gd_ltca_result_free(result);
    free(result);
}

void gd_row_ltca_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_ltca(&p, c, (const gd_ltca_result *)result);
}
