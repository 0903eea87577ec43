/* ffl-test: differential */
/*
 * examples/legacy/bezier_patches.c, a classic evaluator program (bicubic patches with
 * glMap2f and GL_AUTO_NORMAL, lit) written against the system <GL/gl.h> only, built
 * unchanged against fflight and against OSMesa: its feedback compared.
 */
#include "../examples/legacy/bezier_patches.c"
