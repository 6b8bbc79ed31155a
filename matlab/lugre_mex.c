/* The one MEX gateway of lugre for MATLAB and Octave, over the C ABI (crates/lugre-ffi).
 * Called through the documented .m functions (lugre_loop, lugre_cycles, lugre_simulate,
 * lugre_dynamics, lugre_friction_step), not directly:
 *
 *   r = lugre_mex('loop', u, params)
 *   r = lugre_mex('cycles', u, gate, params_or_empty, x0)
 *   r = lugre_mex('simulate', t, x, params, z0)
 *   r = lugre_mex('dynamics', name, times, rtol)
 *   [F, z] = lugre_mex('friction_step', x, dt, params, z0, x0)
 *
 * Every error (a wrong type or size, a NaN, an invalid parameter) is raised as a MATLAB error
 * with identifier lugre:error and lugre's own message; nothing crashes the host.
 *
 * Build: bash scripts/build-mex.sh (Octave: mkoctfile --mex; MATLAB: see matlab/README.md).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "lugre.h"
#include "mex.h"

#define ERROR_ID "lugre:error"

static void fail(const char *message) { mexErrMsgIdAndTxt(ERROR_ID, "%s", message); }

/* Raises lugre's message when a call failed (resources are freed by the caller first when it
 * holds any: see the `guard` pattern below). */
static void check(LugreStatus status) {
    if (status != LUGRE_STATUS_OK) fail(lugre_last_error());
}

/* A real double array argument (any shape: taken as a vector), or an error naming it. */
static const double *vector(const mxArray *a, const char *name, size_t *n) {
    if (!mxIsDouble(a) || mxIsComplex(a) || mxIsSparse(a))
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be a real double array", name);
    *n = mxGetNumberOfElements(a);
    return mxGetPr(a);
}

static double scalar(const mxArray *a, const char *name) {
    size_t n = 0;
    const double *p = vector(a, name, &n);
    if (n != 1) mexErrMsgIdAndTxt(ERROR_ID, "%s must be a scalar, got %d values", name, (int)n);
    return p[0];
}

static const char *PARAMS[] = {"sigma0", "sigma1", "sigma2", "fc", "fs", "vs", "beta"};

/* The parameters from a struct: the CLI's defaults (or Table I with preset = 'canudas1995'),
 * overridden by the struct's fields; an unknown field is an error. */
static LugreParams params_of(const mxArray *s) {
    LugreParams p;
    check(lugre_params_default(&p));
    if (s == NULL || mxIsEmpty(s)) return p;
    if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
        fail("params must be a scalar struct, e.g. struct('sigma0', 1e5, 'fc', 1)");
    const mxArray *preset = mxGetField(s, 0, "preset");
    if (preset != NULL) {
        char name[32];
        if (!mxIsChar(preset) || mxGetString(preset, name, sizeof name) != 0 ||
            strcmp(name, "canudas1995") != 0)
            fail("params.preset must be 'canudas1995'");
        check(lugre_params_canudas1995(&p));
    }
    double *fields[] = {&p.sigma0, &p.sigma1, &p.sigma2, &p.fc, &p.fs, &p.vs, &p.beta};
    int count = mxGetNumberOfFields(s);
    for (int k = 0; k < count; k++) {
        const char *name = mxGetFieldNameByNumber(s, k);
        if (strcmp(name, "preset") == 0) continue;
        int known = -1;
        for (int i = 0; i < 7; i++)
            if (strcmp(name, PARAMS[i]) == 0) known = i;
        if (known < 0)
            mexErrMsgIdAndTxt(ERROR_ID,
                              "unknown parameter '%s' (parameters: sigma0, sigma1, sigma2, fc, "
                              "fs, vs, beta, preset)",
                              name);
        *fields[known] = scalar(mxGetFieldByNumber(s, 0, k), name);
    }
    return p;
}

static mxArray *column(const double *v, size_t n) {
    mxArray *a = mxCreateDoubleMatrix(n, 1, mxREAL);
    if (n > 0) memcpy(mxGetPr(a), v, n * sizeof(double));
    return a;
}

static mxArray *column_i64(const int64_t *v, size_t n) {
    mxArray *a = mxCreateDoubleMatrix(n, 1, mxREAL);
    double *p = mxGetPr(a);
    for (size_t i = 0; i < n; i++) p[i] = (double)v[i];
    return a;
}

static mxArray *column_i32(const int32_t *v, size_t n) {
    mxArray *a = mxCreateDoubleMatrix(n, 1, mxREAL);
    double *p = mxGetPr(a);
    for (size_t i = 0; i < n; i++) p[i] = (double)v[i];
    return a;
}

/* A 1x1 struct with the given fields and values. */
static mxArray *struct_of(int count, const char **names, mxArray **values) {
    mxArray *r = mxCreateStructMatrix(1, 1, count, names);
    for (int i = 0; i < count; i++) mxSetFieldByNumber(r, 0, i, values[i]);
    return r;
}

/* Scratch buffers freed by MATLAB/Octave if an error unwinds through mexErrMsgIdAndTxt. */
static double *doubles(size_t n) { return (double *)mxCalloc(n > 0 ? n : 1, sizeof(double)); }
static int64_t *ints(size_t n) { return (int64_t *)mxCalloc(n > 0 ? n : 1, sizeof(int64_t)); }

static LugreModel *model_of(const mxArray *s) {
    LugreParams p = params_of(s);
    LugreModel *m = NULL;
    check(lugre_model_new(&p, &m));
    return m;
}

static mxArray *loop_struct(const mxArray *u_arg, const mxArray *params) {
    size_t n = 0;
    const double *u = vector(u_arg, "u", &n);
    LugreModel *m = model_of(params);
    LugreLoop *hl = NULL;
    LugreStatus st = lugre_loop_new(m, u, n, &hl);
    lugre_model_free(m);
    check(st);
    size_t k = 0, rows = 0;
    lugre_loop_turning_len(hl, &k);
    lugre_loop_table_len(hl, &rows);
    double *tu = doubles(k), *trho = doubles(k), *ty = doubles(k);
    double work = 0, period = 0;
    lugre_loop_turning(hl, tu, trho, ty, k);
    lugre_loop_summary(hl, &work, &period);
    enum { COLS = 16 };
    static const char *names[COLS] = {"kind",       "start_rho",  "start_u",   "start_y",
                                      "reversal_rho", "reversal_u", "reversal_y", "end_rho",
                                      "end_u",      "end_y",      "work",      "stored_energy_change",
                                      "dissipation", "closure_gap", "parent",    "depth"};
    double *d[13];
    for (int i = 0; i < 13; i++) d[i] = doubles(rows);
    int32_t *kind = (int32_t *)mxCalloc(rows > 0 ? rows : 1, sizeof(int32_t));
    int64_t *parent = ints(rows), *depth = ints(rows);
    LugreLoopColumns c = {kind, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8],
                          d[9], d[10], d[11], d[12], parent, depth};
    st = lugre_loop_table(hl, &c, rows);
    lugre_loop_free(hl);
    check(st);
    mxArray *cols[COLS];
    cols[0] = column_i32(kind, rows);
    for (int i = 0; i < 13; i++) cols[i + 1] = column(d[i], rows);
    cols[14] = column_i64(parent, rows);
    cols[15] = column_i64(depth, rows);
    mxArray *table = struct_of(COLS, names, cols);
    static const char *top[] = {"u", "rho", "y", "loops", "work_per_period", "period"};
    mxArray *v[] = {column(tu, k), column(trho, k), column(ty, k), table,
                    mxCreateDoubleScalar(work), mxCreateDoubleScalar(period)};
    return struct_of(6, top, v);
}

static mxArray *cycles_struct(int nrhs, const mxArray *prhs[]) {
    size_t n = 0;
    const double *u = vector(prhs[0], "u", &n);
    double gate = nrhs > 1 && !mxIsEmpty(prhs[1]) ? scalar(prhs[1], "gate") : 0.0;
    double x0 = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "x0") : 0.0;
    LugreModel *m = nrhs > 2 && !mxIsEmpty(prhs[2]) ? model_of(prhs[2]) : NULL;
    LugreCycles *cy = NULL;
    LugreStatus st = lugre_cycles_new(u, n, gate, m, x0, &cy);
    lugre_model_free(m);
    check(st);
    size_t rows = 0;
    lugre_cycles_len(cy, &rows);
    double *range = doubles(rows), *mean = doubles(rows), *count = doubles(rows);
    double *pos = doubles(rows), *work = doubles(rows), *stored = doubles(rows);
    double *diss = doubles(rows), *gap = doubles(rows);
    int64_t *start = ints(rows), *end = ints(rows), *closure = ints(rows);
    LugreCycleColumns c = {range, mean, count, start, end, closure, pos, work, stored, diss, gap};
    st = lugre_cycles_columns(cy, &c, rows);
    lugre_cycles_free(cy);
    check(st);
    static const char *names[] = {"range",       "mean",         "count", "start",
                                  "end",         "closure",      "closure_position", "work",
                                  "stored_energy_change", "dissipation", "closure_gap"};
    mxArray *v[] = {column(range, rows),     column(mean, rows),   column(count, rows),
                    column_i64(start, rows), column_i64(end, rows), column_i64(closure, rows),
                    column(pos, rows),       column(work, rows),   column(stored, rows),
                    column(diss, rows),      column(gap, rows)};
    return struct_of(11, names, v);
}

static mxArray *simulate_struct(int nrhs, const mxArray *prhs[]) {
    size_t n = 0, nx = 0;
    const double *t = vector(prhs[0], "t", &n);
    const double *x = vector(prhs[1], "x", &nx);
    if (n != nx) mexErrMsgIdAndTxt(ERROR_ID, "t and x must have the same length, got %d and %d", (int)n, (int)nx);
    double z0 = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "z0") : 0.0;
    LugreModel *m = model_of(nrhs > 2 ? prhs[2] : NULL);
    double *z = doubles(n), *f = doubles(n);
    LugreStatus st = lugre_simulate(m, t, x, n, z0, z, f);
    lugre_model_free(m);
    check(st);
    static const char *names[] = {"t", "x", "z", "F"};
    mxArray *v[] = {column(t, n), column(x, n), column(z, n), column(f, n)};
    return struct_of(4, names, v);
}

static mxArray *dynamics_struct(int nrhs, const mxArray *prhs[]) {
    char name[32];
    if (!mxIsChar(prhs[0]) || mxGetString(prhs[0], name, sizeof name) != 0)
        fail("the scenario must be a string: presliding, breakaway, stick-slip, lag or pid");
    size_t n = 0;
    const double *times = vector(prhs[1], "times", &n);
    double rtol = nrhs > 2 && !mxIsEmpty(prhs[2]) ? scalar(prhs[2], "rtol") : 0.0;
    double *x = doubles(n), *v_ = doubles(n), *z = doubles(n), *f = doubles(n);
    check(lugre_dynamics_scenario(name, rtol, times, n, x, v_, z, f));
    static const char *names[] = {"t", "x", "v", "z", "friction"};
    mxArray *v[] = {column(times, n), column(x, n), column(v_, n), column(z, n), column(f, n)};
    return struct_of(5, names, v);
}

/* [F, z] after each step to x(k) over dt (a scalar or one per step), from displacement x0 and
 * deflection z0. */
static void friction_step(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
    size_t n = 0, ndt = 0;
    const double *x = vector(prhs[0], "x", &n);
    const double *dt = vector(prhs[1], "dt", &ndt);
    if (ndt != 1 && ndt != n)
        mexErrMsgIdAndTxt(ERROR_ID, "dt must be a scalar or have one value per step (%d), got %d", (int)n, (int)ndt);
    double z0 = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "z0") : 0.0;
    double x0 = nrhs > 4 && !mxIsEmpty(prhs[4]) ? scalar(prhs[4], "x0") : 0.0;
    LugreModel *m = model_of(nrhs > 2 ? prhs[2] : NULL);
    LugreElement *e = NULL;
    LugreStatus st = lugre_element_new(m, z0, &e);
    lugre_model_free(m);
    check(st);
    st = lugre_element_reset(e, 0.0, x0, z0);
    double *f = doubles(n), *z = doubles(n);
    for (size_t k = 0; k < n && st == LUGRE_STATUS_OK; k++) {
        st = lugre_element_step(e, x[k], dt[ndt == 1 ? 0 : k], &f[k]);
        if (st == LUGRE_STATUS_OK) st = lugre_element_state(e, NULL, NULL, &z[k], NULL);
    }
    lugre_element_free(e);
    check(st);
    plhs[0] = column(f, n);
    if (nlhs > 1) plhs[1] = column(z, n);
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
    char cmd[32];
    if (nrhs < 1 || !mxIsChar(prhs[0]) || mxGetString(prhs[0], cmd, sizeof cmd) != 0)
        fail("lugre_mex: the first argument names the call (use lugre_loop, lugre_cycles, ...)");
    int args = nrhs - 1;
    const mxArray **a = prhs + 1;
    if (strcmp(cmd, "loop") == 0) {
        if (args < 1) fail("lugre_loop(u, params): u is missing");
        plhs[0] = loop_struct(a[0], args > 1 ? a[1] : NULL);
    } else if (strcmp(cmd, "cycles") == 0) {
        if (args < 1) fail("lugre_cycles(u, ...): u is missing");
        plhs[0] = cycles_struct(args, a);
    } else if (strcmp(cmd, "simulate") == 0) {
        if (args < 2) fail("lugre_simulate(t, x, params, z0): t and x are needed");
        plhs[0] = simulate_struct(args, a);
    } else if (strcmp(cmd, "dynamics") == 0) {
        if (args < 2) fail("lugre_dynamics(scenario, times, rtol): scenario and times are needed");
        plhs[0] = dynamics_struct(args, a);
    } else if (strcmp(cmd, "friction_step") == 0) {
        if (args < 2) fail("lugre_friction_step(x, dt, params, z0, x0): x and dt are needed");
        friction_step(nlhs, plhs, args, a);
    } else {
        mexErrMsgIdAndTxt(ERROR_ID, "lugre_mex: unknown call '%s'", cmd);
    }
}
