/*
 * edingcnc_kins.h - the EdingCNC kinematics plug-in interface, as used by edingcnc-lang.
 *
 * Written for this project from the interface description in docs/kinematics.md: the same
 * packed data layout and the same five exported functions the controller calls, so a plug-in
 * built against it also loads in the controller (a .dll on Windows, __stdcall) and in
 * edingcnc-lang (a .so, platform calling convention, loaded with ctypes).
 */
#ifndef EDINGCNC_KINS_H
#define EDINGCNC_KINS_H

#ifdef _WIN32
#define KINS_EXPORT __declspec(dllexport)
#define KINS_CALL __stdcall
#else
#define KINS_EXPORT __attribute__((visibility("default")))
#define KINS_CALL
#endif

#ifdef __cplusplus
extern "C" {
#endif

#pragma pack(push, 1)

/* Tool-tip position: x y z in mm, a b c in degrees. */
typedef struct {
    double x, y, z, a, b, c;
} CNC_CART_DOUBLE;

/* Motor positions. */
typedef struct {
    double jx, jy, jz, ja, jb, jc;
} CNC_JOINT_DOUBLE;

typedef struct {
    double x, y, z;
} CNC_VECTOR;

/* Parameter block of KinematicsControl: KIN CTRL p1..p6 arrive in dData[0..5]. */
typedef union {
    double dData[12];
    int iData[12];
    char cData[64];
} KIN_CONTROLDATA;

#pragma pack(pop)

typedef unsigned int CNC_KINEMATICS_FORWARD_FLAGS;
typedef unsigned int CNC_KINEMATICS_INVERSE_FLAGS;

/* Control IDs. */
#define CNC_KIN_CONTROL_ID_OPEN 1
#define CNC_KIN_CONTROL_ID_CLOSE 2
#define CNC_KIN_CONTROL_ID_OFF 3
#define CNC_KIN_CONTROL_ID_ON 4          /* edingcnc-lang passes the machine position x..c in dData[0..5] */
#define KIN_CONTROL_ID_USER_OUTPUT 5     /* edingcnc-lang: fill dData[0..11] with the user output */
#define KIN_CONTROL_ID_JOINT_LIMITS 9    /* reserved for the system */
#define KIN_CONTROL_ID_KIN_LIMITS 10     /* reserved for the system */
#define KIN_CONTROL_ID_USER1 11
#define KIN_CONTROL_ID_USER2 12
#define KIN_CONTROL_ID_USER3 13
#define KIN_CONTROL_ID_USER4 14
#define KIN_CONTROL_ID_USER5 15
#define KIN_CONTROL_ID_USER6 16
/* edingcnc-lang: at load, once per [KINEMATICS] setting of cnc.ini: the lower-case key in cData
   (NUL-terminated), its value as a number in dData[8] (NaN when it is not a number) */
#define ECNC_KIN_CONTROL_ID_SETTING 100

/* Kinematics types (KinematicsType(), also reported in #5150). */
typedef int CNC_KINEMATICS_TYPE;
#define CNC_KINEMATICS_TYPE_UNDEFINED 0
#define CNC_KINEMATICS_TYPE_TRIVIAL 1
#define CNC_KINEMATICS_TYPE_CYLINDER_A 2
#define CNC_KINEMATICS_TYPE_VIRTUAL_C 3
#define CNC_KINEMATICS_TYPE_LINEAR_DELTA 4
#define CNC_KINEMATICS_TYPE_COREXY 5
#define CNC_KINEMATICS_TYPE_CUSTOM_1 18  /* custom 1..11 = 18..28, custom 12 = 30 */
#define CNC_KINEMATICS_TYPE_TRUNNION_AC 31
#define CNC_KINEMATICS_TYPE_TRUNNION_BC 32

#define CNC_UNUSED(x) ((void)(x))
#define CNC_PI 3.14159265358979323846
#define CNC_D2R(deg) ((deg) * CNC_PI / 180.0)

/* Cartesian -> joints; non-zero means the position cannot be reached. */
KINS_EXPORT int KINS_CALL KinematicsInverse(CNC_CART_DOUBLE pos, CNC_JOINT_DOUBLE *joints,
                                            const CNC_KINEMATICS_INVERSE_FLAGS *iflags,
                                            CNC_KINEMATICS_FORWARD_FLAGS *fflags, double toolLength);

/* Joints -> Cartesian; called after homing and when the kinematics is switched on. */
KINS_EXPORT int KINS_CALL KinematicsForward(CNC_JOINT_DOUBLE joints, CNC_CART_DOUBLE *pos,
                                            const CNC_KINEMATICS_FORWARD_FLAGS *fflags,
                                            CNC_KINEMATICS_INVERSE_FLAGS *iflags, double toolLength);

/* Switching, parameters and queries; returns -1 for an unknown control ID. */
KINS_EXPORT int KINS_CALL KinematicsControl(int controlID, KIN_CONTROLDATA *controlData);

KINS_EXPORT CNC_KINEMATICS_TYPE KINS_CALL KinematicsType(void);

KINS_EXPORT char *KINS_CALL KinematicsVersion(void);

/* Optional: per-axis Cartesian velocity/acceleration limits of a line or an arc. */
KINS_EXPORT int KINS_CALL KinematicsInverseMaxFeed(CNC_CART_DOUBLE start, CNC_CART_DOUBLE end,
                                                   CNC_CART_DOUBLE *maxVel, CNC_CART_DOUBLE *maxAcc,
                                                   double toolLength);
KINS_EXPORT int KINS_CALL KinematicsInverseMaxFeedArc(CNC_CART_DOUBLE start, CNC_CART_DOUBLE end,
                                                      CNC_VECTOR center, CNC_VECTOR normal, int turn,
                                                      CNC_CART_DOUBLE *maxVel, CNC_CART_DOUBLE *maxAcc,
                                                      double toolLength);

#ifdef __cplusplus
}
#endif

#endif /* EDINGCNC_KINS_H */
