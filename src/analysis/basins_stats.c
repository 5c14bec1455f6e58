/* What the labels of the basins give (docs/basins.md section 4): a fraction with its standard error
 * and Wilson score interval, the basin entropy and boundary basin entropy of a grid (Daza et al.
 * 2016), and the boundary cells of a basin. */
#include "geardyn/gd_basins.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_basin_fraction_of(long count, long total, double z, gd_basin_fraction *f)
{
    memset(f, 0, sizeof *f);
    f->count = count;
    f->total = total;
    if (total <= 0) {
        f->p = f->se = f->wilson_lo = f->wilson_hi = NAN;
        return;
    }
    double N = (double)total, p = (double)count / N, z2 = z * z;
    f->p = p;
    f->se = sqrt(p * (1.0 - p) / N);
    /* Wilson (1927): the p whose normal interval at z reaches the observed fraction */
    double den = 1.0 + z2 / N, centre = (p + z2 / (2.0 * N)) / den;
    double half = z * sqrt(p * (1.0 - p) / N + z2 / (4.0 * N * N)) / den;
    f->wilson_lo = fmax(0.0, centre - half);
    f->wilson_hi = fmin(1.0, centre + half);
}

GD_API gd_status gd_basin_entropy_of(const int *labels, int nx, int ny, int box, gd_basin_entropy *e, gd_error *err)
{
    memset(e, 0, sizeof *e);
    e->box = box;
    if (box < 1 || box > nx || box > ny)
        return gd_error_set(err, GD_ERR_INPUT, "basin entropy boxes of %d cells on a grid of %d x %d (valid: 1 to "
                            "the smaller side)", box, nx, ny);
    int *lab = malloc(sizeof(int) * (size_t)box * (size_t)box);
    long *cnt = malloc(sizeof(long) * (size_t)box * (size_t)box);
    if (!lab || !cnt) {
        free(lab);
        free(cnt);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the basin entropy");
    }
    double sum = 0.0;
    for (int by = 0; by + box <= ny; by += box)
        for (int bx = 0; bx + box <= nx; bx += box) {
            int nl = 0;
            for (int j = by; j < by + box; j++)
                for (int i = bx; i < bx + box; i++) {
                    int v = labels[(size_t)j * nx + i], q = 0;
                    while (q < nl && lab[q] != v)
                        q++;
                    if (q == nl) {
                        lab[nl] = v;
                        cnt[nl++] = 0;
                    }
                    cnt[q]++;
                }
            double s = 0.0, tot = (double)box * box;
            for (int q = 0; q < nl; q++) {
                double p = cnt[q] / tot;
                s -= p * log(p);
            }
            e->boxes++;
            sum += s;
            if (nl > 1)
                e->boundary_boxes++;
        }
    free(lab);
    free(cnt);
    e->sb = e->boxes ? sum / e->boxes : 0.0;
    e->sbb = e->boundary_boxes ? sum / e->boundary_boxes : 0.0;
    e->fractal = e->sbb > log(2.0);
    return GD_OK;
}

GD_API void gd_basin_boundary_cells(const int *labels, int nx, int ny, int label, long *boundary, long *cells)
{
    *boundary = *cells = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int v = labels[(size_t)j * nx + i];
            if (v != label)
                continue;
            (*cells)++;
            if ((i > 0 && labels[(size_t)j * nx + i - 1] != v) || (i + 1 < nx && labels[(size_t)j * nx + i + 1] != v) ||
                (j > 0 && labels[(size_t)(j - 1) * nx + i] != v) || (j + 1 < ny && labels[(size_t)(j + 1) * nx + i] != v))
                (*boundary)++;
        }
}
