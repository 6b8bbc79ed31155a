/* Every function of include/lugre.h called from C, each with a check of what it returned
 * (tests/exports.rs compiles and runs this program, and fails when the header declares a
 * function this file does not call). Exits 0 and prints "ok" when every check holds; else
 * prints the failed check and exits 1. LUGRE_EXPECTED_VERSION is set by the test. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lugre.h"

static int failures = 0;

#define CHECK(cond)                                                          \
    do {                                                                     \
        if (!(cond)) {                                                       \
            printf("FAILED line %d: %s (last error: %s)\n", __LINE__, #cond, \
                   lugre_last_error());                                     \
            failures++;                                                      \
        }                                                                    \
    } while (0)

#define OK(call) CHECK((call) == LUGRE_STATUS_OK)

static void versions_and_parameters(void) {
    CHECK(strcmp(lugre_version(), LUGRE_EXPECTED_VERSION) == 0);
    LugreParams p;
    OK(lugre_params_default(&p));
    CHECK(p.sigma0 == 1 && p.fs == 2 && p.sigma2 == 0);
    OK(lugre_params_canudas1995(&p));
    CHECK(p.sigma0 == 1e5 && p.vs == 1e-3);
    OK(lugre_params_set(&p, "beta", 3));
    CHECK(p.beta == 3);
    CHECK(lugre_params_set(&p, "gamma", 3) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(lugre_last_error(), "unknown parameter 'gamma'") != NULL);
    const char *name = NULL;
    OK(lugre_parameter_name(LUGRE_FAMILY_DAHL, 0, &name));
    CHECK(name != NULL && strcmp(name, "rho") == 0);
    /* The named-model rule: energies need sigma0 and fs; a simulation every parameter whose
     * default is not an absence. */
    OK(lugre_params_check_named(LUGRE_NEEDED_RATE_INDEPENDENT, "fs, SIGMA0"));
    CHECK(lugre_params_check_named(LUGRE_NEEDED_RATE_INDEPENDENT, "fs") ==
          LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(lugre_last_error(), "give sigma0 too, or preset 'canudas1995'") != NULL);
    CHECK(lugre_params_check_named(LUGRE_NEEDED_ALL, NULL) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(lugre_params_check_named(2, "") == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(lugre_params_check_named(LUGRE_NEEDED_ALL, "sigma0,kappa") ==
          LUGRE_STATUS_INVALID_ARGUMENT);
    const char *names[] = {"fc", name};
    const double values[] = {0.5, 2.0};
    LugreModel *dahl = NULL;
    OK(lugre_model_new_named(LUGRE_FAMILY_DAHL, 2, names, values, &dahl));
    const double u[] = {0, 1};
    LugreLoop *hl = NULL;
    OK(lugre_loop_new(dahl, u, 2, &hl));
    double work = 0, period = 0;
    OK(lugre_loop_summary(hl, &work, &period));
    CHECK(work > 0 && work < 4 * 0.5); /* below 2 Fc per unit of travel and back */
    lugre_loop_free(hl);
    lugre_model_free(dahl);
}

static void loops(const LugreModel *m) {
    const double u[] = {0, 1, 0.5, 1.5};
    LugreLoop *hl = NULL;
    OK(lugre_loop_new(m, u, 4, &hl));
    size_t k = 0, rows = 0;
    OK(lugre_loop_turning_len(hl, &k));
    CHECK(k == 4);
    double tu[4], ty[4];
    OK(lugre_loop_turning(hl, tu, NULL, ty, 4));
    CHECK(tu[3] == 1.5 && ty[0] < 0 && ty[1] > 0);
    double work = 0, period = 0;
    OK(lugre_loop_summary(hl, &work, &period));
    CHECK(work > 0 && period == 4);
    OK(lugre_loop_table_len(hl, &rows));
    CHECK(rows == 2);
    int32_t kind[2];
    int64_t parent[2];
    double loop_work[2];
    LugreLoopColumns c = {0};
    c.kind = kind;
    c.parent = parent;
    c.work = loop_work;
    OK(lugre_loop_table(hl, &c, rows));
    CHECK(loop_work[0] + loop_work[1] > 0 && (parent[0] == -1 || parent[1] == -1));
    double rho[3], y[3];
    OK(lugre_loop_sample(hl, 3, rho, NULL, y));
    CHECK(rho[0] == 0 && rho[2] == period && y[0] == ty[0]);
    CHECK(lugre_loop_sample(hl, 1, rho, NULL, y) == LUGRE_STATUS_INVALID_ARGUMENT);
    lugre_loop_free(hl);
}

/* Every model of the zoo's table, found by listing it (none named here): its parameters given
 * by name at their defaults, its loop read through the LugreLoop accessors, bad input refused. */
static void zoo(void) {
    size_t count = 0;
    while (lugre_zoo_model_name(count) != NULL) count++;
    CHECK(count >= 2);
    for (size_t i = 0; i < count; i++) {
        const char *model = lugre_zoo_model_name(i);
        LugreZooModelInfo info;
        OK(lugre_zoo_model_info(model, &info));
        enum { MOST = 64 };
        CHECK(strcmp(info.name, model) == 0 && info.parameters >= 1 && info.parameters <= MOST);
        if (info.parameters > MOST) continue;
        const char *names[MOST];
        const double *values[MOST];
        size_t lens[MOST];
        for (size_t k = 0; k < info.parameters; k++) {
            LugreZooParameter p;
            OK(lugre_zoo_parameter(model, k, &p));
            CHECK(p.default_len >= 1 && (p.shape == LUGRE_ZOO_ELEMENTS || p.default_len == 1));
            CHECK(p.shape == LUGRE_ZOO_SCALAR || p.shape == LUGRE_ZOO_ELEMENTS);
            names[k] = p.name;
            values[k] = p.default_values;
            lens[k] = p.default_len;
        }
        LugreZooParameter past;
        CHECK(lugre_zoo_parameter(model, info.parameters, &past) == LUGRE_STATUS_INVALID_ARGUMENT);
        LugreZoo *z = NULL;
        OK(lugre_zoo_new(model, info.parameters, names, values, lens, &z));
        double echo[16];
        size_t len = 0;
        OK(lugre_zoo_value(z, 0, NULL, 0, &len));
        CHECK(len == lens[0]);
        OK(lugre_zoo_value(z, 0, echo, 16, NULL));
        CHECK(echo[0] == values[0][0]);
        const double u[] = {3, 1, 2, -3};
        LugreLoop *hl = NULL;
        OK(lugre_zoo_loop_new(z, u, 4, &hl));
        size_t k = 0, rows = 0;
        OK(lugre_loop_turning_len(hl, &k));
        OK(lugre_loop_table_len(hl, &rows));
        CHECK(k == 4 && rows == 2); /* the major loop and the minor loop 1 -> 2 -> 1 */
        double work = 0, period = 0;
        OK(lugre_loop_summary(hl, &work, &period));
        CHECK(period == 14 && work != 0);
        lugre_loop_free(hl);
        /* The cycles of a history along the model's path from rest: one full cycle of the
         * nine samples closes (the ASTM example's (-1, 3), here (1, 3)) with its energies. */
        const double h[] = {0, 4, 1, 3, -4, -1, -3, 4, 0};
        LugreCycles *cy = NULL;
        OK(lugre_zoo_cycles_new(z, h, 9, 0, NULL, &cy));
        const double x0 = 0;
        CHECK(lugre_zoo_cycles_new(z, h, 9, 0, &x0, &cy) == LUGRE_STATUS_INVALID_ARGUMENT);
        CHECK(strstr(lugre_last_error(), "starts from rest") != NULL);
        /* The force at each sample from rest; an initial state is refused. */
        const double st[] = {0, 1, 2, 3}, su[] = {0, 1, -1, 0.5};
        double sf[4] = {0};
        OK(lugre_zoo_simulate(z, st, su, 4, NULL, sf));
        CHECK(sf[1] == sf[1] && sf[3] == sf[3] && sf[1] != sf[2]);
        CHECK(lugre_zoo_simulate(z, st, su, 4, &x0, sf) == LUGRE_STATUS_INVALID_ARGUMENT); /* z0 given */
        CHECK(strstr(lugre_last_error(), "simulated from rest") != NULL);
        size_t nc = 0;
        OK(lugre_cycles_len(cy, &nc));
        double cw[9] = {0}, cc[9] = {0}, cd[9] = {0};
        LugreCycleColumns cols = {0};
        cols.count = cc;
        cols.work = cw;
        cols.dissipation = cd;
        CHECK(nc <= 9);
        OK(lugre_cycles_columns(cy, &cols, nc));
        size_t full = 0;
        for (size_t i = 0; i < nc; i++) full += cc[i] == 1 && cw[i] == cw[i];
        CHECK(full >= 1);
        lugre_cycles_free(cy);
        lugre_zoo_free(z);
        /* An unknown parameter: the core's message names the model's parameters. */
        const char *bad[] = {"no_such_parameter"};
        CHECK(lugre_zoo_new(model, 1, bad, values, lens, &z) == LUGRE_STATUS_INVALID_ARGUMENT);
        CHECK(strstr(lugre_last_error(), names[0]) != NULL);
    }
    LugreZoo *z = NULL;
    CHECK(lugre_zoo_new("no-such-model", 0, NULL, NULL, NULL, &z) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(z == NULL && strstr(lugre_last_error(), lugre_zoo_model_name(0)) != NULL);
    lugre_zoo_free(NULL);
}

/* A Maxwell-slip loop made here (two elements, slip displacements 0.25 and 0.75 on the grid of
   an amplitude 1 record, stiffnesses 0.4 and 0.3), fitted back. */
static void zoo_fit(void) {
    enum { N = 400 };
    double u[N], f[N], fitted[N];
    const double k[] = {0.4, 0.3}, d[] = {0.25, 0.75};
    double z[] = {0, 0}, at = 0;
    for (int pass = 0; pass < 3; pass++) {
        for (int i = 0; i < N; i++) {
            /* A triangle from 1 down to -1 and back, 200 samples a way. */
            double x = i < N / 2 ? 1 - 2.0 * i / (N / 2) : -1 + 2.0 * (i - N / 2) / (N / 2);
            double force = 0;
            for (int j = 0; j < 2; j++) {
                z[j] += x - at;
                if (z[j] > d[j]) z[j] = d[j];
                if (z[j] < -d[j]) z[j] = -d[j];
                force += k[j] * z[j];
            }
            at = x;
            u[i] = x;
            f[i] = force;
        }
    }
    LugreZooFit *fit = NULL;
    OK(lugre_zoo_fit("maxwell-slip", NULL, u, f, N, 2, NULL, NULL, &fit, fitted));
    LugreZooFitSummary s;
    OK(lugre_zoo_fit_summary(fit, &s));
    CHECK(s.estimates == 2 && s.samples == N && s.converged == 1 && s.rms < 1e-12);
    CHECK(s.starts == 1 && s.full == 0);
    for (size_t i = 0; i < s.estimates; i++) {
        LugreZooEstimate e;
        OK(lugre_zoo_fit_estimate(fit, i, &e));
        CHECK(strncmp(e.name, "stiffness[", 10) == 0 && fabs(e.value / k[i] - 1) < 1e-9);
        CHECK(e.ci95_lo <= e.value && e.value <= e.ci95_hi && e.at_bound == 0);
    }
    LugreZooEstimate past;
    CHECK(lugre_zoo_fit_estimate(fit, s.estimates, &past) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(fabs(fitted[10] - f[10]) < 1e-12);
    LugreZoo *m = NULL;
    OK(lugre_zoo_fit_model(fit, &m));
    double echo[2];
    OK(lugre_zoo_value(m, 1, echo, 2, NULL)); /* slip_force = k Delta */
    CHECK(fabs(echo[0] - 0.1) < 1e-9 && fabs(echo[1] - 0.225) < 1e-9);
    lugre_zoo_free(m);
    lugre_zoo_fit_free(fit);
    fit = NULL;
    CHECK(lugre_zoo_fit("elastoplastic", NULL, u, f, N, 0, NULL, "fc", &fit, NULL) ==
          LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(fit == NULL && strstr(lugre_last_error(), "fc does not enter the slow loop") != NULL);
    lugre_zoo_fit_free(NULL);
    /* The full fit: a model without a finite-rate form is refused with the core's message. */
    double t[N];
    for (int i = 0; i < N; i++) t[i] = i;
    CHECK(lugre_zoo_fit_full("bouc-wen", NULL, t, u, f, N, 0, 0, NULL, NULL, &fit, NULL) ==
          LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(fit == NULL && strstr(lugre_last_error(), "has no finite-rate form") != NULL);
}

static void cycles(const LugreModel *m) {
    const double h[] = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
    LugreCycles *cy = NULL;
    OK(lugre_cycles_new(h, 9, 0, m, 0, &cy));
    size_t n = 0;
    OK(lugre_cycles_len(cy, &n));
    CHECK(n == 7);
    double range[7], count[7], work[7];
    int64_t closure[7];
    LugreCycleColumns c = {0};
    c.range = range;
    c.count = count;
    c.closure = closure;
    c.work = work;
    OK(lugre_cycles_columns(cy, &c, n));
    CHECK(range[2] == 4 && count[2] == 1 && closure[2] == 6 && work[2] > 0);
    lugre_cycles_free(cy);
}

static void simulation_and_element(const LugreModel *m) {
    const double t[] = {0, 1e-2, 2e-2}, x[] = {0, 1e-5, 1e-5};
    double z[3], f[3];
    OK(lugre_simulate(m, t, x, 3, 0, z, f));
    CHECK(z[1] > 0 && f[1] > 0);
    LugreElement *e = NULL;
    OK(lugre_element_new(m, 0, &e));
    double force = 0, now = 0, zz = 0;
    OK(lugre_element_step(e, 1e-5, 1e-2, &force));
    OK(lugre_element_state(e, &now, NULL, &zz, NULL));
    CHECK(now == 1e-2 && zz == z[1]);
    OK(lugre_element_reset(e, 0, 0, 0));
    OK(lugre_element_state(e, &now, NULL, &zz, &force));
    CHECK(now == 0 && zz == 0 && force == 0);
    lugre_element_free(e);
    double times[] = {10, 20}, pos[2];
    OK(lugre_dynamics_scenario("stick-slip", 0, times, 2, pos, NULL, NULL, NULL));
    CHECK(pos[0] > 0 && pos[1] > pos[0]);
    const double amplitudes[] = {1e-6, 1e-5}, frequencies[] = {0.1, 1, 10};
    double table[6 * LUGRE_SWEEP_COLUMNS];
    OK(lugre_sweep(m, amplitudes, 2, frequencies, 3, 0, 0, table, 6));
    /* Row 4 is A = 1e-5, f = 1: dissipation (column 2) > 0, phase (column 9) in (0, pi). */
    const double *row = table + 4 * LUGRE_SWEEP_COLUMNS;
    CHECK(row[0] == 1e-5 && row[1] == 1 && row[2] > 0 && row[9] > 0 && row[9] < 3.15);
    CHECK(lugre_sweep(m, amplitudes, 2, frequencies, 3, 0, 0, table, 5) == LUGRE_STATUS_BUFFER_TOO_SMALL);
    CHECK(strcmp(lugre_sweep_column(2), "dissipation") == 0);
    CHECK(lugre_sweep_column(LUGRE_SWEEP_COLUMNS) == NULL);
}

static void fits(void) {
    /* The paper's Example 4 loop (sigma0 = 6, fs = 2) sampled at 201 points, fitted back. */
    LugreParams p;
    OK(lugre_params_default(&p));
    p.sigma0 = 6;
    LugreModel *m = NULL;
    OK(lugre_model_new(&p, &m));
    const double tp[] = {0, 1, 0.5, 1.5};
    LugreLoop *hl = NULL;
    OK(lugre_loop_new(m, tp, 4, &hl));
    enum { N = 201 };
    double u[N], f[N], t[N], fitted[N];
    OK(lugre_loop_sample(hl, N, NULL, u, f));
    lugre_loop_free(hl);
    for (int i = 0; i < N; i++) t[i] = i;
    LugreFitOptions o;
    OK(lugre_fit_options_default(&o));
    LugreFitResult r;
    OK(lugre_fit_slow(u, f, N, &o, &r, fitted));
    CHECK(r.family == LUGRE_FAMILY_LUGRE && r.fitted[0] == 1 && fabs(r.value[0] - 6) < 1e-9);
    CHECK(fabs(r.value[4] - 2) < 1e-9 && fabs(fitted[7] - f[7]) < 1e-9);
    /* The full fit of the model's own exact simulation of that input at 1 per second, the
     * parameters but sigma0 and fs held: both come back. */
    double z[N], force[N];
    OK(lugre_simulate(m, t, u, N, 0, z, force));
    o.model = m;
    o.fix = "sigma1, sigma2, vs, fc";
    OK(lugre_fit(t, u, force, N, &o, &r, NULL));
    CHECK(r.fitted[0] == 1 && r.fitted[4] == 1 && r.fitted[1] == 0 && r.turning_points == 0);
    CHECK(fabs(r.value[0] - 6) < 1e-6 && fabs(r.value[4] - 2) < 1e-6 && r.value[1] == 1);
    lugre_model_free(m);
}

/* The dynamics request: the PID experiment with new gains keeps its set point (1 m); a model, a
 * force profile and a measured force; two applied forces fail naming both. */
static void dynamics(const LugreModel *m) {
    LugreDynamics *d = NULL;
    LugreMotion *run = NULL;
    OK(lugre_dynamics_new(&d));
    OK(lugre_dynamics_set_scenario(d, "pid"));
    double gains[3] = {3, 8, 6}, t_end = 40, samples = 5;
    OK(lugre_dynamics_set(d, "pid", gains, 3));
    OK(lugre_dynamics_set(d, "t_end", &t_end, 1));
    OK(lugre_dynamics_set(d, "samples", &samples, 1));
    OK(lugre_dynamics_run(d, &run));
    size_t n = 0;
    OK(lugre_motion_len(run, &n));
    CHECK(n == 5);
    double t[5], x[5], drive[5];
    CHECK(lugre_motion_columns(run, 4, t, x, NULL, NULL, NULL, drive) ==
          LUGRE_STATUS_BUFFER_TOO_SMALL);
    OK(lugre_motion_columns(run, 5, t, x, NULL, NULL, NULL, drive));
    CHECK(t[4] == 40 && fabs(x[4] - 1) < 0.15);
    LugreMotionSummary s;
    OK(lugre_motion_summary(run, &s));
    CHECK(s.t_end == 40 && s.steps > 0 && s.energy_input > 0 && s.has_breakaway == 0);
    CHECK(fabs(s.energy_input - (s.stored_end - s.stored_start) - s.dissipated) < 1e-6);
    CHECK(s.loops == 0);
    LugreFrictionLoop l;
    CHECK(lugre_motion_loop(run, 0, &l) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strcmp(lugre_last_error(), "index must be below 0, got 0") == 0);
    lugre_motion_free(run);
    lugre_dynamics_free(d);

    /* The pre-sliding experiment's loops (on by default): each read with its turning points,
     * its work split into the stored energy's change and the dissipation. */
    OK(lugre_dynamics_new(&d));
    OK(lugre_dynamics_set_scenario(d, "presliding"));
    OK(lugre_dynamics_set(d, "samples", &samples, 1));
    OK(lugre_dynamics_run(d, &run));
    OK(lugre_motion_summary(run, &s));
    CHECK(s.loops > 0);
    for (size_t i = 0; i < s.loops; i++) {
        OK(lugre_motion_loop(run, i, &l));
        CHECK(l.t_start < l.t_turn && l.t_turn < l.t_close && l.t_close <= s.t_end);
        CHECK(l.turning_points_len >= 2 && l.turning_points != NULL);
        CHECK(l.turning_points[0] != l.turning_points[1] && l.work > 0);
        CHECK(l.dissipation == l.work - l.bristle_energy_change && l.rate_independent_work > 0);
    }
    CHECK(lugre_motion_loop(run, s.loops, &l) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(lugre_motion_loop(run, 0, NULL) == LUGRE_STATUS_NULL_POINTER);
    CHECK(lugre_motion_loop(NULL, 0, &l) == LUGRE_STATUS_NULL_POINTER);
    lugre_motion_free(run);
    lugre_dynamics_free(d);

    double rate = 10, ft[2] = {0, 1}, f[2] = {0, 1};
    OK(lugre_dynamics_new(&d));
    OK(lugre_dynamics_set_model(d, m));
    OK(lugre_dynamics_set(d, "force_rate", &rate, 1));
    CHECK(lugre_dynamics_set_points(d, "force", ft, f, 2) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strcmp(lugre_last_error(),
                 "give force_rate or force, not both: they set the same thing") == 0);
    CHECK(lugre_dynamics_set(d, "mass", &rate, 2) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(lugre_dynamics_set(d, "gamma", &rate, 1) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(lugre_last_error(), "unknown field 'gamma'") != NULL);
    double end = 0.3;
    OK(lugre_dynamics_set(d, "t_end", &end, 1));
    OK(lugre_dynamics_run(d, &run));
    OK(lugre_motion_summary(run, &s));
    CHECK(s.has_breakaway == 1 && s.breakaway_force > 1 && s.breakaway_force < 1.5);
    lugre_motion_free(run);
    lugre_motion_free(NULL);
    lugre_dynamics_free(d);
    lugre_dynamics_free(NULL);

    /* The zoo's elasto-plastic law as the friction; another model of the zoo refused. */
    LugreZoo *ep = NULL, *ms = NULL;
    const char *zn[1] = {"zba"};
    double zv = 0.25;
    const double *zp[1] = {&zv};
    size_t zl[1] = {1};
    OK(lugre_zoo_new("elastoplastic", 1, zn, zp, zl, &ep));
    OK(lugre_zoo_new("bouc-wen", 0, NULL, NULL, NULL, &ms));
    OK(lugre_dynamics_new(&d));
    OK(lugre_dynamics_set_zoo(d, ep));
    OK(lugre_dynamics_set(d, "force_rate", &rate, 1));
    OK(lugre_dynamics_set(d, "t_end", &end, 1));
    OK(lugre_dynamics_run(d, &run));
    OK(lugre_motion_summary(run, &s));
    CHECK(s.steps > 0 && s.energy_input > 0);
    CHECK(fabs(s.energy_input - (s.stored_end - s.stored_start) - s.dissipated) < 1e-6);
    lugre_motion_free(run);
    CHECK(lugre_dynamics_set_zoo(d, ms) == LUGRE_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(lugre_last_error(), "model bouc-wen: the dynamics take") != NULL);
    CHECK(lugre_dynamics_set_zoo(d, NULL) == LUGRE_STATUS_NULL_POINTER);
    lugre_dynamics_free(d);
    lugre_zoo_free(ep);
    lugre_zoo_free(ms);
}

int main(void) {
    versions_and_parameters();
    LugreParams p;
    OK(lugre_params_canudas1995(&p));
    LugreModel *m = NULL, *dahl = NULL;
    OK(lugre_model_new(&p, &m));
    OK(lugre_model_new_dahl(2, 1, &dahl));
    loops(dahl);
    cycles(dahl);
    simulation_and_element(m);
    dynamics(m);
    lugre_model_free(dahl);
    lugre_model_free(m);
    lugre_model_free(NULL);
    fits();
    zoo();
    zoo_fit();
    if (failures == 0) printf("ok\n");
    return failures == 0 ? 0 : 1;
}
