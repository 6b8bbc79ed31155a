/* lugre from C: a hysteresis loop, rainflow cycles, the exact simulation and a friction element
 * stepped by a host loop.  Build (from the repository root):
 *
 *   cargo build --release -p lugre-ffi
 *   cc examples/c/friction.c -Icrates/lugre-ffi/include target/release/liblugre_c.a -lm -lpthread -ldl -o friction
 *   ./friction
 */
#include <stdio.h>
#include "lugre.h"

#define CHECK(call)                                                              \
    do {                                                                         \
        LugreStatus status_ = (call);                                            \
        if (status_ != LUGRE_STATUS_OK) {                                        \
            fprintf(stderr, "%s failed (%d): %s\n", #call, (int)status_,         \
                    lugre_last_error());                                         \
            return 1;                                                            \
        }                                                                        \
    } while (0)

int main(void) {
    /* The loop of lugre loop --sigma0 6 --turning-points 0,1,0.5,1.5 */
    LugreParams p;
    CHECK(lugre_params_default(&p));
    p.sigma0 = 6.0;
    LugreModel *model = NULL;
    CHECK(lugre_model_new(&p, &model));
    const double u[] = {0.0, 1.0, 0.5, 1.5};
    LugreLoop *hl = NULL;
    CHECK(lugre_loop_new(model, u, 4, &hl));
    size_t n = 0;
    CHECK(lugre_loop_turning_len(hl, &n));
    double tu[16], ty[16];
    CHECK(lugre_loop_turning(hl, tu, NULL, ty, 16));
    for (size_t i = 0; i < n; i++) printf("turning point u = %.17g y = %.17g\n", tu[i], ty[i]);
    double work = 0.0;
    CHECK(lugre_loop_summary(hl, &work, NULL));
    printf("work per period %.17g\n", work);
    size_t loops = 0;
    CHECK(lugre_loop_table_len(hl, &loops));
    double loop_work[16], loop_gap[16];
    LugreLoopColumns columns = {0};
    columns.work = loop_work;
    columns.closure_gap = loop_gap;
    CHECK(lugre_loop_table(hl, &columns, 16));
    for (size_t i = 0; i < loops; i++)
        printf("loop %zu work %.17g closure gap %.17g\n", i, loop_work[i], loop_gap[i]);
    lugre_loop_free(hl);

    /* Rainflow cycles of a short history (ASTM E1049's example) */
    const double history[] = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
    LugreCycles *cycles = NULL;
    CHECK(lugre_cycles_new(history, 9, 0.0, NULL, 0.0, &cycles));
    size_t nc = 0;
    CHECK(lugre_cycles_len(cycles, &nc));
    double range[16], count[16];
    LugreCycleColumns cc = {0};
    cc.range = range;
    cc.count = count;
    CHECK(lugre_cycles_columns(cycles, &cc, 16));
    for (size_t i = 0; i < nc; i++) printf("cycle range %g count %g\n", range[i], count[i]);
    lugre_cycles_free(cycles);
    lugre_model_free(model);

    /* A friction element (Table I of Canudas de Wit et al. 1995) stepped by a host: 10 um in
     * 10 ms, held, then back. */
    CHECK(lugre_params_canudas1995(&p));
    CHECK(lugre_model_new(&p, &model));
    LugreElement *element = NULL;
    CHECK(lugre_element_new(model, 0.0, &element));
    const double x[] = {0.0, 5e-6, 1e-5, 1e-5, 0.0};
    for (int k = 1; k < 5; k++) {
        double force = 0.0, z = 0.0;
        CHECK(lugre_element_step(element, x[k], 5e-3, &force));
        CHECK(lugre_element_state(element, NULL, NULL, &z, NULL));
        printf("step %d: x = %g m, z = %.17g m, F = %.17g N\n", k, x[k], z, force);
    }
    lugre_element_free(element);

    /* Bad input is an error code and a message, never a crash or a NaN. */
    p.sigma0 = -1.0;
    LugreModel *bad = NULL;
    LugreStatus status = lugre_model_new(&p, &bad);
    printf("sigma0 = -1: status %d, message: %s\n", (int)status, lugre_last_error());
    lugre_model_free(model);
    return 0;
}
