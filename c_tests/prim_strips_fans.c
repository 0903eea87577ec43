/* ffl-test: differential */
/*
 * Triangle strips and fans (§2.6.1): GL_TRIANGLE_STRIP and GL_TRIANGLE_FAN
 * with 0 to 10 vertices (fewer than three make nothing). A strip's odd
 * triangles keep the strip's orientation; a fan turns around its first
 * vertex (here sometimes by more than a full turn). Random shapes of both
 * orientations (no culling), a color and a normal per vertex, smooth
 * shading, unlit and lit. Each fed-back vertex that is a drawn vertex carries
 * the reference's window coordinates and color (reference/vertex_ref.h).
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

int main(void)
{
    static const GLenum modes[] = { GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN };
    return vref_run_primitive_program(modes, (int)(sizeof modes / sizeof modes[0]), 10,
                                      0x737472u);
}
