/* Wall-clock time as ROS stamps headers (builtin_interfaces/Time: seconds since the epoch). */
#include <math.h>
#include <time.h>

#include "ros_internal.h"

double ros_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void ros_split_time(double t, int32_t *sec, uint32_t *nsec)
{
    if (!isfinite(t)) t = 0;
    double s = floor(t);
    double ns = rint((t - s) * 1e9);
    if (ns >= 1e9) {
        s += 1;
        ns -= 1e9;
    }
    *sec = (int32_t)s;
    *nsec = (uint32_t)ns;
}
