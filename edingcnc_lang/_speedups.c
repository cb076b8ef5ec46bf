/* The optional compiled core: the hot loops of a big job, byte for byte as the Python reference.
 *
 * non_plain_lines: syntax/parser.py's non_plain_lines (the check pass's scan for lines that are not plain).
 * plain_moves:     machine/plain_runs.py's plain_moves (runs of plain G0/G1 lines into targets).
 * plain_arcs:      machine/bulk.py's arc_run over BulkPath._arc_of_words (runs of arc lines with centre words or R).
 * arc_frame:       kinematics/trajectory.py's arc_frame (an arc's circle, for the planner).
 * arc_frame_rows:  kinematics/trajectory.py's arc_frame_rows (the circles of a batch's arcs, as columns).
 * arc_frame_bytes: the same as the doubles of a bytearray (motion/arc_table.py's ArcTable).
 * column_bounds:   motion/reach.py's column_bounds (the bounds of a batch, for the limit check).
 * trace_rows:      motion/sinks.py's trace_rows (the trace CSV rows of a batch, repr() of every number).
 * hole_moves:      machine/hole_runs.py's hole_moves (the moves of a run of lines that only name the next hole).
 * plan_window:   motion/planner/stage.py's Planner._commit for a window of straight moves and arcs (times, estimate, extremes).
 * arcs_beyond:     motion/reach.py's arcs_beyond (whether an arc of a batch reaches outside the limits).
 * hypot:           math.hypot of two numbers as the other parts compute it (a test entry point).
 * comp_lines:      pipeline/comp_runs.py's comp_lines (a run of plain corners of cutter compensation).
 *
 * One translation unit in parts, a part per job (csrc/speedups_*.c), included below in order: their
 * helpers stay static, private to the extension.
 *
 * Built by setuptools as an optional extension against the stable ABI (abi3, Python 3.10+);
 * without it the Python functions run (edingcnc_lang/speedups.py chooses).  Compiled with
 * -ffp-contract=off so a * b + c is rounded twice, as Python rounds it.
 */
#define Py_LIMITED_API 0x030A0000
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define G0 0
#define G1 10
#define NO_MOTION (-1)
#define NUMBER_BUFFER 512

static PyObject *linear_kind;
static PyObject *rapid_kind;

#include "csrc/common.c"
#include "csrc/speedups_plain.c"
#include "csrc/speedups_trace.c"
#include "csrc/speedups_math.c"
#include "csrc/speedups_arcs.c"
#include "csrc/speedups_frames.c"
#include "csrc/speedups_holes.c"
#include "csrc/speedups_plan.c"
#include "csrc/speedups_comp.c"

static PyMethodDef methods[] = {
    {"non_plain_lines", non_plain_lines, METH_VARARGS, "parser.non_plain_lines, compiled: (max_length, max_digits, chunk)."},
    {"plain_moves", plain_moves, METH_VARARGS, "machine.plain_runs.plain_moves, compiled."},
    {"trace_rows", trace_rows, METH_VARARGS, "outputs.trace_rows, compiled."},
    {"column_bounds", column_bounds, METH_VARARGS, "motion.reach.column_bounds, compiled."},
    {"arc_frame", arc_frame, METH_VARARGS, "kinematics.trajectory.arc_frame, compiled (a plain tuple)."},
    {"arc_frame_rows", arc_frame_rows, METH_VARARGS, "kinematics.trajectory.arc_frame_rows, compiled."},
    {"arc_frame_bytes", arc_frame_bytes, METH_VARARGS, "kinematics.trajectory.arc_frame_rows, compiled, as doubles in a bytearray."},
    {"plain_arcs", plain_arcs, METH_VARARGS, "machine.bulk.arc_run over BulkPath._arc_of_words, compiled."},
    {"hole_moves", hole_moves, METH_VARARGS, "machine.hole_runs.hole_moves, compiled."},
    {"plan_window", plan_window, METH_VARARGS, "motion.planner.stage.Planner._commit of a window of straight moves and arcs, compiled."},
    {"arcs_beyond", arcs_beyond, METH_VARARGS, "motion.reach.arcs_beyond, compiled."},
    {"hypot", hypot_entry, METH_VARARGS, "math.hypot(a, b) as the compiled core computes it, and whose algorithm."},
    {"comp_lines", comp_lines, METH_VARARGS, "pipeline.comp_runs.comp_lines, compiled."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_speedups", "The optional compiled core (see speedups.py).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__speedups(void)
{
    linear_kind = PyUnicode_InternFromString("linear");
    rapid_kind = PyUnicode_InternFromString("rapid");
    if (linear_kind == NULL || rapid_kind == NULL)
        return NULL;
    if (hypot_init() < 0)
        return NULL;
    {
        static const char *names[4] = {"center", "plane", "turn", "full_turns"};
        int k;
        for (k = 0; k < 4; k++)
            if ((arc_fields[k] = PyUnicode_InternFromString(names[k])) == NULL)
                return NULL;
    }
    return PyModule_Create(&module);
}
