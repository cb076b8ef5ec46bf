/*
 * mycorexy.c - a CoreXY machine written as a compiled kinematics plug-in (custom type 1).
 *
 * Two belts drive X and Y together: motor X = x + y, motor Y = x - y.  The user output
 * (control ID 5) is the pair of belt motor positions, written to #1000 and #1001 by the ini.
 * Build: ecnc kins build examples/cplugin/mycorexy.c   (writes mycorexy.so next to it)
 */
#include "edingcnc_kins.h"

static char KIN_VERSION[] = "MY COREXY 1.0";
static int kinEnabled = 0;
static double lastMotorX = 0.0;
static double lastMotorY = 0.0;

int KINS_CALL KinematicsControl(int controlID, KIN_CONTROLDATA *controlData)
{
    int i;
    switch (controlID) {
    case CNC_KIN_CONTROL_ID_OPEN:
    case CNC_KIN_CONTROL_ID_CLOSE:
        break;
    case CNC_KIN_CONTROL_ID_OFF:
        kinEnabled = 0;
        break;
    case CNC_KIN_CONTROL_ID_ON:
        kinEnabled = 1;
        break;
    case KIN_CONTROL_ID_USER_OUTPUT:
        for (i = 0; i < 12; i++)
            controlData->dData[i] = 0.0;
        controlData->dData[0] = lastMotorX;
        controlData->dData[1] = lastMotorY;
        break;
    default:
        return -1;
    }
    return 0;
}

int KINS_CALL KinematicsInverse(CNC_CART_DOUBLE pos, CNC_JOINT_DOUBLE *joints,
                                const CNC_KINEMATICS_INVERSE_FLAGS *iflags,
                                CNC_KINEMATICS_FORWARD_FLAGS *fflags, double toolLength)
{
    CNC_UNUSED(iflags);
    CNC_UNUSED(fflags);
    CNC_UNUSED(toolLength);
    joints->jx = kinEnabled ? pos.x + pos.y : pos.x;
    joints->jy = kinEnabled ? pos.x - pos.y : pos.y;
    joints->jz = pos.z;
    joints->ja = pos.a;
    joints->jb = pos.b;
    joints->jc = pos.c;
    lastMotorX = joints->jx;
    lastMotorY = joints->jy;
    return 0;
}

int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE joints, CNC_CART_DOUBLE *pos,
                                const CNC_KINEMATICS_FORWARD_FLAGS *fflags,
                                CNC_KINEMATICS_INVERSE_FLAGS *iflags, double toolLength)
{
    CNC_UNUSED(fflags);
    CNC_UNUSED(iflags);
    CNC_UNUSED(toolLength);
    pos->x = kinEnabled ? (joints.jx + joints.jy) / 2.0 : joints.jx;
    pos->y = kinEnabled ? (joints.jx - joints.jy) / 2.0 : joints.jy;
    pos->z = joints.jz;
    pos->a = joints.ja;
    pos->b = joints.jb;
    pos->c = joints.jc;
    return 0;
}

CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void)
{
    return CNC_KINEMATICS_TYPE_CUSTOM_1;
}

char *KINS_CALL KinematicsVersion(void)
{
    return KIN_VERSION;
}
