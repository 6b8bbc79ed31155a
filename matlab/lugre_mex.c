/* The one MEX gateway of lugre for MATLAB and Octave, over the C ABI (crates/lugre-ffi).
 * Called through the documented .m functions (lugre_loop, lugre_cycles, lugre_simulate,
 * lugre_dynamics, lugre_friction_step, lugre_fit), not directly:
 *
 *   r = lugre_mex('loop', u, params, n)
 *   r = lugre_mex('cycles', u, gate, params_or_empty, x0_or_empty)
 *   r = lugre_mex('simulate', t, x, params, z0)
 *   r = lugre_mex('dynamics', name, times, rtol)
 *   r = lugre_mex('dynamics', request_struct)
 *   [F, z] = lugre_mex('friction_step', x, dt, params, z0, x0)
 *   r = lugre_mex('fit', u, f, options)
 *   [names, table] = lugre_mex('parameters', model)
 *   models = lugre_mex('models')
 *
 * MATLAB's habits: a numeric argument (or struct field) of any real class (double, single,
 * int8 ... uint64) or logical is taken as double; a matrix (more than one row and more than
 * one column) is refused, naming the argument; indices are 1-based, in outputs (cycle starts,
 * ends, closures, a loop's parent; 0 for "none") and in messages ("u(2) must be ...": the C ABI's
 * 0-based "name[k]" is rewritten to "name(k+1)").
 *
 * Every error (a wrong type or size, a NaN, an invalid parameter) is raised as a MATLAB error
 * with identifier lugre:error and lugre's own message; nothing crashes the host.
 *
 * Build: bash scripts/build-mex.sh (Octave: mkoctfile --mex; MATLAB: see the README).
 */
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "lugre.h"
#include "mex.h"

#define ERROR_ID "lugre:error"

/* `message` with every 0-based index "name[k]" (an identifier, then digits in brackets)
 * written 1-based as MATLAB counts, "name(k+1)". */
static void one_based(const char *message, char *out, size_t size) {
    size_t o = 0;
    for (const char *p = message; *p != '\0' && o + 24 < size; p++) {
        const char *q = p + 1;
        if (*p == '[' && p > message && (isalnum((unsigned char)p[-1]) || p[-1] == '_') &&
            isdigit((unsigned char)*q)) {
            unsigned long long k = 0;
            while (isdigit((unsigned char)*q)) k = k * 10 + (unsigned long long)(*q++ - '0');
            if (*q == ']') {
                o += (size_t)snprintf(out + o, size - o, "(%llu)", k + 1);
                p = q;
                continue;
            }
        }
        out[o++] = *p;
    }
    out[o] = '\0';
}

static void fail(const char *message) {
    char text[1024];
    one_based(message, text, sizeof text);
    mexErrMsgIdAndTxt(ERROR_ID, "%s", text);
}

/* Raises lugre's message when a call failed (resources are freed by the caller first when it
 * holds any). */
static void check(LugreStatus status) {
    if (status != LUGRE_STATUS_OK) fail(lugre_last_error());
}

/* Scratch buffers freed by MATLAB/Octave if an error unwinds through mexErrMsgIdAndTxt. */
static double *doubles(size_t n) { return (double *)mxCalloc(n > 0 ? n : 1, sizeof(double)); }
static int64_t *ints(size_t n) { return (int64_t *)mxCalloc(n > 0 ? n : 1, sizeof(int64_t)); }

/* The values of a real numeric or logical array as doubles (a copy unless it is double). */
static const double *as_doubles(const mxArray *a, size_t n) {
    if (mxIsDouble(a)) return mxGetPr(a);
    double *out = doubles(n);
    const void *p = mxGetData(a);
#define COPY(T) for (size_t i = 0; i < n; i++) out[i] = (double)((const T *)p)[i]
    switch (mxGetClassID(a)) {
        case mxSINGLE_CLASS: COPY(float); break;
        case mxINT8_CLASS: COPY(int8_t); break;
        case mxUINT8_CLASS: COPY(uint8_t); break;
        case mxINT16_CLASS: COPY(int16_t); break;
        case mxUINT16_CLASS: COPY(uint16_t); break;
        case mxINT32_CLASS: COPY(int32_t); break;
        case mxUINT32_CLASS: COPY(uint32_t); break;
        case mxINT64_CLASS: COPY(int64_t); break;
        case mxUINT64_CLASS: COPY(uint64_t); break;
        case mxLOGICAL_CLASS: COPY(mxLogical); break;
        default: break; /* refused by the caller */
    }
#undef COPY
    return out;
}

/* A real numeric or logical vector argument (a row, a column, a scalar or empty), as doubles,
 * or an error naming it. */
static const double *vector(const mxArray *a, const char *name, size_t *n) {
    if (!(mxIsNumeric(a) || mxIsLogical(a)))
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be numeric or logical, got a %s array", name,
                          mxGetClassName(a));
    if (mxIsComplex(a)) mexErrMsgIdAndTxt(ERROR_ID, "%s must be real, got a complex array", name);
    if (mxIsSparse(a)) mexErrMsgIdAndTxt(ERROR_ID, "%s must be a full array, got a sparse one", name);
    mwSize dims = mxGetNumberOfDimensions(a);
    const mwSize *d = mxGetDimensions(a);
    int long_sides = 0;
    for (mwSize i = 0; i < dims; i++) long_sides += d[i] > 1;
    if (long_sides > 1) {
        char shape[96] = "";
        for (mwSize i = 0; i < dims && strlen(shape) < 64; i++)
            snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s%llu",
                     i > 0 ? "x" : "", (unsigned long long)d[i]);
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be a vector (one row or one column), got a %s array",
                          name, shape);
    }
    *n = mxGetNumberOfElements(a);
    return as_doubles(a, *n);
}

static double scalar(const mxArray *a, const char *name) {
    size_t n = 0;
    const double *p = vector(a, name, &n);
    if (n != 1) mexErrMsgIdAndTxt(ERROR_ID, "%s must be a scalar, got %d values", name, (int)n);
    return p[0];
}

/* A struct argument: empty (NULL) or a scalar struct, else an error naming it. */
static const mxArray *options_struct(const mxArray *s, const char *name, const char *example) {
    if (s == NULL || mxIsEmpty(s)) return NULL;
    if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be a scalar struct, e.g. %s", name, example);
    return s;
}

/* The parameters from a struct: the CLI's defaults (or Table I with preset = 'canudas1995'),
 * overridden by the struct's fields, set by name through the C ABI (the core's table: an
 * unknown field is its error). */
static LugreParams params_of(const mxArray *arg) {
    LugreParams p;
    check(lugre_params_default(&p));
    const mxArray *s = options_struct(arg, "params", "struct('sigma0', 1e5, 'fc', 1)");
    if (s == NULL) return p;
    const mxArray *preset = mxGetField(s, 0, "preset");
    if (preset != NULL) {
        char name[32];
        if (!mxIsChar(preset) || mxGetString(preset, name, sizeof name) != 0 ||
            strcmp(name, "canudas1995") != 0)
            fail("params.preset must be 'canudas1995'");
        check(lugre_params_canudas1995(&p));
    }
    int count = mxGetNumberOfFields(s);
    for (int k = 0; k < count; k++) {
        const char *name = mxGetFieldNameByNumber(s, k);
        if (strcmp(name, "preset") == 0) continue;
        char field[80];
        snprintf(field, sizeof field, "params.%s", name);
        check(lugre_params_set(&p, name, scalar(mxGetFieldByNumber(s, 0, k), field)));
    }
    return p;
}

/* The core's named-model rule (lugre_params_check_named): forces and energies of a measured
 * history or a physical system come from a model the struct names (every parameter `needed`
 * uses, or a preset), never from the dimensionless defaults alone. */
static LugreStatus named(const mxArray *arg, int needed) {
    const mxArray *s = options_struct(arg, "params", "struct('sigma0', 1e5, 'fc', 1)");
    if (s != NULL && mxGetField(s, 0, "preset") != NULL) return LUGRE_STATUS_OK;
    int count = s == NULL ? 0 : mxGetNumberOfFields(s);
    size_t size = 1;
    for (int k = 0; k < count; k++) size += strlen(mxGetFieldNameByNumber(s, k)) + 1;
    char *given = (char *)mxCalloc(size, 1);
    for (int k = 0; k < count; k++) {
        if (k > 0) strcat(given, ",");
        strcat(given, mxGetFieldNameByNumber(s, k));
    }
    return lugre_params_check_named(needed, given);
}

static mxArray *column(const double *v, size_t n) {
    mxArray *a = mxCreateDoubleMatrix(n, 1, mxREAL);
    if (n > 0) memcpy(mxGetPr(a), v, n * sizeof(double));
    return a;
}

/* 0-based indices (-1: none) as 1-based doubles (0: none). */
static mxArray *indices(const int64_t *v, size_t n) {
    mxArray *a = mxCreateDoubleMatrix(n, 1, mxREAL);
    double *p = mxGetPr(a);
    for (size_t i = 0; i < n; i++) p[i] = v[i] < 0 ? 0.0 : (double)v[i] + 1.0;
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

static LugreModel *model_of(const mxArray *s) {
    LugreParams p = params_of(s);
    LugreModel *m = NULL;
    check(lugre_model_new(&p, &m));
    return m;
}

/* The model a parameter struct names in its field `model` (NULL: none, a LuGre struct). */
static const char *model_name(const mxArray *params, char *out, size_t size) {
    const mxArray *s = options_struct(params, "params", "struct('sigma0', 1e5, 'fc', 1)");
    const mxArray *model = s == NULL ? NULL : mxGetField(s, 0, "model");
    if (model == NULL) return NULL;
    if (!mxIsChar(model) || mxGetString(model, out, size) != 0)
        fail("params.model must be the name of a model, e.g. 'lugre', 'dahl' or 'maxwell-slip' (lugre_models lists them)");
    return out;
}

/* A model of the zoo (or Dahl, by the same rule) from a struct: every field but `model` is a
 * parameter by name, passed as it is to the C ABI, which knows the model's parameters, their
 * shapes and domains (the gateway lists none). */
static LugreStatus zoo_of(const char *model, const mxArray *s, LugreZoo **zoo, LugreModel **dahl) {
    int fields = mxGetNumberOfFields(s);
    size_t count = 0;
    const char **names = (const char **)mxCalloc(fields > 0 ? fields : 1, sizeof(char *));
    const double **values = (const double **)mxCalloc(fields > 0 ? fields : 1, sizeof(double *));
    size_t *lens = (size_t *)mxCalloc(fields > 0 ? fields : 1, sizeof(size_t));
    double *firsts = doubles(fields);
    for (int k = 0; k < fields; k++) {
        const char *name = mxGetFieldNameByNumber(s, k);
        if (strcmp(name, "model") == 0) continue;
        char field[80];
        snprintf(field, sizeof field, "params.%s", name);
        names[count] = name;
        values[count] = vector(mxGetFieldByNumber(s, 0, k), field, &lens[count]);
        firsts[count] = lens[count] == 1 ? values[count][0] : NAN;
        count++;
    }
    if (strcmp(model, "dahl") == 0) {
        for (size_t i = 0; i < count; i++)
            if (lens[i] != 1)
                mexErrMsgIdAndTxt(ERROR_ID, "params.%s must be a scalar, got %d values", names[i], (int)lens[i]);
        return lugre_model_new_named(LUGRE_FAMILY_DAHL, count, names, firsts, dahl);
    }
    return lugre_zoo_new(model, count, names, values, lens, zoo);
}

/* LuGre's parameter struct without its field `model` (params.model = 'lugre'): a copy in
 * `*copy`, destroyed by the caller; the struct itself when it names no model. */
static const mxArray *lugre_fields(const mxArray *params, const char *model, mxArray **copy) {
    *copy = NULL;
    if (model == NULL) return params;
    *copy = mxDuplicateArray(params);
    mxRemoveField(*copy, mxGetFieldNumber(*copy, "model"));
    return *copy;
}

/* The loop of the model `params` describes: LuGre's (its parameters, or a preset), Dahl's, or a
 * zoo model's (params.model names it), for the turning points u[0..n]. */
static LugreLoop *loop_of(const mxArray *params, const double *u, size_t n) {
    char name[64];
    const char *model = model_name(params, name, sizeof name);
    LugreLoop *hl = NULL;
    if (model == NULL || strcmp(model, "lugre") == 0) {
        mxArray *copy = NULL;
        LugreModel *m = model_of(lugre_fields(params, model, &copy));
        if (copy != NULL) mxDestroyArray(copy);
        LugreStatus st = lugre_loop_new(m, u, n, &hl);
        lugre_model_free(m);
        check(st);
        return hl;
    }
    LugreZoo *zoo = NULL;
    LugreModel *dahl = NULL;
    check(zoo_of(model, params, &zoo, &dahl));
    LugreStatus st = dahl != NULL ? lugre_loop_new(dahl, u, n, &hl) : lugre_zoo_loop_new(zoo, u, n, &hl);
    lugre_zoo_free(zoo);
    lugre_model_free(dahl);
    check(st);
    return hl;
}

static mxArray *loop_struct(const mxArray *u_arg, const mxArray *params, const mxArray *n_arg) {
    size_t n = 0;
    const double *u = vector(u_arg, "u", &n);
    double points = 0;
    int sampled = n_arg != NULL && !mxIsEmpty(n_arg);
    if (sampled) {
        points = scalar(n_arg, "n");
        /* n < 2 is the C ABI's to refuse, in its words (as Python's and C's). */
        if (!(points >= 0 && points <= 1e8 && points == floor(points)))
            mexErrMsgIdAndTxt(ERROR_ID, "n must be a whole number from 2 to 1e8, got %g", points);
    }
    LugreLoop *hl = loop_of(params, u, n);
    LugreStatus st;
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
    if (st != LUGRE_STATUS_OK) lugre_loop_free(hl);
    check(st);
    /* The curve (lugre_loop(u, params, n)) is sampled while the loop is held; the loop is
     * freed before an error unwinds through check(). */
    mxArray *curve = NULL;
    size_t np = (size_t)points;
    if (sampled) {
        double *rho = doubles(np), *cu = doubles(np), *cy = doubles(np);
        st = lugre_loop_sample(hl, np, rho, cu, cy);
        static const char *curve_names[] = {"rho", "u", "y"};
        mxArray *cv[] = {column(rho, np), column(cu, np), column(cy, np)};
        if (st == LUGRE_STATUS_OK) curve = struct_of(3, curve_names, cv);
    }
    lugre_loop_free(hl);
    check(st);
    mxArray *cols[COLS];
    cols[0] = column_i32(kind, rows);
    for (int i = 0; i < 13; i++) cols[i + 1] = column(d[i], rows);
    cols[14] = indices(parent, rows);
    cols[15] = column_i64(depth, rows);
    mxArray *table = struct_of(COLS, names, cols);
    static const char *top[] = {"u", "rho", "y", "loops", "work_per_period", "period", "curve"};
    mxArray *v[] = {column(tu, k), column(trho, k), column(ty, k), table,
                    mxCreateDoubleScalar(work), mxCreateDoubleScalar(period),
                    curve != NULL ? curve : mxCreateDoubleMatrix(0, 0, mxREAL)};
    return struct_of(7, top, v);
}

/* The cycles of u[0..n] with LuGre's energies (params: its parameters or a preset; NULL: no
 * model) from x0. */
static LugreCycles *lugre_cycles_of(const mxArray *params, const double *u, size_t n, double gate,
                                    double x0) {
    LugreModel *m = NULL;
    if (params != NULL) {
        /* The values are checked first (model_of), then that the model is named. */
        m = model_of(params);
        LugreStatus st = named(params, LUGRE_NEEDED_RATE_INDEPENDENT);
        if (st != LUGRE_STATUS_OK) lugre_model_free(m);
        check(st);
    }
    LugreCycles *cy = NULL;
    LugreStatus st = lugre_cycles_new(u, n, gate, m, x0, &cy);
    lugre_model_free(m);
    check(st);
    return cy;
}

/* The cycles of u[0..n] with the energies of the model `params` describes: LuGre's (from x0),
 * or a zoo model's (params.model names it; from rest, x0 refused by the C ABI). */
static LugreCycles *cycles_of(const mxArray *params, const double *u, size_t n, double gate,
                              const double *x0) {
    char name[64];
    const char *model = params == NULL ? NULL : model_name(params, name, sizeof name);
    double start = x0 != NULL ? *x0 : 0.0;
    /* Dahl's energies along a measured history are not taken here (its struct is refused as
     * LuGre's); LuGre's struct may say model = 'lugre'. */
    int lugre = model == NULL || strcmp(model, "lugre") == 0;
    if (lugre || strcmp(model, "dahl") == 0) {
        mxArray *copy = NULL;
        const mxArray *fields = lugre && params != NULL ? lugre_fields(params, model, &copy) : params;
        LugreCycles *cy = lugre_cycles_of(fields, u, n, gate, start);
        if (copy != NULL) mxDestroyArray(copy);
        return cy;
    }
    LugreZoo *zoo = NULL;
    LugreModel *dahl = NULL;
    check(zoo_of(model, params, &zoo, &dahl));
    LugreCycles *cy = NULL;
    LugreStatus st = lugre_zoo_cycles_new(zoo, u, n, gate, x0, &cy);
    lugre_zoo_free(zoo);
    check(st);
    return cy;
}

static mxArray *cycles_struct(int nrhs, const mxArray *prhs[]) {
    size_t n = 0;
    const double *u = vector(prhs[0], "u", &n);
    double gate = nrhs > 1 && !mxIsEmpty(prhs[1]) ? scalar(prhs[1], "gate") : 0.0;
    /* x0 given ([] or missing: not given). */
    double x0 = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "x0") : 0.0;
    const double *given = nrhs > 3 && !mxIsEmpty(prhs[3]) ? &x0 : NULL;
    const mxArray *params = nrhs > 2 && !mxIsEmpty(prhs[2]) ? prhs[2] : NULL;
    LugreCycles *cy = cycles_of(params, u, n, gate, given);
    size_t rows = 0;
    lugre_cycles_len(cy, &rows);
    double *range = doubles(rows), *mean = doubles(rows), *count = doubles(rows);
    double *pos = doubles(rows), *work = doubles(rows), *stored = doubles(rows);
    double *diss = doubles(rows), *gap = doubles(rows);
    int64_t *start = ints(rows), *end = ints(rows), *closure = ints(rows);
    LugreCycleColumns c = {range, mean, count, start, end, closure, pos, work, stored, diss, gap};
    LugreStatus st = lugre_cycles_columns(cy, &c, rows);
    lugre_cycles_free(cy);
    check(st);
    /* The closure position is a sample index with a fraction: 1-based for full cycles too. */
    for (size_t i = 0; i < rows; i++)
        if (closure[i] >= 0) pos[i] += 1.0;
    static const char *names[] = {"range",       "mean",         "count", "start",
                                  "end",         "closure",      "closure_position", "work",
                                  "stored_energy_change", "dissipation", "closure_gap"};
    mxArray *v[] = {column(range, rows),    column(mean, rows),  column(count, rows),
                    indices(start, rows),   indices(end, rows),  indices(closure, rows),
                    column(pos, rows),      column(work, rows),  column(stored, rows),
                    column(diss, rows),     column(gap, rows)};
    return struct_of(11, names, v);
}

/* The force of a model of the zoo at t[0..n], x[0..n] from rest (z0: NULL; given, the C ABI
 * refuses it in the core's words): r.t, r.x, r.F, as `lugre simulate --model NAME`. */
static mxArray *zoo_simulate_struct(LugreZoo *zoo, const double *t, const double *x, size_t n,
                                    const double *z0) {
    double *f = doubles(n);
    LugreStatus st = lugre_zoo_simulate(zoo, t, x, n, z0, f);
    lugre_zoo_free(zoo);
    check(st);
    static const char *names[] = {"t", "x", "F"};
    mxArray *v[] = {column(t, n), column(x, n), column(f, n)};
    return struct_of(3, names, v);
}

/* lugre_simulate(t, x, params, z0): LuGre's (or Dahl's) exact response from z0 (default 0),
 * or a model of the zoo's force from rest (params.model names it, as lugre_loop takes it). */
static mxArray *simulate_struct(int nrhs, const mxArray *prhs[]) {
    size_t n = 0, nx = 0;
    const double *t = vector(prhs[0], "t", &n);
    const double *x = vector(prhs[1], "x", &nx);
    /* The core's words (InputError), the displacement named as here. */
    if (n != nx) mexErrMsgIdAndTxt(ERROR_ID, "t and x have different lengths (%d and %d)", (int)n, (int)nx);
    double z0 = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "z0") : 0.0;
    const double *given = nrhs > 3 && !mxIsEmpty(prhs[3]) ? &z0 : NULL;
    const mxArray *params = nrhs > 2 ? prhs[2] : NULL;
    char name[64];
    const char *model = model_name(params, name, sizeof name);
    LugreModel *m = NULL;
    if (model == NULL || strcmp(model, "lugre") == 0) {
        mxArray *copy = NULL;
        m = model_of(lugre_fields(params, model, &copy));
        if (copy != NULL) mxDestroyArray(copy);
    } else {
        LugreZoo *zoo = NULL;
        check(zoo_of(model, params, &zoo, &m));
        if (zoo != NULL) return zoo_simulate_struct(zoo, t, x, n, given);
    }
    double *z = doubles(n), *f = doubles(n);
    LugreStatus st = lugre_simulate(m, t, x, n, z0, z, f);
    lugre_model_free(m);
    check(st);
    static const char *names[] = {"t", "x", "z", "F"};
    mxArray *v[] = {column(t, n), column(x, n), column(z, n), column(f, n)};
    return struct_of(4, names, v);
}

/* lugre_sweep(amplitudes, frequencies, params, offset, tol): one column per name of
 * lugre_sweep_column, one row per point (amplitude-major). */
static mxArray *sweep_struct(int nrhs, const mxArray *prhs[]) {
    size_t na = 0, nf = 0;
    const double *a = vector(prhs[0], "amplitudes", &na);
    const double *f = vector(prhs[1], "frequencies", &nf);
    double offset = nrhs > 3 && !mxIsEmpty(prhs[3]) ? scalar(prhs[3], "offset") : 0.0;
    double tol = nrhs > 4 && !mxIsEmpty(prhs[4]) ? scalar(prhs[4], "tol") : 0.0;
    LugreModel *m = model_of(nrhs > 2 ? prhs[2] : NULL);
    /* The request checked (values, grid size) before the table is allocated: with no room
     * the call stops at the buffer check, after every other one. */
    LugreStatus pre = lugre_sweep(m, a, na, f, nf, offset, tol, NULL, 0);
    if (pre != LUGRE_STATUS_BUFFER_TOO_SMALL) {
        lugre_model_free(m);
        check(pre);
    }
    size_t rows = na * nf;
    double *table = doubles(rows * LUGRE_SWEEP_COLUMNS);
    LugreStatus st = lugre_sweep(m, a, na, f, nf, offset, tol, table, rows);
    lugre_model_free(m);
    check(st);
    const char *names[LUGRE_SWEEP_COLUMNS];
    mxArray *v[LUGRE_SWEEP_COLUMNS];
    for (size_t c = 0; c < LUGRE_SWEEP_COLUMNS; c++) {
        names[c] = lugre_sweep_column(c);
        v[c] = mxCreateDoubleMatrix(rows, 1, mxREAL);
        double *p = mxGetPr(v[c]);
        for (size_t r = 0; r < rows; r++) p[r] = table[r * LUGRE_SWEEP_COLUMNS + c];
    }
    return struct_of(LUGRE_SWEEP_COLUMNS, names, v);
}

static mxArray *dynamics_scenario(int nrhs, const mxArray *prhs[]) {
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

/* The request fields given as points (t, value): an N-by-2 matrix [t value]. */
static int is_points_field(const char *name, const mxArray *value) {
    if (strcmp(name, "force") == 0 || strcmp(name, "input") == 0 || strcmp(name, "end") == 0 ||
        strcmp(name, "velocity") == 0)
        return 1;
    /* A set point: a number, or steps [t xd]. */
    return strcmp(name, "setpoint") == 0 && mxGetN(value) == 2 && mxGetM(value) > 1;
}

/* One field of a request struct, converted before any handle is made (a bad value raises
 * with nothing to free). */
typedef struct {
    const char *name;
    const double *values; /* numbers, or t then the values for points */
    size_t n;             /* the numbers, or the points */
    int points;
} RequestField;

static RequestField request_field(const mxArray *s, int k) {
    RequestField f;
    f.name = mxGetFieldNameByNumber(s, k);
    const mxArray *value = mxGetFieldByNumber(s, 0, k);
    char label[80];
    snprintf(label, sizeof label, "request.%s", f.name);
    f.points = is_points_field(f.name, value);
    if (!f.points) {
        f.values = vector(value, label, &f.n);
        return f;
    }
    if (!(mxIsNumeric(value) || mxIsLogical(value)) || mxIsComplex(value) || mxIsSparse(value) ||
        mxGetNumberOfDimensions(value) != 2 || mxGetN(value) != 2)
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be an N-by-2 real matrix [t value], got a %dx%d %s array",
                          label, (int)mxGetM(value), (int)mxGetN(value), mxGetClassName(value));
    f.n = mxGetM(value);
    /* Column-major: the times, then the values. */
    f.values = as_doubles(value, 2 * f.n);
    return f;
}

/* Frees what a request holds and raises the C ABI's message. */
static void check_request(LugreStatus st, LugreDynamics *d, LugreModel *m, LugreMotion *run) {
    if (st == LUGRE_STATUS_OK) return;
    char message[1024];
    snprintf(message, sizeof message, "%s", lugre_last_error());
    lugre_motion_free(run);
    lugre_model_free(m);
    lugre_dynamics_free(d);
    fail(message);
}

static mxArray *scalar_struct(int count, const char **names, const double *values) {
    mxArray *v[16];
    for (int i = 0; i < count; i++) v[i] = mxCreateDoubleScalar(values[i]);
    return struct_of(count, names, v);
}

/* The model of the zoo a request's model struct names (params.model other than 'lugre' and
 * 'dahl', e.g. 'elastoplastic'), with its parameters by name; NULL for LuGre's struct. */
static LugreZoo *zoo_request(const mxArray *model) {
    char name[64];
    const char *zoo_name = model == NULL ? NULL : model_name(model, name, sizeof name);
    if (zoo_name == NULL || strcmp(zoo_name, "lugre") == 0 || strcmp(zoo_name, "dahl") == 0)
        return NULL;
    LugreZoo *zoo = NULL;
    LugreModel *dahl = NULL;
    check(zoo_of(zoo_name, model, &zoo, &dahl));
    return zoo;
}

/* The run's friction-displacement loops to *out as a count-by-1 struct array, one element per
 * loop with the fields of `lugre dynamics --json`'s loops (turning_points a column). */
static LugreStatus friction_loops(const LugreMotion *run, size_t count, mxArray **out) {
    enum { FIELDS = 8, TURNING_POINTS = 3 };
    static const char *loop_names[FIELDS] = {"t_start", "t_turn", "t_close", "turning_points",
                                             "work", "bristle_energy_change", "dissipation",
                                             "rate_independent_work"};
    mxArray *a = mxCreateStructMatrix(count, 1, FIELDS, loop_names);
    for (size_t i = 0; i < count; i++) {
        LugreFrictionLoop l;
        LugreStatus st = lugre_motion_loop(run, i, &l);
        if (st != LUGRE_STATUS_OK) {
            mxDestroyArray(a);
            return st;
        }
        double v[FIELDS] = {l.t_start, l.t_turn, l.t_close, 0, l.work, l.bristle_energy_change,
                            l.dissipation, l.rate_independent_work};
        for (int k = 0; k < FIELDS; k++)
            mxSetFieldByNumber(a, i, k, k == TURNING_POINTS
                                            ? column(l.turning_points, l.turning_points_len)
                                            : mxCreateDoubleScalar(v[k]));
    }
    *out = a;
    return LUGRE_STATUS_OK;
}

/* r = lugre_dynamics(request): every field of the core's request by its name. */
static mxArray *dynamics_request(const mxArray *s) {
    if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
        fail("request must be a scalar struct, e.g. struct('scenario', 'pid', 'pid', [3 8 6])");
    int count = mxGetNumberOfFields(s);
    char scenario[32] = "";
    const mxArray *model = NULL;
    RequestField *fields = (RequestField *)mxCalloc(count > 0 ? count : 1, sizeof(RequestField));
    int used = 0;
    for (int k = 0; k < count; k++) {
        const char *name = mxGetFieldNameByNumber(s, k);
        const mxArray *value = mxGetFieldByNumber(s, 0, k);
        if (strcmp(name, "scenario") == 0) {
            if (!mxIsChar(value) || mxGetString(value, scenario, sizeof scenario) != 0)
                fail("request.scenario must be a string: presliding, breakaway, stick-slip, lag or pid");
        } else if (strcmp(name, "model") == 0) {
            model = value;
        } else {
            fields[used++] = request_field(s, k);
        }
    }
    LugreParams p;
    LugreZoo *zoo = zoo_request(model);
    if (zoo != NULL) model = NULL;
    if (model != NULL) {
        /* The values are checked first (a model made and dropped), then that it is named. */
        lugre_model_free(model_of(model));
        p = params_of(model);
        check(named(model, LUGRE_NEEDED_ALL));
    }
    /* Every value is converted: from here on only the C ABI can fail. */
    LugreDynamics *d = NULL;
    LugreModel *m = NULL;
    LugreMotion *run = NULL;
    check_request(lugre_dynamics_new(&d), d, m, run);
    if (scenario[0] != '\0') check_request(lugre_dynamics_set_scenario(d, scenario), d, m, run);
    if (zoo != NULL) {
        /* Copied by the request; the core refuses a model of the zoo without dynamics. */
        LugreStatus st = lugre_dynamics_set_zoo(d, zoo);
        lugre_zoo_free(zoo);
        check_request(st, d, m, run);
    }
    if (model != NULL) {
        check_request(lugre_model_new(&p, &m), d, m, run);
        check_request(lugre_dynamics_set_model(d, m), d, m, run);
    }
    for (int i = 0; i < used; i++) {
        RequestField f = fields[i];
        LugreStatus st = f.points
            ? lugre_dynamics_set_points(d, f.name, f.values, f.values + f.n, f.n)
            : lugre_dynamics_set(d, f.name, f.values, f.n);
        check_request(st, d, m, run);
    }
    check_request(lugre_dynamics_run(d, &run), d, m, run);
    size_t n = 0;
    check_request(lugre_motion_len(run, &n), d, m, run);
    double *c[6];
    for (int i = 0; i < 6; i++) c[i] = doubles(n);
    check_request(lugre_motion_columns(run, n, c[0], c[1], c[2], c[3], c[4], c[5]), d, m, run);
    LugreMotionSummary sum;
    check_request(lugre_motion_summary(run, &sum), d, m, run);
    mxArray *loops = NULL;
    check_request(friction_loops(run, sum.loops, &loops), d, m, run);
    lugre_motion_free(run);
    lugre_model_free(m);
    lugre_dynamics_free(d);
    static const char *energy_names[] = {"input", "stored_start", "stored_end", "dissipated"};
    double energy[] = {sum.energy_input, sum.stored_start, sum.stored_end, sum.dissipated};
    static const char *stats_names[] = {"steps", "rejected", "events"};
    double stats[] = {(double)sum.steps, (double)sum.rejected, (double)sum.events};
    mxArray *breakaway = mxCreateDoubleMatrix(0, 0, mxREAL);
    if (sum.has_breakaway) {
        static const char *b_names[] = {"t", "force", "x"};
        double b[] = {sum.breakaway_t, sum.breakaway_force, sum.breakaway_x};
        breakaway = scalar_struct(3, b_names, b);
    }
    static const char *names[] = {"t", "x", "v", "z", "friction", "drive", "t_end",
                                  "energy", "stats", "breakaway", "slip_onsets", "period",
                                  "loops"};
    mxArray *v[] = {column(c[0], n), column(c[1], n), column(c[2], n), column(c[3], n),
                    column(c[4], n), column(c[5], n), mxCreateDoubleScalar(sum.t_end),
                    scalar_struct(4, energy_names, energy), scalar_struct(3, stats_names, stats),
                    breakaway, mxCreateDoubleScalar((double)sum.slip_onsets),
                    mxCreateDoubleScalar(sum.period), loops};
    return struct_of(13, names, v);
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
    size_t k = 0;
    for (; k < n && st == LUGRE_STATUS_OK; k++) {
        st = lugre_element_step(e, x[k], dt[ndt == 1 ? 0 : k], &f[k]);
        if (st == LUGRE_STATUS_OK) st = lugre_element_state(e, NULL, NULL, &z[k], NULL);
    }
    lugre_element_free(e);
    if (st != LUGRE_STATUS_OK && k > 0) {
        /* Which step failed, as MATLAB counts. */
        char text[1024];
        one_based(lugre_last_error(), text, sizeof text);
        mexErrMsgIdAndTxt(ERROR_ID, "step %d (x(%d)): %s", (int)k, (int)k, text);
    }
    check(st);
    plhs[0] = column(f, n);
    if (nlhs > 1) plhs[1] = column(z, n);
}

/* A string option (a char row) into `out`, or an error naming it. */
static void option_text(const mxArray *a, const char *name, char *out, size_t size) {
    if (!mxIsChar(a) || mxGetM(a) > 1 || mxGetString(a, out, size) != 0)
        mexErrMsgIdAndTxt(ERROR_ID, "%s must be a string (a char row)", name);
}

/* Parameter names: a char row ('sigma2' or 'sigma2,beta') or a cell array of them, joined with
 * commas for the C ABI (mxCalloc'd). */
static char *names_option(const mxArray *a, const char *name) {
    if (mxIsChar(a)) {
        char *out = (char *)mxCalloc(mxGetNumberOfElements(a) + 1, 1);
        option_text(a, name, out, mxGetNumberOfElements(a) + 1);
        return out;
    }
    if (!mxIsCell(a)) mexErrMsgIdAndTxt(ERROR_ID, "%s must be a name or a cell array of names, e.g. {'sigma2', 'beta'}", name);
    size_t n = mxGetNumberOfElements(a), size = 1;
    for (size_t i = 0; i < n; i++) {
        const mxArray *c = mxGetCell(a, i);
        size += (c != NULL ? mxGetNumberOfElements(c) : 0) + 1;
    }
    char *out = (char *)mxCalloc(size, 1);
    for (size_t i = 0; i < n; i++) {
        const mxArray *c = mxGetCell(a, i);
        char item[64];
        snprintf(item, sizeof item, "%s{%d}", name, (int)i + 1);
        if (c == NULL || !mxIsChar(c)) mexErrMsgIdAndTxt(ERROR_ID, "%s must be a name (a char row)", item);
        if (i > 0) strcat(out, ",");
        option_text(c, item, out + strlen(out), size - strlen(out));
    }
    return out;
}

/* The fit's model: options.params (a parameter struct; Dahl: rho and fc) as a handle, or NULL.
 * A Dahl struct's fields are given to the C ABI by name (the core's table: an unknown field is
 * its error, the parameters not given take the table's defaults). */
static LugreModel *fit_model(const mxArray *params, int dahl) {
    if (params == NULL || mxIsEmpty(params)) return NULL;
    if (!dahl) return model_of(params);
    const mxArray *s = options_struct(params, "options.params", "struct('rho', 2, 'fc', 1)");
    int count = mxGetNumberOfFields(s);
    const char **names = (const char **)mxCalloc(count > 0 ? count : 1, sizeof(char *));
    double *values = doubles(count);
    for (int k = 0; k < count; k++) {
        names[k] = mxGetFieldNameByNumber(s, k);
        char field[80];
        snprintf(field, sizeof field, "options.params.%s", names[k]);
        values[k] = scalar(mxGetFieldByNumber(s, 0, k), field);
    }
    LugreModel *m = NULL;
    check(lugre_model_new_named(LUGRE_FAMILY_DAHL, (size_t)count, names, values, &m));
    return m;
}

static const char *FIT_OPTIONS = "kind, t, model, params, fix, free, x0, starts, elements";

static mxArray *logical_column(const int32_t *v, size_t n) {
    mxArray *a = mxCreateLogicalMatrix(n, 1);
    mxLogical *p = mxGetLogicals(a);
    for (size_t i = 0; i < n; i++) p[i] = v[i] != 0;
    return a;
}

/* The numbers of a fit's result the LuGre and the zoo fits share. */
typedef struct {
    double rms, t_quantile, condition_number;
    size_t samples, dof, iterations, evaluations, starts, turning_points;
    int converged, full;
} FitNumbers;

/* The struct lugre_fit.m documents: the estimates (k of them: names, value, stderr, ci95
 * [lo hi], at_bound), the fitted model's values, the fit's numbers, the model's name, the
 * fitted response and the residuals f - fitted at the n samples. */
static mxArray *fit_struct_of(mxArray *names, double *value, double *se, mxArray *ci95,
                              const int32_t *at_bound, size_t k, mxArray *values,
                              const FitNumbers *s, const char *model, const double *f,
                              const double *fitted, size_t n) {
    double *residuals = doubles(n);
    for (size_t i = 0; i < n; i++) residuals[i] = f[i] - fitted[i];
    if (!s->converged)
        mexWarnMsgIdAndTxt("lugre:notConverged",
                           "the fit did not converge; the best point found is reported");
    static const char *fields[] = {
        "names", "value", "stderr", "ci95", "at_bound", "values", "rms", "samples", "dof",
        "t_quantile", "condition_number", "iterations", "evaluations", "starts", "converged",
        "turning_points", "model", "kind", "fitted", "residuals"};
    mxArray *v[] = {
        names,
        column(value, k),
        column(se, k),
        ci95,
        logical_column(at_bound, k),
        values,
        mxCreateDoubleScalar(s->rms),
        mxCreateDoubleScalar((double)s->samples),
        mxCreateDoubleScalar((double)s->dof),
        mxCreateDoubleScalar(s->t_quantile),
        mxCreateDoubleScalar(s->condition_number),
        mxCreateDoubleScalar((double)s->iterations),
        mxCreateDoubleScalar((double)s->evaluations),
        mxCreateDoubleScalar((double)s->starts),
        mxCreateLogicalScalar(s->converged != 0),
        /* A full fit has no slow loop's turning points. */
        s->full ? mxCreateDoubleMatrix(0, 0, mxREAL) : mxCreateDoubleScalar((double)s->turning_points),
        mxCreateString(model),
        mxCreateString(s->full ? "full" : "slow"),
        column(fitted, n),
        column(residuals, n)};
    return struct_of(20, fields, v);
}

/* The fit's result as the struct lugre_fit.m documents. */
static mxArray *fit_result(const LugreFitResult *r, const double *f, const double *fitted,
                           size_t n, int full) {
    size_t k = 0;
    for (size_t i = 0; i < r->parameters; i++) k += r->fitted[i] != 0;
    mxArray *names = mxCreateCellMatrix(k, 1);
    double *value = doubles(k), *se = doubles(k);
    int32_t *at_bound = (int32_t *)mxCalloc(k > 0 ? k : 1, sizeof(int32_t));
    mxArray *ci95 = mxCreateDoubleMatrix(k, 2, mxREAL);
    double *ci = mxGetPr(ci95);
    const char *all[LUGRE_MAX_PARAMETERS];
    for (size_t i = 0, j = 0; i < r->parameters; i++) {
        check(lugre_parameter_name(r->family, i, &all[i]));
        if (!r->fitted[i]) continue;
        mxSetCell(names, j, mxCreateString(all[i]));
        value[j] = r->value[i];
        se[j] = r->std_error[i];
        ci[j] = r->ci95_lo[i];
        ci[j + k] = r->ci95_hi[i];
        at_bound[j] = r->at_bound[i];
        j++;
    }
    mxArray *values = mxCreateStructMatrix(1, 1, (int)r->parameters, all);
    for (size_t i = 0; i < r->parameters; i++)
        mxSetFieldByNumber(values, 0, (int)i, mxCreateDoubleScalar(r->value[i]));
    FitNumbers s = {r->rms, r->t_quantile, r->condition_number, r->samples, r->dof,
                    r->iterations, r->evaluations, r->starts, r->turning_points, r->converged != 0,
                    full};
    return fit_struct_of(names, value, se, ci95, at_bound, k, values, &s,
                         r->family == LUGRE_FAMILY_DAHL ? "dahl" : "lugre", f, fitted, n);
}

/* The fitted model of the zoo as a struct: every parameter by name (element arrays as rows),
 * and its name in the field `model` (lugre_loop(u, r.values) runs it). */
static mxArray *zoo_values(const LugreZoo *zoo, const char *model) {
    LugreZooModelInfo info;
    check(lugre_zoo_model_info(model, &info));
    const char **names = (const char **)mxCalloc(info.parameters + 1, sizeof(char *));
    mxArray **v = (mxArray **)mxCalloc(info.parameters + 1, sizeof(mxArray *));
    for (size_t i = 0; i < info.parameters; i++) {
        LugreZooParameter p;
        check(lugre_zoo_parameter(model, i, &p));
        size_t len = 0;
        check(lugre_zoo_value(zoo, i, NULL, 0, &len));
        v[i] = mxCreateDoubleMatrix(1, len, mxREAL);
        check(lugre_zoo_value(zoo, i, mxGetPr(v[i]), len, NULL));
        names[i] = p.name;
    }
    names[info.parameters] = "model";
    v[info.parameters] = mxCreateString(info.name);
    return struct_of((int)info.parameters + 1, names, v);
}

/* r = lugre_fit(u, f, struct('model', NAME, ...)) for a model of the zoo: the C ABI's
 * lugre_zoo_fit, or with times t (options.kind = 'full') lugre_zoo_fit_full from `starts`
 * starts (0: the default), its result with the fields of the LuGre fit's. */
static mxArray *zoo_fit_struct(const char *model, const mxArray *params, const double *t,
                               const double *u, const double *f, size_t n, size_t elements,
                               size_t starts, const char *fix, const char *free_names) {
    LugreZoo *start = NULL;
    LugreModel *dahl = NULL;
    if (params != NULL && !mxIsEmpty(params)) {
        const mxArray *p = options_struct(params, "options.params", "struct('kw', 1.5)");
        check(zoo_of(model, p, &start, &dahl));
    }
    LugreZooFit *fit = NULL;
    double *fitted = doubles(n);
    LugreStatus st = t != NULL ? lugre_zoo_fit_full(model, start, t, u, f, n, elements, starts, fix,
                                                    free_names, &fit, fitted)
                               : lugre_zoo_fit(model, start, u, f, n, elements, fix, free_names,
                                               &fit, fitted);
    lugre_zoo_free(start);
    check(st);
    LugreZooFitSummary s;
    check(lugre_zoo_fit_summary(fit, &s));
    size_t k = s.estimates;
    mxArray *names = mxCreateCellMatrix(k, 1);
    double *value = doubles(k), *se = doubles(k);
    int32_t *at_bound = (int32_t *)mxCalloc(k > 0 ? k : 1, sizeof(int32_t));
    mxArray *ci95 = mxCreateDoubleMatrix(k, 2, mxREAL);
    double *ci = mxGetPr(ci95);
    for (size_t j = 0; j < k; j++) {
        LugreZooEstimate e;
        check(lugre_zoo_fit_estimate(fit, j, &e));
        mxSetCell(names, j, mxCreateString(e.name));
        value[j] = e.value;
        se[j] = e.std_error;
        ci[j] = e.ci95_lo;
        ci[j + k] = e.ci95_hi;
        at_bound[j] = e.at_bound;
    }
    LugreZoo *fitted_model = NULL;
    check(lugre_zoo_fit_model(fit, &fitted_model));
    LugreZooModelInfo info;
    check(lugre_zoo_model_info(model, &info));
    mxArray *values = zoo_values(fitted_model, model);
    lugre_zoo_free(fitted_model);
    lugre_zoo_fit_free(fit);
    FitNumbers numbers = {s.rms, s.t_quantile, s.condition_number, s.samples, s.dof,
                          s.iterations, s.evaluations, s.starts, s.turning_points,
                          s.converged != 0, s.full != 0};
    return fit_struct_of(names, value, se, ci95, at_bound, k, values, &numbers, info.name, f,
                         fitted, n);
}

/* r = lugre_fit(u, f, options): the C ABI's fit, its result as a struct (see lugre_fit.m). */
static mxArray *fit_struct(int nrhs, const mxArray *prhs[]) {
    size_t n = 0, nf = 0, nt = 0;
    const double *u = vector(prhs[0], "u", &n);
    const double *f = vector(prhs[1], "f", &nf);
    /* The core's words (FitError), the force named as here. */
    if (n != nf)
        mexErrMsgIdAndTxt(ERROR_ID, "the data columns have different lengths: f has %d values, u has %d", (int)nf, (int)n);
    const mxArray *s = options_struct(nrhs > 2 ? prhs[2] : NULL, "options", "struct('kind', 'full', 't', t)");
    LugreFitOptions o;
    check(lugre_fit_options_default(&o));
    int full = 0;
    const double *t = NULL;
    const mxArray *params = NULL;
    char zoo[64] = "lugre";
    size_t elements = 0;
    for (int k = 0; s != NULL && k < mxGetNumberOfFields(s); k++) {
        const char *name = mxGetFieldNameByNumber(s, k);
        const mxArray *v = mxGetFieldByNumber(s, 0, k);
        char text[16];
        if (strcmp(name, "kind") == 0) {
            option_text(v, "options.kind", text, sizeof text);
            if (strcmp(text, "full") != 0 && strcmp(text, "slow") != 0)
                mexErrMsgIdAndTxt(ERROR_ID, "options.kind must be 'slow' or 'full', got '%s'", text);
            full = strcmp(text, "full") == 0;
        } else if (strcmp(name, "t") == 0) {
            t = vector(v, "options.t", &nt);
        } else if (strcmp(name, "model") == 0) {
            option_text(v, "options.model", zoo, sizeof zoo);
            o.family = strcmp(zoo, "dahl") == 0 ? LUGRE_FAMILY_DAHL : LUGRE_FAMILY_LUGRE;
        } else if (strcmp(name, "elements") == 0) {
            double count = scalar(v, "options.elements");
            /* The count's bounds are the core's; here only what a size_t holds. */
            if (!(count >= 1 && count <= 1e15 && count == floor(count)))
                mexErrMsgIdAndTxt(ERROR_ID, "options.elements must be a whole number from 1 to 64, got %g", count);
            elements = (size_t)count;
        } else if (strcmp(name, "params") == 0) {
            params = v;
        } else if (strcmp(name, "fix") == 0) {
            o.fix = names_option(v, "options.fix");
        } else if (strcmp(name, "free") == 0) {
            o.free = names_option(v, "options.free");
        } else if (strcmp(name, "x0") == 0) {
            o.x0 = scalar(v, "options.x0");
        } else if (strcmp(name, "starts") == 0) {
            double starts = scalar(v, "options.starts");
            /* The count's bounds are the core's (its message, as the CLI's and Python's);
             * here only what a size_t holds (0 is the C ABI's default, so refused). */
            if (!(starts >= 1 && starts <= 1e15 && starts == floor(starts)))
                mexErrMsgIdAndTxt(ERROR_ID, "options.starts must be a whole number from 1 to 64, got %g", starts);
            o.starts = (size_t)starts;
        } else {
            mexErrMsgIdAndTxt(ERROR_ID, "unknown option 'options.%s' (options: %s)", name, FIT_OPTIONS);
        }
    }
    if (full && t == NULL) fail("a full fit (options.kind = 'full') needs the sample times options.t");
    if (full && nt != n) mexErrMsgIdAndTxt(ERROR_ID, "options.t and u must have the same length, got %d and %d", (int)nt, (int)n);
    if (strcmp(zoo, "lugre") != 0 && strcmp(zoo, "dahl") != 0) {
        /* A model of the zoo (the C ABI refuses an unknown name, naming every model). */
        if (!full && (t != NULL || o.starts != 0))
            mexErrMsgIdAndTxt(ERROR_ID, "options.%s applies to the full fit (options.kind = 'full')",
                              t != NULL ? "t" : "starts");
        if (o.x0 != 0)
            mexErrMsgIdAndTxt(ERROR_ID, "options.x0 = %g: the model '%s' starts from rest; leave options.x0 out", o.x0, zoo);
        return zoo_fit_struct(zoo, params, t, u, f, n, elements, o.starts, o.fix, o.free);
    }
    if (elements != 0)
        fail("options.elements applies to an element model of the zoo (options.model = 'maxwell-slip' or 'prandtl-ishlinskii')");
    if (!full && (o.x0 != 0 || o.starts != 0))
        mexErrMsgIdAndTxt(ERROR_ID, "options.%s applies to the full fit (options.kind = 'full')",
                          o.x0 != 0 ? "x0" : "starts");
    if (!full && t != NULL)
        fail("options.t is for the full fit (options.kind = 'full'): the slow fit depends on the turning points alone");
    LugreModel *m = fit_model(params, o.family == LUGRE_FAMILY_DAHL);
    o.model = m;
    LugreFitResult r;
    double *fitted = doubles(n);
    LugreStatus st = full ? lugre_fit(t, u, f, n, &o, &r, fitted) : lugre_fit_slow(u, f, n, &o, &r, fitted);
    lugre_model_free(m);
    check(st);
    return fit_result(&r, f, fitted, n, full);
}

/* [names, table] = lugre_parameters(model) of a model of the zoo: the names, and a struct array
 * of name, unit, description, domain, shape ('scalar' or 'elements') and default, from the C
 * ABI's table. */
static void zoo_parameters(const char *model, int nlhs, mxArray *plhs[]) {
    LugreZooModelInfo info;
    check(lugre_zoo_model_info(model, &info));
    size_t count = info.parameters;
    static const char *fields[] = {"name", "unit", "description", "domain", "shape", "default"};
    mxArray *names = mxCreateCellMatrix(1, count);
    mxArray *table = mxCreateStructMatrix(count, 1, 6, fields);
    for (size_t i = 0; i < count; i++) {
        LugreZooParameter p;
        check(lugre_zoo_parameter(model, i, &p));
        mxSetCell(names, i, mxCreateString(p.name));
        const char *texts[] = {p.name, p.unit, p.description, p.domain,
                               p.shape == LUGRE_ZOO_SCALAR ? "scalar" : "elements"};
        for (int f = 0; f < 5; f++) mxSetFieldByNumber(table, i, f, mxCreateString(texts[f]));
        mxArray *d = mxCreateDoubleMatrix(1, p.default_len, mxREAL);
        if (p.default_len > 0) memcpy(mxGetPr(d), p.default_values, p.default_len * sizeof(double));
        mxSetFieldByNumber(table, i, 5, d);
    }
    plhs[0] = names;
    if (nlhs > 1) plhs[1] = table;
    else mxDestroyArray(table);
}

/* models = lugre_models(): the names of the zoo's models, from the C ABI's table. */
static mxArray *zoo_models(void) {
    size_t count = 0;
    while (lugre_zoo_model_name(count) != NULL) count++;
    mxArray *names = mxCreateCellMatrix(1, count);
    for (size_t i = 0; i < count; i++) mxSetCell(names, i, mxCreateString(lugre_zoo_model_name(i)));
    return names;
}

/* names = lugre_parameters(model): the model's parameter names ('lugre', 'dahl' or a model of
 * the zoo), in the core's order, from the C ABI (the core's table). */
static void parameter_names(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
    char model[64] = "lugre";
    if (nrhs > 0 && (!mxIsChar(prhs[0]) || mxGetString(prhs[0], model, sizeof model) != 0))
        fail("model must be the name of a model, e.g. 'lugre', 'dahl' or 'maxwell-slip' (lugre_models lists them)");
    int family;
    if (strcmp(model, "lugre") == 0) {
        family = LUGRE_FAMILY_LUGRE;
    } else if (strcmp(model, "dahl") == 0) {
        family = LUGRE_FAMILY_DAHL;
    } else {
        zoo_parameters(model, nlhs, plhs);
        return;
    }
    size_t count = 0;
    const char *name = NULL;
    while (count < LUGRE_MAX_PARAMETERS && lugre_parameter_name(family, count, &name) == LUGRE_STATUS_OK)
        count++;
    mxArray *names = mxCreateCellMatrix(1, count);
    for (size_t i = 0; i < count; i++) {
        check(lugre_parameter_name(family, i, &name));
        mxSetCell(names, i, mxCreateString(name));
    }
    plhs[0] = names;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
    char cmd[32];
    if (nrhs < 1 || !mxIsChar(prhs[0]) || mxGetString(prhs[0], cmd, sizeof cmd) != 0)
        fail("lugre_mex: the first argument names the call (use lugre_loop, lugre_cycles, ...)");
    int args = nrhs - 1;
    const mxArray **a = prhs + 1;
    if (strcmp(cmd, "loop") == 0) {
        if (args < 1) fail("lugre_loop(u, params, n): u is missing");
        plhs[0] = loop_struct(a[0], args > 1 ? a[1] : NULL, args > 2 ? a[2] : NULL);
    } else if (strcmp(cmd, "cycles") == 0) {
        if (args < 1) fail("lugre_cycles(u, ...): u is missing");
        plhs[0] = cycles_struct(args, a);
    } else if (strcmp(cmd, "simulate") == 0) {
        if (args < 2) fail("lugre_simulate(t, x, params, z0): t and x are needed");
        plhs[0] = simulate_struct(args, a);
    } else if (strcmp(cmd, "sweep") == 0) {
        if (args < 2) fail("lugre_sweep(amplitudes, frequencies, params, offset, tol): amplitudes and frequencies are needed");
        plhs[0] = sweep_struct(args, a);
    } else if (strcmp(cmd, "dynamics") == 0) {
        if (args == 1 && mxIsStruct(a[0])) {
            plhs[0] = dynamics_request(a[0]);
        } else {
            if (args < 2)
                fail("lugre_dynamics(request) with a struct, or lugre_dynamics(scenario, times, rtol)");
            plhs[0] = dynamics_scenario(args, a);
        }
    } else if (strcmp(cmd, "friction_step") == 0) {
        if (args < 2) fail("lugre_friction_step(x, dt, params, z0, x0): x and dt are needed");
        friction_step(nlhs, plhs, args, a);
    } else if (strcmp(cmd, "fit") == 0) {
        if (args < 2) fail("lugre_fit(u, f, options): u and f are needed");
        plhs[0] = fit_struct(args, a);
    } else if (strcmp(cmd, "parameters") == 0) {
        parameter_names(nlhs, plhs, args, a);
    } else if (strcmp(cmd, "models") == 0) {
        plhs[0] = zoo_models();
    } else {
        mexErrMsgIdAndTxt(ERROR_ID, "lugre_mex: unknown call '%s'", cmd);
    }
}
