"""Hand-written C around the printed formulas and the table data: the header's API and the
functions that evaluate the tables the way ``zener_sym.exact.table`` and ``zener_sym.ham.table``
do (piece lookup, lambda maps, time maps, Horner per sub-piece), the square-root integrals of
``zener_sym.ham.quadrature``, and the inverse e -> lambda. The emitter (``codegen.c``) fills in
the ``@NAME@`` slots."""

HEADER = r'''#ifndef ZENER_SYM_H
#define ZENER_SYM_H
/*
 * Zener's impact equation delta'' + (1 + lambda d/dtau) delta^{3/2} = 0, delta(0) = 0,
 * delta'(0) = 1 (Eq. 10, dimensionless): exact summaries and histories from Chebyshev tables,
 * and the paper's HAM solutions (Eqs. 35, 42) printed from the SymPy derivation.
 *
 * C99, libm only, no global mutable state (every function is thread-safe and reentrant). Compile
 * zener_sym.c with your code (C or C++) and link -lm. Every function checks its inputs: outside
 * the allowed range it returns ZS_EDOM and sets every output to NaN.
 *
 * Units: lambda, tau, delta, velocity, force and impulse are the paper's dimensionless ones
 * (Eq. 9); the caller scales them to SI (see examples/c/README.md).
 */
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ZS_DELTA 0   /* contact ends at delta = 0 (the plate) */
#define ZS_FORCE 1   /* contact ends where the force vanishes (grains) */
#define ZS_OK    0
#define ZS_EDOM  1   /* lambda, tau, e or contact_end outside the allowed range; outputs set to NaN */

/* Range of the exact tables: ZS_LAM_MIN <= lambda <= ZS_LAM_MAX. */
#define ZS_LAM_MIN @LAM_MIN@
#define ZS_LAM_MAX @LAM_MAX@
/* The HAM solutions need 0 <= lambda < ZS_LAM_CRIT (omega0 = 0 there, Eq. 81). */
#define ZS_LAM_CRIT @LAM_CRIT@

/* One impact: lam, delta_m (max compression), tau_dc (end of compression), tau_d (end of
   contact), tau_dr = tau_d - tau_dc, eta = tau_dr / tau_dc, e (restitution), F_m = delta_m^{3/2},
   impulse (integral of the force over the contact), int_F2 (integral of the force squared),
   xi (energy loss: 2 lambda int_F2 for the exact model, 2 I - I^2 for ham1). */
typedef struct {
    double lam, delta_m, tau_dc, tau_d, tau_dr, eta, e, F_m, impulse, int_F2, xi;
} zs_summary_t;

/* Exact model, ZS_LAM_MIN <= lam <= ZS_LAM_MAX, from the tables (the Python package's
   model "exact", backend "table": same coefficients). out must not be NULL.
   Ends of contact with tables in this build (summary, history and zs_lam_for_e):
   @ENDS@. */
int zs_summary(double lam, int contact_end, zs_summary_t *out);

/* Exact history at n times tau[i] (finite, >= 0): compression delta, velocity delta', force
   and impulse; any output pointer may be NULL. ZS_DELTA: velocity = 1 - impulse, force
   delta^{3/2} (the plate's reading); ZS_FORCE: force sqrt(delta) (delta + (3/2) lambda delta')
   (the grains' reading), impulse 1 - delta'. Past the end of contact the fields are those the
   Python history gives there (delta = force = 0, impulse = 1 + e, velocity = -e). */
int zs_history(double lam, int contact_end, size_t n, const double *tau,
               double *delta, double *velocity, double *force, double *impulse);

/* The inverse: lambda in [ZS_LAM_MIN, ZS_LAM_MAX] whose restitution is e; NaN for e outside
   the reachable range (0 < e(ZS_LAM_MAX) <= e <= 1) or a bad contact_end. */
double zs_lam_for_e(double e, int contact_end);

/* The paper's HAM solutions, 0 <= lam < ZS_LAM_CRIT, printed from the derivation by SymPy's C
   printer: zeroth order (35) and first order (42) delta and force at n times tau[i] (finite,
   >= 0; 0 from the end of contact on; outputs may be NULL), and the first-order summary (from
   the ham1 Chebyshev tables in lambda, as the Python model's numpy backend). */
int zs_ham0_history(double lam, size_t n, const double *tau, double *delta, double *force);
int zs_ham1_history(double lam, size_t n, const double *tau, double *delta, double *force);
int zs_ham1_summary(double lam, zs_summary_t *out);

#ifdef __cplusplus
}
#endif
#endif /* ZENER_SYM_H */
'''

TYPES = r'''#include <math.h>
#include <stddef.h>
#include <string.h>

#include "zener_sym.h"

#define ZS__PI 3.14159265358979323846264338328
/* largest sizes of the tables below (checked by the emitter) */
#define ZS__MAX_SUB @MAX_SUB@
#define ZS__MAX_ROWS @MAX_ROWS@
#define ZS__MAX_LAMDEG @MAX_LAMDEG@
#define ZS__MAX_SUM @MAX_SUM@
#define ZS__MAX_H1 @MAX_H1@
#define ZS__MAX_FSUM @MAX_FSUM@
#define ZS__NFSUM 8  /* delta_m, tau_dc, log_tau_d, log_e, xi_over_lam, log_F_m, log_int_F2,
                        log_tau_p */
#define ZS__BLOCK 256 /* points per block of a history */
#define ZS__NSUM 6   /* delta_m, tau_dc, log_tau_d, log_e, int_F2, rest_over_lam */

/* one sub-piece's history: [cols: lambda degree, Chebyshev][rows: power of x][2 fields] */
typedef struct {
    int rows, cols;
    const double *c;
} zs__mat;

/* one time piece of the history: per lambda piece and sub-piece a matrix */
typedef struct {
    int n_sub;
    const zs__mat *m;
} zs__tpiece;

/* the summary of a force-free-end table (generated/exact_force_table.py): Chebyshev variable
   sqrt(lambda) below LOG_FROM, ln lambda above */
typedef struct {
    int n_lam;
    const double *edges, *ga, *gb;
    const int *log_piece;
    double lam_min, lam_max;
    const double *const *sum;   /* per piece [degree][ZS__NFSUM field] */
    const int *sum_len;
    zs__tpiece piece[2];        /* C, R; fields f and v = delta' */
} zs__force_table;

/* an exact table (the layout of generated/exact_table.py) */
typedef struct {
    int n_lam, n_hist;          /* lambda pieces; those with a history table */
    const double *edges, *ga, *gb, *xk, *xo; /* x = (2 g - ga - gb) / (gb - ga) ~ g xk - xo */
    const int *log_piece;       /* Chebyshev variable ln lambda (1) or lambda (0) */
    double lam_min, lam_max, hist_max;
    double log_from, c_stretch, c_end, s_orbit, s_transient;
    const double *const *sum;   /* per piece [degree][ZS__NSUM field] */
    const int *sum_len;
    zs__tpiece piece[4];        /* C, A, M, B */
} zs__exact_table;

'''

RUNTIME = r'''
/* ============================== runtime (hand-written) ============================== */

static const zs__exact_table *zs__table(int contact_end)
{
@TABLE_SWITCH@
}

static double zs__nan(void)
{
    return nan("");
}

static void zs__summary_nan(double lam, zs_summary_t *out)
{
    double q = zs__nan();
    out->lam = lam;
    out->delta_m = out->tau_dc = out->tau_d = out->tau_dr = out->eta = out->e = q;
    out->F_m = out->impulse = out->int_F2 = out->xi = q;
}


/* T_0(x) .. T_{deg-1}(x). recurrence: T_j = 2x T_{j-1} - T_{j-2}, as numpy's chebvander
   (the same doubles as Python: a history's piece ends then fall where Python's do). Else, for a
   summary alone, the same values to a few ulps with a shorter dependency chain: T_2 .. T_7 from
   T_{m+n} = 2 T_m T_n - T_{|m-n|}, then four interleaved chains T_j = 2 T_4 T_{j-4} - T_{j-8}
   (the one-step recurrence waits on a multiply and a subtraction per degree, most of a
   summary's time) */
static void zs__cheb_T(double x, int deg, int recurrence, double *T)
{
    int j;
    double x2 = 2.0 * x, t4;
    T[0] = 1.0;
    if (deg > 1)
        T[1] = x;
    if (recurrence || deg <= 8) {
        for (j = 2; j < deg; j++)
            T[j] = T[j - 1] * x2 - T[j - 2];
        return;
    }
    T[2] = x2 * x - 1.0;
    T[3] = x2 * T[2] - x;
    T[4] = 2.0 * T[2] * T[2] - 1.0;
    T[5] = 2.0 * T[2] * T[3] - x;
    T[6] = 2.0 * T[3] * T[3] - 1.0;
    T[7] = 2.0 * T[3] * T[4] - x;
    t4 = 2.0 * T[4];
    for (j = 8; j < deg; j++)
        T[j] = t4 * T[j - 4] - T[j - 8];
}

/* the summary fields of one lambda (exact.table._core) */
typedef struct {
    int ip;            /* lambda piece */
    double x;          /* its Chebyshev variable */
    double v[ZS__NSUM];
    double tau_d, e, tau_w0;
} zs__core_t;

static void zs__core(const zs__exact_table *t, double lam, int history, zs__core_t *c)
{
    int last = (history ? t->n_hist : t->n_lam) - 1, i, j, deg = 0;
    double g, a, b, x, T[ZS__MAX_SUM], xi, e_direct;
    /* piece: searchsorted(edges, lam, 'right') - 1, clipped to [0, last] (lam >= edges[0]);
       an early exit the branch predictor learns, not a scan every call waits on */
    i = 0;
    while (i < last && t->edges[i + 1] <= lam)
        i++;
    g = t->log_piece[i] ? log(lam) : lam;
    a = t->ga[i];
    b = t->gb[i];
    /* a history: Python's division (the same x, the same piece ends); a summary: the division
       folded into two constants (within an ulp or two of x, off the summary's critical path) */
    x = history ? (2.0 * g - a - b) / (b - a) : g * t->xk[i] - t->xo[i];
    if (x < -1.0)
        x = -1.0;
    if (x > 1.0)
        x = 1.0;
    deg = t->sum_len[i];
    /* for a history T_k(x) by the recurrence and each sum in order of k, as numpy's chebvander
       and exact.table._core: the same doubles as Python, so a time at a piece boundary (tau_dc,
       tau_w0, tau_d) falls in the same piece on both sides */
    zs__cheb_T(x, deg, history, T);
    {  /* every field's sum in order of degree, the fields side by side (the block is
           [degree][field], zero-padded) */
        /* one named accumulator a field (an array would be kept in memory, every addition
           then waiting on a store); T[0] = 1 */
        const double *cf = t->sum[i];
        double a0 = cf[0], a1 = cf[1], a2 = cf[2], a3 = cf[3], a4 = cf[4], a5 = cf[5];
        if (history) { /* in order of degree, as Python */
            for (j = 1; j < deg; j++) {
                const double *r = cf + j * ZS__NSUM, tj = T[j];
                a0 += tj * r[0];
                a1 += tj * r[1];
                a2 += tj * r[2];
                a3 += tj * r[3];
                a4 += tj * r[4];
                a5 += tj * r[5];
            }
            c->v[0] = a0;
            c->v[1] = a1;
            c->v[2] = a2;
            c->v[3] = a3;
            c->v[4] = a4;
            c->v[5] = a5;
        } else { /* odd and even degrees apart: half the chain of dependent additions */
            double b0 = 0.0, b1 = 0.0, b2 = 0.0, b3 = 0.0, b4 = 0.0, b5 = 0.0;
            for (j = 1; j + 1 < deg; j += 2) {
                const double *r = cf + j * ZS__NSUM, ta = T[j], tb = T[j + 1];
                a0 += ta * r[0];
                b0 += tb * r[ZS__NSUM + 0];
                a1 += ta * r[1];
                b1 += tb * r[ZS__NSUM + 1];
                a2 += ta * r[2];
                b2 += tb * r[ZS__NSUM + 2];
                a3 += ta * r[3];
                b3 += tb * r[ZS__NSUM + 3];
                a4 += ta * r[4];
                b4 += tb * r[ZS__NSUM + 4];
                a5 += ta * r[5];
                b5 += tb * r[ZS__NSUM + 5];
            }
            if (j < deg) {
                const double *r = cf + j * ZS__NSUM, ta = T[j];
                a0 += ta * r[0];
                a1 += ta * r[1];
                a2 += ta * r[2];
                a3 += ta * r[3];
                a4 += ta * r[4];
                a5 += ta * r[5];
            }
            c->v[0] = a0 + b0;
            c->v[1] = a1 + b1;
            c->v[2] = a2 + b2;
            c->v[3] = a3 + b3;
            c->v[4] = a4 + b4;
            c->v[5] = a5 + b5;
        }
    }
    c->ip = i;
    c->x = x;
    c->tau_d = exp(c->v[2]);
    /* e from the energy loss while xi < 1/2 (exact.solver.restitution), else exp(log e) */
    xi = 2.0 * lam * c->v[4];
    if (xi < 0.5) {
        c->e = sqrt(1.0 - xi > 0.0 ? 1.0 - xi : 0.0);
    } else {
        e_direct = exp(c->v[3]);
        c->e = e_direct;
    }
    c->tau_w0 = c->v[1] + lam * c->v[5];
}

static const zs__force_table *zs__force_table_of(int contact_end)
{
@FORCE_SWITCH@
}

/* the force-free end's summary fields of one lambda (exact.force_table._core) */
static void zs__force_core(const zs__force_table *t, double lam, int history,
                           double v[ZS__NFSUM], double *e, double *xi, int *ip, double *xl)
{
    int i, j, deg = 0;
    double g, x, T[ZS__MAX_FSUM];
    i = 0; /* searchsorted(edges, lam, 'right') - 1, clipped (lam >= edges[0]) */
    while (i < t->n_lam - 1 && t->edges[i + 1] <= lam)
        i++;
    g = t->log_piece[i] ? log(lam) : sqrt(lam);
    x = (2.0 * g - t->ga[i] - t->gb[i]) / (t->gb[i] - t->ga[i]);
    if (x < -1.0)
        x = -1.0;
    if (x > 1.0)
        x = 1.0;
    deg = t->sum_len[i];
    zs__cheb_T(x, deg, history, T);
    {  /* every field's sum in order of degree, the fields side by side (the block is
           [degree][field], zero-padded) */
        /* one named accumulator a field (an array would be kept in memory, every addition
           then waiting on a store); T[0] = 1 */
        const double *cf = t->sum[i];
        double a0 = cf[0], a1 = cf[1], a2 = cf[2], a3 = cf[3], a4 = cf[4], a5 = cf[5], a6 = cf[6], a7 = cf[7];
        if (history) { /* in order of degree, as Python */
            for (j = 1; j < deg; j++) {
                const double *r = cf + j * ZS__NFSUM, tj = T[j];
                a0 += tj * r[0];
                a1 += tj * r[1];
                a2 += tj * r[2];
                a3 += tj * r[3];
                a4 += tj * r[4];
                a5 += tj * r[5];
                a6 += tj * r[6];
                a7 += tj * r[7];
            }
            v[0] = a0;
            v[1] = a1;
            v[2] = a2;
            v[3] = a3;
            v[4] = a4;
            v[5] = a5;
            v[6] = a6;
            v[7] = a7;
        } else { /* odd and even degrees apart: half the chain of dependent additions */
            double b0 = 0.0, b1 = 0.0, b2 = 0.0, b3 = 0.0, b4 = 0.0, b5 = 0.0, b6 = 0.0, b7 = 0.0;
            for (j = 1; j + 1 < deg; j += 2) {
                const double *r = cf + j * ZS__NFSUM, ta = T[j], tb = T[j + 1];
                a0 += ta * r[0];
                b0 += tb * r[ZS__NFSUM + 0];
                a1 += ta * r[1];
                b1 += tb * r[ZS__NFSUM + 1];
                a2 += ta * r[2];
                b2 += tb * r[ZS__NFSUM + 2];
                a3 += ta * r[3];
                b3 += tb * r[ZS__NFSUM + 3];
                a4 += ta * r[4];
                b4 += tb * r[ZS__NFSUM + 4];
                a5 += ta * r[5];
                b5 += tb * r[ZS__NFSUM + 5];
                a6 += ta * r[6];
                b6 += tb * r[ZS__NFSUM + 6];
                a7 += ta * r[7];
                b7 += tb * r[ZS__NFSUM + 7];
            }
            if (j < deg) {
                const double *r = cf + j * ZS__NFSUM, ta = T[j];
                a0 += ta * r[0];
                a1 += ta * r[1];
                a2 += ta * r[2];
                a3 += ta * r[3];
                a4 += ta * r[4];
                a5 += ta * r[5];
                a6 += ta * r[6];
                a7 += ta * r[7];
            }
            v[0] = a0 + b0;
            v[1] = a1 + b1;
            v[2] = a2 + b2;
            v[3] = a3 + b3;
            v[4] = a4 + b4;
            v[5] = a5 + b5;
            v[6] = a6 + b6;
            v[7] = a7 + b7;
        }
    }
    *xi = lam * v[4];
    *e = *xi < 0.5 ? sqrt(1.0 - *xi > 0.0 ? 1.0 - *xi : 0.0) : exp(v[3]);
    *ip = i;
    *xl = x;
}

static int zs__contact_end_ok(int contact_end)
{
    return contact_end == ZS_DELTA || contact_end == ZS_FORCE;
}

int zs_summary(double lam, int contact_end, zs_summary_t *out)
{
    const zs__exact_table *t;
    zs__core_t c;
    double tau_dr;
    if (out == NULL)
        return ZS_EDOM;
    t = zs__contact_end_ok(contact_end) ? zs__table(contact_end) : NULL;
    if (t == NULL && zs__contact_end_ok(contact_end) && zs__force_table_of(contact_end) != NULL) {
        const zs__force_table *ft = zs__force_table_of(contact_end);
        double v[ZS__NFSUM], e, xi, x;
        int ip;
        if (!(lam >= ft->lam_min && lam <= ft->lam_max)) {
            zs__summary_nan(lam, out);
            return ZS_EDOM;
        }
        zs__force_core(ft, lam, 0, v, &e, &xi, &ip, &x);
        out->lam = lam;
        out->delta_m = v[0];
        out->tau_dc = v[1];
        out->tau_d = exp(v[2]);
        out->tau_dr = out->tau_d - v[1];
        out->eta = out->tau_dr / v[1];
        out->e = e;
        out->F_m = exp(v[5]);
        out->impulse = 1.0 + e;
        out->int_F2 = exp(v[6]);
        out->xi = xi;
        return ZS_OK;
    }
    if (t == NULL || !(lam >= t->lam_min && lam <= t->lam_max)) {
        zs__summary_nan(lam, out);
        return ZS_EDOM;
    }
    zs__core(t, lam, 0, &c);
    tau_dr = c.tau_d - c.v[1];
    out->lam = lam;
    out->delta_m = c.v[0];
    out->tau_dc = c.v[1];
    out->tau_d = c.tau_d;
    out->tau_dr = tau_dr;
    out->eta = tau_dr / c.v[1];
    out->e = c.e;
    out->F_m = c.v[0] * sqrt(c.v[0]); /* delta_m^{3/2} */
    out->impulse = 1.0 + c.e;
    out->int_F2 = c.v[4];
    out->xi = 2.0 * lam * c.v[4];
    return ZS_OK;
}

/* inputs of a history: every tau finite and >= 0 */
static int zs__tau_ok(size_t n, const double *tau)
{
    size_t i;
    if (n > 0 && tau == NULL)
        return 0;
    for (i = 0; i < n; i++)
        if (!(tau[i] >= 0.0 && tau[i] <= 1.7976931348623157e308))
            return 0;
    return 1;
}

static void zs__fill_nan(size_t n, double *a)
{
    size_t i;
    if (a != NULL)
        for (i = 0; i < n; i++)
            a[i] = zs__nan();
}

/* the per-call state of one time piece: its map's constants and its sub-pieces' monomial
   coefficients in x (f and I side by side), contracted in lambda when first needed */
typedef struct {
    double a, u0, s, e, i1, i2, i3, d, ra;
    int deg[ZS__MAX_SUB];                   /* 0: not contracted yet */
    double m[ZS__MAX_SUB][ZS__MAX_ROWS][2];
} zs__piece_t;

static void zs__contract(const zs__tpiece *tp, int ip, int sub, const double *Tl, zs__piece_t *P)
{
    const zs__mat *m = tp->m + ip * tp->n_sub + sub;
    double (*o)[2] = P->m[sub];
    int j, k, n = m->rows;
    double acc[2 * ZS__MAX_ROWS]; /* a local the table cannot alias: the pairs vectorise */
    if (n == 0) { /* no coefficients: the polynomial 0 */
        o[0][0] = o[0][1] = 0.0;
        P->deg[sub] = 1;
        return;
    }
    /* sum over the lambda degree k in order; the rows of field pairs are contiguous, so the
       two fields' multiply-adds go as one pair (and the rows' sums overlap) */
    for (j = 0; j < 2 * n; j++)
        acc[j] = m->c[j] * Tl[0];
    for (k = 1; k < m->cols; k++) {
        const double *c = m->c + (size_t)k * 2 * (size_t)n, tk = Tl[k];
        for (j = 0; j < 2 * n; j++)
            acc[j] += c[j] * tk;
    }
    for (j = 0; j < n; j++) {
        o[j][0] = acc[2 * j];
        o[j][1] = acc[2 * j + 1];
    }
    P->deg[sub] = n;
}

/* ln(1 + r) for r > -1 to a few ulps relative (Goldberg, "What every computer scientist should
   know about floating-point arithmetic", Thm. 4): libm's log of w = 1 + r, times r / (w - 1),
   which undoes the rounding of w. libm's log1p is twice log's time, most of a history point's */
static double zs__log1p(double r)
{
    double w = 1.0 + r;
    return w == 1.0 ? r : log(w) * (r / (w - 1.0));
}

/* constants of the lin_log map of piece A or M (exact.table._scaled_maps) */
static void zs__lin_log(zs__piece_t *P, int k, double start, double end, double c1, double c2,
                        double c3)
{
    double span = end - start;
    double u0 = -log1p(span / c2);
    double u1 = log1p(span / c1) + span / c3;
    P->a = k / (u1 - u0);
    P->u0 = u0;
    P->s = start;
    P->e = end;
    P->i1 = 1.0 / c1;
    P->i2 = 1.0 / c2;
    P->i3 = 1.0 / c3;
}

/* the force-free end's history (exact.force_table.history): time piece C, tau <= tau_dc,
   y = sqrt(tau / tau_dc), delta = tau exp(f); piece R, tau_dc < tau < tau_d, on ln-lambda pieces
   y linear in tau and delta = exp(f), on sqrt-lambda pieces y = (1 - sqrt((tau_P - tau) /
   (tau_P - tau_dc))) / (1 - z_end) and delta = (tau_P - tau) exp(f), tau_P the plate end's
   tau_d (the series log_tau_p) that the recovery is anchored on; v = delta' tabulated */
static int zs__force_history(const zs__force_table *t, double lam, size_t n, const double *tau,
                             double *delta, double *velocity, double *force, double *impulse)
{
    double v[ZS__NFSUM], e, xi, xl, Tl[ZS__MAX_LAMDEG], tau_dc, tau_d, tau_p = HUGE_VAL;
    double r_a, r_b = 0.0, c_a, lam_1 = 1.5 * lam;
    int ip, lg, p, s, k[2];
    zs__piece_t P[2];
    size_t i;
    zs__force_core(t, lam, 1, v, &e, &xi, &ip, &xl);
    lg = t->log_piece[ip];
    tau_dc = v[1];
    tau_d = exp(v[2]);
    if (lg) {
        r_a = 1.0 / (tau_d - tau_dc);
    } else {
        /* z at tau_d of tau = tau_P - (tau_P - tau_dc) z^2, clipped at 0: at lambda = 0 tau_d
           and tau_P are the same time, each to rounding (force_table_layout.recovery_z_end) */
        double gap = tau_p = exp(v[7]);
        gap -= tau_d;
        r_b = 1.0 / (tau_p - tau_dc);
        r_a = 1.0 / (1.0 - sqrt((gap > 0.0 ? gap : 0.0) * r_b));
    }
    c_a = 1.0 / tau_dc;
    Tl[0] = 1.0;
    Tl[1] = xl;
    for (s = 2; s < ZS__MAX_LAMDEG; s++)
        Tl[s] = Tl[s - 1] * 2.0 * xl - Tl[s - 2];
    for (p = 0; p < 2; p++) {
        k[p] = t->piece[p].n_sub;
        for (s = 0; s < ZS__MAX_SUB; s++)
            P[p].deg[s] = 0;
    }
    for (i = 0; i < n; i++) {
        double tt = tau[i], d = 0.0, vel = -e, gap = 1.0, z, x;
        double (*m)[2];
        int sub, j;
        if (tt < tau_d || tt <= tau_dc) {
            if (tt <= tau_dc) {
                p = 0;
                z = sqrt(tt * c_a) * k[0];
            } else if (lg) {
                p = 1;
                z = (tt - tau_dc) * r_a * k[1];
            } else {
                p = 1;
                gap = tau_p - tt;
                if (!(gap > 0.0))
                    gap = 0.0;
                z = r_a * (1.0 - sqrt(gap * r_b)) * k[1];
            }
            /* the sub-piece, as numpy's astype(intp) then clip: a z rounded below 0 stays in
               the first sub-piece (its x a hair below -1), past k in the last */
            sub = z >= 0.0 ? (z < (double)k[p] ? (int)z : k[p] - 1) : 0;
            x = 2.0 * (z - sub) - 1.0;
            if (P[p].deg[sub] == 0)
                zs__contract(&t->piece[p], ip, sub, Tl, &P[p]);
            m = P[p].m[sub];
            j = P[p].deg[sub] - 1;
            d = m[j][0];
            vel = m[j][1];
            for (j = j - 1; j >= 0; j--) {
                d = d * x + m[j][0];
                vel = vel * x + m[j][1];
            }
            d = exp(d) * (p == 0 ? tt : gap);
        }
        if (delta != NULL)
            delta[i] = d;
        if (velocity != NULL)
            velocity[i] = vel;
        if (force != NULL)
            force[i] = sqrt(d) * (d + lam_1 * vel);
        if (impulse != NULL)
            impulse[i] = 1.0 - vel;
    }
    return ZS_OK;
}

int zs_history(double lam, int contact_end, size_t n, const double *tau,
               double *delta, double *velocity, double *force, double *impulse)
{
    const zs__exact_table *t;
    zs__core_t c;
    zs__piece_t P[4];
    double Tl[ZS__MAX_LAMDEG], tau_s, inf = HUGE_VAL, tau_dc, imp_end;
    int p, s, log_piece;
    size_t i0;
    t = zs__contact_end_ok(contact_end) ? zs__table(contact_end) : NULL;
    if (t == NULL && zs__contact_end_ok(contact_end)) {
        const zs__force_table *ft = zs__force_table_of(contact_end);
        if (ft != NULL && lam >= ft->lam_min && lam <= ft->lam_max && zs__tau_ok(n, tau))
            return zs__force_history(ft, lam, n, tau, delta, velocity, force, impulse);
    }
    if (t == NULL || !(lam >= t->lam_min && lam <= t->hist_max) || !zs__tau_ok(n, tau)) {
        zs__fill_nan(n, delta);
        zs__fill_nan(n, velocity);
        zs__fill_nan(n, force);
        zs__fill_nan(n, impulse);
        return ZS_EDOM;
    }
    zs__core(t, lam, 1, &c);
    tau_dc = c.v[1];
    log_piece = t->log_piece[c.ip];
    tau_s = log_piece ? tau_dc + lam * (t->s_orbit + t->s_transient * pow(lam, -5.0 / 3.0))
                      : c.tau_w0;
    /* T_k(x_lambda) for the lambda contraction */
    Tl[0] = 1.0;
    Tl[1] = c.x;
    for (s = 2; s < ZS__MAX_LAMDEG; s++)
        Tl[s] = Tl[s - 1] * 2.0 * c.x - Tl[s - 2];
    for (p = 0; p < 4; p++) {
        for (s = 0; s < ZS__MAX_SUB; s++)
            P[p].deg[s] = 0;
        P[p].i1 = P[p].i2 = P[p].i3 = 0.0;
    }
    P[0].a = t->piece[0].n_sub * (double)t->piece[0].n_sub / tau_dc;
    zs__lin_log(&P[1], t->piece[1].n_sub, tau_dc, tau_s,
                t->c_stretch * (log_piece ? pow(t->log_from / lam, 2.0 / 3.0) : 1.0),
                log_piece ? inf : t->c_end * (1.0 + lam), inf);
    if (log_piece)
        zs__lin_log(&P[2], t->piece[2].n_sub, tau_s, c.tau_w0, inf, lam, lam);
    P[3].a = t->piece[3].n_sub * (double)t->piece[3].n_sub / (c.tau_d - c.tau_w0);
    P[3].d = c.tau_d;
    /* 1 / sqrt(a) of the square-root maps: sqrt(tau) = z / sqrt(a) for the force */
    P[0].ra = 1.0 / sqrt(P[0].a);
    P[3].ra = 1.0 / sqrt(P[3].a);
    imp_end = 1.0 + c.e;
    /* blocks of points in three passes (piece and local variable; Horner; exp and outputs):
       the Horner pass has no calls, so the processor overlaps the points' chains */
    for (i0 = 0; i0 < n; i0 += ZS__BLOCK) {
        size_t nb = n - i0 < ZS__BLOCK ? n - i0 : ZS__BLOCK, b;
        int pc[ZS__BLOCK], sb[ZS__BLOCK];
        double xs[ZS__BLOCK], fv[ZS__BLOCK], Iv[ZS__BLOCK], zr[ZS__BLOCK];
        for (b = 0; b < nb; b++) {
            double tt = tau[i0 + b], z;
            int k, sub;
            zs__piece_t *Q;
            if (tt > tau_dc)
                p = 1 + (tt >= tau_s) + (tt >= c.tau_w0) + (tt >= c.tau_d);
            else
                p = 0;
            pc[b] = p;
            if (p == 4)
                continue;
            Q = &P[p];
            k = t->piece[p].n_sub;
            if (p == 0) {
                z = sqrt(tt * Q->a);
                zr[b] = z;
            } else if (p == 3) {
                z = sqrt((Q->d - tt) * Q->a);
                zr[b] = z;
            } else {
                /* u = ln(1 + p) + ts i3 - ln(1 + q), p = ts i1, q = te i2 (table_build.lin_log),
                   the logarithms as one, ln(1 + (p - q) / (1 + q)): log1p of a small argument
                   keeps u's relative accuracy on a short piece (where u is small and
                   a = k / (u1 - u0) large), at the cost of one log1p a point instead of two */
                double ts = tt - Q->s, pp = ts * Q->i1, qq = (Q->e - tt) * Q->i2;
                z = -Q->u0;
                if (Q->i3 != 0.0)
                    z += ts * Q->i3;
                z += zs__log1p((pp - qq) / (1.0 + qq));
                z *= Q->a;
            }
            if (!(z >= 0.0)) /* rounding at a piece's start (or a NaN): the first sub-piece */
                z = 0.0;
            sub = z < (double)k ? (int)z : k - 1;
            xs[b] = 2.0 * (z - sub) - 1.0;
            sb[b] = sub;
            if (Q->deg[sub] == 0)
                zs__contract(&t->piece[p], c.ip, sub, Tl, Q);
        }
        for (b = 0; b < nb; b++) {
            double (*m)[2];
            double x = xs[b], f, I;
            int j;
            if (pc[b] == 4) {
                fv[b] = 0.0;
                Iv[b] = imp_end;
                continue;
            }
            m = P[pc[b]].m[sb[b]];
            j = P[pc[b]].deg[sb[b]] - 1;
            f = m[j][0];
            I = m[j][1];
            for (j = j - 1; j >= 0; j--) {
                f = f * x + m[j][0];
                I = I * x + m[j][1];
            }
            fv[b] = f;
            Iv[b] = I;
        }
        for (b = 0; b < nb; b++) {
            double tt = tau[i0 + b], d, sd, I = Iv[b];
            p = pc[b];
            /* h = exp(f / 2): delta = h^2 (times tau or tau_d - tau), and sqrt(delta) for the
               force without a square root (the maps' z = sqrt(a tau) gives sqrt(tau)) */
            if (p == 4) {
                d = sd = 0.0;
            } else {
                double h = exp(0.5 * fv[b]);
                d = h * h;
                sd = h;
                if (p == 0) {
                    d *= tt;
                    sd *= zr[b] * P[0].ra;
                } else if (p == 3) {
                    d *= P[3].d - tt;
                    sd *= zr[b] * P[3].ra;
                }
            }
            if (delta != NULL)
                delta[i0 + b] = d;
            if (impulse != NULL)
                impulse[i0 + b] = I;
            if (velocity != NULL)
                velocity[i0 + b] = 1.0 - I;
            if (force != NULL)
                force[i0 + b] = sd * d;
        }
    }
    return ZS_OK;
}

/* the quantity the inverse solves for: xi = 2 lambda int_F2 (increasing) where the target's
   xi = 1 - e^2 is below 1/2, as e itself is formed there (exact.solver.restitution), so lambda
   keeps its relative accuracy as e -> 1; e (decreasing) below */
static double zs__q_of(const zs__exact_table *t, const zs__force_table *ft, double lam,
                       int use_xi)
{
    if (t != NULL) {
        zs__core_t c;
        zs__core(t, lam, 0, &c);
        return use_xi ? 2.0 * lam * c.v[4] : -c.e;
    } else {
        double v[ZS__NFSUM], e, xi, x;
        int ip;
        zs__force_core(ft, lam, 0, v, &e, &xi, &ip, &x);
        return use_xi ? xi : -e;
    }
}

/* ordered 64-bit key of a double >= 0 (bisection on the representable numbers) */
static unsigned long long zs__key(double x)
{
    unsigned long long u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static double zs__from_key(unsigned long long u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

double zs_lam_for_e(double e, int contact_end)
{
    const zs__exact_table *t = zs__contact_end_ok(contact_end) ? zs__table(contact_end) : NULL;
    const zs__force_table *ft = zs__contact_end_ok(contact_end) && t == NULL
                                    ? zs__force_table_of(contact_end) : NULL;
    unsigned long long lo, hi;
    double xi_t, q, q_top, lam_min, lam_max;
    int use_xi;
    if ((t == NULL && ft == NULL) || !(e > 0.0 && e <= 1.0))
        return zs__nan();
    lam_min = t != NULL ? t->lam_min : ft->lam_min;
    lam_max = t != NULL ? t->lam_max : ft->lam_max;
    if (e == 1.0)
        return lam_min;
    xi_t = (1.0 - e) * (1.0 + e);
    use_xi = xi_t < 0.5;
    q = use_xi ? xi_t : -e;
    /* the target beyond the table's reach (e below e(ZS_LAM_MAX)) */
    if (!(-e <= zs__q_of(t, ft, lam_max, 0)))
        return zs__nan();
    q_top = zs__q_of(t, ft, lam_max, use_xi);
    if (q >= q_top)
        return lam_max;
    /* q(lambda) increases: bisection over the doubles of [lam_min, lam_max] to the last ulp,
       keeping q(lo) < q <= q(hi); at most 64 steps */
    lo = zs__key(lam_min);
    hi = zs__key(lam_max);
    while (hi - lo > 1) {
        unsigned long long mid = lo + (hi - lo) / 2;
        if (zs__q_of(t, ft, zs__from_key(mid), use_xi) < q)
            lo = mid;
        else
            hi = mid;
    }
    /* the nearer of the two neighbours */
    {
        double l0 = zs__from_key(lo), l1 = zs__from_key(hi);
        return q - zs__q_of(t, ft, l0, use_xi) < zs__q_of(t, ft, l1, use_xi) - q ? l0 : l1;
    }
}

/* ------------------------------------------------------------------------ HAM runtime */

static int zs__ham_lam_ok(double lam)
{
    return lam >= 0.0 && lam < ZS_LAM_CRIT;
}

int zs_ham0_history(double lam, size_t n, const double *tau, double *delta, double *force)
{
    double k, beta, omega0, tau_d;
    size_t i;
    if (!zs__ham_lam_ok(lam) || !zs__tau_ok(n, tau)) {
        zs__fill_nan(n, delta);
        zs__fill_nan(n, force);
        return ZS_EDOM;
    }
    zs__ham_params(lam, &k, &beta, &omega0);
    tau_d = ZS__PI * pow(omega0, -1.0); /* (54), as the Python model */
    for (i = 0; i < n; i++) {
        double d = tau[i] >= tau_d ? 0.0 : zs__ham0_delta(tau[i], beta, omega0);
        if (delta != NULL)
            delta[i] = d;
        if (force != NULL)
            force[i] = sqrt(d) * d;
    }
    return ZS_OK;
}

/* K_cc, K_sc, K_ss (a, theta) on [0, T] (left, T <= pi/2) or [pi - r, pi] (right) by the
   Gauss-Jacobi rule with the square-root singularity in the weight (ham.quadrature) */
static void zs__K_piece(double a, double T, int right, double K[3])
{
    int i;
    double scale = T * sqrt(T);
    K[0] = K[1] = K[2] = 0.0;
    for (i = 0; i < ZS__GJ_N; i++) {
        double x = T * zs__gj_u[i];
        double s = sin(x), c = right ? -cos(x) : cos(x);
        double so = x > 0.0 ? s / x : 1.0;
        double base = exp(-a * (right ? ZS__PI - x : x)) * sqrt(so) * zs__gj_w[i];
        K[0] += base * (c * c);
        K[1] += base * (s * c);
        K[2] += base * (s * s);
    }
    K[0] *= scale;
    K[1] *= scale;
    K[2] *= scale;
}

/* theta clipped at pi (the integrals freeze there); full[] = the right piece over [pi/2, pi] */
static void zs__K(double a, double theta, const double full[3], double K[3])
{
    double half = ZS__PI / 2.0, th = theta < ZS__PI ? theta : ZS__PI;
    double cap = a > 0.0 ? ZS__GJ_CUT / a : HUGE_VAL;
    double T = th < half ? th : half;
    if (cap < T)
        T = cap;
    zs__K_piece(a, T, 0, K);
    if (th > half) {
        double tail[3];
        int j;
        zs__K_piece(a, ZS__PI - th, 1, tail);
        for (j = 0; j < 3; j++)
            K[j] += full[j] - tail[j];
    }
}

static void zs__h1_eval(double lam, double v[6])
{
    int i, j, f, deg = 0;
    double g, x, acx, T[ZS__MAX_H1];
    i = 0;
    for (j = 1; j < ZS__H1_PIECES; j++)
        if (zs__h1_start[j] <= lam)
            i = j;
    g = zs__h1_sqrt[i] ? sqrt(lam - zs__h1_start[i] > 0.0 ? lam - zs__h1_start[i] : 0.0) : lam;
    x = (2.0 * g - zs__h1_ga[i] - zs__h1_gb[i]) / (zs__h1_gb[i] - zs__h1_ga[i]);
    if (x < -1.0)
        x = -1.0;
    if (x > 1.0)
        x = 1.0;
    for (f = 0; f < 6; f++)
        if (zs__h1_len[i * 6 + f] > deg)
            deg = zs__h1_len[i * 6 + f];
    acx = acos(x);
    for (j = 0; j < deg; j++) /* T_k(x) = cos(k arccos x), as ham.table */
        T[j] = cos(acx * j);
    for (f = 0; f < 6; f++) {
        const double *c = zs__h1_coef[i * 6 + f];
        double s = 0.0;
        for (j = 0; j < zs__h1_len[i * 6 + f]; j++)
            s += T[j] * c[j];
        v[f] = s;
    }
}

static int zs__h1_lam_ok(double lam)
{
    return lam >= 0.0 && lam < ZS__H1_TOP;
}

int zs_ham1_summary(double lam, zs_summary_t *out)
{
    double v[6];
    if (out == NULL)
        return ZS_EDOM;
    if (!zs__h1_lam_ok(lam)) {
        zs__summary_nan(lam, out);
        return ZS_EDOM;
    }
    zs__h1_eval(lam, v);
    out->lam = lam;
    out->delta_m = v[0];
    out->tau_dc = v[1];
    out->tau_d = exp(v[2]);
    out->e = exp(v[3]);
    out->F_m = v[0] * sqrt(v[0]);
    out->impulse = v[4];
    out->int_F2 = v[5];
    out->tau_dr = out->tau_d - out->tau_dc;
    out->eta = out->tau_dr / out->tau_dc;
    out->xi = 2.0 * v[4] - v[4] * v[4];
    return ZS_OK;
}

int zs_ham1_history(double lam, size_t n, const double *tau, double *delta, double *force)
{
    double k, beta, omega0, a, v[6], tau_d, full[3];
    size_t i;
    if (!zs__ham_lam_ok(lam) || !zs__h1_lam_ok(lam) || !zs__tau_ok(n, tau)) {
        zs__fill_nan(n, delta);
        zs__fill_nan(n, force);
        return ZS_EDOM;
    }
    zs__ham_params(lam, &k, &beta, &omega0);
    a = zs__ham1_rate(beta, omega0);
    zs__h1_eval(lam, v);
    tau_d = exp(v[2]); /* the summary's end of contact, as the Python model */
    zs__K_piece(a, ZS__PI / 2.0, 1, full);
    for (i = 0; i < n; i++) {
        double d = 0.0;
        if (tau[i] < tau_d) {
            double K[3];
            zs__K(a, omega0 * tau[i], full, K);
            d = zs__ham1_delta(tau[i], lam, k, beta, omega0, K[0], K[1], K[2]);
            if (!(d > 0.0))
                d = 0.0;
        }
        if (delta != NULL)
            delta[i] = d;
        if (force != NULL)
            force[i] = sqrt(d) * d;
    }
    return ZS_OK;
}
'''
