/* Plane geometry the tools, the commitments and the offline robot share. */
#include <math.h>

#include "agent_internal.h"

double agent_wrap_angle(double a)
{
    if (!isfinite(a)) return a;
    a = fmod(a + M_PI, 2 * M_PI);
    if (a < 0) a += 2 * M_PI;
    return a - M_PI;
}

double agent_dist2d(double ax, double ay, double bx, double by) { return hypot(ax - bx, ay - by); }

double agent_path_length(const double *wp, int n)
{
    double d = 0;
    for (int i = 0; i + 1 < n; i++)
        d += agent_dist2d(wp[i * 4], wp[i * 4 + 1], wp[(i + 1) * 4], wp[(i + 1) * 4 + 1]);
    return d;
}

double agent_dist_to_footprint(const agent_instance *in, double x, double y)
{
    if (!isfinite(in->extent_min[0]) || !isfinite(in->extent_max[0]) ||
        !isfinite(in->extent_min[1]) || !isfinite(in->extent_max[1]))
        return agent_dist2d(in->position[0], in->position[1], x, y);
    double dx = fmax(fmax(in->extent_min[0] - x, 0), x - in->extent_max[0]);
    double dy = fmax(fmax(in->extent_min[1] - y, 0), y - in->extent_max[1]);
    return hypot(dx, dy);
}

const char *agent_cell_name(int cell)
{
    static const char *const names[] = {"free", "occupied", "unknown", "outside the map"};
    return cell >= 0 && cell < 4 ? names[cell] : "invalid";
}
