/* The cost of one call through the C ABI with tiny inputs: each case makes its call `calls`
 * times, so that the time per call (printed) or the instructions per call (valgrind
 * --tool=cachegrind, of `calls` minus of 0 calls, divided by `calls`) can be compared across
 * commits. Builds against any version of include/lugre.h; the dynamics request and the fits
 * (cases "dynamics_request", "fit_slow") only where the header has them.
 *
 *   cargo build --release -p lugre-ffi
 *   cc -O2 bench/percall.c -Icrates/lugre-ffi/include $CARGO_TARGET_DIR/release/liblugre_c.a \
 *      -lm -lpthread -ldl -o percall
 *   ./percall                 # every case, 10^5 calls each (10^3 for dynamics), ns per call
 *   ./percall simulate 1000   # one case, 1000 calls, no output (for valgrind)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "lugre.h"

#define CHECK(call)                                                            \
    do {                                                                       \
        if ((call) != LUGRE_STATUS_OK) {                                       \
            fprintf(stderr, "%s failed: %s\n", #call, lugre_last_error());     \
            exit(1);                                                           \
        }                                                                      \
    } while (0)

static LugreModel *model;
static double sink;

static void model_new(void) {
    LugreParams p;
    LugreModel *m = NULL;
    CHECK(lugre_params_default(&p));
    p.sigma0 = 6.0;
    CHECK(lugre_model_new(&p, &m));
    lugre_model_free(m);
}

static void loop_table(void) {
    const double u[] = {0.0, 1.0, 0.5, 1.5};
    LugreLoop *hl = NULL;
    size_t n = 0;
    double work = 0.0, period = 0.0;
    CHECK(lugre_loop_new(model, u, 4, &hl));
    CHECK(lugre_loop_table_len(hl, &n));
    CHECK(lugre_loop_summary(hl, &work, &period));
    sink += work + (double)n;
    lugre_loop_free(hl);
}

static void loop_sample(void) {
    const double u[] = {0.0, 1.0, 0.5, 1.5};
    double rho[16], uu[16], y[16];
    LugreLoop *hl = NULL;
    CHECK(lugre_loop_new(model, u, 4, &hl));
    CHECK(lugre_loop_sample(hl, 16, rho, uu, y));
    sink += y[15];
    lugre_loop_free(hl);
}

/* The rainflow count of 8 samples, with energies when `with` is a model. */
static void count(const LugreModel *with) {
    const double u[] = {0.0, 1.0, 0.2, 0.8, -0.5, 1.2, 0.1, 0.9};
    LugreCycles *c = NULL;
    size_t n = 0;
    CHECK(lugre_cycles_new(u, 8, 0.0, with, 0.0, &c));
    CHECK(lugre_cycles_len(c, &n));
    sink += (double)n;
    lugre_cycles_free(c);
}

static void cycles(void) { count(NULL); }

static void cycles_energy(void) { count(model); }

static void simulate(void) {
    const double t[] = {0.0, 1.0, 1.5, 2.5};
    const double x[] = {0.0, 1.0, 0.5, 1.5};
    double z[4], f[4];
    CHECK(lugre_simulate(model, t, x, 4, 0.0, z, f));
    sink += f[3];
}

static LugreElement *element;
static double element_x;

static void element_step(void) {
    double f = 0.0;
    element_x = element_x > 1.0 ? 0.0 : element_x + 0.01;
    CHECK(lugre_element_step(element, element_x, 1e-3, &f));
    sink += f;
}

/* The break-away experiment (10 N/s, run to 0.2 s), reported at four times. */
static const double dyn_times[] = {0.05, 0.1, 0.15, 0.2};

static void dynamics_scenario(void) {
    double x[4];
    CHECK(lugre_dynamics_scenario("breakaway", 0.0, dyn_times, 4, x, NULL, NULL, NULL));
    sink += x[3];
}

#ifdef LUGRE_MAX_PARAMETERS
/* The same run as a request built field by field. */
static void dynamics_request(void) {
    LugreDynamics *r = NULL;
    LugreMotion *m = NULL;
    double x[4];
    CHECK(lugre_dynamics_new(&r));
    CHECK(lugre_dynamics_set_scenario(r, "breakaway"));
    CHECK(lugre_dynamics_set(r, "times", dyn_times, 4));
    CHECK(lugre_dynamics_run(r, &m));
    CHECK(lugre_motion_columns(m, 4, NULL, x, NULL, NULL, NULL, NULL));
    sink += x[3];
    lugre_motion_free(m);
    lugre_dynamics_free(r);
}

/* The slow fit of 12 samples, three periods of a loop. */
static void fit_slow(void) {
    const double u[] = {0.0, 1.0, 0.5, 1.5, 0.0, 1.0, 0.5, 1.5, 0.0, 1.0, 0.5, 1.5};
    const double f[] = {-1.2, 1.1, 0.2, 1.3, -1.3, 1.2, 0.1, 1.3, -1.25, 1.15, 0.15, 1.3};
    LugreFitResult r;
    CHECK(lugre_fit_slow(u, f, 12, NULL, &r, NULL));
    sink += r.value[0];
}
#endif

struct Case {
    const char *name;
    void (*call)(void);
    long calls;
};

static const struct Case cases[] = {
    {"model_new", model_new, 100000},
    {"loop_table", loop_table, 100000},
    {"loop_sample", loop_sample, 100000},
    {"cycles", cycles, 100000},
    {"cycles_energy", cycles_energy, 100000},
    {"simulate", simulate, 100000},
    {"element_step", element_step, 1000000},
    {"dynamics_scenario", dynamics_scenario, 1000},
#ifdef LUGRE_MAX_PARAMETERS
    {"dynamics_request", dynamics_request, 1000},
    {"fit_slow", fit_slow, 10000},
#endif
};

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv) {
    LugreParams p;
    CHECK(lugre_params_default(&p));
    p.sigma0 = 6.0;
    CHECK(lugre_model_new(&p, &model));
    CHECK(lugre_element_new(model, 0.0, &element));
    size_t n = sizeof cases / sizeof cases[0];
    for (size_t i = 0; i < n; i++) {
        if (argc > 1 && strcmp(argv[1], cases[i].name) != 0) continue;
        long calls = argc > 2 ? atol(argv[2]) : cases[i].calls;
        double t0 = now();
        for (long k = 0; k < calls; k++) cases[i].call();
        double dt = now() - t0;
        if (argc == 1) printf("%s %.1f\n", cases[i].name, 1e9 * dt / (double)calls);
    }
    lugre_element_free(element);
    lugre_model_free(model);
    return sink == 12345.0;
}
