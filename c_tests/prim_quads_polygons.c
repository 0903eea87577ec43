/* ffl-test: differential */
/*
 * Quadrilaterals and polygons (§2.6.1): GL_QUADS with 0 to 13 vertices (an
 * incomplete last group of one to three vertices dropped), GL_QUAD_STRIP
 * (an odd last vertex dropped, fewer than four make nothing) and GL_POLYGON
 * (fewer than three make nothing). Convex shapes of both orientations (no
 * culling), a color and a normal per vertex, smooth shading, unlit and lit.
 * Feedback returns them as triangles; how a quad or polygon is split is the
 * implementation's choice (fflight splits as Mesa's draw module does, so the
 * streams compare one for one). Each fed-back vertex that is a drawn vertex
 * carries the reference's window coordinates and color.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

int main(void)
{
    static const GLenum modes[] = { GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    return vref_run_primitive_program(modes, (int)(sizeof modes / sizeof modes[0]), 13,
                                      0x717561u);
}
