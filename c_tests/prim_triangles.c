/* ffl-test: differential */
/*
 * Separate triangles (§2.6.1): GL_TRIANGLES with 0 to 10 vertices, the
 * incomplete last group (one or two vertices) dropped; random triangles of
 * both orientations (no culling, so both facings are fed back), a color and a
 * normal per vertex, smooth shading, unlit and lit (two lights, specular,
 * color material). Each fed-back vertex that is a drawn vertex carries the
 * reference's window coordinates and color (reference/vertex_ref.h).
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

int main(void)
{
    static const GLenum modes[] = { GL_TRIANGLES };
    return vref_run_primitive_program(modes, (int)(sizeof modes / sizeof modes[0]), 10,
                                      0x747269u);
}
