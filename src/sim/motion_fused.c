/* Forces + integrator in one pass for the common case (see motion_fused.h). */
#include "sim/motion_fused.h"

#include <math.h>
#include <stdint.h>

#include "raster/span_simd.h" /* ISK__SPAN_AVX2, ISK__AVX2_FN, isk__have_avx2 */
#include "sim/kernels.h"

/* One particle-step as the general path computes it, specialised by the
 * compile-time flags G (gravity), A (constant acceleration), D (linear drag,
 * saturated at m/|dt|) and E (explicit Euler, else semi-implicit).  Each
 * force is added to the sums in forces.c's order: gravity, acceleration,
 * drag.  Returns the or-ed non-finite bits of the four new values. */
static inline uint64_t fused_loop(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                                  double *restrict vy, const double *restrict m, double g, double ax, double ay,
                                  double b, double inv_h, double dt, const int G, const int A, const int D,
                                  const int E)
{
    uint64_t acc = 0;
    for (size_t i = 0; i < n; i++) {
        const double mi = m[i];
        double ux = vx[i], uy = vy[i];
        double fx = 0.0, fy = 0.0; /* memset's +0.0 */
        if (G)
            fy = fy + isk_k_gravity_fy(mi, g);
        if (A) {
            fx = fx + mi * ax;
            fy = fy + mi * ay;
        }
        if (D) {
            ux = isk_k_flush(ux);
            uy = isk_k_flush(uy);
            const double lim = mi * inv_h, be = isless(lim, b) ? lim : b;
            fx = fx + isk_k_drag(ux, be);
            fy = fy + isk_k_drag(uy, be);
        }
        double px = x[i], py = y[i];
        if (E)
            isk_k_euler(&px, &py, &ux, &uy, mi, fx, fy, dt);
        else
            isk_k_semi_euler(&px, &py, &ux, &uy, mi, fx, fy, dt);
        x[i] = px;
        y[i] = py;
        vx[i] = ux;
        vy[i] = uy;
        acc |= (isk_k_nonfinite_bits(px) | isk_k_nonfinite_bits(py)) |
               (isk_k_nonfinite_bits(ux) | isk_k_nonfinite_bits(uy));
    }
    return acc;
}

typedef uint64_t (*fused_fn)(size_t n, double *restrict x, double *restrict y, double *restrict vx,
                             double *restrict vy, const double *restrict m, double g, double ax, double ay,
                             double b, double inv_h, double dt);

/* Each combination twice: baseline x86-64 (SSE2, two lanes) and, chosen at
 * run time, AVX2 (four lanes).  The same IEEE operations in the same order
 * either way (no FMA: -ffp-contract=off, and AVX2 does not include it), so
 * the same bits. */
#define FUSED_AS(name, attr, G, A, D, E)                                                                        \
    static attr uint64_t name(size_t n, double *restrict x, double *restrict y, double *restrict vx,           \
                              double *restrict vy, const double *restrict m, double g, double ax, double ay,   \
                              double b, double inv_h, double dt)                                               \
    {                                                                                                            \
        return fused_loop(n, x, y, vx, vy, m, g, ax, ay, b, inv_h, dt, G, A, D, E);                             \
    }
#if ISK__SPAN_AVX2
#define FUSED(G, A, D, E)                                                                                        \
    FUSED_AS(fused_##G##A##D##E, , G, A, D, E) FUSED_AS(fused_avx2_##G##A##D##E, ISK__AVX2_FN, G, A, D, E)
#else
#define FUSED(G, A, D, E) FUSED_AS(fused_##G##A##D##E, , G, A, D, E)
#endif
FUSED(0, 0, 0, 0) FUSED(0, 0, 0, 1) FUSED(0, 0, 1, 0) FUSED(0, 0, 1, 1)
FUSED(0, 1, 0, 0) FUSED(0, 1, 0, 1) FUSED(0, 1, 1, 0) FUSED(0, 1, 1, 1)
FUSED(1, 0, 0, 0) FUSED(1, 0, 0, 1) FUSED(1, 0, 1, 0) FUSED(1, 0, 1, 1)
FUSED(1, 1, 0, 0) FUSED(1, 1, 0, 1) FUSED(1, 1, 1, 0) FUSED(1, 1, 1, 1)
#undef FUSED
#undef FUSED_AS

/* Indexed by [avx2][G*8 + A*4 + D*2 + E]. */
#define ROW(p)                                                                                                   \
    {                                                                                                            \
        p##0000, p##0001, p##0010, p##0011, p##0100, p##0101, p##0110, p##0111, p##1000, p##1001, p##1010,      \
            p##1011, p##1100, p##1101, p##1110, p##1111,                                                         \
    }
#if ISK__SPAN_AVX2
static const fused_fn fused_table[2][16] = {ROW(fused_), ROW(fused_avx2_)};
#else
static const fused_fn fused_table[1][16] = {ROW(fused_)};
#endif
#undef ROW

int isk_motion_fused_build(int avx2, isk_integrator method, const isk_forces *f, size_t n, double *x, double *y,
                           double *vx, double *vy, const double *m, double dt, int *nonfinite)
{
    const int E = method == ISK_INTEGRATE_EULER;
    if ((!E && method != ISK_INTEGRATE_SEMI_EULER) || isk_forces_potentials_on(f))
        return 0;
    /* The tests isk_forces_eval_step makes, with the step h = |dt|. */
    const int G = f->gravity != 0.0, A = f->ax != 0.0 || f->ay != 0.0, D = f->drag != 0.0;
    const double h = fabs(dt);
    if (D && !(h > 0.0))
        return 0; /* the unsaturated drag of a zero step: left to the general path */
    const fused_fn loop = fused_table[avx2 && isk__have_avx2()][G * 8 + A * 4 + D * 2 + E];
    const uint64_t acc = loop(n, x, y, vx, vy, m, f->gravity, f->ax, f->ay, f->drag, D ? 1.0 / h : 0.0, dt);
    *nonfinite = (int)(acc >> 63);
    return 1;
}

int isk_motion_fused(isk_integrator method, const isk_forces *f, size_t n, double *x, double *y, double *vx,
                     double *vy, const double *m, double dt, int *nonfinite)
{
    return isk_motion_fused_build(1, method, f, n, x, y, vx, vy, m, dt, nonfinite);
}
