/* The fields of one line of the project's own CSV tables, as the readers of an earlier run's tables
 * (sweep_states.c, basins_continuation.c, curve_start.c) split them: no quoting, since geardyn
 * writes none. */
#include "output_internal.h"

#include <string.h>

int gd_csv_split(char *line, char **f, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = 0;
    for (char *p = line; n < max;) {
        f[n++] = p;
        char *q = strchr(p, ',');
        if (!q)
            break;
        *q = 0;
        p = q + 1;
    }
    return n;
}

int gd_csv_column(char *const *f, int nf, const char *name)
{
    for (int i = 0; i < nf; i++)
        if (strcmp(f[i], name) == 0)
            return i;
    return -1;
}
