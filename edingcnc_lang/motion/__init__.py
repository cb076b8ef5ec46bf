"""The motion stage (kinematics, joints, limits) and the sinks that write what a run did."""
