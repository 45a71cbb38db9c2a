/* The ROS 2 robot (--ros): adapts the ros module's bridge (odometry, NavigateToPose, feedback,
 * cancel) to the agent's robot interface. The ros module (issue 20) is not on main yet, so this
 * refuses with a clear message until it lands. */
#include "agent_internal.h"

int agent_robot_open_ros(sp_agent_robot *out, const sp_agent_config *cfg, sp_error *err)
{
    out->ops = NULL;
    out->ctx = NULL;
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "--ros: the ROS 2 bridge (ros module) is not in this build yet; "
                        "use the offline robot");
}
