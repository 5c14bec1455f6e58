/* The tca row: the TCA of the case, then gte.csv, contact_path.csv, the separation topography
 * of each half and summary.json. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_tca.h"
#include "../output/output_internal.h"

#include <stdlib.h>

gd_status gd_row_tca_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result, gd_error *err)
{
    (void)out;
    *result = NULL;
    gd_case c = *cp;
    gd_tca_result *r = malloc(sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    const gd_pair pair = gd_pair_from_case(&c);
    gd_tca_settings set = gd_tca_settings_from_case(&c);
    set.stop = gd_row_stop(env);
    gd_status st = gd_tca_run(&pair, &set, r, err);
    if (st != GD_OK) {
        free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_tca_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    gd_geometry g;
    const gd_pair pair = gd_pair_from_case(c);
    gd_status st = gd_geometry_compute(&pair, &g, err);
    if (st != GD_OK)
        return st;
    return gd_tca_write_tables(out, c, result, g.rb, err);
}

gd_status gd_row_tca_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    return gd_summary_write_tca(out, c, result, err);
}

void gd_row_tca_free(void *result)
{
    if (!result)
        return;
    gd_tca_result_free(result);
    free(result);
}

void gd_row_tca_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_tca(&p, c, (const gd_tca_result *)result);
}
