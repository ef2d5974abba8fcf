/* The tape interpreter of method="taylor" in C (the only interpreter; see docs/guide.md, "The Taylor method:
   what is kept and why").

   Built at install time as the optional extension module lagrange.integrate._ctaylor (setup.py; compiled with
   -DLAGRANGE_PY_EXTENSION, which adds an empty module init) or, without it, by lagrange.codegen.c_interpreter
   with the machine's C compiler (once per machine, cached and sealed next to the numba modules). Either way
   it is called through ctypes (lagrange.integrate.c_taylor): loading it costs about a millisecond, so a first
   result needs no numba at all. Same arithmetic in the same order as the compiled series
   (lagrange.codegen.taylor_source; no contraction into fused multiply-adds: -ffp-contract=off).
   At most max_steps steps per call (status 4): the caller runs long integrations in chunks and resumes from
   (t_end, z_end), which gives the same result as one call, so Ctrl-C can be answered between chunks.

   Conventions (see _taylor_loop.py): S is n_slots x (p_order + 1), row-major, S[slot][k] the k-th normalized
   Taylor coefficient; instructions are rows (op, a, b, out) with one double constant each; status codes as
   lagrange.integrate.compiled.LoopStatus (0 success, 1 step too small, 2 non-finite, 3 division by zero,
   4 maximum number of steps, 5 out of memory). */

#ifdef LAGRANGE_PY_EXTENSION
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#endif
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { LOADC, LOADP, ADD, ADDC, SUB, SUBVC, SUBCV, MUL, MULC, DIV, DIVVC, DIVCV, NEG, SINCOS, EXP, LOG, POW };

static const double E = 2.718281828459045; /* Python's math.e */

#define AT(S, w, i, k) ((S)[(int64_t)(i) * (w) + (k)])

static double pow0(double x, double c) {
    if (c == -1.5) return 1.0 / (x * sqrt(x));
    if (c == -0.5) return 1.0 / sqrt(x);
    if (c == 0.5) return sqrt(x);
    if (c == 1.5) return x * sqrt(x);
    return pow(x, c);
}

static void coefficient(int64_t op, int64_t a, int64_t b, int64_t o, double c, double *S, int64_t w, int64_t k) {
    double s, cc;
    int64_t j;
    switch (op) {
    case MUL:
        s = 0.0;
        for (j = 0; j < k + 1; j++) s += AT(S, w, a, j) * AT(S, w, b, k - j);
        AT(S, w, o, k) = s;
        break;
    case ADD: AT(S, w, o, k) = AT(S, w, a, k) + AT(S, w, b, k); break;
    case MULC: AT(S, w, o, k) = AT(S, w, a, k) * AT(S, w, b, 0); break;
    case SUB: AT(S, w, o, k) = AT(S, w, a, k) - AT(S, w, b, k); break;
    case ADDC: AT(S, w, o, k) = k == 0 ? AT(S, w, a, k) + AT(S, w, b, 0) : AT(S, w, a, k); break;
    case SUBVC: AT(S, w, o, k) = k == 0 ? AT(S, w, a, k) - AT(S, w, b, 0) : AT(S, w, a, k); break;
    case SUBCV: AT(S, w, o, k) = k == 0 ? AT(S, w, a, 0) - AT(S, w, b, 0) : -AT(S, w, b, k); break;
    case NEG: AT(S, w, o, k) = -AT(S, w, a, k); break;
    case DIVVC: AT(S, w, o, k) = AT(S, w, a, k) * (1.0 / AT(S, w, b, 0)); break;
    case DIV:
    case DIVCV:
        s = (op == DIV || k == 0) ? AT(S, w, a, k) : 0.0;
        for (j = 1; j < k + 1; j++) s -= AT(S, w, b, j) * AT(S, w, o, k - j);
        AT(S, w, o, k) = s * (1.0 / AT(S, w, b, 0));
        break;
    case SINCOS: /* o = sin(a), b = cos(a) */
        if (k == 0) {
            AT(S, w, o, 0) = sin(AT(S, w, a, 0));
            AT(S, w, b, 0) = cos(AT(S, w, a, 0));
        } else {
            s = 0.0;
            cc = 0.0;
            for (j = 1; j < k + 1; j++) {
                s += (double)j * AT(S, w, a, j) * AT(S, w, b, k - j);
                cc += (double)j * AT(S, w, a, j) * AT(S, w, o, k - j);
            }
            AT(S, w, o, k) = s * (1.0 / (double)k);
            AT(S, w, b, k) = -cc * (1.0 / (double)k);
        }
        break;
    case EXP:
        if (k == 0) {
            AT(S, w, o, 0) = exp(AT(S, w, a, 0));
        } else {
            s = 0.0;
            for (j = 1; j < k + 1; j++) s += (double)j * AT(S, w, a, j) * AT(S, w, o, k - j);
            AT(S, w, o, k) = s * (1.0 / (double)k);
        }
        break;
    case LOG:
        if (k == 0) {
            AT(S, w, o, 0) = AT(S, w, a, 0) > 0.0 ? log(AT(S, w, a, 0)) : NAN;
        } else {
            s = 0.0;
            for (j = 1; j < k; j++) s += (double)j * AT(S, w, o, j) * AT(S, w, a, k - j);
            AT(S, w, o, k) = (AT(S, w, a, k) - s * (1.0 / (double)k)) * (1.0 / AT(S, w, a, 0));
        }
        break;
    case POW:
        if (k == 0) {
            AT(S, w, o, 0) = pow0(AT(S, w, a, 0), c);
        } else {
            s = 0.0;
            for (j = 0; j < k; j++) s += (c * (double)(k - j) - (double)j) * AT(S, w, a, k - j) * AT(S, w, o, j);
            AT(S, w, o, k) = s * (1.0 / ((double)k * AT(S, w, a, 0)));
        }
        break;
    case LOADC: AT(S, w, o, 0) = c; break;
    default: break;
    }
}

static int64_t imin(int64_t a, int64_t b) { return a < b ? a : b; }
static int64_t imax(int64_t a, int64_t b) { return a > b ? a : b; }

/* LDL^T of M_0 (upper slots `mass`, -1 = structural zero); 0 when a pivot is not positive relative to its
   diagonal entry (1e-13). */
static int ldl(int64_t n, const int64_t *mass, const double *S, int64_t w, double *Mk, double *L, double *d) {
    int64_t i, j, k, s;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            s = mass[imin(i, j) * n + imax(i, j)];
            Mk[i * n + j] = s >= 0 ? AT(S, w, s, 0) : 0.0;
        }
    for (j = 0; j < n; j++) {
        double dj = Mk[j * n + j];
        for (k = 0; k < j; k++) dj -= L[j * n + k] * L[j * n + k] * d[k];
        if (!(dj > 1e-13 * fabs(Mk[j * n + j]))) return 0;
        d[j] = dj;
        L[j * n + j] = 1.0;
        for (i = j + 1; i < n; i++) {
            double v = Mk[i * n + j];
            for (k = 0; k < j; k++) v -= L[i * n + k] * L[j * n + k] * d[k];
            L[i * n + j] = v / dj;
        }
    }
    return 1;
}

static int series(const int64_t *code, const double *consts, int64_t n_ins, int64_t n, int64_t slot_t, int64_t slot_w,
                  const int64_t *mass, const int64_t *force, int64_t power, int64_t p_order, double t, double *S,
                  int64_t w, double *acc, double *L, double *d, double *Mk, double *r) {
    int64_t k, i, l, j, m;
    AT(S, w, slot_t, 0) = t;
    AT(S, w, slot_t, 1) = 1.0;
    for (k = 0; k < p_order; k++) {
        for (i = 0; i < n_ins; i++)
            coefficient(code[4 * i], code[4 * i + 1], code[4 * i + 2], code[4 * i + 3], consts[i], S, w, k);
        if (k == 0 && !ldl(n, mass, S, w, Mk, L, d)) return 0;
        for (i = 0; i < n; i++) { /* r = f_k - sum_{j=1..k} M_j a_{k-j} */
            double s = AT(S, w, force[i], k);
            for (l = 0; l < n; l++) {
                m = mass[imin(i, l) * n + imax(i, l)];
                if (m >= 0)
                    for (j = 1; j < k + 1; j++) s -= AT(S, w, m, j) * AT(acc, w, l, k - j);
            }
            r[i] = s;
        }
        for (i = 0; i < n; i++) { /* L D L^T a_k = r */
            double s = r[i];
            for (j = 0; j < i; j++) s -= L[i * n + j] * r[j];
            r[i] = s;
        }
        for (i = n - 1; i >= 0; i--) {
            double s = r[i] * (1.0 / d[i]);
            for (j = i + 1; j < n; j++) s -= L[j * n + i] * AT(acc, w, j, k);
            AT(acc, w, i, k) = s;
        }
        for (i = 0; i < n; i++) {
            AT(S, w, i, k + 1) = AT(S, w, n + i, k) * (1.0 / (double)(k + 1));
            AT(S, w, n + i, k + 1) = AT(acc, w, i, k) * (1.0 / (double)(k + 1));
        }
        if (slot_w >= 0) AT(S, w, slot_w, k + 1) = AT(S, w, power, k) * (1.0 / (double)(k + 1));
    }
    return 1;
}

static void horner(const double *S, int64_t w, int64_t nz, int64_t p_order, double x, double *out) {
    int64_t i, k;
    for (i = 0; i < nz; i++) {
        double v = AT(S, w, i, p_order);
        for (k = p_order - 1; k > -1; k--) v = v * x + AT(S, w, i, k);
        out[i] = v;
    }
}

static double step_size(const double *S, int64_t w, int64_t nz, int64_t p_order, double floor_, const double *rule) {
    double n0 = 0.0, n1 = 0.0, n2 = 0.0, bad = 0.0, v, scale, rho;
    int64_t i;
    for (i = 0; i < nz; i++) {
        v = fabs(AT(S, w, i, 0));
        n0 = v > n0 ? v : n0;
        v = fabs(AT(S, w, i, p_order - 1));
        n1 = v > n1 ? v : n1;
        v = fabs(AT(S, w, i, p_order));
        n2 = v > n2 ? v : n2;
        bad += 0.0 * (AT(S, w, i, 0) + AT(S, w, i, p_order - 1) + AT(S, w, i, p_order));
    }
    if (bad != 0.0) return NAN;
    scale = n0 > floor_ ? n0 : floor_;
    rho = INFINITY;
    if (n1 > 0.0) rho = pow(scale / n1, rule[0]);
    if (n2 > 0.0) {
        v = pow(scale / n2, rule[1]);
        rho = v < rho ? v : rho;
    }
    return rho * rule[2];
}

/* Integrate from (t0, z0) to t1; outputs at t_eval (sorted in the direction of integration) into Y (n_eval x nz).
   Returns the status; *t_end, z_end (nz), *n_out and *steps say where it stopped. */
#ifdef _WIN32
__declspec(dllexport)
#endif
int64_t lagrange_taylor(const int64_t *const_code, const double *const_vals, int64_t n_const, const int64_t *code,
                        const double *consts, int64_t n_ins, int64_t n_slots, int64_t n, int64_t nz,
                        const int64_t *mass, const int64_t *force, int64_t power, int64_t slot_t, double t0, double t1,
                        const double *z0, const double *p, double floor_, int64_t p_order, double max_step,
                        const double *t_eval, int64_t n_eval, int64_t max_steps, double *Y, double *t_end,
                        double *z_end, int64_t *n_out_, int64_t *steps_) {
    const int64_t w = p_order + 1;
    int64_t i, status = 0, n_out = 0, steps = 0;
    const int64_t slot_w = nz > 2 * n ? 2 * n : -1;
    const double direction = t1 >= t0 ? 1.0 : -1.0;
    double t = t0, h_abs, t_new, rule[3];
    double *S = calloc((size_t)(n_slots * w + n * w + 2 * n * n + 2 * n + 1), sizeof(double));
    double *acc, *L, *d, *Mk, *r, *z = z_end;
    if (S == NULL) return 5;
    acc = S + n_slots * w;
    L = acc + n * w;
    Mk = L + n * n;
    d = Mk + n * n;
    r = d + n;
    for (i = 0; i < n_const; i++) {
        if (const_code[4 * i] == LOADP)
            AT(S, w, const_code[4 * i + 3], 0) = p[const_code[4 * i + 1]];
        else
            coefficient(const_code[4 * i], const_code[4 * i + 1], const_code[4 * i + 2], const_code[4 * i + 3],
                        const_vals[i], S, w, 0);
    }
    rule[0] = 1.0 / (double)(p_order - 1);
    rule[1] = 1.0 / (double)p_order;
    rule[2] = exp(-0.7 / (double)(p_order - 1)) / (E * E);
    memcpy(z, z0, (size_t)nz * sizeof(double));
    while (direction * (t - t1) < 0.0) {
        if (steps >= max_steps) { status = 4; break; }
        for (i = 0; i < nz; i++) AT(S, w, i, 0) = z[i];
        if (!series(code, consts, n_ins, n, slot_t, slot_w, mass, force, power, p_order, t, S, w, acc, L, d, Mk, r)) {
            status = 3;
            break;
        }
        h_abs = step_size(S, w, nz, p_order, floor_, rule);
        if (h_abs != h_abs) { status = 2; break; } /* a NaN norm: non-finite coefficients */
        h_abs = max_step < h_abs ? max_step : h_abs;
        if (!(h_abs >= 10.0 * fabs(nextafter(t, direction * INFINITY) - t))) { status = 1; break; }
        t_new = t + direction * h_abs;
        if (direction * (t_new - t1) >= 0.0) t_new = t1;
        /* the new state sums every coefficient: finite exactly when they all are (checked before any output) */
        horner(S, w, nz, p_order, t_new - t, z);
        for (i = 0; i < nz; i++)
            if (!isfinite(z[i])) break;
        if (i < nz) {
            horner(S, w, nz, 0, 0.0, z); /* back to the state at t */
            status = 2;
            break;
        }
        while (n_out < n_eval && direction * (t_eval[n_out] - t_new) <= 0.0) {
            horner(S, w, nz, p_order, t_eval[n_out] - t, Y + n_out * nz);
            n_out++;
        }
        t = t_new;
        steps++;
    }
    free(S);
    *t_end = t;
    *n_out_ = n_out;
    *steps_ = steps;
    return status;
}

#ifdef LAGRANGE_PY_EXTENSION
/* An extension module with no Python-level functions: the import system finds and installs it like any other
   module; lagrange loads its file with ctypes and calls lagrange_taylor. */
static struct PyModuleDef ctaylor_module = {PyModuleDef_HEAD_INIT, "_ctaylor",
                                            "The C Taylor tape interpreter (called through ctypes).", -1, NULL};

PyMODINIT_FUNC PyInit__ctaylor(void) { return PyModule_Create(&ctaylor_module); }
#endif
