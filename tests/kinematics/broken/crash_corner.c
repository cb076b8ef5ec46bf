/* Broken on purpose: KinematicsInverse writes through a NULL pointer for X > 90 and Y > 90 (K602). */
#include "edingcnc_kins.h"

KINS_EXPORT int KINS_CALL KinematicsInverse(CNC_CART_DOUBLE pos, CNC_JOINT_DOUBLE *joints,
                                            const CNC_KINEMATICS_INVERSE_FLAGS *iflags,
                                            CNC_KINEMATICS_FORWARD_FLAGS *fflags, double toolLength)
{
    CNC_UNUSED(iflags); CNC_UNUSED(fflags); CNC_UNUSED(toolLength);
    if (pos.x > 90.0 && pos.y > 90.0) {
        *(volatile int *)0 = 1;
    }
    joints->jx = pos.x; joints->jy = pos.y; joints->jz = pos.z;
    joints->ja = pos.a; joints->jb = pos.b; joints->jc = pos.c;
    return 0;
}

KINS_EXPORT int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE joints, CNC_CART_DOUBLE *pos,
                                            const CNC_KINEMATICS_FORWARD_FLAGS *fflags,
                                            CNC_KINEMATICS_INVERSE_FLAGS *iflags, double toolLength)
{
    CNC_UNUSED(iflags); CNC_UNUSED(fflags); CNC_UNUSED(toolLength);
    pos->x = joints.jx; pos->y = joints.jy; pos->z = joints.jz;
    pos->a = joints.ja; pos->b = joints.jb; pos->c = joints.jc;
    return 0;
}

KINS_EXPORT int KINS_CALL KinematicsControl(int id, KIN_CONTROLDATA *data)
{
    CNC_UNUSED(data);
    return (id >= 1 && id <= 4) ? 0 : -1;
}

KINS_EXPORT CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void) { return CNC_KINEMATICS_TYPE_CUSTOM_1; }

KINS_EXPORT char *KINS_CALL KinematicsVersion(void) { return (char *)"CRASH CORNER 1.0"; }
