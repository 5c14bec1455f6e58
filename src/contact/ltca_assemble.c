/* LTCA of one pinion position (docs/ltca.md sections 3 and 4): the contact lines of both halves from
 * TCA, the normal flexibility matrix of every tooth pair (potential-energy tooth with exact
 * influence coefficients, Sainsot's fillet foundation as a bilinear form, face coupling kernel,
 * linear Hertz), the rigid freedoms (gear rotation; axial shift of a floating herringbone pinion),
 * and the exact solution of the contact problem (Eq. 11). */
#include "ltca_internal.h"
#include "geardyn/gd_case.h" /* the enum of the pinion's axial support */
#include "geardyn/gd_geometry.h"

#include <gsl/gsl_spline.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_ltca_free(gd_ltca *w)
{
    if (!w)
        return;
    gd_tca_free(w->t);
    for (int b = 0; b < 2; b++) {
        gd_tooth_free(&w->body[b].tooth);
        free(w->pb[b]);
    }
    free(w->pts);
    free(w->bstart);
    free(w->L);
    free(w->w);
    free(w->G);
    free(w->p);
    free(w->d);
    free(w->kappa);
    free(w->hint);
    free(w->prev);
    ltca_qp_free(w->qp);
    gd_contact_workspace_free(w->cws);
    free(w);
}

/* Sainsot's coefficients L*, M*, P*, Q* of a tooth, read back from gd_tooth_foundation, which is
 * the quadratic form  cos^2 a / E' [L* u^2 + M* u + P* (1 + Q* tan^2 a)]  in u = u_f / S_f and
 * tan a: three loads across the centre line at u = -1, 0, 1 and one at 45 degrees give the four
 * numbers exactly. */
static void foundation_coefficients(ltca_body *B)
{
    const gd_tooth *t = &B->tooth;
    gd_load_point p = {0};
    p.h = 0;
    p.cos_a = 1;
    p.sin_a = 0;
    p.x = t->x_root;
    double c0 = gd_tooth_foundation(t, &p) * B->E1;
    p.x = t->x_root + B->Sf;
    double c1 = gd_tooth_foundation(t, &p) * B->E1;
    p.x = t->x_root - B->Sf;
    double cm = gd_tooth_foundation(t, &p) * B->E1;
    p.x = t->x_root;
    p.cos_a = p.sin_a = sqrt(0.5);
    double c45 = gd_tooth_foundation(t, &p) * B->E1 / 0.5;
    B->fnd[2] = c0;                         /* P* */
    B->fnd[1] = 0.5 * (c1 - cm);            /* M* */
    B->fnd[0] = 0.5 * (c1 + cm) - c0;       /* L* */
    B->fnd[3] = c0 != 0 ? c45 / c0 - 1 : 0; /* Q* */
}

GD_API gd_status gd_ltca_create(const gd_pair *pair, const gd_ltca_settings *set, gd_ltca **out, gd_error *err)
{
    *out = NULL;
    gd_ltca *w = calloc(1, sizeof *w);
    if (!w)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA: out of memory");
    /* the TCA face grid is the LTCA slicing */
    const gd_tca_settings ts = {.profile_points = set->profile_points, .face_points = set->face_slices,
                                .refine = set->refine};
    gd_status st = gd_tca_create(pair, &ts, &w->t, err);
    if (st != GD_OK) {
        gd_ltca_free(w);
        return st;
    }
    w->g = *gd_tca_geometry(w->t);
    const gd_geometry *g = &w->g;
    w->halves = gd_tca_halves(w->t);
    w->nslices = set->face_slices;
    w->floating = w->halves == 2 && set->pinion_axial == GD_PINION_FLOATING;
    w->m = w->floating ? 2 : 1;
    w->cb = cos(g->beta_b);
    w->cbeta = cos(g->beta);
    double E = pair->youngs_modulus_gpa * 1e9, nu = pair->poisson_ratio;
    w->hertz = gd_hertz_compliance(E, nu) * w->cb;
    w->Estar = E / (2.0 * (1.0 - nu * nu));
    w->rb2cb = g->rb[1] * w->cb;
    /* The teeth are the virtual spur teeth of the normal section (ISO 21771: z_n = z / (cos^2 beta_b
     * cos beta), normal module and pressure angle, the same addendum and dedendum): a helical tooth
     * bends across its length, in the normal section, and a transverse slice (thicker by
     * 1 / cos beta) would be too stiff (docs/ltca.md section 3.2). Load points keep their height
     * above the root circle. */
    gd_geometry gv = *g;
    for (int b = 0; b < 2; b++) {
        double zn = g->z[b] / (w->cb * w->cb * w->cbeta);
        double rv = 0.5 * zn * g->mn;
        gv.r[b] = rv;
        gv.rb[b] = rv * cos(g->alpha_n);
        gv.ra[b] = rv + (g->ra[b] - g->r[b]);
        gv.rf[b] = rv + (g->rf[b] - g->r[b]);
        w->body[b].rshift = rv - g->r[b];
    }
    gv.mt = g->mn;
    gv.alpha_t = g->alpha_n;
    for (int b = 0; b < 2; b++) {
        ltca_body *B = &w->body[b];
        st = gd_tooth_init(pair, &gv, b, &B->tooth, err);
        if (st != GD_OK) {
            gd_ltca_free(w);
            return st;
        }
        double rbore = 0.5e-3 * (b == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm);
        if (rbore > 0)
            B->tooth.h_fi = g->rf[b] / rbore; /* the rim ratio of the actual body */
        B->E1 = E / (1.0 - nu * nu);
        B->Sf = 2.0 * B->tooth.rf * sin(B->tooth.theta_f);
        foundation_coefficients(B);
    }
    for (int h = 0; h < w->halves; h++)
        for (int b = 0; b < 2; b++) {
            const gd_flank *f = gd_tca_flank(w->t, h, b);
            w->face[h][b][0] = f->z_min;
            w->face[h][b][1] = f->z_max;
        }
    const gd_flank *f1 = gd_tca_flank(w->t, 0, 0);
    w->dz = (f1->z_max - f1->z_min) / (w->nslices - 1);
    /* the first gap window: three times the deflection of the ISO 6336-1 stiffness under the
     * load, at least 2 um; widened whenever a position needs more (docs/ltca.md section 3.1) */
    double kiso = gd_iso6336_mesh_stiffness(pair, g) * w->halves;
    double fn = set->torque_nm > 0 ? set->torque_nm / (g->rb[0] * w->cb) : 0;
    w->window0 = w->window = fmax(3.0 * fn / kiso, 2e-6);
    size_t nbits = (size_t)2 * LTCA_PAIR_SPAN * (size_t)w->nslices;
    w->prev = calloc(nbits, 1);
    if (!w->prev) {
        gd_ltca_free(w);
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA: out of memory");
    }
    *out = w;
    return GD_OK;
}

GD_API int gd_ltca_halves(const gd_ltca *w) { return w->halves; }
GD_API gd_tca *gd_ltca_tca(gd_ltca *w) { return w->t; }
GD_API void gd_ltca_use_dense_solver(gd_ltca *w, int on) { w->dense = on != 0; }
GD_API double gd_ltca_normal_force(const gd_ltca *w, double torque_nm)
{
    return torque_nm / (w->g.rb[0] * w->cb);
}

GD_API const gd_ltca_point *gd_ltca_points(const gd_ltca *w, int *npoints)
{
    *npoints = w->n;
    return w->pts;
}

GD_API void gd_ltca_problem(const gd_ltca *w, gd_contact_problem *pb)
{
    pb->n = w->n;
    pb->m = w->m;
    pb->L = w->L;
    pb->w = w->w;
    pb->G = w->G;
    pb->f = w->f;
}

static gd_status reserve(gd_ltca *w, int n, gd_error *err)
{
    if (n <= w->cap)
        return GD_OK;
    int cap = w->cap ? w->cap : 64;
    while (cap < n)
        cap *= 2;
    size_t N = (size_t)cap;
    gd_ltca_point *pts = realloc(w->pts, N * sizeof *pts);
    if (pts)
        w->pts = pts;
    int ok = pts != NULL;
    for (int b = 0; b < 2 && ok; b++) {
        ltca_pt_body *q = realloc(w->pb[b], N * sizeof *q);
        if (q)
            w->pb[b] = q;
        ok = q != NULL;
    }
#define GROW(ptr, count)                                                                                           \
    do {                                                                                                           \
        if (ok) {                                                                                                  \
            void *np_ = realloc(ptr, (count) * sizeof *(ptr));                                                     \
            if (np_)                                                                                               \
                ptr = np_;                                                                                         \
            ok = np_ != NULL;                                                                                      \
        }                                                                                                          \
    } while (0)
    GROW(w->bstart, N + 1);
    GROW(w->L, N * N);
    GROW(w->w, N);
    GROW(w->G, N * GD_CONTACT_MAX_FREEDOMS);
    GROW(w->p, N);
    GROW(w->d, N);
    GROW(w->kappa, N);
    GROW(w->hint, N);
#undef GROW
    if (!ok)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA: out of memory for %d contact points", n);
    w->cap = cap;
    ltca_qp_free(w->qp);
    w->qp = NULL;
    gd_status st = ltca_qp_alloc(cap, w->nslices, w->m, &w->qp, err);
    if (st != GD_OK)
        return st;
    return GD_OK;
}

/* Largest principal curvature of the relative curvature tensor K1 + K2 in the tangent plane:
 * the curvature across the contact line (both flanks convex). */
static double relative_curvature(const gd_tca_line_point *lp)
{
    double e1[3], e2[3];
    memcpy(e1, lp->dir1[0], sizeof e1);
    e2[0] = lp->normal[1] * e1[2] - lp->normal[2] * e1[1];
    e2[1] = lp->normal[2] * e1[0] - lp->normal[0] * e1[2];
    e2[2] = lp->normal[0] * e1[1] - lp->normal[1] * e1[0];
    double M[3] = {0, 0, 0}; /* 11, 12, 22 */
    for (int a = 0; a < 2; a++) {
        double p1 = tca_dot3(lp->dir1[a], e1), p2 = tca_dot3(lp->dir1[a], e2);
        M[0] += lp->k1[a] * p1 * p1;
        M[1] += lp->k1[a] * p1 * p2;
        M[2] += lp->k1[a] * p2 * p2;
        double q1 = tca_dot3(lp->dir2[a], e1), q2 = tca_dot3(lp->dir2[a], e2);
        M[0] += lp->k2[a] * q1 * q1;
        M[1] += lp->k2[a] * q1 * q2;
        M[2] += lp->k2[a] * q2 * q2;
    }
    double tr = 0.5 * (M[0] + M[2]), det = M[0] * M[2] - M[1] * M[1];
    return tr + sqrt(fmax(tr * tr - det, 0.0));
}

static double spline_F(const gd_tooth *t, int k, double r)
{
    /* clamp to the table's own end points: its last node, r0 + (r1 - r0) * 1, may round below r1 */
    const gsl_spline *sp = t->spline[k];
    r = fmin(fmax(r, sp->interp->xmin), sp->interp->xmax);
    return gsl_spline_eval(sp, r, (gsl_interp_accel *)t->acc[k]);
}

static void point_body(const gd_ltca *w, int half, int b, double r, double z, double lo, double hi, ltca_pt_body *q)
{
    const ltca_body *B = &w->body[b];
    gd_load_point lp;
    r += B->rshift;
    gd_load_point_at(&B->tooth, r, &lp);
    q->x = lp.x;
    for (int k = 0; k < 5; k++)
        q->F[k] = spline_F(&B->tooth, k, r);
    q->c = lp.cos_a;
    q->s = lp.sin_a;
    q->a = lp.cos_a * lp.x - lp.sin_a * lp.h;
    double uf = lp.x - lp.h * lp.sin_a / lp.cos_a - B->tooth.x_root;
    q->U = lp.cos_a * uf / B->Sf;
    q->C = lp.cos_a;
    q->T = lp.sin_a;
    /* the kernel's decay length along the tooth at this load's height (gd_tooth_spread); a tooth
     * length ds is an axial length dz = ds cos(beta) */
    double l = gd_tooth_spread(&B->tooth, &lp) * w->cbeta;
    q->ell = l;
    q->lo = z + lo;
    q->hi = z + hi;
    q->z0 = w->face[half][b][0];
    q->z1 = w->face[half][b][1];
}

/* Bending, shear and compression (the formula of gd_tooth_influence with the integrals at the
 * lower point precomputed) plus the fillet foundation as the bilinear form of Sainsot's formula,
 * per unit slice width, transverse (m^2/N). */
double ltca_influence(const ltca_pt_body *j, const ltca_pt_body *k, const ltca_body *b)
{
    const double *F = j->x < k->x ? j->F : k->F;
    double c = j->a * k->a * F[0] - (j->a * k->c + k->a * j->c) * F[1] + j->c * k->c * F[2] + 1.2 * j->c * k->c * F[3] +
               j->s * k->s * F[4];
    const double *X = b->fnd;
    double f = X[0] * j->U * k->U + 0.5 * X[1] * (j->U * k->C + j->C * k->U) + X[2] * j->C * k->C +
               X[2] * X[3] * j->T * k->T;
    return c + f / b->E1;
}

/* The face kernel between the slices of two points of one body (gd_face_kernel_cells: a load
 * spread over its slice, the deflection averaged over the other; docs/ltca.md section 3.2). */
double ltca_kernel(const ltca_pt_body *j, const ltca_pt_body *k)
{
    return gd_face_kernel_cells(j->lo, j->hi, k->lo, k->hi, j->z0, j->z1, j->ell, k->ell);
}

/* A point's initial gap above its half's first contact less the pinion's profile relief there: what
 * the lead (its relief, the helix slope) and the misalignment leave, plus the geometry of a contact
 * off the nominal path. */
static double lead_gap(const gd_ltca *w, const gd_ltca_point *P)
{
    double profile, feed;
    gd_flank_relief(gd_tca_flank(w->t, P->half, 0), P->u1, P->z1, &profile, &feed);
    return P->gap - w->gstar[P->half] - profile;
}

/* Corner contact: a point on a tooth's tip edge or on the form circle the mating tip meets, off the
 * nominal path of contact (its gap above the first contact, the profile relief aside, is above
 * GD_LTCA_CORNER_GAP); where a contact line ends on a tip edge within the path (a helical line, a spur
 * pair at the path's end) the gap is the first contact's. */
static int corner(const gd_ltca *w, const gd_ltca_point *P)
{
    return (P->edge & GD_EDGE_TIPS_ROOTS) && lead_gap(w, P) > GD_LTCA_CORNER_GAP;
}

/* Edge loading at the face ends (docs/ltca.md section 4), and the corner contacts. Each block of
 * points is one tooth pair's contact line on one half. A loaded face-end point is edge-loaded when
 * the flanks meet first at that end: its gap (the profile relief aside, lead_gap) is the least of
 * the line's loaded points and theirs rise from it by more than GD_LTCA_EDGE_MARGIN of the line's
 * mean elastic deflection, so that the load concentrates on the end that cuts the line off (corner
 * contacts are left out of the line). The flat gaps of an aligned pair of unmodified flanks (1e-11 m)
 * raise nothing, whatever the line load does along a helical line; a crowned lead has its least gap
 * inside the face. edge_ratio: the largest line load of a loaded face end over its line's mean, for
 * the reader. */
static void ltca_face_ends(const gd_ltca *w, gd_ltca_position *out)
{
    for (int b = 0; b < w->nb; b++) {
        int lo = w->bstart[b], hi = w->bstart[b + 1];
        double load = 0, length = 0, defl = 0, gmin = INFINITY, gmax = -INFINITY;
        int n = 0;
        for (int i = lo; i < hi; i++) {
            const gd_ltca_point *P = &w->pts[i];
            if (!(P->load > 0))
                continue;
            load += P->load;
            length += P->width;
            if (corner(w, P)) {
                out->edge_loaded[P->half] |= P->edge & GD_EDGE_TIPS_ROOTS;
                continue;
            }
            double g = lead_gap(w, P);
            defl += w->z[0] + (w->m > 1 ? P->normal[2] * w->z[1] : 0.0) - P->gap;
            gmin = fmin(gmin, g);
            gmax = fmax(gmax, g);
            n++;
        }
        if (!(length > 0))
            continue;
        double mean = load * w->cb / length;
        defl /= n > 0 ? n : 1;
        for (int i = lo; i < hi; i++) {
            const gd_ltca_point *P = &w->pts[i];
            if (!(P->load > 0) || !(P->edge & GD_EDGE_FACE_ENDS) || corner(w, P))
                continue;
            out->edge_ratio[P->half] = fmax(out->edge_ratio[P->half], P->line_load / mean);
            double g = lead_gap(w, P);
            if (g <= gmin + 1e-3 * defl && gmax - g > GD_LTCA_EDGE_MARGIN * defl)
                out->edge_loaded[P->half] |= P->edge & GD_EDGE_FACE_ENDS;
        }
    }
}

gd_status ltca_collect(gd_ltca *w, double phi1, double window, gd_error *err)
{
    w->n = 0;
    w->nb = 0;
    for (int h = 0; h < w->halves; h++) {
        const gd_tca_line_point *lp;
        int n;
        gd_status st = gd_tca_lines_at(w->t, h, phi1, window, &lp, &n, err);
        if (st != GD_OK)
            return st;
        if (n < 1)
            return gd_error_set(err, GD_ERR_INTERNAL, "LTCA: no contact line on the %s half at %.9g rad",
                                h ? "right" : "left", phi1);
        st = reserve(w, w->n + n, err);
        if (st != GD_OK)
            return st;
        w->gstar[h] = lp[0].gap_nominal - lp[0].gap;
        w->nzmax[h] = 0;
        w->nzlo[h] = INFINITY;
        w->nzhi[h] = -INFINITY;
        const gd_flank *f1 = gd_tca_flank(w->t, h, 0), *f2 = gd_tca_flank(w->t, h, 1);
        for (int a = 0; a < n; a++) {
            int i = w->n++;
            gd_ltca_point *P = &w->pts[i];
            memset(P, 0, sizeof *P);
            P->half = h;
            P->pair = lp[a].pair;
            P->slice = lp[a].slice;
            P->u1 = lp[a].u1;
            P->z1 = lp[a].z1;
            P->u2 = lp[a].u2;
            P->z2 = lp[a].z2;
            P->rho1 = f1->rb * lp[a].u1;
            P->width = (lp[a].slice == 0 || lp[a].slice == w->nslices - 1) ? 0.5 * w->dz : w->dz;
            P->gap = lp[a].gap_nominal;
            memcpy(P->pos, lp[a].pos, sizeof P->pos);
            memcpy(P->normal, lp[a].normal, sizeof P->normal);
            P->edge = lp[a].edge;
            w->kappa[i] = relative_curvature(&lp[a]);
            w->nzmax[h] = fmax(w->nzmax[h], fabs(lp[a].normal[2]));
            w->nzlo[h] = fmin(w->nzlo[h], lp[a].normal[2]);
            w->nzhi[h] = fmax(w->nzhi[h], lp[a].normal[2]);
            double r1 = f1->rb * sqrt(1.0 + P->u1 * P->u1), r2 = f2->rb * sqrt(1.0 + P->u2 * P->u2);
            /* the point's slice: half a spacing either side, the end slices inward only */
            double lo = lp[a].slice == 0 ? 0.0 : -0.5 * w->dz;
            double hi = lp[a].slice == w->nslices - 1 ? 0.0 : 0.5 * w->dz;
            point_body(w, h, 0, r1, P->z1, lo, hi, &w->pb[0][i]);
            point_body(w, h, 1, r2, P->z2, lo, hi, &w->pb[1][i]);
            /* a new block at every change of half or tooth pair */
            if (i == 0 || w->pts[i - 1].half != h || w->pts[i - 1].pair != P->pair)
                w->bstart[w->nb++] = i;
        }
    }
    w->bstart[w->nb] = w->n;
    return GD_OK;
}

void ltca_assemble(gd_ltca *w)
{
    int n = w->n, m = w->m;
    const ltca_body *Bp = &w->body[0], *Bg = &w->body[1];
    for (int b = 0; b < w->nb; b++) {
        int lo = w->bstart[b], hi = w->bstart[b + 1];
        /* rows of this block: zero outside it, the tooth pair's influences inside */
        for (int i = lo; i < hi; i++) {
            double *row = w->L + (size_t)i * (size_t)n;
            memset(row, 0, sizeof(double) * (size_t)n);
            for (int k = lo; k <= i; k++) {
                const ltca_pt_body *pi = &w->pb[0][i], *pk = &w->pb[0][k];
                const ltca_pt_body *gi = &w->pb[1][i], *gk = &w->pb[1][k];
                double v = w->cbeta * (ltca_influence(pi, pk, Bp) * ltca_kernel(pi, pk) +
                                     ltca_influence(gi, gk, Bg) * ltca_kernel(gi, gk));
                row[k] = v;
                w->L[(size_t)k * (size_t)n + (size_t)i] = v;
            }
            row[i] += w->hertz / w->pts[i].width;
        }
    }
    for (int i = 0; i < n; i++) {
        w->w[i] = w->pts[i].gap;
        w->G[(size_t)i * (size_t)m] = 1.0;
        if (m > 1)
            w->G[(size_t)i * (size_t)m + 1] = w->pts[i].normal[2];
    }
}

void ltca_hertz(const gd_ltca *w, int i, double q, double *p0, double *b)
{
    double kap = w->kappa[i];
    if (!(q > 0) || !(kap > 0)) {
        *p0 = 0;
        *b = 0;
        return;
    }
    *p0 = sqrt(q * w->Estar * kap / M_PI);
    *b = sqrt(4.0 * q / (M_PI * w->Estar * kap));
}

static size_t bit_index(const gd_ltca *w, int half, int pair, int slice)
{
    int pp = pair + LTCA_PAIR_OFFSET;
    if (pp < 0 || pp >= LTCA_PAIR_SPAN || slice < 0 || slice >= w->nslices)
        return (size_t)-1;
    return ((size_t)half * LTCA_PAIR_SPAN + (size_t)pp) * (size_t)w->nslices + (size_t)slice;
}

static gd_status solve_qp(gd_ltca *w, int *iters, double *residual, gd_error *err)
{
    gd_contact_problem pb;
    gd_ltca_problem(w, &pb);
    gd_contact_solution sol = {0};
    sol.p = w->p;
    sol.d = w->d;
    int any = 0;
    for (int i = 0; i < w->n; i++) {
        size_t k = bit_index(w, w->pts[i].half, w->pts[i].pair, w->pts[i].slice);
        w->hint[i] = w->have_prev && k != (size_t)-1 ? w->prev[k] : 0;
        any |= w->hint[i];
    }
    gd_status st;
    if (w->dense) {
        if (!w->cws || w->cws_n < w->n) {
            gd_contact_workspace_free(w->cws);
            w->cws = NULL;
            st = gd_contact_workspace_alloc(w->cap, w->m, &w->cws, err);
            if (st != GD_OK)
                return st;
            w->cws_n = w->cap;
        }
        /* gd_contact_solve drops a warm start that has a non-positive load and falls back to its
         * own cold start, which fails on the nearly parallel rows of G of a floating pinion: give
         * it the feasible two-point start then */
        if (!any)
            any = ltca_qp_start(&pb, w->hint);
        st = gd_contact_solve(&pb, any ? w->hint : NULL, w->cws, &sol, err);
        if (st == GD_ERR_PHYSICS && ltca_qp_start(&pb, w->hint)) {
            gd_error_clear(err);
            st = gd_contact_solve(&pb, w->hint, w->cws, &sol, err);
        }
    } else {
        st = ltca_qp_solve(w->qp, &pb, w->nb, w->bstart, any ? w->hint : NULL, &sol, err);
    }
    if (st != GD_OK)
        return st;
    memcpy(w->z, sol.z, sizeof w->z);
    *iters = sol.iterations;
    *residual = sol.residual;
    return GD_OK;
}

GD_API gd_status gd_ltca_solve_at(gd_ltca *w, double phi1, double torque_nm, gd_ltca_position *out, gd_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(torque_nm > 0) || !isfinite(torque_nm))
        return gd_error_set(err, GD_ERR_INPUT, "LTCA: pinion torque %g N m (valid: > 0)", torque_nm);
    double fn = gd_ltca_normal_force(w, torque_nm);
    double window = w->window;
    int iters = 0;
    double residual = 0;
    for (int attempt = 0;; attempt++) {
        gd_status st = ltca_collect(w, phi1, window, err);
        if (st != GD_OK)
            return st;
        ltca_assemble(w);
        w->f[0] = fn;
        w->f[1] = 0.0;
        st = solve_qp(w, &iters, &residual, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "LTCA at phi1 = %.9g rad", phi1);
        /* The lines hold every point within `window` of its half's first contact; a point left out
         * has a gap w > gstar + window, so it stays open as long as the rigid approach at it,
         * z_0 + n_z z_1, is below that (n_z within the range of the half's points, 2 % margin). */
        double need = 0;
        for (int h = 0; h < w->halves; h++) {
            double reach = w->z[0];
            if (w->m > 1) /* n_z of the half's points, widened by 2 % of the largest */
                reach += fmax(w->z[1] * w->nzlo[h], w->z[1] * w->nzhi[h]) + 0.02 * fabs(w->z[1]) * w->nzmax[h];
            need = fmax(need, reach - w->gstar[h]);
        }
        if (need < window * (1.0 - 1e-9))
            break;
        if (attempt >= 20)
            return gd_error_set(err, GD_ERR_INTERNAL, "LTCA at phi1 = %.9g rad: the contact window does not settle "
                                "(%.3g um needed)", phi1, need * 1e6);
        window = fmax(2.0 * window, 1.5 * need);
    }
    w->window = window;
    /* the loaded set is the next position's warm start */
    memset(w->prev, 0, (size_t)2 * LTCA_PAIR_SPAN * (size_t)w->nslices);
    for (int i = 0; i < w->n; i++) {
        size_t k = bit_index(w, w->pts[i].half, w->pts[i].pair, w->pts[i].slice);
        if (k != (size_t)-1 && w->p[i] > 0)
            w->prev[k] = 1;
    }
    w->have_prev = 1;

    out->phi1 = phi1;
    out->torque_nm = torque_nm;
    out->approach = w->z[0];
    out->axial_shift = w->m > 1 ? w->z[1] : 0.0;
    out->lte = -w->z[0] / w->rb2cb;
    out->npoints = w->n;
    out->iterations = iters;
    out->residual = residual;
    out->window = window;
    double wsum[2] = {0, 0}, asum[2] = {0, 0}, nzsum[2] = {0, 0};
    int npts[2] = {0, 0}, lastpair[2] = {INT_MIN, INT_MIN};
    double total = 0;
    for (int i = 0; i < w->n; i++) {
        gd_ltca_point *P = &w->pts[i];
        int h = P->half;
        P->load = w->p[i];
        P->deformed_gap = w->d[i];
        double gz = w->z[0] + (w->m > 1 ? P->normal[2] * w->z[1] : 0.0);
        nzsum[h] += P->normal[2];
        npts[h]++;
        if (P->load > 0) {
            out->loaded++;
            total += P->load;
            out->load[h] += P->load;
            wsum[h] += P->load;
            asum[h] += P->load * gz;
            P->line_load = P->load * w->cb / P->width;
            ltca_hertz(w, i, P->line_load, &P->pressure, &P->hertz_half_width);
            out->max_pressure[h] = fmax(out->max_pressure[h], P->pressure);
            if (P->pair != lastpair[h]) {
                out->pairs_loaded[h]++;
                lastpair[h] = P->pair;
            }
        }
    }
    out->balance = fabs(total - fn) / fn;
    ltca_face_ends(w, out);
    for (int h = 0; h < w->halves; h++) {
        out->geometric[h] = w->gstar[h];
        double nz = npts[h] ? nzsum[h] / npts[h] : 0.0;
        out->approach_half[h] = wsum[h] > 0 ? asum[h] / wsum[h] : w->z[0] + (w->m > 1 ? nz * w->z[1] : 0.0);
        double defl = out->approach_half[h] - out->geometric[h];
        out->stiffness[h] = out->load[h] > 0 && defl > 0 ? out->load[h] / defl : 0.0;
    }
    return GD_OK;
}
