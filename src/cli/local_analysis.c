/* Local analysis of one operating point: the chosen response variable's time history,
 * phase portrait, amplitude spectrum and Poincare section (tables and the four-panel
 * figure of the paper's Figs. 16-42). */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { VAR_LAMBDA, VAR_DTE, VAR_DOF };

int cli_variable_resolve(const gd_case *c, const gd_model *m, cli_variable *v, gd_error *err)
{
    memset(v, 0, sizeof *v);
    const char *name = c->response_variable[0] ? c->response_variable : "lambda_L";
    snprintf(v->name, sizeof v->name, "%s", name);
    if (strcmp(name, "lambda_L") == 0 || strcmp(name, "lambda_R") == 0 || strcmp(name, "dte_L") == 0 ||
        strcmp(name, "dte_R") == 0) {
        v->kind = name[0] == 'l' ? VAR_LAMBDA : VAR_DTE;
        v->index = name[strlen(name) - 1] == 'R' && m->nmesh > 1 ? 1 : 0;
        return 0;
    }
    for (int i = 0; i < m->ndof; i++)
        if (strcmp(name, m->dof_name[i]) == 0) {
            v->kind = VAR_DOF;
            v->index = i;
            return 0;
        }
    char valid[512] = "lambda_L, lambda_R, dte_L, dte_R";
    for (int i = 0; i < m->ndof; i++) {
        size_t l = strlen(valid);
        snprintf(valid + l, sizeof valid - l, ", %s", m->dof_name[i]);
    }
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    int line = 0;
    gd_source src = gd_case_source(c, (size_t)(gd_case_find_key("output", "response_variable") - s), &line);
    char where[GD_PATH_MAX + 32];
    if (src == GD_SRC_FILE)
        snprintf(where, sizeof where, "%s:%d", c->path, line);
    else
        snprintf(where, sizeof where, "--set #%d", line);
    gd_error_set(err, GD_ERR_INPUT, "%s: output.response_variable: '%s' is not a variable of this model (valid: %s)",
                 where, name, valid);
    return 2;
}

/* value (um) and rate (m/s) of the variable at dimensionless time t in state y */
void cli_variable_value(const gd_model *m, const cli_variable *v, double t, const double *y, double *x, double *xdot)
{
    gd_modes md;
    memset(&md, 0, sizeof md);
    double um = m->bc_m * 1e6, mps = m->bc_m * m->omega_n;
    if (v->kind == VAR_LAMBDA) {
        gd_model_clearance(m, m->mesh_clear[v->index], t, y, &md, x, xdot);
    } else if (v->kind == VAR_DTE) {
        *x = y[m->q_dof[v->index]] / m->dte_scale;
        *xdot = y[m->ndof + m->q_dof[v->index]] / m->dte_scale;
    } else {
        *x = y[v->index];
        *xdot = y[m->ndof + v->index];
    }
    *x *= um;
    *xdot *= mps;
}

int cli_local_add_sample(cli_local *L, double t_s, double x, double xdot)
{
    if (L->n == L->cap) {
        size_t cap = L->cap ? 2 * L->cap : 4096;
        double *nt = realloc(L->t, cap * sizeof(double)), *nx = nt ? realloc(L->x, cap * sizeof(double)) : NULL;
        double *nv = nx ? realloc(L->xd, cap * sizeof(double)) : NULL;
        if (nt) L->t = nt;
        if (nx) L->x = nx;
        if (!nv)
            return 1;
        L->xd = nv;
        L->cap = cap;
    }
    L->t[L->n] = t_s;
    L->x[L->n] = x;
    L->xd[L->n] = xdot;
    L->n++;
    return 0;
}

int cli_local_add_poincare(cli_local *L, double x, double xdot)
{
    if (L->np == L->pcap) {
        size_t cap = L->pcap ? 2 * L->pcap : 256;
        double *a = realloc(L->px, cap * sizeof(double)), *b = a ? realloc(L->pxd, cap * sizeof(double)) : NULL;
        if (a) L->px = a;
        if (!b)
            return 1;
        L->pxd = b;
        L->pcap = cap;
    }
    L->px[L->np] = x;
    L->pxd[L->np] = xdot;
    L->np++;
    return 0;
}

void cli_local_free(cli_local *L)
{
    free(L->t);
    free(L->x);
    free(L->xd);
    free(L->px);
    free(L->pxd);
    memset(L, 0, sizeof *L);
}

/* variable.csv and variable_poincare.csv. */
static gd_status write_variable_tables(const char *dir, const cli_local *L, const char **files, int *nfiles,
                                       gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "variable.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "t_s,%s_um,%s_rate_mps\n", L->var.name, L->var.name);
    for (size_t i = 0; i < L->n; i++)
        fprintf(f.fp, "%.12g,%.9g,%.9g\n", L->t[i], L->x[i], L->xd[i]);
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;
    files[(*nfiles)++] = "variable.csv";
    if ((st = gd_atomic_open(&f, dir, "variable_poincare.csv", err)) != GD_OK)
        return st;
    fprintf(f.fp, "%s_um,%s_rate_mps\n", L->var.name, L->var.name);
    for (size_t i = 0; i < L->np; i++)
        fprintf(f.fp, "%.12g,%.12g\n", L->px[i], L->pxd[i]);
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;
    files[(*nfiles)++] = "variable_poincare.csv";
    return GD_OK;
}

/* spectrum.csv: the amplitude spectrum of the samples; its largest amplitude in L->spec_amax. */
static gd_status write_spectrum(const char *dir, const gd_case *c, const gd_model *m, cli_local *L,
                                const char **files, int *nfiles, gd_error *err)
{
    gd_atomic_file f;
    size_t nf = L->n / 2 + 1;
    double *fr = malloc(nf * sizeof(double)), *am = malloc(nf * sizeof(double));
    if (!fr || !am) {
        free(fr);
        free(am);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the spectrum");
    }
    double dt = (1.0 / m->mesh_freq_hz) / c->samples_per_period;
    gd_status st = gd_amplitude_spectrum(L->x, L->n, dt, fr, am, err);
    if (st == GD_OK)
        st = gd_atomic_open(&f, dir, "spectrum.csv", err);
    if (st == GD_OK) {
        fprintf(f.fp, "frequency_hz,order,amplitude_um\n");
        L->spec_amax = 0;
        for (size_t k = 0; k < nf; k++) {
            fprintf(f.fp, "%.9g,%.9g,%.9g\n", fr[k], fr[k] / m->mesh_freq_hz, am[k]);
            if (am[k] > L->spec_amax)
                L->spec_amax = am[k];
        }
        st = gd_atomic_commit(&f, err);
        if (st == GD_OK)
            files[(*nfiles)++] = "spectrum.csv";
    }
    free(fr);
    free(am);
    return st;
}

/* The four panels (PNG and SVG), drawn under temporary names then renamed; a failure is a note. */
static void draw_response(const char *dir, const gd_case *c, const gd_model *m, const gd_response_result *r,
                          const cli_local *L, const char **files, int *nfiles)
{
    int shown = c->record_periods < 20 ? c->record_periods : 20;
    double t_end = L->n ? L->t[L->n - 1] : 0, t_from = t_end - shown / m->mesh_freq_hz;
    double fmax_order = c->samples_per_period / 2.0 < 10 ? c->samples_per_period / 2.0 : 10;
    static const char *fmt[2][2] = {{"pngcairo size 1400,1000 font ',11'", ".png"},
                                    {"svg size 1400,1000 dynamic font 'sans,11'", ".svg"}};
    char script[8192];
    int n = 0;
    const char *v = L->var.name;
    double floor_amp = L->spec_amax > 0 ? 1e-6 * L->spec_amax : 1e-12;
    /* the Poincare section in the axes of the phase portrait (a zoom onto a converged point
     * would only show the integration noise) */
    double xlo = 0, xhi = 0, vlo = 0, vhi = 0;
    for (size_t i = 0; i < L->n; i++) {
        if (i == 0 || L->x[i] < xlo) xlo = L->x[i];
        if (i == 0 || L->x[i] > xhi) xhi = L->x[i];
        if (i == 0 || L->xd[i] < vlo) vlo = L->xd[i];
        if (i == 0 || L->xd[i] > vhi) vhi = L->xd[i];
    }
    double px = 0.05 * (xhi - xlo) + 1e-9, pv = 0.05 * (vhi - vlo) + 1e-12;
    xlo -= px;
    xhi += px;
    vlo -= pv;
    vhi += pv;
    for (int k = 0; k < 2; k++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.response%s.tmp'\nset datafile separator ','\n"
            "set multiplot layout 2,2 title '%s: %s, %s, largest Lyapunov exponent %.4g per mesh period'\n"
            "set grid\nunset key\n"
            "set title 'Time history (last %d mesh periods)'\nset xlabel 't (ms)'\nset ylabel '%s (um)'\n"
            "set xrange [%.12g:%.12g]\n"
            "plot '%s/variable.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $2 : 1/0) with lines lw 1.2\n"
            "set xrange [*:*]\n"
            "set title 'Phase portrait'\nset xlabel '%s (um)'\nset ylabel 'rate (m/s)'\n"
            "plot '%s/variable.csv' every ::1 using 2:3 with lines lw 0.6 lc rgb '#4477aa', "
            "'%s/variable_poincare.csv' every ::1 using 1:2 with points pt 7 ps 0.8 lc rgb '#cc2222'\n"
            "set title 'Amplitude spectrum (Hann window)'\nset xlabel 'order of the mesh frequency (%.6g Hz)'\n"
            "set ylabel 'amplitude (um)'\nset xrange [0:%g]\nset x2tics\nset x2label 'frequency (Hz)'\n"
            "set link x2 via x*%.12g inverse x/%.12g\nset logscale y\nset format y '%%g'\nset yrange [%.6g:*]\n"
            "plot '%s/spectrum.csv' every ::1 using 2:($3 > %.6g ? $3 : %.6g) with impulses lw 1.5\n"
            "unset logscale y\nset yrange [*:*]\nunset x2tics\nunset x2label\nunset link x2\nset xrange [*:*]\n"
            "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n"
            "set title 'Poincare section (%d distinct points)'\nset xlabel '%s (um)'\nset ylabel 'rate (m/s)'\n"
            "plot '%s/variable_poincare.csv' every ::1 using 1:2 with points pt 7 ps 0.8 lc rgb '#cc2222'\n"
            "unset multiplot\nunset output\nset xrange [*:*]\nset yrange [*:*]\n",
            fmt[k][0], dir, fmt[k][1], v, r->motion, gd_impact_regime_name(r->impact_regime[2]),
            r->n_lyapunov ? r->mle_per_period : 0.0 / 0.0, shown, v, 1e3 * t_from, 1e3 * t_end, dir, t_from, v, dir,
            dir, m->mesh_freq_hz, fmax_order, m->mesh_freq_hz, m->mesh_freq_hz, floor_amp, dir, floor_amp, floor_amp,
            xlo, xhi, vlo, vhi, r->poincare_distinct, v, dir);
    }
    gd_error perr = {0};
    static const char *names[] = {"response"};
    if (gd_gnuplot_draw(dir, script, names, 1, &perr) == GD_OK) {
        files[(*nfiles)++] = "response.png";
        files[(*nfiles)++] = "response.svg";
    } else {
        fprintf(stderr, "geardyn: note: the four-panel picture was not drawn: %s\n", perr.msg);
    }
}

/* variable.csv, variable_poincare.csv, spectrum.csv; then the figure. files[] gets the names. */
gd_status cli_local_write(const char *dir, const gd_case *c, const gd_model *m, const gd_response_result *r,
                          cli_local *L, const char **files, int *nfiles, int draw, gd_error *err)
{
    gd_status st = write_variable_tables(dir, L, files, nfiles, err);
    if (st == GD_OK)
        st = write_spectrum(dir, c, m, L, files, nfiles, err);
    if (st != GD_OK || !draw)
        return st;
    draw_response(dir, c, m, r, L, files, nfiles);
    return GD_OK;
}
