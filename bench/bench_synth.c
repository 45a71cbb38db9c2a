/* synth benchmarks: world loading, CPU rendering (views/s at 640x480, 1 and 2 threads) and the
 * full capture of the bundled house. Prints `name  value  unit  (settings)`. */
#include "semsplat/synth.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    char world[1200];
    snprintf(world, sizeof world, "%s/worlds/house.world", sp_data_dir());
    int n_views = argc > 1 ? atoi(argv[1]) : 24;
    if (n_views < 1) n_views = 24;
    sp_error err = {0};
    sp_world w;
    sp_synth_load_opts lo = {.no_env = 1};
    double t0 = sp_time_now();
    if (sp_synth_load_world(world, &lo, &w, &err)) {
        fprintf(stderr, "bench_synth: %s\n", err.msg);
        return 1;
    }
    printf("synth_load_house  %.1f  ms  (%zu triangles, %zu models)\n", (sp_time_now() - t0) * 1e3,
           w.n_triangles, w.n_objects);
    sp_synth_capture_opts co = {.n_views = n_views, .width = 640, .height = 480, .seed = 1};
    sp_camera *cams = NULL;
    size_t n = 0;
    t0 = sp_time_now();
    if (sp_synth_plan_views(&w, &co, &cams, &n, &err)) {
        fprintf(stderr, "bench_synth: %s\n", err.msg);
        return 1;
    }
    printf("synth_plan_views  %.1f  ms  (%zu views, house)\n", (sp_time_now() - t0) * 1e3, n);
    for (int threads = 1; threads <= 2; threads++) {
        sp_pool *pool = NULL;
        if (sp_pool_create(&pool, threads, &err)) return 1;
        for (int ss = 1; ss <= 2; ss++) {
            sp_synth_frame f = {0};
            sp_synth_render_opts ro = {.supersample = ss};
            t0 = sp_time_now();
            for (size_t i = 0; i < n; i++)
                if (sp_synth_render(&w, &cams[i], &ro, pool, &f, &err)) {
                    fprintf(stderr, "bench_synth: %s\n", err.msg);
                    return 1;
                }
            double dt = sp_time_now() - t0;
            printf("synth_render_640x480  %.2f  views/s  (house, %d thread%s, supersample %dx%d, %zu views)\n",
                   n / dt, threads, threads > 1 ? "s" : "", ss, ss, n);
            sp_synth_frame_free(&f);
        }
        sp_pool_free(pool);
    }
    char out[] = "/tmp/bench_synth_XXXXXX";
    if (mkdtemp(out)) {
        co.n_threads = 2;
        t0 = sp_time_now();
        if (sp_synth_capture(&w, out, &co, &err)) {
            fprintf(stderr, "bench_synth: %s\n", err.msg);
            return 1;
        }
        double dt = sp_time_now() - t0;
        printf("synth_capture_house  %.2f  s  (%d views 640x480, 2 threads, with PNG/npy/COLMAP writing; %.0f s per 150)\n",
               dt, n_views, dt * 150.0 / n_views);
        char cmd[1100];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", out);
        if (system(cmd) != 0) fprintf(stderr, "bench_synth: could not remove %s\n", out);
    }
    free(cams);
    sp_world_free(&w);
    return 0;
}
