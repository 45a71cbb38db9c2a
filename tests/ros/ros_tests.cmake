# ROS tests that need more than one executable (see tests/ros/)
