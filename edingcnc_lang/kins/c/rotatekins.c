/*
 * rotatekins.c - the virtual C axis: C rotates the XY plane about a rotation point.
 *
 * The C twin of kins/rotatekins.py (the same behaviour, checked against it by the tests).
 * Build: ecnc kins build rotatekins.c   (or: cc -shared -fPIC -O2 -I. rotatekins.c -o rotatekins.so -lm)
 */
#include <math.h>
#include "edingcnc_kins.h"

static char KIN_VERSION[] = "EDINGCNC-LANG VIRTUAL C 1.0";

static int kinEnabled = 0;
static double rotationPointX = 0.0;
static double rotationPointY = 0.0;
static double rotationAngle = 0.0; /* degrees: the C of the last inverse call */

/* Rotate (x, y) about the rotation point by angleDeg, counter-clockwise. */
static void rotate(double angleDeg, double *x, double *y)
{
    double t = CNC_D2R(angleDeg);
    double dx = *x - rotationPointX;
    double dy = *y - rotationPointY;
    *x = rotationPointX + dx * cos(t) - dy * sin(t);
    *y = rotationPointY + dx * sin(t) + dy * cos(t);
}

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
        /* the rotation point is where the kinematics is switched on */
        kinEnabled = 1;
        rotationPointX = controlData->dData[0];
        rotationPointY = controlData->dData[1];
        break;
    case KIN_CONTROL_ID_USER_OUTPUT:
        for (i = 0; i < 12; i++)
            controlData->dData[i] = 0.0;
        controlData->dData[0] = rotationPointX;
        controlData->dData[1] = rotationPointY;
        controlData->dData[2] = rotationAngle;
        break;
    case KIN_CONTROL_ID_USER1: /* set the rotation point */
        rotationPointX = controlData->dData[0];
        rotationPointY = controlData->dData[1];
        break;
    case KIN_CONTROL_ID_USER2: /* set the rotation angle */
        rotationAngle = controlData->dData[0];
        break;
    case KIN_CONTROL_ID_USER3: /* get the rotation point */
        controlData->dData[0] = rotationPointX;
        controlData->dData[1] = rotationPointY;
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
    joints->jx = pos.x;
    joints->jy = pos.y;
    if (kinEnabled) {
        rotationAngle = pos.c;
        rotate(rotationAngle, &joints->jx, &joints->jy);
    }
    joints->jz = pos.z;
    joints->ja = pos.a;
    joints->jb = pos.b;
    joints->jc = 0.0; /* C exists only in Cartesian space */
    return 0;
}

int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE joints, CNC_CART_DOUBLE *pos,
                                const CNC_KINEMATICS_FORWARD_FLAGS *fflags,
                                CNC_KINEMATICS_INVERSE_FLAGS *iflags, double toolLength)
{
    CNC_UNUSED(fflags);
    CNC_UNUSED(iflags);
    CNC_UNUSED(toolLength);
    pos->x = joints.jx;
    pos->y = joints.jy;
    if (kinEnabled)
        rotate(-rotationAngle, &pos->x, &pos->y);
    pos->z = joints.jz;
    pos->a = joints.ja;
    pos->b = joints.jb;
    pos->c = rotationAngle; /* no C motor: report the angle of the last inverse */
    return 0;
}

CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void)
{
    return CNC_KINEMATICS_TYPE_VIRTUAL_C;
}

char *KINS_CALL KinematicsVersion(void)
{
    return KIN_VERSION;
}
