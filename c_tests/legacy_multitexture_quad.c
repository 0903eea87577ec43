/* ffl-test: differential */
/*
 * examples/legacy/multitexture_quad.c, a classic multitexturing program (a lit quad, two
 * texture units each with its own coordinates from glMultiTexCoord2f and its own texture
 * matrix) written against the system <GL/gl.h> only: its init(), reshape() and display()
 * built unchanged against fflight and against OSMesa, display() run in feedback mode.
 * Feedback carries unit 0's coordinates (§5.3): positions, colors and coordinates are
 * compared across the builds, and each vertex's coordinates in both builds against unit
 * 0's texture matrix times its glMultiTexCoord2f(GL_TEXTURE0, ...) (reference/legacy_ref.h).
 * Unit 1's coordinates never reach feedback; they are checked where GL 1.5 keeps them:
 * each unit's current coordinates after the draw, and each unit's raster position
 * coordinates (§2.13: the unit's current coordinates through its texture matrix) against
 * the stored texture matrix times the current coordinates, in double.
 */
#include <GL/gl.h>
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"
#include "reference/texgen_ref.h"
#include "reference/legacy_ref.h"

#define glBegin lref_begin
#define glNormal3f lref_normal3f
#define glVertex3f lref_vertex3f
#define glMultiTexCoord2f lref_multi_tex_coord2f
#define main multitexture_quad_main
#include "../examples/legacy/multitexture_quad.c"
#undef main
#undef glMultiTexCoord2f

/* Unit 0's current coordinates through its texture matrix. */
static void unit0(const double *object, double *strq)
{
    double current[4];
    int k;
    (void)object;
    for (k = 0; k < 4; k++)
        current[k] = lref.tex_coord[k];
    tref_mul(lref.texture_matrix, current, strq);
}

/* "<tag> unit <u> strq <raster coordinates> current <current coordinates> ref strq
 * <texture matrix times current>" for both units, then the active unit restored. */
static void raster_units(const char *tag)
{
    GLint active;
    int unit, k;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (unit = 0; unit < 2; unit++) {
        GLfloat raster[4], current[4];
        double matrix[16], c[4], expected[4];
        glActiveTexture((GLenum)(GL_TEXTURE0 + unit));
        glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, raster);
        glGetFloatv(GL_CURRENT_TEXTURE_COORDS, current);
        tref_read_matrix(GL_TEXTURE_MATRIX, matrix);
        for (k = 0; k < 4; k++)
            c[k] = current[k];
        tref_mul(matrix, c, expected);
        printf("%s unit %d", tag, unit);
        ffl_pfv("strq", raster, 4);
        ffl_pfv("current", current, 4);
        printf(" ref");
        ffl_pdv("strq", expected, 4);
        printf("\n");
    }
    glActiveTexture((GLenum)active);
}

int main(void)
{
    int failed;
    ffl_test_init();
    lref_init(unit0, NULL);
    init();
    reshape(64, 64);
    failed = lref_run("quad", display);
    vref_print_counts(&lref.vref);
    /* after the draw: the last corner's coordinates of each unit */
    glRasterPos3f(0.25f, -0.5f, 0.0f);
    raster_units("raster_after_draw");
    /* new coordinates per unit, then a raster position */
    glMultiTexCoord2f(GL_TEXTURE0, 0.75f, -0.25f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.125f, 0.625f);
    glRasterPos3f(-0.5f, 0.25f, 0.5f);
    raster_units("raster_new");
    ffl_print_error("raster");
    return failed;
}
